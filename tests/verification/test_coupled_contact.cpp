// The one-sided contact of chucks not expanded at the coupled-harmonic level
// (models/coupled/contact_layer, contact_static; docs/theory/coupled.md "The
// one-sided contact"): the static state against the rigid-body closed form
// and against the 3D solid, the parity of the couplings about the vertical,
// the modes verified and falling with N, and against the solid mode by mode.
#include "tube_scenes.hpp"

#include "models/choose.hpp"
#include "models/coupled/contact_static.hpp"
#include "models/coupled/coupled_level.hpp"
#include "models/solve_steps.hpp"
#include "scene/case_file.hpp"
#include "scene/mesh_levels.hpp"
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

CoupledContactState coupled_static(const Scene& s, int n_max = kContactStaticHarmonics) {
    const Section sec = section_of(s);
    return solve_coupled_contact(s, sec.mesh, sec.materials, n_max, Printer{false});
}

double peak_interpenetration(const GravityContact& c) {
    double peak = 0;
    for (const ContactPointState& p : c.state) peak = std::max(peak, p.d);
    return peak;
}

CoupledModes coupled_at_n(const Scene& s, const Section& sec, int n_max, const Attachments& attached) {
    return solve_coupled(s, sec.mesh, sec.materials, n_max, solve_request(s), attached);
}

}  // namespace

TEST_CASE("Coupled contact: a rigid core on rigid chucks carries its weight over the rigid-body closed form's arc",
          "[coupled][contact]") {
    // The solid's test of the same name, at the coupled level.
    const Scene s = rigid_core_not_expanded(16);
    const CoupledContactState state = coupled_static(s);
    const GravityContact& run = state.contact;
    const double weight = s.roll_mass() * kStandardGravity;
    const StackContact law{1e8, contact_law().residual_pressure};
    const double delta = rigid_contact_drop(weight / 2, kChuckClearance, kChuckBore, kChuckInserted, law);
    const double half_arc_deg = std::acos(kChuckClearance / delta) * 180 / M_PI;
    REQUIRE(run.chucks.size() == 2);
    INFO("closed form: drop " << delta << " m, top interpenetration " << delta - kChuckClearance << " m, arc "
                              << 2 * half_arc_deg << " deg; coupled: peak " << peak_interpenetration(run) << " m, arc "
                              << run.chucks[0].arc_deg << " deg, " << run.iterations << " iterations");
    // Equilibrium of the y translation at any N (its block (1, sin) holds the whole load), up to
    // the static tangential spring's share (kStaticTangentialFraction = 1e-6 of k_n: 1.1e-6 here).
    CHECK(run.chucks[0].vertical_force_n + run.chucks[1].vertical_force_n == Approx(weight).epsilon(1e-5));
    CHECK(run.chucks[0].vertical_force_n == Approx(run.chucks[1].vertical_force_n).epsilon(1e-6));
    // A rigid core drops as a whole: the top's interpenetration and the arc of the closed form.
    CHECK(peak_interpenetration(run) == Approx(delta - kChuckClearance).epsilon(0.01));
    const double spacing = 360.0 / kContactPointsAround;
    CHECK(run.chucks[0].arc_deg <= 2 * half_arc_deg + 1e-9);
    CHECK(run.chucks[0].arc_deg >= 2 * half_arc_deg - 2 * spacing);
    CHECK(run.iterations <= 15);
}

TEST_CASE("Coupled contact: the static state of a paper core agrees with the 3D solid's", "[coupled][contact][long]") {
    // The solid test's scene (0.9 m paper core, k_n0 = 1e9 Pa/m); the solid
    // at 16 around has 64 points around (5.6 deg apart), the coupled level 128.
    const Scene s = not_expanded(paper_core(0.9, 16, 24), 1e9);
    const GravityContact coupled = coupled_static(s).contact, solid = solid_static_contact(s);
    const double weight = s.roll_mass() * kStandardGravity;
    REQUIRE(coupled.chucks.size() == 2);
    REQUIRE(solid.chucks.size() == 2);
    const ChuckContactState &c = coupled.chucks[0], &b = solid.chucks[0];
    INFO("coupled: arc " << c.arc_deg << " deg, z " << c.z_from_m << " to " << c.z_to_m << " m, peak " << c.max_pressure_pa
                         << " Pa, d " << peak_interpenetration(coupled) << " m; solid: arc " << b.arc_deg << " deg, z "
                         << b.z_from_m << " to " << b.z_to_m << " m, peak " << b.max_pressure_pa << " Pa, d "
                         << peak_interpenetration(solid) << " m");
    CHECK(c.vertical_force_n + coupled.chucks[1].vertical_force_n == Approx(weight).epsilon(1e-5));
    CHECK(c.arc_deg > 0);
    CHECK(c.arc_deg < 180);
    // The closed arc within the solid's point spacing (360 / 64 deg) and one of ours on each side.
    CHECK(std::abs(c.arc_deg - b.arc_deg) <= 2 * (360.0 / 64 + 360.0 / kContactPointsAround));
    // The closed length along z within one solid element (0.11 m inserted over its axial cells).
    CHECK(std::abs((c.z_to_m - c.z_from_m) - (b.z_to_m - b.z_from_m)) <= 0.03);
    // The top's interpenetration (the core's drop less the clearance) to a few per cent: the solid's 16
    // around is a polygonal bore of 32 quadratic arcs.
    CHECK(peak_interpenetration(coupled) == Approx(peak_interpenetration(solid)).epsilon(0.05));
    CHECK(c.max_pressure_pa == Approx(b.max_pressure_pa).epsilon(0.1));
}

TEST_CASE("Coupled contact: blocks of opposite parity about the vertical do not meet", "[coupled][contact]") {
    // Mirror x -> -x: cos n theta is even for n even, sin n theta for n odd
    // (contact_static.hpp). The closed arc is symmetric about theta = 90 deg,
    // so its couplings vanish between an even and an odd block, component
    // by component (n = 0's torsion V is odd, its U and W even).
    const Scene s = not_expanded(paper_core(0.6, 16, 12), 1e9);
    const ContactLayer layer = coupled_static(s, 6).layer;
    double total = 0;  // the layer's radial stiffness summed over its points, N/m
    for (const Eigen::Vector3d& k : layer.weight_around) total += k[0];
    REQUIRE(total > 0);
    const auto odd_partner = [](HarmonicFamily h) {
        return h.n == 0 ? HarmonicFamily{1, Family::cos} : HarmonicFamily{h.n, h.family == Family::cos ? Family::sin : Family::cos};
    };
    for (int n = 0; n <= 6; ++n)
        for (Family f : {Family::cos, Family::sin}) {
            const HarmonicFamily a{n, f};
            if (n == 0 && f == Family::sin) continue;
            INFO("block " << n << (f == Family::cos ? " cos" : " sin"));
            CHECK(contact_couples(layer, a, HarmonicFamily{1, Family::sin}) == mirror_even(a));
            if (n > 0) CHECK_FALSE(contact_couples(layer, a, odd_partner(a)));
            for (int c = 0; c < 3; ++c)
                if (n > 0) CHECK(std::abs(contact_integral(layer, a, odd_partner(a), c)) <= 1e-13 * total);
        }
    // n = 0 couples to both sets, through U, W to the even and V to the odd blocks.
    CHECK(contact_integral(layer, {0, Family::cos}, {2, Family::cos}, 0) != 0);
    CHECK(contact_integral(layer, {0, Family::cos}, {2, Family::sin}, 1) != 0);
    CHECK(std::abs(contact_integral(layer, {0, Family::cos}, {2, Family::sin}, 0)) <= 1e-13 * total);
    SECTION("so coupled_components finds two sets, n = 0's (U, W) with the even blocks and its V with the odd") {
        const SectionMesh mesh = make_section_mesh(make_tube_section(s), s.supports.clamps);
        const CoupledDofs all = coupled_dofs(s, mesh, 6);
        Attachments attached = attachments(s);
        attached.contact = layer;
        const std::vector<CoupledComponent> sets = coupled_components(all, attached);
        REQUIRE(sets.size() == 2);
        int dofs = 0;
        for (const CoupledComponent& set : sets) {
            CHECK(set.partner_of < 0);  // not turned copies: the arc is not symmetric under a quarter turn
            dofs += set.dofs.n_dofs;
            const bool even = mirror_even(set.dofs.blocks.at(1).harmonic);
            for (const CoupledBlock& b : set.dofs.blocks)
                if (b.harmonic.n > 0) CHECK(mirror_even(b.harmonic) == even);
            REQUIRE(set.dofs.blocks.front().harmonic.n == 0);
            const std::vector<int>& of = set.dofs.blocks.front().dofs.of_component;
            for (size_t i = 0; i < of.size(); ++i)  // the odd set holds n = 0's V only, the even its U, W
                if (of[i] >= 0) CHECK((i % 3 == 1) != even);
        }
        CHECK(dofs == all.n_dofs);  // every DOF in exactly one set
    }
}

TEST_CASE("Coupled contact: every mode verified, counted and falling with N", "[coupled][contact][long]") {
    Scene s = not_expanded(paper_core(0.6, 16, 12), 1e9);
    s.analysis.n_modes = 6;
    const Section sec = section_of(s);
    Attachments attached = attachments(s);
    REQUIRE(attached.one_sided);
    CHECK(attached.step() == 1);
    attached.contact = solve_coupled_contact(s, sec.mesh, sec.materials, kContactStaticHarmonics, Printer{false}).layer;
    std::vector<std::vector<double>> lambdas;
    for (int n_max : {2, 3, 4, 5}) {
        const CoupledModes c = coupled_at_n(s, sec, n_max, attached);
        INFO("N = " << n_max);
        REQUIRE(c.verification.complete);
        CHECK(c.verification.max_relative_residual < 1e-8);
        CHECK(c.verification.max_orthonormality_error < 1e-8);
        CHECK(c.verification.modes_below_shift == c.verification.negative_pivots_at_shift);
        CHECK(c.n_coupling_entries > 0);
        lambdas.push_back({c.eigenvalues.begin(), c.eigenvalues.begin() + 6});
    }
    for (size_t k = 1; k < lambdas.size(); ++k)
        for (size_t i = 0; i < 6; ++i) CHECK(lambdas[k][i] <= lambdas[k - 1][i] * (1 + 1e-10));
    CHECK(lambdas.back()[0] < lambdas.front()[0]);
}

TEST_CASE("Coupled contact: auto runs a chuck not expanded at the coupled level and lists the contact as simulated",
          "[coupled][contact][long]") {
    Scene s = not_expanded(paper_core(0.6, 16, 12), 1e9);
    s.analysis.n_modes = 4;
    CHECK(chosen_level(at_level(s, ModelChoice::automatic)) == ModelChoice::coupled);
    const RunReport r = solve_without_chuck_factor(at_level(s, ModelChoice::automatic));
    CHECK(r.model.level == ModelChoice::coupled);
    REQUIRE(r.modes.verification.complete);
    CHECK(r.modes.modes.size() == 4);
    CHECK(r.model.mass_kg == Approx(r.model.expected_mass_kg).epsilon(1e-9));
    const std::vector<std::string> effects = r.scene.effects();
    CHECK(std::count(effects.begin(), effects.end(), "one_sided_contact") == 1);
    CHECK(std::count(effects.begin(), effects.end(), "gravity_preload") == 1);
    SECTION("and model = \"coupled\" no longer refuses it") {
        check_same_eigenvalues(solve_without_chuck_factor(at_level(s, ModelChoice::coupled)), r, 1e-12);
    }
}

TEST_CASE("Coupled contact against the 3D solid on chucks not expanded, mode by mode", "[coupled][contact][long]") {
    // A 0.6 m paper core on both chucks not expanded (k_n0 = 1e9 Pa/m),
    // 6 modes: the roll rocking on its arcs, then the split bending pair.
    // The solid at 16 and 32 around (check_within_solid_error); the contact
    // arc's edge cuts its faces, so it converges at first order at worst.
    // Measured (docs/theory/coupled.md): the gap is the contact quadrature's.
    const auto scene_at = [](int around, ModelChoice level) {
        Scene s = not_expanded(paper_core(0.6, around, 12), 1e9);
        s.analysis.n_modes = 6;
        s.model = level;
        return s;
    };
    const RunReport c = solve_without_chuck_factor(scene_at(16, ModelChoice::coupled));
    REQUIRE(c.model.level == ModelChoice::coupled);
    REQUIRE(c.modes.verification.complete);
    CHECK(c.modes.verification.max_relative_residual < 1e-8);
    CHECK(c.modes.verification.max_orthonormality_error < 1e-8);
    const RunReport coarse = solve_without_chuck_factor(scene_at(16, ModelChoice::solid));
    const RunReport fine = solve_without_chuck_factor(scene_at(32, ModelChoice::solid));
    check_within_solid_error(c, coarse, fine, false);
}

TEST_CASE("Coupled contact: convergence in N on case 09 (a measurement for docs/theory/coupled.md, not a check)",
          "[.][coupled][contact][convergence]") {
    // build/tests/coremodal_tests "[convergence]" -- prints the static state's
    // arc and peak for N = 8, 16, 32, then, for N = 2 ... 24 (the static state
    // at kContactStaticHarmonics), the frequencies of case 09's 12 wanted
    // modes and the largest relative change per step. COREMODAL_MESH =
    // coarse | default picks the section (default: coarse), COREMODAL_N_MAX the last N.
    const char* level = std::getenv("COREMODAL_MESH");
    const std::string path = std::string(COREMODAL_SOURCE_DIR) + "/cases/09-news-chucks-not-expanded-76x15-2200.toml";
    Scene s = parse_case_text(slurp(path), path);
    apply_mesh_level(s, level ? level : "coarse");
    const Section sec = section_of(s);
    for (int n_static : {8, 16, 32}) {  // the static state's own convergence
        const GravityContact g = solve_coupled_contact(s, sec.mesh, sec.materials, n_static, Printer{false}).contact;
        std::printf("static N = %2d: arc %.2f deg, z %.1f to %.1f mm, peak pressure %.1f kPa, peak d %.3f um\n", n_static,
                    g.chucks[0].arc_deg, g.chucks[0].z_from_m * 1e3, g.chucks[0].z_to_m * 1e3,
                    g.chucks[0].max_pressure_pa / 1e3, peak_interpenetration(g) * 1e6);
    }
    Attachments attached = attachments(s);
    attached.contact = solve_coupled_contact(s, sec.mesh, sec.materials, kContactStaticHarmonics, Printer{false}).layer;
    std::vector<double> last;
    const char* top = std::getenv("COREMODAL_N_MAX");
    for (int n_max = 2; n_max <= (top ? std::atoi(top) : 24); ++n_max) {
        const CoupledModes c = coupled_at_n(s, sec, n_max, attached);
        REQUIRE(c.verification.complete);
        std::vector<double> f;
        for (size_t i = 0; i < 12; ++i) f.push_back(std::sqrt(c.eigenvalues.at(i)) / (2 * M_PI));
        double change = 0;
        for (size_t i = 0; i < last.size(); ++i) change = std::max(change, std::abs(last[i] - f[i]) / f[i]);
        std::printf("N = %2d: %7d DOFs, f = ", n_max, c.dofs.n_dofs);
        for (double x : f) std::printf("%.5f ", x);
        std::printf(" max change %.2e\n", change);
        last = f;
    }
}
