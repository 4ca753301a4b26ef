// Eigenvalue sensitivities from the assembled operators (analyses/sensitivity)
// against closed forms and against re-solved frequencies.
#include "support/tiny_case.hpp"
#include "analyses/sensitivity/sensitivity.hpp"

#include "beam/beam_model.hpp"
#include "common/error.hpp"
#include "scene/toml_text.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>

using namespace coremodal;

namespace {

// An ISO 11093-8 sample: a free 76x15 paperboard tube, 1.5 m (case 01's tube).
std::string free_tube(const std::string& model) {
    return coremodal::testing::iso_sample_case(model, 14, "[mesh]\nlevel = \"coarse\"\n");
}

std::string case_08_coarse() {
    std::string text = read_input_file(std::string(COREMODAL_SOURCE_DIR) + "/cases/08-news-chucks-76x15-2200.toml", "case");
    return text + "\n[mesh]\nlevel = \"coarse\"\n";
}

const ModeSensitivity& mode(const SensitivityResult& r, const std::string& type, int n, int m) {
    const ModeSensitivity* s = r.find(ModeKey{type, n, m, 1});
    REQUIRE(s != nullptr);
    return *s;
}

// The frequency of a mode with parameter j at factor (1 + e), re-solved.
double resolved_hz(const CaseParameters& c, size_t j, double factor, const ModeKey& key) {
    std::vector<double> v = c.values();
    v[j] *= factor;
    SensitivityOptions o;
    o.chuck_factor = false;
    const SensitivityResult r = eigen_sensitivities(c, v, o);
    const ModeSensitivity* s = r.find(key);
    REQUIRE(s != nullptr);
    return s->frequency_hz;
}

}  // namespace

TEST_CASE("sensitivity: a free tube at the beam level, d ln f / d ln p in closed form", "[sensitivity]") {
    const CaseParameters c = CaseParameters::from_text(
        free_tube("beam"), "iso.toml", {"core.material.E_z", "core.material.G_thetaz", "core.material.density"});
    CHECK(c.values()[0] == Approx(6.5e9));  // the library's paperboard_core
    const SensitivityResult r = eigen_sensitivities(c, c.values());
    CHECK(r.level == ModelChoice::beam);
    for (const std::string& method : r.methods) CHECK(method == "operators");
    // Free–free bending modes have m = 2, 3, 4 axial nodes.
    for (int m = 2; m <= 4; ++m) {
        const ModeSensitivity& b = mode(r, "bending", 1, m);
        // M is linear in the density and K does not depend on it: f ∝ 1/sqrt(ρ) exactly.
        CHECK(b.dlnf_dlnp[2] == Approx(-0.5).margin(1e-9));
        // K is homogeneous of degree 1 in the moduli: their sensitivities sum to 1/2 (Euler's theorem).
        CHECK(b.dlnf_dlnp[0] + b.dlnf_dlnp[1] == Approx(0.5).margin(1e-6));
        // Euler–Bernoulli dominates the first bending mode of a slender tube (L/D = 14):
        // f ∝ sqrt(E_z) but for the Timoshenko shear share, a few per cent.
        if (m == 2) CHECK(b.dlnf_dlnp[0] == Approx(0.5).margin(0.03));
        CHECK(b.dlnf_dlnp[0] < 0.5);
        CHECK(b.dlnf_dlnp[1] > 0);
    }
    // Higher bending modes have shorter half-waves: more shear.
    CHECK(mode(r, "bending", 1, 4).dlnf_dlnp[1] > mode(r, "bending", 1, 2).dlnf_dlnp[1]);
}

TEST_CASE("sensitivity: operators' derivative equals re-solved central differences (beam level)", "[sensitivity]") {
    const CaseParameters c =
        CaseParameters::from_text(free_tube("beam"), "iso.toml", {"core.material.E_z", "core.material.G_thetaz"});
    const SensitivityResult r = eigen_sensitivities(c, c.values());
    // Central differences of re-solved frequencies at ±1 %: truncation error
    // ~ e²/6 |d³ ln f / d ln p³| < 1e-4 · O(1); eigenvalues to 1e-10.
    constexpr double e = 0.01, tolerance = 2e-4;
    for (size_t j = 0; j < 2; ++j)
        for (int m = 2; m <= 3; ++m) {
            const ModeKey key{"bending", 1, m, 1};
            const double fd =
                std::log(resolved_hz(c, j, 1 + e, key) / resolved_hz(c, j, 1 - e, key)) / std::log((1 + e) / (1 - e));
            CHECK(r.find(key)->dlnf_dlnp[j] == Approx(fd).margin(tolerance));
        }
}

TEST_CASE("sensitivity: harmonic level, case 08's contact and wall shear against re-solved frequencies",
          "[long][sensitivity]") {
    const CaseParameters c = CaseParameters::from_text(case_08_coarse(), "08.toml",
                                                       {"core.material.G_rz", "supports.left.normal_stiffness",
                                                        "core.material.density"});
    // The contact stiffness the reader derived from 6 bar (scene/chuck_contact.hpp): 50 (0.6 MPa + 20 kPa) / 1 mm.
    CHECK(c.values()[1] == Approx(50 * (0.6e6 + 20e3) / 1e-3));
    const SensitivityResult r = eigen_sensitivities(c, c.values());
    CHECK(r.level == ModelChoice::harmonic);
    const ModeKey f1{"bending", 1, 0, 1};
    const ModeSensitivity& b = *r.find(f1);
    // The core's density is most but not all of the mass (steel chucks move too).
    CHECK(b.dlnf_dlnp[2] < -0.4);
    CHECK(b.dlnf_dlnp[2] > -0.5);
    constexpr double e = 0.01, tolerance = 5e-4;
    for (size_t j = 0; j < 2; ++j) {
        const double fd =
            std::log(resolved_hz(c, j, 1 + e, f1) / resolved_hz(c, j, 1 - e, f1)) / std::log((1 + e) / (1 - e));
        CHECK(b.dlnf_dlnp[j] == Approx(fd).margin(tolerance));
        CHECK(b.dlnf_dlnp[j] > 0);
    }
    // The chuck factor: k = f1 / f2 and d ln k = d ln f1 − d ln f2.
    REQUIRE(r.k);
    CHECK(*r.k == Approx(0.768).margin(0.01));
    CHECK(r.dlnk_dlnp[0] == Approx(b.dlnf_dlnp[0] - r.f2->dlnf_dlnp[0]));
}

TEST_CASE("sensitivity: bad keys are named", "[sensitivity]") {
    CHECK_THROWS_WITH(CaseParameters::from_text(free_tube("beam"), "iso.toml", {"core.material.E_q"}),
                      Catch::Contains("no key 'E_q'"));
    CHECK_THROWS_WITH(CaseParameters::from_text(free_tube("beam"), "iso.toml", {"core.material"}),
                      Catch::Contains("core.material"));
    const CaseParameters solid = CaseParameters::from_text(free_tube("solid"), "iso.toml", {"core.length"});
    CHECK(solid.values()[0] == Approx(1.5));
    CHECK_THROWS_WITH(eigen_sensitivities(solid, solid.values()), Catch::Contains("the beam and the harmonic level"));
}

TEST_CASE("sensitivity: a length, f ∝ 1/L for torsion, by operators (beam) or re-solved (harmonic)", "[long][sensitivity]") {
    // Free–free torsion: f = m/(2L) sqrt(G/ρ), exactly 1/L at every level.
    const ModeKey torsion{"torsion", 0, 1, 1}, bending{"bending", 1, 2, 1};
    const CaseParameters beam = CaseParameters::from_text(free_tube("beam"), "iso.toml", {"core.length"});
    const SensitivityResult b = eigen_sensitivities(beam, beam.values());
    CHECK(b.methods[0] == "operators");  // the nodes move with L, the DOFs stay
    CHECK(b.find(torsion)->dlnf_dlnp[0] == Approx(-1).margin(1e-6));
    // Bending: -2 for Euler–Bernoulli, less steep with shear.
    CHECK(b.find(bending)->dlnf_dlnp[0] < -1.9);
    CHECK(b.find(bending)->dlnf_dlnp[0] > -2);
    const CaseParameters harmonic = CaseParameters::from_text(free_tube("harmonic"), "iso.toml", {"core.length"});
    const SensitivityResult h = eigen_sensitivities(harmonic, harmonic.values());
    CHECK(h.methods[0] == "re-solved");  // the element count along the core follows L
    CHECK(h.find(torsion)->dlnf_dlnp[0] == Approx(-1).margin(2e-3));
    CHECK(h.find(bending)->dlnf_dlnp[0] == Approx(b.find(bending)->dlnf_dlnp[0]).margin(0.02));
}
