// The winder's beam model: geometry and loads by hand, the drum alone
// against the Timoshenko tube (simply supported on stiff bearings, free-free
// on soft ones), the model's mass, the rigid rolls as a constraint of the
// beam rolls, and the reduced dense solve against the project's network solver.
#include "beam/network_modes.hpp"
#include "support/timoshenko_exact.hpp"
#include "winder/winder_modes.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;

namespace {

WinderScene default_scene() {
    WinderScene s;
    s.source_file = "test.toml";
    return s;
}

// The drums alone: no load on any nip, so rolls and rider are decoupled.
WinderScene drums_alone(double bearing_stiffness) {
    WinderScene s = default_scene();
    s.drums.line_load = 0.0;
    s.rider.line_load = 0.0;
    s.drums.bearing_stiffness_vertical = s.drums.bearing_stiffness_horizontal = bearing_stiffness;
    return s;
}

BeamSection drum_section() {
    // 850 x 50 mm steel tube: E 210 GPa, nu 0.3, 7850 kg/m^3.
    return tube_beam_section(0.85, 0.75, OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850));
}

// The lowest drum-dominated frequency above `floor_hz`.
double first_drum_hz(const WinderModes& modes, double floor_hz) {
    for (int i = 0; i < modes.n_reported; ++i)
        if (modes.modes[i].type == BodyKind::drum && modes.modes[i].frequency_hz > floor_hz)
            return modes.modes[i].frequency_hz;
    FAIL("no drum mode");
    return 0;
}

}  // namespace

TEST_CASE("The nip angle and the drum line load follow the roll's geometry and equilibrium", "[winder][model]") {
    const WinderScene s = default_scene();
    // d = 1.2 m: s = 0.85 + 0.1 = 0.95 m; sin(alpha) = 0.95 / (1.2 + 0.85) = 0.463415 -> alpha = 27.6077 deg;
    // h = sqrt(1.025^2 - 0.475^2) = sqrt(1.050625 - 0.225625) = sqrt(0.825) = 0.908295 m.
    const WinderState st = winder_state(s, 1.2);
    CHECK(st.geometry.nip_angle * 180 / M_PI == Approx(27.6077).epsilon(1e-5));
    CHECK(st.geometry.roll_height == Approx(0.908295).epsilon(1e-6));
    // Roll mass per width: core pi/4 (0.176^2 - 0.15^2) 920 = 0.00665697 * 920 = 6.12441 kg/m,
    // paper pi/4 (1.2^2 - 0.176^2) 800 = 1.10665 * 800 = 885.317 kg/m: 891.441 kg/m.
    CHECK(st.roll_mass_per_width == Approx(891.441).epsilon(1e-5));
    // Two drum nips carry weight and rider: 2 P cos(alpha) = 9.81 * 891.441 + 2000.
    CHECK(2 * st.drum_line_load * std::cos(st.geometry.nip_angle) == Approx(9.81 * 891.441 + 2000).epsilon(1e-5));
    // The nips turn towards the vertical as the roll grows.
    CHECK(winder_state(s, 1.8).geometry.nip_angle < st.geometry.nip_angle);
}

TEST_CASE("A drum alone on stiff bearings is the simply supported Timoshenko tube", "[long][winder][model]") {
    // Bearing compliance shifts lambda by about 2 EI pi^2 / (k L^3) = 4e-7 at 1e14 N/m.
    const WinderScene s = drums_alone(1e14);
    const WinderModel m = build_winder_model(s, 1.2);
    const WinderModes modes = solve_winder_modes(m, s.damping, 200.0);
    const double exact = testing::simply_supported_timoshenko_hz(drum_section(), 10.0, 1);
    CHECK(first_drum_hz(modes, 1.0) == Approx(exact).epsilon(1e-5));
    // Euler-Bernoulli pi/(2 L^2) sqrt(EI/rhoA) lies a little above: shear and
    // rotary inertia of a tube with D/L = 0.085 take about 1 %.
    const BeamSection sec = drum_section();
    const double euler = M_PI / (2 * 10.0 * 10.0) * std::sqrt(sec.EI / sec.rho_A);  // Hz
    CHECK(exact < euler);
    CHECK(exact > 0.97 * euler);
    // Both drums in both planes: four modes at the same frequency.
    int at_exact = 0;
    for (const auto& mode : modes.modes)
        if (std::abs(mode.frequency_hz / exact - 1) < 1e-5) ++at_exact;
    CHECK(at_exact == 4);
}

TEST_CASE("A drum alone on soft bearings is the free-free Timoshenko tube", "[long][winder][model]") {
    // 0.01 N/m bearings: the drum floats (rigid modes near 1e-4 Hz); its first
    // bending mode moves by k / (modal stiffness) ~ 1e-12. The default mesh (30
    // elements) is 1.5e-6 high, falling as h^4 (54 elements: 1.3e-7).
    const WinderScene s = drums_alone(1e-2);
    const WinderModel m = build_winder_model(s, 1.2);
    const WinderModes modes = solve_winder_modes(m, s.damping, 200.0);
    const double exact = testing::exact_timoshenko_first_hz(drum_section(), 10.0, BeamEnds::free_free);
    CHECK(first_drum_hz(modes, 1.0) == Approx(exact).epsilon(3e-6));
}

TEST_CASE("The model's mass is the drums', the rider's and the rolls'", "[winder][model]") {
    const WinderScene s = default_scene();
    const WinderModel m = build_winder_model(s, 1.2);
    // A unit sideways translation of everything: the reduced vector whose
    // network image is ux = 1 at every node.
    Eigen::VectorXd ux = Eigen::VectorXd::Zero(m.T.rows());
    for (size_t r = 0; r < m.network_dofs.size(); ++r)
        if (m.network_dofs[r] % beam_dof::per_node == beam_dof::ux) ux[static_cast<Eigen::Index>(r)] = 1;
    const Eigen::VectorXd e = Eigen::MatrixXd(m.T).colPivHouseholderQr().solve(ux);
    REQUIRE((Eigen::MatrixXd(m.T) * e - ux).norm() < 1e-10);
    // Drums 2 x 7850 pi/4 (0.85^2 - 0.75^2) 10 = 2 x 9864.60; rider 7850 pi/4 (0.5^2 - 0.44^2) 9.1 = 3164.37;
    // rolls 5 x 1.68 x 891.441 = 7488.10 (test above): 29381.7 kg.
    CHECK(e.dot(m.M * e) == Approx(2 * 9864.60 + 3164.37 + 7488.10).epsilon(1e-5));
    // A rigid translation strains only the bearings and supports, never the nips.
    CHECK(std::abs(e.dot(m.K_nips * e)) < 1e-9 * m.state.drum_nip.stiffness_per_length);
}

TEST_CASE("The modes are verified: residuals, M-orthonormality, none missed", "[long][winder][model]") {
    const WinderScene s = default_scene();
    const WinderModes modes = solve_winder_modes(build_winder_model(s, 0.8), s.damping, s.sweep.max_frequency);
    CHECK(modes.verification.complete);
    CHECK(modes.verification.max_relative_residual < 1e-12);
    CHECK(modes.verification.max_orthonormality_error < 1e-10);
    CHECK(modes.n_reported > 10);
}

TEST_CASE("Rigid rolls constrain beam rolls: no frequency falls, drum modes barely move", "[long][winder][model]") {
    WinderScene s = default_scene();
    const double d = 1.0;
    const WinderModes rigid = solve_winder_modes(build_winder_model(s, d), s.damping, 100.0);
    s.rolls.model = RollModel::beam;
    const WinderModes beam = solve_winder_modes(build_winder_model(s, d), s.damping, 100.0);
    // A constraint raises every eigenvalue or leaves it (Rayleigh's theorem): the i-th of the
    // rigid-roll model is at least the i-th of the beam-roll one.
    for (int i = 0; i < rigid.n_reported; ++i) CHECK(rigid.modes[i].eigenvalue >= beam.modes[i].eigenvalue * (1 - 1e-12));
    // The rolls' own bending lies far above the drums' range: drum modes agree to 1 %.
    CHECK(first_drum_hz(beam, 1.0) == Approx(first_drum_hz(rigid, 1.0)).epsilon(0.01));
}

TEST_CASE("The reduced dense solve agrees with the network solver on beam rolls", "[long][winder][model]") {
    WinderScene s = default_scene();
    s.rolls.model = RollModel::beam;  // no rigid constraint: the network is the whole model
    const WinderModel m = build_winder_model(s, 1.2);
    const WinderModes mine = solve_winder_modes(m, s.damping, 60.0);
    BeamNetwork net = m.network;
    for (int node = 0; node < net.n_nodes(); ++node) net.hold(node, beam_dof::uz), net.hold(node, beam_dof::rz);
    NetworkSolveRequest request;
    request.n_modes = mine.n_reported;
    request.lambda_scale = std::pow(2 * M_PI * 10.0, 2);
    const NetworkModes theirs = solve_network_modes(net, request);
    REQUIRE(theirs.eigenvalues.size() >= static_cast<size_t>(mine.n_reported));
    for (int i = 0; i < mine.n_reported; ++i) CHECK(mine.modes[i].eigenvalue == Approx(theirs.eigenvalues[i]).epsilon(1e-8));
}
