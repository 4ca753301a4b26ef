// Cylindrically orthotropic materials: compliance, stiffness, admissibility
// and the rotation to global axes.
#include "material/material.hpp"

#include "support/test_materials.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

using coremodal::testing::paperboard;

OrthotropicMaterial steel() { return OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850); }

// Symmetric to round-off (1e-15 of the largest entry: the 3x3 inverse may
// order its products differently across the diagonal) and Cholesky-factorable.
bool is_symmetric_positive_definite(const Matrix6& A) {
    if ((A - A.transpose()).cwiseAbs().maxCoeff() > 1e-15 * A.cwiseAbs().maxCoeff()) return false;
    return Eigen::LLT<Matrix6>(A).info() == Eigen::Success &&
           Eigen::SelfAdjointEigenSolver<Matrix6>(A).eigenvalues().minCoeff() > 0;
}

// Kelvin (Mandel) form: shear rows and columns scaled by sqrt(2). In this
// form a rotation acts orthogonally, so eigenvalues are invariants; in the
// engineering-shear Voigt form the change of basis is not orthogonal and its
// eigenvalues legitimately change under rotation.
Matrix6 kelvin(const Matrix6& C) {
    Eigen::Matrix<double, 6, 1> w;
    w << 1, 1, 1, std::sqrt(2.0), std::sqrt(2.0), std::sqrt(2.0);
    return w.asDiagonal() * C * w.asDiagonal();
}

}  // namespace

TEST_CASE("Compliance and stiffness are symmetric positive definite inverses", "[material]") {
    for (const OrthotropicMaterial& m : {paperboard(), steel()}) {
        INFO(m.name);
        const Matrix6 S = compliance_cylindrical(m);
        const Matrix6 C = stiffness_cylindrical(m);
        CHECK(is_symmetric_positive_definite(S));
        CHECK(is_symmetric_positive_definite(C));
        // C*S = I up to round-off amplified by the condition number of S
        // (~1e3 for paperboard: E_z / G_rz = 50, E_z / E_r = 200): 1e-12.
        CHECK((C * S - Matrix6::Identity()).cwiseAbs().maxCoeff() < 1e-12);
    }
}

TEST_CASE("Compliance follows the nu_ij = -eps_j/eps_i convention", "[material]") {
    const OrthotropicMaterial m = paperboard();
    const Matrix6 S = compliance_cylindrical(m);
    // Uniaxial radial stress: eps_theta = -nu_rtheta * eps_r, eps_z = -nu_rz * eps_r.
    Eigen::Matrix<double, 6, 1> sigma = Eigen::Matrix<double, 6, 1>::Zero();
    sigma(0) = 1e6;
    const Eigen::Matrix<double, 6, 1> eps = S * sigma;
    // Exact up to a couple of round-offs in one division and one product.
    CHECK(eps(0) == Approx(1e6 / m.E_r).epsilon(1e-14));
    CHECK(eps(1) == Approx(-m.nu_rtheta * eps(0)).epsilon(1e-14));
    CHECK(eps(2) == Approx(-m.nu_rz * eps(0)).epsilon(1e-14));
    // Uniaxial axial stress: eps_r = -nu_zr * eps_z with nu_zr = nu_rz E_z / E_r = 0.394.
    sigma.setZero();
    sigma(2) = 1e6;
    const Eigen::Matrix<double, 6, 1> eps_z = S * sigma;
    CHECK(-eps_z(0) / eps_z(2) == Approx(m.nu_rz * m.E_z / m.E_r).epsilon(1e-14));
}

TEST_CASE("Isotropic materials are recognised and have the Lame stiffness", "[material]") {
    const OrthotropicMaterial m = steel();
    CHECK(m.is_isotropic());
    CHECK_FALSE(paperboard().is_isotropic());
    const double E = 210e9, nu = 0.3;
    const double mu = E / (2 * (1 + nu)), lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
    const Matrix6 C = stiffness_cylindrical(m);
    // A 3x3 inverse of well-conditioned data: a few ulps of E.
    CHECK(C(0, 0) == Approx(lambda + 2 * mu).epsilon(1e-13));
    CHECK(C(0, 1) == Approx(lambda).epsilon(1e-13));
    CHECK(C(3, 3) == Approx(mu).epsilon(1e-15));
    CHECK(C(5, 5) == Approx(mu).epsilon(1e-15));
}

TEST_CASE("Admissible materials pass the admissibility check", "[material]") {
    CHECK_FALSE(why_not_admissible(paperboard()).has_value());
    CHECK_FALSE(why_not_admissible(steel()).has_value());
}

TEST_CASE("A Poisson set making the compliance indefinite is rejected by name", "[material]") {
    SECTION("pair condition: nu_rz = 0.1 gives nu_zr = 19.7 and 1 - nu_rz*nu_zr < 0") {
        OrthotropicMaterial m = paperboard();
        m.nu_rz = 0.1;
        const auto reason = why_not_admissible(m);
        REQUIRE(reason.has_value());
        CHECK_THAT(*reason, Catch::Contains("not positive definite") &&
                                Catch::Contains("1 - nu_rz*nu_zr") && Catch::Contains("paperboard"));
        CHECK(Eigen::SelfAdjointEigenSolver<Matrix6>(compliance_cylindrical(m)).eigenvalues()(0) < 0);
    }
    SECTION("determinant condition: isotropic nu = 0.6 passes every pair but not the determinant") {
        const OrthotropicMaterial m = OrthotropicMaterial::isotropic("rubbery", 1e6, 0.6, 1000);
        const auto reason = why_not_admissible(m);
        REQUIRE(reason.has_value());
        CHECK_THAT(*reason, Catch::Contains("2*nu_rtheta*nu_thetaz*nu_zr") &&
                                Catch::Contains("-0.512"));  // 1 - 3*0.36 - 2*0.216
        CHECK(Eigen::SelfAdjointEigenSolver<Matrix6>(compliance_cylindrical(m)).eigenvalues()(0) < 0);
    }
}

TEST_CASE("Non-positive moduli and density are rejected by name and value", "[material]") {
    OrthotropicMaterial m = paperboard();
    m.G_rz = 0;
    CHECK_THAT(why_not_admissible(m).value_or(""), Catch::Contains("G_rz = 0"));
    m = paperboard();
    m.density = -700;
    CHECK_THAT(why_not_admissible(m).value_or(""), Catch::Contains("density = -700"));
}

TEST_CASE("The admissibility verdict agrees with the eigenvalues of S", "[material]") {
    // Sweep Poisson ratios across the boundary; the closed-form conditions
    // must say the same as a numerical eigenvalue check.
    for (double nu_rz : {0.0, 0.002, 0.02, 0.05, 0.08}) {
        for (double nu_thetaz : {-0.9, 0.0, 0.3, 0.7, 1.0, 1.3}) {
            OrthotropicMaterial m = paperboard();
            m.nu_rz = nu_rz;
            m.nu_thetaz = nu_thetaz;
            const double min_eig =
                Eigen::SelfAdjointEigenSolver<Matrix6>(compliance_cylindrical(m)).eigenvalues()(0);
            INFO("nu_rz = " << nu_rz << ", nu_thetaz = " << nu_thetaz);
            CHECK(why_not_admissible(m).has_value() == (min_eig <= 0));
        }
    }
}

TEST_CASE("At theta = 0 the global stiffness is the cylindrical one", "[material][rotation]") {
    // e_r = x, e_theta = y: (rr, tt, zz, tz, rz, rt) -> (xx, yy, zz, yz, xz, xy),
    // the same Voigt positions; cos 0 and sin 0 are exact, so equality is exact.
    const Matrix6 C = stiffness_cylindrical(paperboard());
    CHECK((rotate_to_global(C, 0.0) - C).cwiseAbs().maxCoeff() == 0.0);
}

TEST_CASE("At theta = 90 degrees the radial modulus acts along y", "[material][rotation]") {
    const OrthotropicMaterial m = paperboard();
    const Matrix6 C = stiffness_cylindrical(m);
    const Matrix6 Cg = rotate_to_global(C, M_PI / 2);
    // cos(pi/2) = 6e-17, not 0: errors of 6e-17 * C_tt / C_rr ~ 1e-14 relative.
    const double tol = 1e-12;
    // Uniaxial strain eps_yy = 1 is radial there: sigma = C(:, rr).
    Eigen::Matrix<double, 6, 1> eps_yy = Eigen::Matrix<double, 6, 1>::Zero();
    eps_yy(1) = 1;
    const Eigen::Matrix<double, 6, 1> sigma = Cg * eps_yy;
    CHECK(sigma(1) == Approx(C(0, 0)).epsilon(tol));  // sigma_yy = sigma_rr (stiff if r, theta swapped)
    CHECK(sigma(0) == Approx(C(1, 0)).epsilon(tol));  // sigma_xx = sigma_tt
    CHECK(sigma(2) == Approx(C(2, 0)).epsilon(tol));  // sigma_zz
    // The radial direction is ~100 times softer than the hoop direction here.
    CHECK(Cg(1, 1) < 0.05 * Cg(0, 0));
    CHECK(Cg(0, 0) == Approx(C(1, 1)).epsilon(tol));
    // Shears: yz is rz, xz is (-theta) z, xy is -(r theta) -> same moduli.
    CHECK(Cg(3, 3) == Approx(m.G_rz).epsilon(tol));
    CHECK(Cg(4, 4) == Approx(m.G_thetaz).epsilon(tol));
    CHECK(Cg(5, 5) == Approx(m.G_rtheta).epsilon(tol));
}

TEST_CASE("Rotation preserves symmetry and Kelvin-form eigenvalues", "[material][rotation]") {
    const Matrix6 C = stiffness_cylindrical(paperboard());
    const Eigen::Matrix<double, 6, 1> expected =
        Eigen::SelfAdjointEigenSolver<Matrix6>(kelvin(C)).eigenvalues();
    for (double theta : {0.3, 1.0, 2.5, -2.0, 7.0}) {
        INFO("theta = " << theta);
        const Matrix6 Cg = rotate_to_global(C, theta);
        // Round-off of two 6x6 products, relative to the largest entry.
        CHECK((Cg - Cg.transpose()).cwiseAbs().maxCoeff() < 1e-14 * C.cwiseAbs().maxCoeff());
        const Eigen::Matrix<double, 6, 1> got =
            Eigen::SelfAdjointEigenSolver<Matrix6>(kelvin(Cg)).eigenvalues();
        // Eigenvalue perturbation <= ||dC|| ~ 1e-15 * ||C||; 1e-12 of the largest.
        CHECK((got - expected).cwiseAbs().maxCoeff() < 1e-12 * expected.maxCoeff());
    }
}

TEST_CASE("Isotropic stiffness is unchanged by rotation", "[material][rotation]") {
    const Matrix6 C = stiffness_cylindrical(steel());
    // Round-off only, relative to the largest entry.
    CHECK((rotate_to_global(C, 0.7) - C).cwiseAbs().maxCoeff() < 1e-14 * C.maxCoeff());
}
