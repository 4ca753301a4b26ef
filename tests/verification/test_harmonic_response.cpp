// The forced response at the harmonic level (analyses/response:
// harmonic_response, modal_response, harmonic_loads) against independent
// truths: in the complete basis of wave number n = 1 the superposition is
// the direct solve of the full problem; with the cutoff's modes and the
// static part of the others it converges to it as modes are added; the
// amplitude is linear in the excitation and goes as 1/zeta at resonance;
// and the beam level gives the same answer within the two levels'
// difference in the first bending frequency.
#include "models/response/harmonic_loads.hpp"
#include "models/response/modal_response.hpp"
#include "analyses/response/response.hpp"
#include "eigensolve/tolerances.hpp"
#include "models/solve_steps.hpp"
#include "scene/case_file.hpp"
#include "scene/response_spec.hpp"

#include "support/response_setup.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <complex>
#include <string>

using namespace coremodal;
using cd = std::complex<double>;

namespace {

// A rest roll held in rigid clamps over 100 mm at each end, isotropic
// (the beam and harmonic levels then differ only by beam theory: Timoshenko
// against the 3D field of the wall), 2 m long so that the n = 1 problem on
// the coarse section is small enough for a complete dense basis.
std::string clamped_roll_text(const std::string& model, const std::string& length = "2 m") {
    return "model = \"" + model + "\"\n"
           "[core]\ninner_diameter = \"150 mm\"\nouter_diameter = \"176 mm\"\nlength = \"" + length + "\"\n"
           "material = { E = \"6.5 GPa\", nu = 0.3, density = \"920 kg/m^3\" }\n"
           "[rest_paper]\nouter_diameter = \"196 mm\"\n"
           "material = { E = \"5 GPa\", nu = 0.3, density = \"1350 kg/m^3\" }\n"
           "[supports]\ntype = \"clamped\"\n[supports.left]\nlength = \"100 mm\"\nstart = \"0 mm\"\n"
           "[analysis]\nmodes = 8\n[mesh]\nlevel = \"coarse\"\n";
}

Scene clamped_roll(const std::string& model, const std::string& length = "2 m") {
    return parse_case_text(clamped_roll_text(model, length), "roll.toml");
}

// Every mode at rest of the plane, dense (the problem is small).
ModalBasis complete_basis(const HarmonicPlane& plane) {
    const Eigen::MatrixXd K(plane.K), M(plane.M);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
    REQUIRE(solver.info() == Eigen::Success);
    ModalBasis basis{solver.eigenvectors(), solver.eigenvalues()};  // M-orthonormal, ascending
    return basis;
}

ResponseSetup setup_of(double zeta, ExcitationSpec x, double v0, double v1, int points, double mid_span = 1.0) {
    return testing::response_setup(zeta, x, v0, v1, points, mid_span);
}

ExcitationSpec bow_unbalance_ovality() {
    ExcitationSpec x;
    x.bow_m = 0.5e-3;
    x.unbalance_kg_m = 2e-3;
    x.ovality_m = 0.3e-3;
    return x;
}

double relative_difference(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST_CASE("Harmonic level: superposition in the complete basis of n = 1 is the direct solve", "[response][harmonic][long]") {
    const Scene scene = clamped_roll("harmonic");
    const HarmonicPlane plane = assemble_harmonic_plane(scene);
    REQUIRE(plane.dofs.n_dofs < 1500);  // a dense basis in well under a second
    const double scale = solve_request(scene).lambda_scale;
    ModalResponse response(plane.K, plane.M, plane.G, kOnePlane, complete_basis(plane), scale);
    const double f1 = response.mode_frequency_hz(0);
    const LevelLoads loads = build_harmonic_loads(scene, bow_unbalance_ovality(), plane, response, {});
    REQUIRE(loads.orders.size() == 2);
    const auto check_all = [&](const char* what) {
        INFO(what);
        for (const OrderLoad& load : loads.orders)
            for (const double share : {0.2, 0.97, 1.0, 1.6, 3.0}) {  // below, near, at and above the first mode
                const double spin = 2 * M_PI * share * f1 / load.order, omega = load.order * spin;
                const Eigen::VectorXcd p = load.at(spin);
                const Eigen::VectorXcd x = response.superpose(p, spin, omega, response.n_modes());
                // 1e-6: the same linear system in other coordinates, round-off times its condition (~1e-10 measured).
                CHECK(relative_difference(x, response.direct(p, spin, omega)) < 1e-6);
            }
    };
    response.set_damping({}, std::vector<std::optional<double>>(static_cast<size_t>(response.n_modes()), 0.01));
    check_all("modal damping 0.01 on every mode");
    std::vector<std::optional<double>> mixed(static_cast<size_t>(response.n_modes()));
    mixed[0] = 0.02;  // one mode's own ratio over a Rayleigh base
    response.set_damping(RayleighDamping::at_two_frequencies(0.01, 2 * M_PI * f1, 2 * M_PI * 3 * f1), mixed);
    check_all("Rayleigh base, mode 1 at 0.02");
}

TEST_CASE("Harmonic level: the kept modes and the static part of the others converge to the direct solve",
          "[response][harmonic]") {
    const Scene scene = clamped_roll("harmonic");
    const HarmonicPlane plane = assemble_harmonic_plane(scene);
    ModalResponse response(plane.K, plane.M, plane.G, kOnePlane, complete_basis(plane), solve_request(scene).lambda_scale);
    response.set_damping({}, std::vector<std::optional<double>>(static_cast<size_t>(response.n_modes()), 0.01));
    const double f1 = response.mode_frequency_hz(0);
    ExcitationSpec x;
    x.bow_m = 0.5e-3;
    const LevelLoads loads = build_harmonic_loads(scene, x, plane, response, {});
    const double spin = 2 * M_PI * 0.8 * f1;
    const Eigen::VectorXcd p = loads.orders.front().at(spin), exact = response.direct(p, spin, spin);
    // Measured (bow at 0.8 f1, 552 modes in all): kept up to 3, 6, 12, 24 x
    // the load frequency (1, 3, 5, 8 modes) 2.4e-3, 2.3e-3, 2.2e-3, 2.2e-3
    // with the static part of the others, 1.7 % to 1.3 % without; up to 48 x
    // (21 modes) 2.8e-5 and 0.8 %. What the static part leaves out is each
    // left-out mode's dynamics: its inertia, its damping in quadrature and
    // its gyroscopic coupling to the kept, resonant first mode (n = 1's Gamma
    // is of the order of its mass matrix on every component, not only on the
    // tilts as a beam's): here one mode between 24 and 48 x carries most of
    // it. The run's 3 x cutoff is within 0.5 %; the sum converges.
    for (const int cutoff : {3, 6, 12, 24, 48}) {
        const int n = response.modes_below(cutoff * spin);
        const double without = relative_difference(response.superpose(p, spin, spin, n), exact);
        const double with = relative_difference(response.superpose(p, spin, spin, n, true), exact);
        INFO("cutoff " << cutoff << " x: " << n << " modes, " << without << " without the static part, " << with << " with it");
        CHECK(with < without / 4);  // the static part of the left-out modes is most of what they do
        CHECK(with < 5e-3);
    }
    CHECK(relative_difference(response.superpose(p, spin, spin, response.modes_below(48 * spin), true), exact) < 1e-4);
}

TEST_CASE("Harmonic level: the amplitude is linear in the excitation and goes as 1/zeta at resonance",
          "[response][harmonic]") {
    const Scene scene = clamped_roll("harmonic");
    ExcitationSpec bow;
    bow.bow_m = 0.5e-3;
    ExcitationSpec twice = bow;
    twice.bow_m = 1e-3;
    const ResponseResult a = run_forced_response(scene, setup_of(0.01, bow, 20, 120, 101));
    const ResponseResult b = run_forced_response(scene, setup_of(0.01, twice, 20, 120, 101));
    REQUIRE(a.level == ModelChoice::harmonic);
    for (size_t i = 0; i < a.points.size(); ++i)
        CHECK(b.points[i].probes[0].total_m == Approx(2 * a.points[i].probes[0].total_m).epsilon(1e-12));
    ExcitationSpec unbalance;
    unbalance.unbalance_kg_m = 2e-3;
    ExcitationSpec thrice = unbalance;
    thrice.unbalance_kg_m = 6e-3;
    CHECK(run_forced_response(scene, setup_of(0.01, thrice, 20, 120, 101)).max_amplitude_m ==
          Approx(3 * run_forced_response(scene, setup_of(0.01, unbalance, 20, 120, 101)).max_amplitude_m).epsilon(1e-9));
    // The refined order-1 peak halves from zeta 0.01 to 0.02 (the off-resonant
    // modes answer in quadrature: O(zeta^2), as at the beam level).
    const ResponseResult damped = run_forced_response(scene, setup_of(0.02, bow, 20, 120, 101));
    REQUIRE(a.peaks.size() == 1);
    REQUIRE(damped.peaks.size() == 1);
    CHECK(a.peaks[0].amplitude_m / damped.peaks[0].amplitude_m == Approx(2.0).epsilon(1e-3));
    CHECK(a.peaks[0].mode.type == "bending");
    CHECK(a.checks.direct_max_relative < 1e-2);  // the truncation's effect against the direct solve
    CHECK_FALSE(a.checks.complete_basis);
}

TEST_CASE("Harmonic and beam levels give the same response within their difference in the first bending frequency",
          "[response][harmonic][beam]") {
    // A 4 m rest roll in rigid clamps (isotropic), bow, unbalance and an oval
    // core under gravity, 5-30 m/s: both levels find the order-1 peak at the
    // first bending pair and the order-2 peak at half its speed. Measured
    // (docs/validation/response.md, "The three levels"): f1 33.241 / 32.612 Hz (beam /
    // harmonic, coarse section; -1.9 %: the 3D wall against Timoshenko beam
    // theory at the clamp edges), order-1 peak 20.53 / 20.14 m/s and
    // 9.115 / 9.244 mm, order-2 peak 10.27 / 10.07 m/s and 0.161 / 0.167 mm,
    // +-5 mm reached at 20.22 / 19.83 m/s.
    const ResponseSetup setup = setup_of(0.01, bow_unbalance_ovality(), 5, 30, 251, 2.0);
    const ResponseResult beam = run_forced_response(clamped_roll("beam", "4 m"), setup);
    const ResponseResult harmonic = run_forced_response(clamped_roll("harmonic", "4 m"), setup);
    REQUIRE(beam.level == ModelChoice::beam);
    REQUIRE(harmonic.level == ModelChoice::harmonic);
    const double f1_ratio = harmonic.speeds_at_rest.f1_hz / beam.speeds_at_rest.f1_hz;
    CHECK(std::abs(f1_ratio - 1) < 0.03);
    REQUIRE(beam.peaks.size() == 2);
    REQUIRE(harmonic.peaks.size() == 2);
    for (size_t k = 0; k < 2; ++k) {
        INFO("peak " << k << ": order " << beam.peaks[k].order);
        CHECK(harmonic.peaks[k].order == beam.peaks[k].order);
        CHECK(harmonic.peaks[k].mode.type == "bending");
        // The peak speeds scale as the first bending frequencies: the whirl's
        // gyroscopic shift is 0.2 % of the frequency at both levels, alike to 1e-3.
        CHECK(harmonic.peaks[k].web_speed_m_s / beam.peaks[k].web_speed_m_s == Approx(f1_ratio).epsilon(1e-3));
    }
    // The amplitudes: the same loads on two models of the roll. The peak is
    // ~1/(2 zeta) times the runout the clamps leave of the bow (modelled as a
    // beam's section against the clamped bore of a 3D wall): 1.4 % apart at
    // order 1, 3.8 % at order 2 (the ovality's split acts on the core cells'
    // whole stiffness, shear included, against E_c I_c alone); margins 5 % and 10 %.
    CHECK(harmonic.peaks[1].amplitude_m / beam.peaks[1].amplitude_m == Approx(1.0).epsilon(0.05));
    CHECK(harmonic.peaks[0].amplitude_m / beam.peaks[0].amplitude_m == Approx(1.0).epsilon(0.10));
    // The safe speed from the +-5 mm limit follows the frequency (same implied factor within 0.5 %).
    REQUIRE(beam.safe.reached);
    REQUIRE(harmonic.safe.reached);
    CHECK(harmonic.safe.implied_factor == Approx(beam.safe.implied_factor).epsilon(5e-3));
    CHECK(harmonic.sag_m / beam.sag_m == Approx(1.0).epsilon(0.05));
}

TEST_CASE("Both families with the skew G (the solid's form) give the one-plane answer (a, -i a)",
          "[response][harmonic][solid][long]") {
    // The n = 1 problem written as the solid writes a spinning body: both
    // planes (the cos and sin families) as unknowns, G2 = 2 [[0, Gamma],
    // [-Gamma, 0]] skew with the gyroscopic unit i, a load (p, -i p). Its
    // superposition in the complete basis (each mode of n = 1 in each family),
    // its direct solve and the one-plane response must all be (a, -i a).
    const Scene scene = clamped_roll("harmonic");
    const HarmonicPlane plane = assemble_harmonic_plane(scene);
    const ModalBasis one = complete_basis(plane);
    const Eigen::Index n = one.lambda.size();
    const double scale = solve_request(scene).lambda_scale;
    ModalResponse plane_response(plane.K, plane.M, plane.G, kOnePlane, one, scale);
    // [[A, 0], [0, A]] or, skew, [[0, A], [-A, 0]] of an n x n matrix.
    const auto blocks = [&](const Eigen::SparseMatrix<double>& A, bool skew) {
        std::vector<Eigen::Triplet<double>> t;
        for (int k = 0; k < A.outerSize(); ++k)
            for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it) {
                t.emplace_back(it.row(), skew ? it.col() + n : it.col(), it.value());
                t.emplace_back(it.row() + n, skew ? it.col() : it.col() + n, skew ? -it.value() : it.value());
            }
        Eigen::SparseMatrix<double> out(2 * n, 2 * n);
        out.setFromTriplets(t.begin(), t.end());
        return out;
    };
    const Eigen::SparseMatrix<double> K2 = blocks(plane.K, false), M2 = blocks(plane.M, false), G2 = blocks(plane.G, true);
    ModalBasis two{Eigen::MatrixXd::Zero(2 * n, 2 * n), Eigen::VectorXd(2 * n)};
    two.Phi.topLeftCorner(n, n) = one.Phi;
    two.Phi.bottomRightCorner(n, n) = one.Phi;
    two.lambda << one.lambda, one.lambda;
    ModalResponse families(K2, M2, G2, kTwoPlanes, two, scale);
    const std::vector<std::optional<double>> zeta1(static_cast<size_t>(n), 0.01), zeta2(static_cast<size_t>(2 * n), 0.01);
    plane_response.set_damping({}, zeta1);
    families.set_damping({}, zeta2);
    ExcitationSpec x;
    x.bow_m = 0.5e-3;
    x.unbalance_kg_m = 2e-3;
    const LevelLoads loads = build_harmonic_loads(scene, x, plane, plane_response, {});
    const double f1 = plane_response.mode_frequency_hz(0);
    for (const double share : {0.5, 1.0, 2.0}) {
        const double spin = 2 * M_PI * share * f1;
        const Eigen::VectorXcd p = loads.orders.front().at(spin);
        Eigen::VectorXcd p2(2 * n);
        p2 << p, cd(0, -1) * p;
        const Eigen::VectorXcd a = plane_response.direct(p, spin, spin);
        Eigen::VectorXcd expected(2 * n);
        expected << a, cd(0, -1) * a;
        CHECK(relative_difference(families.direct(p2, spin, spin), expected) < 1e-6);
        CHECK(relative_difference(families.superpose(p2, spin, spin, static_cast<int>(2 * n)), expected) < 1e-6);
    }
}

TEST_CASE("Solid and harmonic levels give the same response on one section", "[response][harmonic][solid][long]") {
    // The 2 m clamped roll on the coarse mesh at both levels: the solid's
    // 3D cells are the section turned (16 around), its G the same spin term
    // in Cartesian components, its loads the same fields as nodal forces.
    // Measured on the 4 m roll (docs/validation/response.md): f1 32.611 / 32.612 Hz,
    // order-1 peak 9.244 mm at 20.14 m/s at both levels, order-2 0.1667 mm.
    ExcitationSpec x;
    x.bow_m = 0.5e-3;
    x.unbalance_kg_m = 2e-3;
    const ResponseSetup setup = setup_of(0.01, x, 20, 120, 101);
    const ResponseResult harmonic = run_forced_response(clamped_roll("harmonic"), setup);
    const ResponseResult solid = run_forced_response(clamped_roll("solid"), setup);
    REQUIRE(solid.level == ModelChoice::solid);
    REQUIRE(harmonic.peaks.size() == 1);
    REQUIRE(solid.peaks.size() == 1);
    // The solid's 16 quadratic cells around: 1e-4 stiffer (docs/theory/harmonic.md).
    CHECK(solid.speeds_at_rest.f1_hz == Approx(harmonic.speeds_at_rest.f1_hz).epsilon(1e-3));
    CHECK(solid.peaks[0].web_speed_m_s == Approx(harmonic.peaks[0].web_speed_m_s).epsilon(1e-3));
    CHECK(solid.peaks[0].amplitude_m == Approx(harmonic.peaks[0].amplitude_m).epsilon(1e-2));
    CHECK(solid.peaks[0].mode.type == "bending");
    CHECK(solid.safe.reached == harmonic.safe.reached);
    for (size_t i = 0; i < solid.points.size(); i += 10)
        CHECK(solid.points[i].probes[0].total_m == Approx(harmonic.points[i].probes[0].total_m).epsilon(2e-2));
    CHECK(solid.checks.direct_max_relative < 1e-2);  // the truncation's effect against the direct solve
}
