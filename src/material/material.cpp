// Cylindrically orthotropic linear elastic materials: compliance, stiffness,
// admissibility and the rotation from the cylindrical to the global frame.
#include "material/material.hpp"

#include <array>
#include <cmath>
#include <sstream>
#include <utility>

namespace coremodal {

namespace {

// Two moduli (or Poisson ratios) that agree to this relative tolerance count as
// equal in is_isotropic(): values typed by users or converted from other units
// carry round-off of a few ulps, far below any physically meaningful anisotropy.
constexpr double isotropy_relative_tolerance = 1e-12;

bool nearly_equal(double a, double b) {
    return std::abs(a - b) <= isotropy_relative_tolerance * std::max(std::abs(a), std::abs(b));
}

// The Poisson ratios below the diagonal follow from symmetry of S:
// nu_ji = nu_ij * E_j / E_i.
struct ReciprocalPoisson {
    double nu_thetar, nu_zr, nu_ztheta;
};

ReciprocalPoisson reciprocal_poisson(const OrthotropicMaterial& m) {
    return {m.nu_rtheta * m.E_theta / m.E_r, m.nu_rz * m.E_z / m.E_r,
            m.nu_thetaz * m.E_z / m.E_theta};
}

std::string format_value(double value) {
    std::ostringstream out;
    out.precision(6);
    out << value;
    return out.str();
}

std::string material_label(const OrthotropicMaterial& m) {
    return m.name.empty() ? std::string("material") : "material '" + m.name + "'";
}

// First non-positive (or non-finite) modulus or density, as a sentence.
std::optional<std::string> why_not_positive(const OrthotropicMaterial& m) {
    const std::array<std::pair<const char*, double>, 7> quantities{{{"E_r", m.E_r},
                                                                    {"E_theta", m.E_theta},
                                                                    {"E_z", m.E_z},
                                                                    {"G_rtheta", m.G_rtheta},
                                                                    {"G_rz", m.G_rz},
                                                                    {"G_thetaz", m.G_thetaz},
                                                                    {"density", m.density}}};
    for (const auto& [key, value] : quantities) {
        if (!(value > 0) || !std::isfinite(value))
            return material_label(m) + ": " + key + " = " + format_value(value) +
                   " must be positive and finite";
    }
    return std::nullopt;
}

}  // namespace

OrthotropicMaterial OrthotropicMaterial::isotropic(std::string name, double E, double nu,
                                                   double density, std::string source) {
    OrthotropicMaterial m;
    m.name = std::move(name);
    m.E_r = m.E_theta = m.E_z = E;
    m.G_rtheta = m.G_rz = m.G_thetaz = E / (2.0 * (1.0 + nu));
    m.nu_rtheta = m.nu_rz = m.nu_thetaz = nu;
    m.density = density;
    m.source = std::move(source);
    return m;
}

bool OrthotropicMaterial::is_isotropic() const {
    const double G = E_r / (2.0 * (1.0 + nu_rtheta));
    return nearly_equal(E_r, E_theta) && nearly_equal(E_r, E_z) &&
           nearly_equal(nu_rtheta, nu_rz) && nearly_equal(nu_rtheta, nu_thetaz) &&
           nearly_equal(G_rtheta, G) && nearly_equal(G_rz, G) && nearly_equal(G_thetaz, G);
}

// S(i, j) = -nu_ij / E_i off the diagonal of the normal block; the symmetric
// partner -nu_ji / E_j equals it by the reciprocity relation, so we fill both
// from nu_ij / E_i and never need nu_ji explicitly.
Matrix6 compliance_cylindrical(const OrthotropicMaterial& m) {
    Matrix6 S = Matrix6::Zero();
    S(0, 0) = 1.0 / m.E_r;
    S(1, 1) = 1.0 / m.E_theta;
    S(2, 2) = 1.0 / m.E_z;
    S(0, 1) = S(1, 0) = -m.nu_rtheta / m.E_r;
    S(0, 2) = S(2, 0) = -m.nu_rz / m.E_r;
    S(1, 2) = S(2, 1) = -m.nu_thetaz / m.E_theta;
    S(3, 3) = 1.0 / m.G_thetaz;  // tz
    S(4, 4) = 1.0 / m.G_rz;      // rz
    S(5, 5) = 1.0 / m.G_rtheta;  // rt
    return S;
}

// S is block diagonal (normal 3x3, shear diagonal), so invert the blocks
// separately: exact for the shears and cheaper than a 6x6 inverse.
Matrix6 stiffness_cylindrical(const OrthotropicMaterial& m) {
    const Matrix6 S = compliance_cylindrical(m);
    Matrix6 C = Matrix6::Zero();
    C.topLeftCorner<3, 3>() = S.topLeftCorner<3, 3>().inverse();
    C(3, 3) = m.G_thetaz;
    C(4, 4) = m.G_rz;
    C(5, 5) = m.G_rtheta;
    return C;
}

// With positive moduli, S is positive definite iff its normal 3x3 block is,
// i.e. iff each 2x2 minor condition 1 - nu_ij*nu_ji > 0 holds and the
// determinant condition Delta > 0 holds (E_r*E_theta*E_z*det = Delta).
std::optional<std::string> why_not_admissible(const OrthotropicMaterial& m) {
    if (auto reason = why_not_positive(m)) return reason;
    const ReciprocalPoisson rec = reciprocal_poisson(m);
    const std::string prefix = material_label(m) + ": compliance matrix is not positive definite: ";
    const std::array<std::pair<const char*, double>, 3> pair_conditions{
        {{"1 - nu_rtheta*nu_thetar", 1.0 - m.nu_rtheta * rec.nu_thetar},
         {"1 - nu_rz*nu_zr", 1.0 - m.nu_rz * rec.nu_zr},
         {"1 - nu_thetaz*nu_ztheta", 1.0 - m.nu_thetaz * rec.nu_ztheta}}};
    for (const auto& [expression, value] : pair_conditions) {
        if (!(value > 0)) return prefix + expression + " = " + format_value(value) + " <= 0";
    }
    const double delta = 1.0 - m.nu_rtheta * rec.nu_thetar - m.nu_rz * rec.nu_zr -
                         m.nu_thetaz * rec.nu_ztheta -
                         2.0 * m.nu_rtheta * m.nu_thetaz * rec.nu_zr;
    if (!(delta > 0))
        return prefix +
               "1 - nu_rtheta*nu_thetar - nu_rz*nu_zr - nu_thetaz*nu_ztheta - "
               "2*nu_rtheta*nu_thetaz*nu_zr = " +
               format_value(delta) + " <= 0";
    return std::nullopt;
}

namespace {

// Voigt index -> tensor index pair, same order in both frames.
constexpr int voigt_pair[6][2] = {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};

// Bond matrix T with sigma_global = T * sigma_cyl (Voigt), for
// sigma_global = A * sigma_cyl * A^T. A shear component sigma_kl (k != l)
// stands for both sigma_kl and sigma_lk, hence the two terms.
Matrix6 stress_rotation(const Eigen::Matrix3d& A) {
    Matrix6 T;
    for (int I = 0; I < 6; ++I) {
        const int i = voigt_pair[I][0], j = voigt_pair[I][1];
        for (int J = 0; J < 6; ++J) {
            const int k = voigt_pair[J][0], l = voigt_pair[J][1];
            T(I, J) = (k == l) ? A(i, k) * A(j, k) : A(i, k) * A(j, l) + A(i, l) * A(j, k);
        }
    }
    return T;
}

}  // namespace

// Columns of A are e_r, e_theta, e_z in global components. With engineering
// shear strains, eps_cyl = T^T eps_global, so the strain energy
// eps_cyl^T C eps_cyl gives C_global = T C T^T.
Matrix6 rotate_to_global(const Matrix6& C_cylindrical, double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    Eigen::Matrix3d A;
    A << c, -s, 0,  //
        s, c, 0,    //
        0, 0, 1;
    const Matrix6 T = stress_rotation(A);
    return T * C_cylindrical * T.transpose();
}

}  // namespace coremodal
