// Beam networks (src/beam/beam_network.hpp) and their modes
// (src/beam/network_modes.hpp) against closed forms: Timoshenko beams with
// simple, clamped and free ends, bars in tension and torsion, a rigid body on
// springs, a tilting spring, a frame mass, and a spring layer between two
// beams; then the solver's own claims: the split into independent problems,
// the mirrored bending planes, the Krylov solver against the dense one.
#include "beam/beam_model.hpp"  // spring_layer_per_length
#include "beam/beam_network.hpp"
#include "beam/network_modes.hpp"
#include "support/timoshenko_exact.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

// Steel tube 200 x 100 mm: thick, so shear and rotary inertia matter (as in
// test_beam_theory.cpp).
BeamSection thick_steel_tube() {
    return tube_beam_section(0.2, 0.1, OrthotropicMaterial::isotropic("steel", 210e9, 0.3, 7850));
}

// A section that hardly deforms: every stiffness times `factor`.
BeamSection stiffened(BeamSection s, double factor) {
    s.EI *= factor, s.kappa_GA *= factor, s.EA *= factor, s.GJ *= factor;
    return s;
}

// One uniform beam from z = 0 to L; returns the network (beam 0).
BeamNetwork uniform_beam(const BeamSection& s, double L, int n_elements) {
    BeamNetwork net;
    std::vector<double> z;
    for (int i = 0; i <= n_elements; ++i) z.push_back(L * i / n_elements);
    net.add_beam("beam", z, std::vector<BeamSection>(n_elements, s), [&](double zi) { return net.add_node(zi); });
    return net;
}

int first_node(const BeamNetwork& net) { return net.beams[0].nodes.front(); }
int last_node(const BeamNetwork& net) { return net.beams[0].nodes.back(); }
int middle_node(const BeamNetwork& net) { return net.beams[0].nodes[net.beams[0].nodes.size() / 2]; }

void hold_everywhere(BeamNetwork& net, std::initializer_list<int> dofs) {
    for (int node = 0; node < net.n_nodes(); ++node)
        for (int d : dofs) net.hold(node, d);
}

NetworkModes solve(const BeamNetwork& net, int n_modes, double lambda_scale, bool dense = false) {
    NetworkSolveRequest r;
    r.n_modes = n_modes;
    r.lambda_scale = lambda_scale;
    r.force_dense = dense;
    return solve_network_modes(net, r);
}

double hz(double lambda) { return std::sqrt(std::max(lambda, 0.0)) / (2 * M_PI); }

// Frequencies of the modes whose kinetic energy lies in one motion family.
std::vector<double> family_hz(const NetworkModes& m, MotionFamily family) {
    std::vector<double> f;
    for (size_t i = 0; i < m.eigenvalues.size(); ++i) {
        double share = 0;
        for (Eigen::Index d = 0; d < m.shapes[i].size(); ++d)
            if (motion_family(int(d)) == family) share += m.shapes[i](d) * m.mass_shapes[i](d);
        if (share > 0.5) f.push_back(hz(m.eigenvalues[i]));
    }
    return f;
}

double lambda_of(double f_hz) { return std::pow(2 * M_PI * f_hz, 2); }

Matrix6 diagonal_spring(std::initializer_list<int> dofs, double k) {
    Matrix6 s = Matrix6::Zero();
    for (int d : dofs) s(d, d) = k;
    return s;
}

}  // namespace

TEST_CASE("A simply supported Timoshenko beam bends at the closed-form frequencies", "[beam][network]") {
    const BeamSection s = thick_steel_tube();
    const double L = 1.0;
    BeamNetwork net = uniform_beam(s, L, 40);
    for (int end : {first_node(net), last_node(net)}) net.hold(end, beam_dof::ux), net.hold(end, beam_dof::uy);
    hold_everywhere(net, {beam_dof::uz, beam_dof::rz});
    const NetworkModes m = solve(net, 8, lambda_of(simply_supported_timoshenko_hz(s, L, 1)));
    REQUIRE(m.verification.complete);
    CHECK(m.mirrored_planes);
    for (int k = 1; k <= 4; ++k) {
        // Modes 2k-1 and 2k: the degenerate pair of the k-th half-wave.
        const double exact = simply_supported_timoshenko_hz(s, L, k);
        INFO("half-waves " << k << ": exact " << exact << " Hz");
        CHECK(hz(m.eigenvalues[2 * k - 2]) == Approx(exact).epsilon(2e-6 * k * k * k * k));
        CHECK(m.eigenvalues[2 * k - 1] == Approx(m.eigenvalues[2 * k - 2]).epsilon(1e-12));
    }
}

TEST_CASE("Clamped and free Timoshenko beams match the exact frequency equation", "[beam][network]") {
    const BeamSection s = thick_steel_tube();
    const double L = 1.0;
    for (BeamEnds ends : {BeamEnds::clamped_clamped, BeamEnds::free_free}) {
        BeamNetwork net = uniform_beam(s, L, 40);
        if (ends == BeamEnds::clamped_clamped) net.hold_all(first_node(net)), net.hold_all(last_node(net));
        const double exact = exact_timoshenko_first_hz(s, L, ends);
        const NetworkModes m = solve(net, 12, lambda_of(exact));
        REQUIRE(m.verification.complete);
        const std::vector<double> bending = family_hz(m, MotionFamily::bending_xz);
        INFO((ends == BeamEnds::clamped_clamped ? "clamped-clamped" : "free-free") << ": exact " << exact << " Hz");
        if (ends == BeamEnds::free_free) {
            // Six rigid-body modes first: two translations and two rotations
            // sideways, one along, one about the axis.
            for (int i = 0; i < 6; ++i) CHECK(std::abs(m.eigenvalues[i]) < 1e-9 * lambda_of(exact));
            CHECK(m.eigenvalues[6] > 0.5 * lambda_of(exact));
        }
        const double first_elastic = ends == BeamEnds::free_free ? bending.at(2) : bending.at(0);
        CHECK(first_elastic == Approx(exact).epsilon(1e-6));
    }
}

TEST_CASE("A free bar stretches and twists at m/(2L) sqrt(stiffness/inertia)", "[beam][network]") {
    const BeamSection s = thick_steel_tube();
    const double L = 2.0;
    BeamNetwork net = uniform_beam(s, L, 30);
    hold_everywhere(net, {beam_dof::ux, beam_dof::uy, beam_dof::rx, beam_dof::ry});
    const double axial = std::sqrt(s.EA / s.rho_A) / (2 * L), torsion = std::sqrt(s.GJ / s.rho_J) / (2 * L);
    const NetworkModes m = solve(net, 10, lambda_of(torsion));
    const std::vector<double> fa = family_hz(m, MotionFamily::axial), ft = family_hz(m, MotionFamily::torsion);
    // Quadratic bars: the frequency error falls as h^4; (k h)^4 / 1440 = 1.3e-6
    // for the second mode at 30 elements.
    for (int k = 1; k <= 2; ++k) {
        CHECK(fa.at(k) == Approx(k * axial).epsilon(2e-6));  // fa[0]: rigid translation
        CHECK(ft.at(k) == Approx(k * torsion).epsilon(2e-6));
    }
}

TEST_CASE("A rigid body on springs: sqrt(k/m), a tilting spring and a frame mass", "[beam][network]") {
    // A short beam stiffened 1e3 times on soft springs: its own elasticity
    // shifts the eigenvalues by about k L^3 / (100 EI) ~ 2e-7, rounding in a
    // system this stiff by ~1e-7 (a stiffer beam loses more to rounding than
    // it gains), hence 1e-6.
    const BeamSection s = stiffened(thick_steel_tube(), 1e3);
    const double L = 0.5, m = s.rho_A * L, J = m * L * L / 12 + s.rho_I * L;  // J about the middle
    const double k = 2e6;                                                      // N/m

    SECTION("Two radial springs k/2 at the ends: bounce sqrt(k/m), rock sqrt(k L^2/4 / J)") {
        BeamNetwork net = uniform_beam(s, L, 4);
        for (int end : {first_node(net), last_node(net)})
            net.springs.push_back({end, -1, diagonal_spring({beam_dof::ux, beam_dof::uy}, k / 2)});
        hold_everywhere(net, {beam_dof::uz, beam_dof::rz});
        const NetworkModes modes = solve(net, 4, k / m);
        REQUIRE(modes.verification.complete);
        CHECK(hz(modes.eigenvalues[0]) == Approx(std::sqrt(k / m) / (2 * M_PI)).epsilon(1e-6));
        CHECK(hz(modes.eigenvalues[1]) == Approx(std::sqrt(k / m) / (2 * M_PI)).epsilon(1e-6));
        CHECK(hz(modes.eigenvalues[2]) == Approx(std::sqrt(k * L * L / 4 / J) / (2 * M_PI)).epsilon(1e-6));
    }
    SECTION("Pinned in the middle on a tilting spring k_t: sqrt(k_t / J)") {
        const double k_tilt = 3e4;  // N m/rad
        BeamNetwork net = uniform_beam(s, L, 4);
        net.hold(middle_node(net), beam_dof::ux), net.hold(middle_node(net), beam_dof::uy);
        net.springs.push_back({middle_node(net), -1, diagonal_spring({beam_dof::rx, beam_dof::ry}, k_tilt)});
        hold_everywhere(net, {beam_dof::uz, beam_dof::rz});
        const NetworkModes modes = solve(net, 2, k_tilt / J);
        CHECK(hz(modes.eigenvalues[0]) == Approx(std::sqrt(k_tilt / J) / (2 * M_PI)).epsilon(1e-6));
    }
    SECTION("Bearing spring k1 to a frame mass m2 on a frame spring k2: the two-mass system") {
        const double k1 = k, m2 = 0.7 * m, k2 = 0.4 * k;
        BeamNetwork net = uniform_beam(s, L, 4);
        const int frame = net.add_node(L / 2);
        net.springs.push_back({middle_node(net), frame, diagonal_spring({beam_dof::ux, beam_dof::uy}, k1)});
        net.springs.push_back({frame, -1, diagonal_spring({beam_dof::ux, beam_dof::uy}, k2)});
        net.masses.push_back({frame, m2});
        for (int d : {beam_dof::uz, beam_dof::rx, beam_dof::ry, beam_dof::rz}) net.hold(frame, d);
        net.hold(middle_node(net), beam_dof::rx), net.hold(middle_node(net), beam_dof::ry);
        hold_everywhere(net, {beam_dof::uz, beam_dof::rz});
        // m m2 w^4 - (k1 m2 + (k1 + k2) m) w^2 + k1 k2 = 0.
        const double b = k1 * m2 + (k1 + k2) * m, root = std::sqrt(b * b - 4 * m * m2 * k1 * k2);
        const double low = (b - root) / (2 * m * m2), high = (b + root) / (2 * m * m2);
        const NetworkModes modes = solve(net, 4, low);
        REQUIRE(modes.eigenvalues.size() == 4);
        CHECK(modes.eigenvalues[0] == Approx(low).epsilon(1e-6));
        CHECK(modes.eigenvalues[1] == Approx(low).epsilon(1e-6));
        CHECK(modes.eigenvalues[2] == Approx(high).epsilon(1e-6));
        CHECK(modes.eigenvalues[3] == Approx(high).epsilon(1e-6));
    }
}

TEST_CASE("A spring layer holds a rigid beam inside a fixed one at the closed-form frequencies",
          "[beam][network]") {
    // Beam 1 (stiff) inside beam 0 (held), joined by a full band over their
    // whole length: per length k_lat = pi R (k_n + k_t), k_axial = 2 pi R k_t,
    // k_torsion = 2 pi R^3 k_t, k_rock = pi R^3 k_t (axial shear of a tilt).
    // Beam 1 stiffened 1e3 times: elasticity and rounding as in the test above.
    const BeamSection s = stiffened(thick_steel_tube(), 1e3);
    const double L = 0.4, R = 0.075, kn = 3e7, kt = 2.5e7;
    BeamNetwork net = uniform_beam(s, L, 4);
    hold_everywhere(net, {0, 1, 2, 3, 4, 5});
    std::vector<double> z;
    for (int i = 0; i <= 3; ++i) z.push_back(L * i / 3);  // elements that do not line up with beam 0's
    net.add_beam("inner", z, std::vector<BeamSection>(3, s), [&](double zi) { return net.add_node(zi); });
    net.couplings.push_back({0, 1, 0.0, L, spring_layer_per_length({kn, kt}, {}, R)});
    const double m = s.rho_A * L, k_lat = M_PI * R * (kn + kt);
    const NetworkModes modes = solve(net, 6, k_lat * L / m);
    REQUIRE(modes.verification.complete);
    const double lateral = k_lat * L / m, axial = 2 * M_PI * R * kt * L / m;
    const double torsion = 2 * M_PI * std::pow(R, 3) * kt * L / (s.rho_J * L);
    const double rocking = (k_lat * std::pow(L, 3) / 12 + M_PI * std::pow(R, 3) * kt * L) / (m * L * L / 12 + s.rho_I * L);
    std::vector<double> expected = {lateral, lateral, axial, torsion, rocking, rocking};
    std::sort(expected.begin(), expected.end());
    for (size_t i = 0; i < expected.size(); ++i) CHECK(modes.eigenvalues[i] == Approx(expected[i]).epsilon(1e-6));
}

TEST_CASE("A spring layer's stiffness per length integrates its band or pads", "[beam][network]") {
    const double R = 0.075, kn = 3e10, kt = 2e10;
    using namespace beam_dof;
    SECTION("A full band: pi R (k_n + k_t) sideways, 2 pi R k_t along, 2 pi R^3 k_t in torsion") {
        const Matrix6 k = spring_layer_per_length({kn, kt}, {}, R);
        CHECK(k(ux, ux) == Approx(M_PI * R * (kn + kt)));
        CHECK(k(uy, uy) == Approx(M_PI * R * (kn + kt)));
        CHECK(k(uz, uz) == Approx(2 * M_PI * R * kt));
        CHECK(k(rz, rz) == Approx(2 * M_PI * std::pow(R, 3) * kt));
        CHECK(k(rx, rx) == Approx(M_PI * std::pow(R, 3) * kt));
        CHECK(std::abs(k(ux, uy)) + std::abs(k(uz, ry)) + std::abs(k(uy, rz)) < 1e-9 * k(ux, ux));
    }
    SECTION("Pads: the closed-form arc integrals against a fine midpoint sum") {
        for (int n : {1, 2, 3, 4}) {
            ExpandingElement e;
            e.segments = n;
            e.segment_angle = 50 * M_PI / 180;
            const Matrix6 k = spring_layer_per_length({kn, kt}, e, R);
            Matrix6 sum = Matrix6::Zero();
            const int steps = 20000;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < steps; ++j) {
                    const double t = 2 * M_PI * i / n + e.segment_angle * ((j + 0.5) / steps - 0.5), c = std::cos(t),
                                 s = std::sin(t);
                    Eigen::Matrix<double, 6, 1> normal, tangential, axial;
                    normal << c, s, 0, 0, 0, 0;
                    tangential << -s, c, 0, 0, 0, R;
                    axial << 0, 0, 1, R * s, -R * c, 0;
                    sum += R * e.segment_angle / steps *
                           (kn * normal * normal.transpose() + kt * tangential * tangential.transpose() +
                            kt * axial * axial.transpose());
                }
            INFO(n << " pads of 50 deg");
            CHECK((k - sum).cwiseAbs().maxCoeff() < 1e-6 * k.cwiseAbs().maxCoeff());
            // Three or more evenly spaced pads act alike in x and y; one or two do not.
            CHECK((std::abs(k(ux, ux) - k(uy, uy)) < 1e-9 * k(ux, ux)) == (n >= 3));
        }
    }
}

TEST_CASE("The split into independent problems and the mirrored planes are exact", "[beam][network]") {
    // A beam inside a held one on pads: one pad couples sideways motion with
    // twist and tilt with stretching, two pads make x and y differ, four act alike.
    const BeamSection s = thick_steel_tube();
    const double L = 0.6, R = 0.075;
    for (int pads : {1, 2, 4}) {
        BeamNetwork net = uniform_beam(s, L, 6);
        net.hold_all(first_node(net)), net.hold_all(last_node(net));
        std::vector<double> z = {0.1, 0.3, 0.5};
        net.add_beam("inner", z, std::vector<BeamSection>(2, s), [&](double zi) { return net.add_node(zi); });
        ExpandingElement e;
        e.segments = pads;
        e.segment_angle = 60 * M_PI / 180;
        net.couplings.push_back({0, 1, 0.1, 0.5, spring_layer_per_length({3e9, 2e9}, e, R)});
        const NetworkModes m = solve(net, 16, 1e6);
        INFO(pads << " pads");
        CHECK(m.mirrored_planes == (pads == 4));
        CHECK(m.n_problems == (pads == 1 ? 2 : pads == 2 ? 4 : 3));
        CHECK(m.verification.complete);
        CHECK_FALSE(m.dense_retry);
        // Every mode is a mode of the whole, unsplit system.
        const NetworkMatrices all = assemble_network(net);
        for (size_t i = 0; i < m.eigenvalues.size(); ++i) {
            Eigen::VectorXd x(all.free_dofs.size());
            for (size_t j = 0; j < all.free_dofs.size(); ++j) x(j) = m.shapes[i](all.free_dofs[j]);
            const double residual = (all.K * x - m.eigenvalues[i] * (all.M * x)).norm() /
                                    (all.K.cwiseAbs().toDense().colwise().sum().maxCoeff() * x.norm());
            CHECK(residual < 1e-12);
            CHECK(x.dot(all.M * x) == Approx(1.0).epsilon(1e-10));
        }
    }
}

TEST_CASE("The Krylov solver finds the dense solver's modes and proves none missed", "[beam][network]") {
    // Large enough for the Krylov path (more than 16 DOFs per problem),
    // free-free so that the rigid-body pairs test the block size.
    const BeamSection s = thick_steel_tube();
    const BeamNetwork net = uniform_beam(s, 3.0, 60);
    const double scale = lambda_of(exact_timoshenko_first_hz(s, 3.0, BeamEnds::free_free));
    const NetworkModes krylov = solve(net, 20, scale), dense = solve(net, 20, scale, true);
    REQUIRE(krylov.eigenvalues.size() == dense.eigenvalues.size());
    CHECK(krylov.verification.complete);
    CHECK_FALSE(krylov.dense_retry);
    CHECK(krylov.verification.negative_pivots_at_shift == krylov.verification.modes_below_shift);
    CHECK(krylov.verification.max_relative_residual < 1e-10);
    CHECK(krylov.verification.max_orthonormality_error < 1e-10);
    for (size_t i = 0; i < dense.eigenvalues.size(); ++i)
        CHECK(krylov.eigenvalues[i] == Approx(dense.eigenvalues[i]).epsilon(1e-9).margin(1e-9 * scale));
}

TEST_CASE("A band of frequencies returns exactly the modes inside it", "[beam][network]") {
    const BeamSection s = thick_steel_tube();
    BeamNetwork net = uniform_beam(s, 2.0, 30);
    net.hold_all(first_node(net)), net.hold_all(last_node(net));
    const NetworkModes all = solve(net, 30, 1e6);
    // Band edges in the gaps after modes a and b (never inside a pair).
    std::vector<size_t> gaps;
    for (size_t i = 0; i + 1 < all.eigenvalues.size(); ++i)
        if (all.eigenvalues[i + 1] > all.eigenvalues[i] * (1 + 1e-6)) gaps.push_back(i);
    const size_t a = gaps.at(1), b = gaps.at(6);
    NetworkSolveRequest r;
    r.lambda_scale = 1e6;
    r.lambda_min = 0.5 * (all.eigenvalues[a] + all.eigenvalues[a + 1]);
    r.lambda_max = 0.5 * (all.eigenvalues[b] + all.eigenvalues[b + 1]);
    const NetworkModes band = solve_network_modes(net, r);
    REQUIRE(band.eigenvalues.size() == b - a);
    for (size_t i = 0; i < band.eigenvalues.size(); ++i)
        CHECK(band.eigenvalues[i] == Approx(all.eigenvalues[a + 1 + i]).epsilon(1e-10));
    CHECK(band.verification.complete);
}
