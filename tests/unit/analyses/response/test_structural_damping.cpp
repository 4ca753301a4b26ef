// Structural (hysteretic) damping, a loss factor per part (effects/damping.hpp
// StructuralDamping, [damping] loss_factor and [damping.loss_factors]),
// against independent truth: a single degree of freedom with the complex
// stiffness k (1 + i eta) answers F / (k (1 - r^2 + i eta)) (its closed form,
// d_h(r) = 1 / sqrt((1 - r^2)^2 + eta^2)); at resonance that is the viscous
// answer with zeta = eta / 2 exactly, off resonance the two differ as their
// closed forms say; superposition in the complete basis is the direct solve
// with i H (beam and harmonic levels); a loss factor on every part is the
// complex stiffness K (1 + i eta) of the whole roll (each mode's eta_j = eta).
#include "models/response/harmonic_loads.hpp"
#include "models/response/lateral_response.hpp"
#include "models/response/modal_response.hpp"
#include "analyses/response/response.hpp"
#include "models/response/response_loads.hpp"
#include "beam/beam_model.hpp"
#include "effects/damping.hpp"
#include "models/solve_steps.hpp"
#include "scene/case_file.hpp"
#include "scene/response_spec.hpp"

#include "support/response_setup.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <complex>
#include <string>

using namespace coremodal;
using cd = std::complex<double>;

namespace {

// One degree of freedom, k = 4e6 N/m, m = 10 kg, through the response code
// path (ModalResponse: the modal equations and the direct sparse solve).
struct SingleMode {
    double k = 4e6, m = 10.0;
    double omega_n() const { return std::sqrt(k / m); }
    ModalResponse response() const {
        Eigen::SparseMatrix<double> K(1, 1), M(1, 1), G(1, 1);
        K.insert(0, 0) = k;
        M.insert(0, 0) = m;
        ModalBasis basis{Eigen::MatrixXd::Constant(1, 1, 1 / std::sqrt(m)), Eigen::VectorXd::Constant(1, k / m)};
        return ModalResponse(K, M, G, kOnePlane, basis, k / m);
    }
    Eigen::SparseMatrix<double> hysteretic(double eta) const {
        Eigen::SparseMatrix<double> H(1, 1);
        H.insert(0, 0) = eta * k;
        return H;
    }
};

Eigen::VectorXcd force(double F) { return Eigen::VectorXcd::Constant(1, F); }

// The clamped rest roll of test_response.cpp (isotropic; a core and a rest
// paper of different moduli, so that their strain-energy shares differ).
std::string clamped_roll_text(const std::string& model, const std::string& length) {
    return "model = \"" + model + "\"\n"
           "[core]\ninner_diameter = \"150 mm\"\nouter_diameter = \"176 mm\"\nlength = \"" + length + "\"\n"
           "material = { E = \"6.5 GPa\", nu = 0.3, density = \"920 kg/m^3\" }\n"
           "[rest_paper]\nouter_diameter = \"196 mm\"\n"
           "material = { E = \"5 GPa\", nu = 0.3, density = \"1350 kg/m^3\" }\n"
           "[supports]\ntype = \"clamped\"\n[supports.left]\nlength = \"100 mm\"\nstart = \"0 mm\"\n"
           "[analysis]\nmodes = 8\n[mesh]\nlevel = \"coarse\"\n";
}

ResponseSetup structural_setup(double base, std::map<std::string, double> parts, double length) {
    ExcitationSpec x;
    x.bow_m = 0.5e-3;
    x.unbalance_kg_m = 2e-3;
    x.gravity = false;
    ResponseSetup s = testing::response_setup(0.0, x, 2, 25, 4, 0.5 * length);
    s.damping.source = "[damping] no viscous damping: the loss factors alone";
    s.damping.loss_factor = base;
    s.damping.part_loss_factors = std::move(parts);
    return s;
}

double relative_difference(const Eigen::VectorXcd& a, const Eigen::VectorXcd& b) { return (a - b).norm() / b.norm(); }

}  // namespace

TEST_CASE("A single mode with a loss factor answers F / (k (1 - r^2 + i eta)) (its closed form)", "[damping][response]") {
    const SingleMode sdof;
    ModalResponse r = sdof.response();
    const double eta = 0.04, F = 100.0;
    r.set_imaginary_stiffness(sdof.hysteretic(eta));
    CHECK(StructuralDamping::modal_loss_factor(r.imaginary_stiffness_on_modes()(0, 0), r.eigenvalue(0)) == Approx(eta).epsilon(1e-15));
    for (const double ratio : {0.0, 0.3, 0.9, 1.0, 1.05, 2.0, 5.0}) {
        const double omega = ratio * sdof.omega_n();
        const cd exact = F / (sdof.k * (1 - ratio * ratio + cd(0, eta)));  // independent: the closed form
        const cd modal = r.superpose(force(F), 0.0, omega, 1)(0), direct = r.direct(force(F), 0.0, omega)(0);
        // 1e-13: a handful of operations on numbers of order 1 (round-off).
        CHECK(std::abs(modal - exact) / std::abs(exact) < 1e-13);
        CHECK(std::abs(direct - exact) / std::abs(exact) < 1e-13);
        CHECK(std::abs(modal) / (F / sdof.k) == Approx(hysteretic_amplification(ratio, eta)).epsilon(1e-13));
    }
}

TEST_CASE("At resonance a loss factor eta is the viscous zeta = eta / 2; off resonance the closed forms differ",
          "[damping][response]") {
    const SingleMode sdof;
    const double eta = 0.03, zeta = StructuralDamping::equivalent_zeta(eta);
    REQUIRE(zeta == 0.015);
    ModalResponse hysteretic = sdof.response(), viscous = sdof.response();
    hysteretic.set_imaginary_stiffness(sdof.hysteretic(eta));
    viscous.set_damping({}, {zeta});
    const auto amplitude = [&](const ModalResponse& r, double ratio) {
        return std::abs(r.superpose(force(1.0), 0.0, ratio * sdof.omega_n(), 1)(0)) * sdof.k;
    };
    // Exactly at r = 1 both are 1 / eta = 1 / (2 zeta).
    CHECK(amplitude(hysteretic, 1.0) == Approx(1 / eta).epsilon(1e-13));
    CHECK(amplitude(hysteretic, 1.0) == Approx(amplitude(viscous, 1.0)).epsilon(1e-13));
    for (const double ratio : {0.5, 0.95, 1.05, 2.0}) {
        // Each against its own closed form, and their ratio as the closed forms give it.
        CHECK(amplitude(hysteretic, ratio) == Approx(hysteretic_amplification(ratio, eta)).epsilon(1e-13));
        CHECK(amplitude(viscous, ratio) == Approx(amplification(ratio, zeta)).epsilon(1e-13));
        CHECK(amplitude(hysteretic, ratio) / amplitude(viscous, ratio) ==
              Approx(hysteretic_amplification(ratio, eta) / amplification(ratio, zeta)).epsilon(1e-12));
    }
    // The hysteretic force eta k x is the viscous 2 zeta omega_n m xdot at r = 1 only: below resonance
    // it is larger (less motion), above it smaller (more motion).
    CHECK(amplitude(hysteretic, 0.5) < amplitude(viscous, 0.5));
    CHECK(amplitude(hysteretic, 2.0) > amplitude(viscous, 2.0));
}

TEST_CASE("Beam level: a loss factor on every part is K (1 + i eta); per part, superposition is the direct solve",
          "[damping][response]") {
    const Scene scene = parse_case_text(clamped_roll_text("beam", "4 m"), "roll.toml");
    // Every part at eta: H = eta K (the clamps hold, no springs), so every kept mode's eta_j is eta.
    const ResponseResult uniform = run_forced_response(scene, structural_setup(0.03, {}, 4.0));
    REQUIRE(!uniform.mode_damping.empty());
    for (const ModeDamping& m : uniform.mode_damping) CHECK(m.value_of("/loss_factor") == Approx(0.03).epsilon(1e-9));
    // The complete basis against the direct dense solve with i H (ResponseChecking::full); 1e-8: one
    // linear system in two bases (round-off times its condition, ~1e-11 measured).
    CHECK(uniform.checks.direct_max_relative < 1e-8);
    CHECK(std::count(uniform.effects.begin(), uniform.effects.end(), "structural_damping") == 1);
    CHECK(std::count(uniform.effects.begin(), uniform.effects.end(), "modal_damping") == 0);  // no viscous base

    // A lossy rest paper on a nearly lossless core: each mode's eta_j is the rest paper's share of its
    // strain energy times 0.05 plus the core's times 0.002, so it lies between them.
    const ResponseResult parts =
        run_forced_response(scene, structural_setup(0.0, {{"core", 0.002}, {"rest_paper", 0.05}}, 4.0));
    CHECK(parts.checks.direct_max_relative < 1e-8);
    for (const ModeDamping& m : parts.mode_damping) {
        CHECK(m.value_of("/loss_factor") > 0.002);
        CHECK(m.value_of("/loss_factor") < 0.05);
    }
    // Bending: the layers' EI shares (plane sections; shear adds little on a 4 m roll): E I of each tube.
    const double Ic = M_PI / 64 * (std::pow(0.176, 4) - std::pow(0.150, 4));
    const double Ip = M_PI / 64 * (std::pow(0.196, 4) - std::pow(0.176, 4));
    const double share = 5e9 * Ip / (5e9 * Ip + 6.5e9 * Ic);
    // 1 %: the first bending mode's shear energy (Timoshenko) is ~0.1 % of it; both layers share nu.
    CHECK(parts.mode_damping.front().value_of("/loss_factor") == Approx(0.05 * share + 0.002 * (1 - share)).epsilon(0.01));
}

TEST_CASE("Harmonic level: superposition in the complete basis of n = 1 with a loss factor per part is the direct solve",
          "[damping][response][long]") {
    const Scene scene = parse_case_text(clamped_roll_text("harmonic", "2 m"), "roll.toml");
    const HarmonicPlane plane = assemble_harmonic_plane(scene);
    REQUIRE(plane.dofs.n_dofs < 1500);  // a dense basis in well under a second
    const Eigen::MatrixXd K(plane.K), M(plane.M);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
    REQUIRE(solver.info() == Eigen::Success);
    ModalResponse response(plane.K, plane.M, plane.G, kOnePlane, ModalBasis{solver.eigenvectors(), solver.eigenvalues()},
                           solve_request(scene).lambda_scale);
    // Every part at eta: H = eta K exactly (the roll's cells are all of K here).
    StructuralDamping every;
    every.base = 0.03;
    const PartStiffness by_part = harmonic_part_stiffness(plane);
    const auto H_of = [&](const StructuralDamping& d) {
        return hysteretic_operator(d, by_part.parts, Eigen::SparseMatrix<double>(by_part.n, by_part.n), by_part.of);
    };
    const Eigen::SparseMatrix<double> H_every = H_of(every);
    CHECK((Eigen::MatrixXd(H_every) - 0.03 * K).norm() <= 1e-12 * 0.03 * K.norm());
    StructuralDamping parts;
    parts.parts = {{"core", 0.002}, {"rest_paper", 0.05}};
    response.set_imaginary_stiffness(H_of(parts));
    response.set_damping({}, std::vector<std::optional<double>>(static_cast<size_t>(response.n_modes()), 0.005));
    ExcitationSpec x;
    x.bow_m = 0.5e-3;
    x.unbalance_kg_m = 2e-3;
    x.gravity = false;
    const LevelLoads loads = build_harmonic_loads(scene, x, plane, response, {});
    const double f1 = response.mode_frequency_hz(0);
    const double eta_1 = StructuralDamping::modal_loss_factor(response.imaginary_stiffness_on_modes()(0, 0), response.eigenvalue(0));
    CHECK(eta_1 > 0.002);
    CHECK(eta_1 < 0.05);
    // The static part of the modes left out carries their loss: at rest (omega = 0) six kept
    // modes and the static part of the others are (K + i H)^-1 p exactly, whatever H couples.
    const Eigen::VectorXcd p0 = loads.orders.front().at(2 * M_PI * 10.0);
    CHECK(relative_difference(response.superpose(p0, 0.0, 0.0, 6, true), response.direct(p0, 0.0, 0.0)) < 1e-10);
    for (const OrderLoad& load : loads.orders)
        for (const double share : {0.2, 1.0, 1.6}) {  // below, at and above the first mode
            const double spin = 2 * M_PI * share * f1, omega = load.order * spin;
            const Eigen::VectorXcd p = load.at(spin);
            // 1e-6 as the viscous check's (~1e-10 measured): one linear system in two bases.
            CHECK(relative_difference(response.superpose(p, spin, omega, response.n_modes()),
                                      response.direct(p, spin, omega)) < 1e-6);
        }
}
