// Centrifugal stiffening at the harmonic level (effects/rotation.hpp,
// models/harmonic/centrifugal_prestress) against independent truths: the
// stresses of a thin spinning disc (Timoshenko & Goodier, Theory of
// Elasticity, 3rd ed., sec. 32), the invariance of a free body's rigid
// motions (K_Omega of a rigid translation or tilt is zero: the prestress's
// geometric stiffness and the convective softening cancel there, each alone
// does not), and the exact stationary-frame frequencies of a thin spinning
// ring, omega = sqrt(omega_0^2 + beta^2 Omega^2) +- beta Omega.
#include "assembly/harmonic_system.hpp"
#include "eigensolve/gyroscopic_solver.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "eigensolve/projected_gyroscopic.hpp"
#include "geometry/section_mesh.hpp"
#include "geometry/tube_section.hpp"
#include "models/harmonic/centrifugal_prestress.hpp"
#include "models/harmonic/rotating_harmonics.hpp"
#include "models/harmonic/spinning_harmonic.hpp"
#include "models/part_materials.hpp"
#include "models/solve_steps.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;
using coremodal::testing::Section;
using coremodal::testing::section_of;

namespace {

constexpr double kGauss[3] = {-0.7745966692414834, 0.0, 0.7745966692414834};

Quad8Coords coords(const SectionMesh& mesh, int c) {
    Quad8Coords x;
    for (int a = 0; a < 8; ++a) x.row(a) << mesh.nodes[mesh.cells[c][a]][0], mesh.nodes[mesh.cells[c][a]][1];
    return x;
}

// Sum over the cells of K_e q_e on the section's nodes (3 per node): a free
// body's section has no held component away from the axis.
std::vector<double> apply_cells(const Section& s, const std::vector<SectionStress>& stress, double density_factor,
                                int n, const std::function<Eigen::Vector3d(double r, double z)>& field) {
    std::vector<double> y(3 * s.mesh.n_nodes(), 0.0);
    for (int c = 0; c < s.mesh.n_cells(); ++c) {
        const Quad8Coords x = coords(s.mesh, c);
        Eigen::Matrix<double, 24, 1> q;
        for (int a = 0; a < 8; ++a) q.segment<3>(3 * a) = field(x(a, 0), x(a, 1));
        const double rho = density_factor * s.materials.at(s.mesh.cell_part[c]).density;
        const Eigen::Matrix<double, 24, 1> Kq = harmonic_quad8_centrifugal(x, rho, stress.at(c), n) * q;
        for (int a = 0; a < 8; ++a)
            for (int k = 0; k < 3; ++k) y[3 * s.mesh.cells[c][a] + k] += Kq[3 * a + k];
    }
    return y;
}

double max_abs(const std::vector<double>& v) {
    double m = 0;
    for (double x : v) m = std::max(m, std::abs(x));
    return m;
}

}  // namespace

// The largest differences (radial, hoop) of the prestress of a thin steel
// annulus a = 50 mm, b = 200 mm, 4 mm thick, free, `cells` quad8 across the
// wall, from the plane-stress closed form, relative to (3 + nu)/8 rho b^2,
// over every Gauss point. Plane stress holds to O(nu (h/b)^2) ~ 1e-4.
std::pair<double, double> disc_stress_errors(int cells) {
    const Scene disc = testing::steel_tube(0.4, 0.1, 0.004, cells, 16, 2);
    const Section s = section_of(disc);
    const CentrifugalPrestress p = centrifugal_prestress(disc, s.mesh, s.materials);
    CHECK(p.held_rigid_motions == 2);
    CHECK(p.relative_residual < 1e-10);
    const double nu = 0.3, rho = 7850, a = 0.05, b = 0.2, c = (3 + nu) / 8 * rho;
    double worst_r = 0, worst_t = 0;
    for (int cell = 0; cell < s.mesh.n_cells(); ++cell) {
        const Quad8Coords x = coords(s.mesh, cell);
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) {
                const double r = quad8_values(kGauss[i], kGauss[j]).dot(x.col(0));
                const double radial = c * (a * a + b * b - a * a * b * b / (r * r) - r * r);
                const double hoop = c * (a * a + b * b + a * a * b * b / (r * r) - (1 + 3 * nu) / (3 + nu) * r * r);
                worst_r = std::max(worst_r, std::abs(p.stress[cell](0, 3 * i + j) - radial) / (c * b * b));
                worst_t = std::max(worst_t, std::abs(p.stress[cell](1, 3 * i + j) - hoop) / (c * b * b));
            }
    }
    return {worst_r, worst_t};
}

TEST_CASE("The centrifugal prestress of a thin spinning disc is Timoshenko's", "[rotation][harmonic][centrifugal]") {
    // The error is largest at the bore, where a^2 b^2 / r^2 bends fastest,
    // and falls as the cells narrow towards h^2 (quadratic elements):
    // measured with 12, 24, 48, 96, 192 cells, radial 1.5e-2, 5.0e-3, 1.5e-3,
    // 4.0e-4, 1.2e-4 and hoop 4.9e-3, 1.7e-3, 5.6e-4, 1.8e-4, 6.9e-5 (the
    // hoop's last step nears the plane-stress floor). Halving the width
    // must divide both by more than 2.5 (3.3 and 3.0 measured).
    const auto [coarse_r, coarse_t] = disc_stress_errors(24);
    const auto [fine_r, fine_t] = disc_stress_errors(48);
    INFO("radial " << coarse_r << " -> " << fine_r << ", hoop " << coarse_t << " -> " << fine_t);
    CHECK(fine_r < 2e-3);
    CHECK(fine_t < 1e-3);
    CHECK(coarse_r / fine_r > 2.5);
    CHECK(coarse_t / fine_t > 2.5);
}

TEST_CASE("K_Omega leaves a free spinning body's rigid motions alone", "[rotation][harmonic][centrifugal]") {
    // A thick free steel tube (106 x 40 mm, 60 mm long): the prestress is far
    // from a thin ring's, so the geometric stiffness and the convective
    // softening are each large on a rigid tilt; their sum must vanish (the
    // static solve's equilibrium, discretely: effects/rotation.hpp).
    Scene tube = testing::steel_tube(0.106, 0.040, 0.06, 6, 16, 8);
    const Section s = section_of(tube);
    const CentrifugalPrestress p = centrifugal_prestress(tube, s.mesh, s.materials);
    const std::vector<SectionStress> no_stress(p.stress.size(), SectionStress::Zero());
    // n = 1, cos family: a sideways translation U = V = 1; a tilt about y,
    // u = e_y x (x, y, z) = (z, 0, -x): U = V = z, W = -r.
    const auto translation = [](double, double) { return Eigen::Vector3d(1, 1, 0); };
    const auto tilt = [](double r, double z) { return Eigen::Vector3d(z, z, -r); };
    for (const auto& [name, field] : {std::pair{"translation", std::function<Eigen::Vector3d(double, double)>(translation)},
                                      std::pair{"tilt", std::function<Eigen::Vector3d(double, double)>(tilt)}}) {
        const double both = max_abs(apply_cells(s, p.stress, 1, 1, field));
        const double geometric = max_abs(apply_cells(s, p.stress, 0, 1, field));
        const double softening = max_abs(apply_cells(s, no_stress, 1, 1, field));
        INFO(name << ": |K_Omega q| " << both << ", geometric part alone " << geometric << ", softening alone "
                  << softening);
        if (std::string(name) == "tilt") {
            CHECK(geometric > 1e-3);
            CHECK(softening > 1e-3);
        }
        CHECK(both <= 1e-9 * std::max({geometric, softening, 1e-3}));
    }
}

TEST_CASE("A thin spinning ring with centrifugal stiffening: the exact stationary-frame split",
          "[rotation][harmonic][centrifugal]") {
    // The ring of Bryan's test (R ~ 0.5 m, t = 5 mm, free). Inextensional,
    // in the stationary frame: m q'' + Omega g q' + (k + Omega^2 (k_sigma -
    // m_L)) q = 0 with k_sigma = m_L for a thin free ring (hoop stress
    // rho R^2 Omega^2), so omega = sqrt(omega_0^2 + beta^2 Omega^2) +-
    // beta Omega, beta = n (n^2 - 1) / (n^2 + 1), at any speed. At f_rot =
    // 0.4 f_0 the split is of the order of omega_0 itself; the ring's
    // thickness and extensibility move the result by O((t/R)^2) ~ 1e-4, the
    // bound (measured: 5e-6 and 7e-6 at n = 2).
    Scene ring = testing::steel_tube(1.0, 0.99, 0.02, 2, 64, 2, 16);
    ring.model = ModelChoice::harmonic;
    const RotatingHarmonics harmonics(ring, 16, true);
    REQUIRE(harmonics.prestress());
    const std::vector<RotatingMode> rest = harmonics.modes_at(0.0);
    for (int n : {2, 3}) {
        const auto at_rest = std::find_if(rest.begin(), rest.end(), [&](const RotatingMode& m) {
            return m.label.type == "ovalling" && m.label.n == n;
        });
        REQUIRE(at_rest != rest.end());
        const double f0 = at_rest->frequency_hz, f_rot = 0.4 * f0;
        const double beta = n * (n * n - 1.0) / (n * n + 1.0);
        const double exact_fw = std::sqrt(f0 * f0 + beta * beta * f_rot * f_rot) + beta * f_rot;
        const double exact_bw = std::sqrt(f0 * f0 + beta * beta * f_rot * f_rot) - beta * f_rot;
        double fw = 0, bw = 0, worst = 0;
        for (const RotatingMode& m : harmonics.modes_at(f_rot)) {
            if (m.label.type != "ovalling" || m.label.n != n) continue;
            double& f = m.whirl == Whirl::forward ? fw : bw;
            if (f == 0) f = m.frequency_hz;  // the lowest of each direction
            worst = std::max(worst, m.relative_residual);
        }
        INFO("n = " << n << ", f0 " << f0 << " Hz, f_rot " << f_rot << " Hz: FW " << fw << " (exact " << exact_fw
                    << "), BW " << bw << " (exact " << exact_bw << ")");
        CHECK(fw == Approx(exact_fw).epsilon(1e-4));  // (t/R)^2 = 1e-4; measured 5e-6
        CHECK(bw == Approx(exact_bw).epsilon(1e-4));  // measured 7e-6
        CHECK(worst < 1e-8);
    }
}

namespace {

// The thin free ring (R = 0.5 m, t = 5 mm, 2 cm wide) of the exact split.
Scene thin_ring() { return testing::steel_tube(1.0, 0.99, 0.02, 2, 64, 2, 16); }

// Its n = 2 spinning set with the prestress's stress set to zero: the
// convective softening -Omega^2 M_L alone as K_Omega.
SpinningHarmonic softening_only(const Scene& ring, const Section& s) {
    CentrifugalPrestress prestress = centrifugal_prestress(ring, s.mesh, s.materials);
    for (SectionStress& st : prestress.stress) st.setZero();
    return assemble_spinning_harmonic(ring, s.mesh, s.materials, 2, &prestress);
}

}  // namespace

TEST_CASE("A thin spinning ring with the convective softening alone misses the exact split",
          "[rotation][harmonic][centrifugal]") {
    // The control of the test above: the same ring and wave number n = 2 with
    // the prestress's stress set to zero (softening -Omega^2 M_L only) is
    // off by far more than that test's tolerance, so the test can fail.
    const Scene ring = thin_ring();
    const Section s = section_of(ring);
    const SpinningHarmonic h = softening_only(ring, s);
    const SpinningHarmonic full_model =
        assemble_spinning_harmonic(ring, s.mesh, s.materials, 2, nullptr);  // no Omega^2 term: the exact split too
    SolveRequest request = solve_request(ring);
    request.n_modes = 2;
    const Progress quiet = [](const std::string&) {};
    request.lambda_scale = std::pow(solve_gyroscopic(full_model.operators, 0.0, request, quiet).modes.at(0).omega, 2);
    const double omega0 = std::sqrt(request.lambda_scale), spin = 0.4 * omega0, beta = 1.2;
    const double exact_fw = std::sqrt(omega0 * omega0 + beta * beta * spin * spin) + beta * spin;
    const double fw_softening = solve_gyroscopic(h.operators, spin, request, quiet).modes.back().omega;
    INFO("FW with softening only " << fw_softening << " rad/s, exact " << exact_fw);
    CHECK(std::abs(fw_softening / exact_fw - 1) > 0.05);
}

TEST_CASE("A stiffness the spin has made indefinite is refused by both gyroscopic solvers, never counted",
          "[rotation][harmonic][centrifugal]") {
    // The ring of the test above with the convective softening alone,
    // K_Omega = -M_L: on the inextensional n = 2 wave (V = U / n) the
    // softening's Rayleigh quotient is (n - 1/n)^2 / (1 + 1/n^2) = 1.8, so
    // K - Omega^2 M_L turns negative on it above Omega = omega_0 / sqrt 1.8
    // = 0.745 omega_0. At 0.4 omega_0 (the test above) both solvers answer;
    // at 1.0 omega_0 the stiffness has a direction below -omega_0^2 / 4 (an
    // inertia count of K(Omega) + omega_0^2/4 M, the independent check),
    // and both must refuse with the speed and the reason.
    const Scene ring = thin_ring();
    const Section s = section_of(ring);
    const SpinningHarmonic h = softening_only(ring, s);
    SolveRequest request = solve_request(ring);
    request.n_modes = 2;
    const Progress quiet = [](const std::string&) {};
    request.lambda_scale = std::pow(solve_gyroscopic(h.operators, 0.0, request, quiet).modes.at(0).omega, 2);
    const double omega0 = std::sqrt(request.lambda_scale);
    {
        const EffectiveStiffness at_speed(h.operators, omega0);
        PetscMatrix A;
        COREMODAL_PETSC(MatDuplicate(at_speed.get(), MAT_COPY_VALUES, A.out()));
        COREMODAL_PETSC(MatAXPY(A, 0.25 * request.lambda_scale, h.operators.M(), DIFFERENT_NONZERO_PATTERN));
        REQUIRE(negative_eigenvalue_count(A, "K(Omega) + omega_0^2 / 4 M") > 0);
    }
    CHECK_NOTHROW(solve_gyroscopic(h.operators, 0.4 * omega0, request, quiet));
    CHECK_THROWS_WITH(solve_gyroscopic(h.operators, omega0, request, quiet),
                      Catch::Contains("is indefinite") && Catch::Contains("no modes are reported"));
    // The projected sweep: the rigid line is not clear over [0, omega_0]
    // (Q(omega_0) is indefinite at the top), nor the stiffness; the speed's
    // own count refuses.
    ProjectedGyroscopic projected(h.operators, request, 8, h.cos_rows, h.sin_rows);
    CHECK_FALSE(projected.prove_rigid_line_clear(omega0));
    CHECK(projected.modes_at(0.4 * omega0).has_value());
    CHECK_THROWS_WITH(projected.modes_at(omega0), Catch::Contains("is indefinite"));
}
