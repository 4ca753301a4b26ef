// The spinning beam network (src/beam/rotating_modes.hpp) against closed
// forms: a rigid rotor on springs (the conical whirl split by polar against
// transverse inertia, Jeffcott/rigid-rotor theory) and a simply supported
// Timoshenko tube (forward and backward whirl of each sine mode); the
// gyroscopic element's skew symmetry; at speed 0 the modes at rest.
#include "beam/beam_model.hpp"
#include "beam/beam_network.hpp"
#include "beam/network_modes.hpp"
#include "beam/rotating_modes.hpp"
#include "beam/timoshenko_element.hpp"
#include "scene/case_file.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

using namespace coremodal;

namespace {

BeamNetwork uniform_beam(const BeamSection& s, double L, int n_elements) {
    BeamNetwork net;
    std::vector<double> z;
    for (int i = 0; i <= n_elements; ++i) z.push_back(L * i / n_elements);
    net.add_beam("rotor", z, std::vector<BeamSection>(n_elements, s), [&](double zi) { return net.add_node(zi); });
    return net;
}

// Omega per the rotor's own frequency scale, rad/s -> Hz.
double hz(double omega) { return omega / (2 * M_PI); }

// The positive root of a omega^2 - b omega - c = 0 (a, c > 0): the forward
// whirl for b = +Ip Omega, the backward one for b = -Ip Omega.
double whirl_root(double a, double b, double c) { return (b + std::sqrt(b * b + 4 * a * c)) / (2 * a); }

const RotatingMode* nearest(const std::vector<RotatingMode>& modes, double f_hz) {
    const RotatingMode* best = nullptr;
    for (const RotatingMode& m : modes)
        if (!best || std::abs(m.frequency_hz - f_hz) < std::abs(best->frequency_hz - f_hz)) best = &m;
    return best;
}

}  // namespace

TEST_CASE("The gyroscopic element is skew-symmetric and holds rho_J L on the tilts", "[rotation][beam]") {
    TimoshenkoElement e{0.4, tube_beam_section(0.106, 0.076, OrthotropicMaterial::isotropic("s", 210e9, 0.3, 7850))};
    const BeamElementMatrix G = element_gyroscopic(e);
    CHECK((G + G.transpose()).cwiseAbs().maxCoeff() == 0.0);
    // A uniform tilt rx = 1 everywhere: the rows ry sum to -rho_J L (the consistent mass sums to rho_J L).
    double sum = 0;
    for (int a = 0; a < kElementNodes; ++a)
        for (int b = 0; b < kElementNodes; ++b) sum += G(6 * a + beam_dof::ry, 6 * b + beam_dof::rx);
    CHECK(sum == Approx(-e.section.rho_J * e.length).epsilon(1e-13));
}

TEST_CASE("A rigid rotor on springs whirls as the closed form says", "[rotation][beam]") {
    // A disc-like rotor (Ip = 1.6 Id) and a long one (Ip = 0.2 Id), 0.5 m,
    // 10 kg, on two equal radial springs at its ends; the beam is made 1e7
    // times stiffer than the springs: rigid to ~1e-8 (its bending under the
    // spring forces, k L^3 / (48 EI)).
    for (const double polar_share : {1.6, 0.2}) {
        const double L = 0.5, m = 10.0, k = 1e6;
        BeamSection s;
        s.rho_A = m / L;
        s.rho_I = 0.01;  // kg m
        const double Id = s.rho_I * L + m * L * L / 12;
        s.rho_J = polar_share * Id / L;
        s.EI = s.kappa_GA = s.EA = s.GJ = 1e7 * k * L * L * L;
        BeamNetwork net = uniform_beam(s, L, 4);
        Matrix6 spring = Matrix6::Zero();
        spring(beam_dof::ux, beam_dof::ux) = spring(beam_dof::uy, beam_dof::uy) = k;
        for (int node : {net.beams[0].nodes.front(), net.beams[0].nodes.back()}) net.springs.push_back({node, -1, spring});
        const double k_tilt = 2 * k * (L / 2) * (L / 2), lambda_scale = 2 * k / m;
        const RotatingNetwork rotor(net, lambda_scale);
        for (const double omega : {0.0, 300.0, 1500.0}) {
            const double Ip = s.rho_J * L;
            const std::vector<RotatingMode> modes = rotor.modes_at(hz(omega), 12);
            const RotatingMode* fw = nearest(modes, hz(whirl_root(Id, Ip * omega, k_tilt)));
            const RotatingMode* bw = nearest(modes, hz(whirl_root(Id, -Ip * omega, k_tilt)));
            const RotatingMode* bounce = nearest(modes, hz(std::sqrt(2 * k / m)));
            // 1e-5: what is left of the beam's own elasticity at the disc's
            // fastest forward whirl (417 Hz) is a few 1e-6.
            CHECK(fw->frequency_hz == Approx(hz(whirl_root(Id, Ip * omega, k_tilt))).epsilon(1e-5));
            CHECK(bw->frequency_hz == Approx(hz(whirl_root(Id, -Ip * omega, k_tilt))).epsilon(1e-5));
            CHECK(bounce->frequency_hz == Approx(hz(std::sqrt(2 * k / m))).epsilon(1e-6));
            if (omega > 0) {
                CHECK(fw->whirl == Whirl::forward);
                CHECK(bw->whirl == Whirl::backward);
                CHECK(fw->circularity == Approx(1.0).epsilon(1e-6));
            }
            for (const RotatingMode& mode : modes)  // the rotor's modes, not the stiff beam's own
                if (mode.frequency_hz < 1e3) CHECK(mode.relative_residual < 1e-10);
        }
    }
}

// The simply supported spinning Timoshenko beam: with w = W sin(beta z) and
// the section rotation phi = P cos(beta z) in complex coordinates, the
// frequencies are the roots of
//   D(omega) = (rho_A omega^2 - kGA beta^2)(rho_I omega^2 - s Omega rho_J omega - EI beta^2 - kGA) - (kGA beta)^2
// (s = +1 forward, -1 backward); for kGA -> infinity the Rayleigh beam's
// (rho_A + rho_I beta^2) omega^2 - s rho_J Omega beta^2 omega - EI beta^4 = 0,
// whose root starts the bisection (shear only lowers it).
double timoshenko_whirl(const BeamSection& s, double beta, double omega_spin, int sign) {
    const auto D = [&](double w) {
        return (s.rho_A * w * w - s.kappa_GA * beta * beta) *
                   (s.rho_I * w * w - sign * omega_spin * s.rho_J * w - s.EI * beta * beta - s.kappa_GA) -
               std::pow(s.kappa_GA * beta, 2);
    };
    const double rayleigh = whirl_root(s.rho_A + s.rho_I * beta * beta, sign * s.rho_J * omega_spin * beta * beta,
                                       s.EI * std::pow(beta, 4));
    double lo = 0.5 * rayleigh, hi = rayleigh * (1 + 1e-9);
    REQUIRE(D(lo) * D(hi) < 0);
    for (int i = 0; i < 200; ++i) {
        const double mid = 0.5 * (lo + hi);
        (D(lo) * D(mid) <= 0 ? hi : lo) = mid;
    }
    return 0.5 * (lo + hi);
}

TEST_CASE("A spinning simply supported Timoshenko tube splits each sine mode into forward and backward whirl",
          "[rotation][beam]") {
    // A steel tube 106 x 76 mm, 2 m: shear, rotary and gyroscopic inertia.
    const BeamSection s = tube_beam_section(0.106, 0.076, OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850));
    const double L = 2.0;
    BeamNetwork net = uniform_beam(s, L, 40);
    for (int node : {net.beams[0].nodes.front(), net.beams[0].nodes.back()})
        for (int d : {beam_dof::ux, beam_dof::uy}) net.hold(node, d);
    net.hold(net.beams[0].nodes.front(), beam_dof::uz);
    net.hold(net.beams[0].nodes.front(), beam_dof::rz);
    const double beta1 = M_PI / L;
    const double lambda_scale = s.EI * std::pow(beta1, 4) / s.rho_A;
    const RotatingNetwork tube(net, lambda_scale);
    for (const double speed_share : {0.0, 1.0, 5.0}) {  // Omega per the first frequency at rest
        const double omega_spin = speed_share * std::sqrt(lambda_scale);
        const std::vector<RotatingMode> modes = tube.modes_at(hz(omega_spin), 12);
        for (int n = 1; n <= 3; ++n) {
            const double beta = n * M_PI / L;
            const double f_fw = hz(timoshenko_whirl(s, beta, omega_spin, +1));
            const double f_bw = hz(timoshenko_whirl(s, beta, omega_spin, -1));
            INFO("n = " << n << ", Omega = " << omega_spin);
            // The 40 elements' discretisation error (h^4): 1e-7 at n = 1, 6e-6 at n = 3.
            const double tolerance = n == 1 ? 1e-6 : 1e-5;
            CHECK(nearest(modes, f_fw)->frequency_hz == Approx(f_fw).epsilon(tolerance));
            CHECK(nearest(modes, f_bw)->frequency_hz == Approx(f_bw).epsilon(tolerance));
            if (speed_share > 0) {
                CHECK(nearest(modes, f_fw)->whirl == Whirl::forward);
                CHECK(nearest(modes, f_bw)->whirl == Whirl::backward);
                CHECK(nearest(modes, f_fw)->label.type == "bending");
                CHECK(nearest(modes, f_fw)->label.m == n - 1);
            }
        }
        for (const RotatingMode& mode : modes) CHECK(mode.relative_residual < 1e-9);
    }
}

TEST_CASE("At speed 0 the rotating network gives the modes at rest", "[rotation][beam]") {
    // Case 08's scene at the beam level (chucks, spring layers): every
    // frequency of the solver at rest, to its own tolerance.
    Scene scene = parse_case_file(std::string(COREMODAL_SOURCE_DIR) + "/cases/08-news-chucks-76x15-2200.toml");
    scene.model = ModelChoice::beam;
    const BeamModelResult rest = solve_beam_model(scene);
    const RotatingNetwork rotating(rest.network, rest.lambda_scale);
    const std::vector<RotatingMode> modes = rotating.modes_at(0.0, 40);
    REQUIRE(modes.size() >= rest.modes.size());
    for (size_t i = 0; i < rest.modes.size(); ++i) {
        CHECK(modes[i].frequency_hz == Approx(rest.modes[i].frequency_hz).epsilon(1e-9).margin(1e-9));
        CHECK(modes[i].label.type == rest.modes[i].label.type);
        CHECK(modes[i].whirl == Whirl::none);
    }
}

TEST_CASE("The general path (planes unlike) and the plane path (planes alike) give the same whirl", "[rotation][beam]") {
    // The Timoshenko tube of above, simply supported; a spring of 1e-9 of
    // the tube's bending stiffness scale on ux alone at mid-span makes the
    // planes unlike (the complex 2n Hermitian path) without moving a
    // frequency by more than ~1e-9.
    const BeamSection s = tube_beam_section(0.106, 0.076, OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850));
    const double L = 2.0;
    BeamNetwork alike = uniform_beam(s, L, 20);
    for (int node : {alike.beams[0].nodes.front(), alike.beams[0].nodes.back()})
        for (int d : {beam_dof::ux, beam_dof::uy}) alike.hold(node, d);
    alike.hold(alike.beams[0].nodes.front(), beam_dof::uz);
    alike.hold(alike.beams[0].nodes.front(), beam_dof::rz);
    BeamNetwork unlike = alike;
    Matrix6 tiny = Matrix6::Zero();
    tiny(beam_dof::ux, beam_dof::ux) = 1e-9 * s.EI / (L * L * L);
    unlike.springs.push_back({unlike.beams[0].nodes[unlike.beams[0].nodes.size() / 2], -1, tiny});
    REQUIRE(bending_planes_alike(alike));
    REQUIRE_FALSE(bending_planes_alike(unlike));
    const double lambda_scale = s.EI * std::pow(M_PI / L, 4) / s.rho_A;
    const double speed = 3 * std::sqrt(lambda_scale) / (2 * M_PI);
    const std::vector<RotatingMode> a = RotatingNetwork(alike, lambda_scale).modes_at(speed, 10);
    const std::vector<RotatingMode> b = RotatingNetwork(unlike, lambda_scale).modes_at(speed, 10);
    REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        CHECK(b[i].frequency_hz == Approx(a[i].frequency_hz).epsilon(1e-8));
        CHECK(b[i].whirl == a[i].whirl);
        CHECK(b[i].relative_residual < 1e-9);
        CHECK(a[i].relative_residual < 1e-9);
    }
}
