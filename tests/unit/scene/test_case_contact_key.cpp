// The chuck's `contact` key (issue 13 item 2): a chuck not expanded rests on
// one side of the bore unless the case asks for the uniform soft layer; the
// effects it names; the levels that refuse it.
#include "scene/case_file.hpp"

#include "beam/beam_model.hpp"
#include "common/error.hpp"
#include "effects/support_effects.hpp"
#include "models/choose.hpp"

#include "support/case_errors.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <string>

using namespace coremodal;
using coremodal::testing::error_of;

namespace {

const std::string kChucks =
    "[core]\ninner_diameter = \"76 mm\"\nwall = \"15 mm\"\nlength = \"2.2 m\"\n"
    "[supports]\ntype = \"chucks\"\n"
    "[supports.left]\ninserted_length = \"110 mm\"\nclearance = \"0.5 mm\"\n";
const std::string kBand = "[[supports.left.expanding]]\ncenter = \"70 mm\"\nwidth = \"60 mm\"\n";

Scene scene_of(const std::string& keys, const std::string& model = "auto") {
    return parse_case_text("model = \"" + model + "\"\n" + kChucks + keys + kBand, "cases/x.toml");
}

bool lists(const std::vector<std::string>& v, const std::string& item) {
    return std::find(v.begin(), v.end(), item) != v.end();
}

}  // namespace

TEST_CASE("A chuck not expanded rests on one side of the bore unless contact = \"uniform\"", "[scene][chucks][contact]") {
    const Scene loose = scene_of("expanded = false\n");
    for (const ChuckSpec& c : loose.supports.chucks) CHECK(c.interface.contact == ContactKind::one_sided);
    // k_n0: the law at zero pressure, K2 K1 / h = 50 x 20 kPa / 1 mm.
    CHECK(loose.supports.chucks[0].interface.normal_stiffness == Approx(1e9));
    CHECK(std::any_of(loose.assumptions.begin(), loose.assumptions.end(), [](const std::string& a) {
        return a.find("one-sided contact") != std::string::npos && a.find("-y") != std::string::npos;
    }));
    CHECK(scene_of("expanded = false\ncontact = \"uniform\"\n").supports.chucks[0].interface.contact ==
          ContactKind::uniform);
    CHECK(scene_of("").supports.chucks[0].interface.contact == ContactKind::uniform);
    SECTION("Refused where it cannot be: an expanded chuck, a bonded one") {
        CHECK_THAT(error_of(kChucks + "contact = \"one-sided\"\n" + kBand),
                   Catch::Contains("cases/x.toml:") && Catch::Contains("expected expanded = false"));
        CHECK_THAT(error_of(kChucks + "interface = \"bonded\"\ncontact = \"uniform\"\n" + kBand),
                   Catch::Contains("takes no stiffness, pressure, expanded state or contact"));
        CHECK_THAT(error_of(kChucks + "expanded = false\ncontact = \"loose\"\n" + kBand), Catch::Contains("one-sided"));
    }
}

TEST_CASE("The effects list names exactly the one-sided contact and the gravity preload", "[effects][chucks][contact]") {
    const std::vector<std::string> loose = scene_of("expanded = false\n").effects();
    CHECK(lists(loose, "one_sided_contact"));
    CHECK(lists(loose, "gravity_preload"));
    CHECK_FALSE(lists(loose, "contact_compliance"));
    const std::vector<std::string> expanded = scene_of("").effects();
    CHECK(expanded == std::vector<std::string>{"core", "elastic_chucks", "contact_compliance"});
    const SupportEffects e = support_effects(scene_of("expanded = false\n"));
    REQUIRE(e.chucks[0].one_sided);
    CHECK(e.chucks[0].one_sided->clearance == Approx(0.5e-3));
    CHECK(e.chucks[0].one_sided->law.u0() == Approx(20e-6));  // h / K2
    CHECK(e.chucks[0].one_sided->linearised(20e3).normal == Approx(2e9));  // k_n0 (1 + p/K1)
}

TEST_CASE("The coupled harmonics and the 3D solid model a one-sided contact: auto chooses the first, harmonic and beam refuse",
          "[model][choose][contact]") {
    const Scene loose = scene_of("expanded = false\n");
    CHECK(chosen_level(loose) == ModelChoice::coupled);
    CHECK_THAT(*why_not_axisymmetric(loose), Catch::Contains("not expanded"));
    CHECK_THROWS_WITH(require_axisymmetric(scene_of("expanded = false\n", "harmonic")),
                      Catch::Contains("model = \"harmonic\"") && Catch::Contains("contact = \"uniform\""));
    CHECK_THROWS_WITH(solve_beam_model(scene_of("expanded = false\n", "beam")),
                      Catch::Contains("model = \"beam\"") && Catch::Contains("the coupled harmonics model"));
    CHECK(chosen_level(scene_of("expanded = false\ncontact = \"uniform\"\n")) == ModelChoice::harmonic);
}

TEST_CASE("StackContact: the integrated stack law and its tangent", "[scene][chucks][contact]") {
    const StackContact law{1e9, 20e3};
    CHECK(law.pressure(-1e-6) == 0);
    CHECK(law.pressure(0) == 0);
    const double d = 30e-6, h = 1e-9;
    CHECK((law.pressure(d + h) - law.pressure(d - h)) / (2 * h) == Approx(law.stiffness(law.pressure(d))).epsilon(1e-6));
    CHECK(law.pressure(law.u0() * std::log(2.0)) == Approx(20e3));  // p = K1 at d = u0 ln 2
}
