// The scale of the first elastic eigenvalue (src/beam/eigenvalue_scale.hpp):
// each family's estimate against its closed form, and which family is the
// smallest for a long core, a ring, a disc and a roll on soft springs.
#include "beam/eigenvalue_scale.hpp"

#include "beam/beam_theory.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace coremodal;
using namespace coremodal::testing;

namespace {

double estimate_of(const Scene& s, ModeFamilies families, const std::string& family) {
    for (const EigenvalueEstimate& e : elastic_eigenvalue_estimates(s, families))
        if (e.family == family) return e.lambda;
    FAIL("no estimate for " << family);
    return 0;
}

bool has_family(const Scene& s, ModeFamilies families, const std::string& family) {
    for (const EigenvalueEstimate& e : elastic_eigenvalue_estimates(s, families))
        if (e.family == family) return true;
    return false;
}

double hz(double lambda) { return std::sqrt(lambda) / (2 * M_PI); }

}  // namespace

TEST_CASE("A long core's scale is its Euler-Bernoulli bending, as before the other families", "[beam][scale]") {
    const Scene core = paper_core(1.5);
    const EigenvalueEstimate scale = elastic_eigenvalue_scale(core, ModeFamilies::beam_and_section);
    CHECK(scale.family == "bending");
    CHECK(hz(scale.lambda) == Approx(euler_bernoulli_first_bending_hz(beam_section(core), 1.5)).epsilon(1e-12));
    CHECK(elastic_eigenvalue_scale(core, ModeFamilies::beam).lambda == scale.lambda);
}

TEST_CASE("Each family's estimate is its closed form", "[beam][scale]") {
    // Steel tube 210 x 200 mm, 0.5 m: every family present.
    const double E = 210e9, G = E / 2.6, rho = 7850, L = 0.5, ro = 0.105, ri = 0.1;
    const Scene tube = steel_tube(2 * ro, 2 * ri, L, 2, 16, 4);
    const ModeFamilies all = ModeFamilies::beam_and_section;
    // Bar in tension and in torsion, free-free: (pi / L)^2 E / rho and G / rho.
    CHECK(estimate_of(tube, all, "axial") == Approx(std::pow(M_PI / L, 2) * E / rho).epsilon(1e-12));
    CHECK(estimate_of(tube, all, "torsion") == Approx(std::pow(M_PI / L, 2) * G / rho).epsilon(1e-12));
    // Thin ring in its plane, n = 2 (docs/validation/models.md): E t^2 / 12 / (rho R^4) * 36 / 5.
    const double t = ro - ri, R = (ro + ri) / 2;
    CHECK(estimate_of(tube, all, "ring in-plane n = 2") ==
          Approx(E * t * t / 12 / (rho * std::pow(R, 4)) * 36 / 5).epsilon(1e-12));
    CHECK(estimate_of(tube, all, "breathing") == Approx(E / (rho * R * R)).epsilon(1e-12));
    // A tube longer than its wall is thick does not bend out of its plane first.
    CHECK_FALSE(has_family(tube, all, "ring out-of-plane n = 2"));
    // The beam level has no section modes.
    CHECK_FALSE(has_family(tube, ModeFamilies::beam, "ring in-plane n = 2"));
    CHECK_FALSE(has_family(tube, ModeFamilies::beam, "breathing"));
}

TEST_CASE("A thin disc's scale is its out-of-plane ring mode, of the order of the free plate's", "[beam][scale]") {
    // Steel disc 200 mm across, 20 mm hole, 2 mm thick.
    const double E = 210e9, nu = 0.3, rho = 7850, a = 0.1, h = 0.002;
    const Scene disc = steel_tube(2 * a, 0.02, h, 4, 16, 2);
    const EigenvalueEstimate scale = elastic_eigenvalue_scale(disc, ModeFamilies::beam_and_section);
    CHECK(scale.family == "ring out-of-plane n = 2");
    // The free plate's n = 2 saddle, omega = 5.25 / a^2 sqrt(D / (rho h)) (Leissa):
    // the thin-ring estimate of so wide a ring is within a factor of 3 in frequency.
    const double D = E * h * h * h / (12 * (1 - nu * nu));
    const double plate = 5.25 / (a * a) * std::sqrt(D / (rho * h)) / (2 * M_PI);
    CHECK(hz(scale.lambda) > plate / 3);
    CHECK(hz(scale.lambda) < plate * 3);
}

TEST_CASE("A roll on a very soft chuck interface has the scale of its motion on the springs", "[beam][scale]") {
    // The near-mechanism of hard case 07: k_n = 1e7 Pa/m over the expanding elements.
    Scene s = with_chucks(paper_core(1.0), InterfaceKind::spring, 1e7);
    const double k_t = s.supports.chucks[0].interface.tangential_stiffness;
    double area = 0;
    for (const ChuckSpec& c : s.supports.chucks)
        for (const ExpandingElement& e : c.expanding) area += 2 * M_PI * s.core.inner_diameter / 2 * e.width;
    const EigenvalueEstimate scale = elastic_eigenvalue_scale(s, ModeFamilies::beam);
    CHECK(scale.family == "roll on the chuck interfaces");
    // Sliding along the axis on k_t: the Rayleigh quotient k_t A / m of the roll.
    CHECK(scale.lambda == Approx(k_t * area / s.roll_mass()).epsilon(1e-12));
}

TEST_CASE("Every estimate is positive and finite, for every example case shape", "[beam][scale]") {
    for (const Scene& s : {paper_core(1.5), steel_tube(0.21, 0.2, 0.0105, 2, 16, 2), steel_tube(0.2, 0.02, 1e-5, 2, 16, 2),
                           with_chucks(paper_core(1.0), InterfaceKind::bonded)})
        for (ModeFamilies f : {ModeFamilies::beam, ModeFamilies::beam_and_section})
            for (const EigenvalueEstimate& e : elastic_eigenvalue_estimates(s, f)) {
                INFO(e.family);
                CHECK(std::isfinite(e.lambda));
                CHECK(e.lambda > 0);
            }
}
