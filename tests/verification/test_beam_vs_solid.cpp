// The Timoshenko beam level against the solid level on the same scenes
// (docs/validation/models.md; docs/theory/beam.md, "When the beam level holds"). Slender
// tubes: a beam is what they are, and the two models agree within 1 %. A
// short thick tube: they differ, for reasons a beam cannot represent.
#include "verification/tube_scenes.hpp"

#include "beam/formulas.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

struct Pair {
    RunReport solid, beam;
};

Pair both_models(Scene s) {
    Pair p;
    p.solid = solve_quietly(s);
    s.model = ModelChoice::beam;
    p.beam = solve_quietly(s);
    return p;
}

double ratio(const Pair& p, const std::string& type, int k = 1) {
    return nth_of_type(p.beam, type, k).frequency_hz / nth_of_type(p.solid, type, k).frequency_hz;
}

}  // namespace

TEST_CASE("Slender free-free tubes: beam and solid agree within 1 %", "[verification][beam_vs_solid]") {
    SECTION("A steel tube, 100 x 5 mm, 1.2 m (L/Do = 12)") {
        const Pair p = both_models(steel_tube(0.100, 0.090, 1.2, 2, 16, 24, 26));
        REQUIRE(p.solid.modes.verification.complete);
        REQUIRE(p.beam.modes.verification.complete);
        CHECK(p.beam.model.level == ModelChoice::beam);
        CHECK(p.beam.model.mass_kg == Approx(p.beam.model.expected_mass_kg).epsilon(1e-12));
        // Measured: bending 0.9988 and 0.9963 (the beam's Cowper coefficient
        // and the wall's shell behaviour, a few tenths of a per cent), torsion
        // 1.0000 (a circular tube twists without warping), axial 1.0007
        // (Love's lateral inertia, 2.4e-4, which a beam leaves out).
        CHECK(ratio(p, "bending", 1) == Approx(1).epsilon(0.01));
        CHECK(ratio(p, "bending", 2) == Approx(1).epsilon(0.01));
        CHECK(ratio(p, "torsion") == Approx(1).epsilon(0.01));
        CHECK(ratio(p, "axial") == Approx(1).epsilon(0.01));
        for (int i = 0; i < 6; ++i) CHECK(p.beam.modes.modes[i].label.type == "rigid");
        CHECK(nth_of_type(p.beam, "bending").label.m == nth_of_type(p.solid, "bending").label.m);
    }
    SECTION("The same tube under 10 mm of aluminium: the composite section of two layers") {
        Scene s = steel_tube(0.100, 0.090, 1.2, 2, 16, 24, 14);
        RestPaperSpec layer;
        layer.outer_diameter = 0.120;
        layer.material = OrthotropicMaterial::isotropic("aluminium", 70e9, 0.33, 2700);
        s.rest_paper = layer;
        s.mesh.n_rest_paper = 1;
        const Pair p = both_models(s);
        // Measured: bending 0.9978 and 0.9936, torsion 1.0000, axial 1.0008.
        CHECK(ratio(p, "bending", 1) == Approx(1).epsilon(0.01));
        CHECK(ratio(p, "bending", 2) == Approx(1).epsilon(0.01));
        CHECK(ratio(p, "torsion") == Approx(1).epsilon(0.01));
        CHECK(ratio(p, "axial") == Approx(1).epsilon(0.01));
    }
}

TEST_CASE("A slender clamped tube: the beam lies within 1 %, above the solid", "[verification][beam_vs_solid]") {
    // 100 x 5 mm steel, 1.4 m, clamped over 100 mm at each end. The beam's
    // clamp holds the whole section; the solid's holds the inner surface,
    // and the wall turns a little inside it: the solid is softer (measured
    // 0.83 % in the first bending pair, 0.63 % in the second). On a
    // paperboard wall, soft in through-thickness shear, the same effect is
    // ten times larger (case 05 against case 03): that is the chuck factor.
    const Pair p = both_models(clamp_both_ends(steel_tube(0.100, 0.090, 1.4, 2, 24, 28, 6), 0.1));
    REQUIRE(p.solid.modes.verification.complete);
    for (int k : {1, 2}) {
        CHECK(ratio(p, "bending", k) > 1.0);
        CHECK(ratio(p, "bending", k) < 1.01);
    }
    CHECK(p.beam.beam.fe_over_timoshenko == Approx(1).epsilon(1e-5));  // the beam level is beam theory here
}

TEST_CASE("A short thick tube: beam and solid differ, because the section deforms", "[verification][beam_vs_solid]") {
    // Steel 200 x 50 mm wall, 0.3 m long (L/Do = 1.5). Why they differ:
    //  - the solid's lowest elastic mode is ovalling (n = 2): the cross-section
    //    itself deforms, which a beam (rigid sections) cannot represent, so the
    //    beam's lowest elastic mode (torsion) lies 7 % above the solid's;
    //  - the second bending mode: with 0.6 half-waves per diameter, shear is
    //    no longer the beam's single kappa G A, the section warps and the
    //    ends relax: the beam is 3 % stiff;
    //  - stretching: the wall thins as it stretches (Poisson); its radial
    //    inertia (Love: (nu pi r_p / L)^2 / 2 = 3 %) softens the solid's
    //    axial mode, measured 5.5 %.
    // Only the first bending mode stays within 0.5 %: shear and rotary
    // inertia, which Timoshenko's beam does carry, dominate it.
    const Pair p = both_models(steel_tube(0.200, 0.100, 0.3, 2, 16, 6, 24));
    REQUIRE(p.solid.modes.verification.complete);
    INFO("beam / solid: bending " << ratio(p, "bending", 1) << ", " << ratio(p, "bending", 2) << "; torsion "
                                  << ratio(p, "torsion") << "; axial " << ratio(p, "axial"));
    const Mode* solid_first = nullptr;
    for (const Mode& m : p.solid.modes.modes)
        if (m.label.type != "rigid") {
            solid_first = &m;
            break;
        }
    REQUIRE(solid_first);
    CHECK(solid_first->label.type == "ovalling");
    CHECK(solid_first->label.n == 2);
    const Mode& beam_first = p.beam.modes.modes.at(6);
    CHECK(beam_first.frequency_hz > 1.05 * solid_first->frequency_hz);
    CHECK(ratio(p, "bending", 2) > 1.02);
    CHECK(ratio(p, "axial") > 1.03);
    CHECK(ratio(p, "bending", 1) == Approx(1).epsilon(0.005));
}

TEST_CASE("I-13 round trip: the solid's free-free frequency of an isotropic tube gives back its modulus",
          "[verification][beam_vs_solid][formulas]") {
    // ISO 11093-8 on a steel tube of the 76 x 15 core's section, 1.5 m (the
    // standard's length): the FE free-free first bending frequency, put into
    // I-13/I-14 with the tube's mass per length, returns E within the shear
    // correction Q's accuracy. Q's fixed 82.66 assumes a shear stiffness; for
    // an isotropic tube (E/G = 2.6) the Timoshenko beam gives 1.1 % low
    // (test_formulas.cpp), and the solid is a Timoshenko beam here to ~0.1 %
    // (case 01: 1.0012): the modulus comes back within 1.5 %, and without Q
    // about 5 % low.
    const Scene s = steel_tube(0.106, 0.076, 1.5, 2, 16, 30, 8);
    const RunReport r = solve_quietly(s);
    REQUIRE(r.modes.verification.complete);
    const double f = r.beam.fe_first_bending_hz;
    const double Ic = tube_inertia(0.106, 0.076), Ac = tube_area(0.106, 0.076);
    const double Ec = iso_flexural_modulus(f, 7850 * Ac, 1.5, Ic, Ac);
    INFO("FE free-free " << f << " Hz; Ec by I-13/14 " << Ec / 1e9 << " GPa");
    CHECK(Ec == Approx(210e9).epsilon(0.015));
    CHECK(Ec / iso_free_free_shear_factor(1.5, Ic, Ac) < 0.97 * 210e9);
}
