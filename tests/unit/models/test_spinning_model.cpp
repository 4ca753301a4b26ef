// Each level hands out its spinning model behind one interface
// (models/spinning_model.hpp, ModelLevel::spinning): the beam's and the
// harmonic level's on the rotation tester's core (case 12,
// tests/support/tiny_case.hpp), what each lacks an empty member, and a
// level that cannot spin refusing with the reason.
#include "models/choose.hpp"
#include "models/spinning_model.hpp"

#include "common/error.hpp"
#include "scene/response_spec.hpp"

#include "support/tiny_case.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <memory>
#include <optional>
#include <string>

using namespace coremodal;

namespace {

// The tester's core at `model` (a coarse section at the harmonic level), spinning to 2000 rpm.
ResponseCase tester(const std::string& model, const std::string& damping = "") {
    std::string core = testing::kClampedTesterCore;
    core.replace(core.find("model = \"beam\""), 14, "model = \"" + model + "\"");
    core += "[mesh]\nalong = 24\nthrough_wall = 1\n[rotation]\nspeeds = [\"0 rpm\", \"2000 rpm\"]\npoints = 2\n";
    if (!damping.empty()) core += "[damping]\n" + damping + "\n";
    return parse_response_case_text(core, "spinning.toml");
}

std::unique_ptr<SpinningModel> spinning_of(const ResponseCase& c, int extra) {
    return make_model_level(c.scene.model)->spinning(c.scene, {*c.rotation, extra, c.damping ? &*c.damping : nullptr});
}

}  // namespace

TEST_CASE(
    "The beam level's spinning model: at speed 0 its linearization gives the modes at rest; it lacks the "
    "optional members",
    "[rotation][campbell][model]") {
    // Two solvers of the same network: the run's (modes at rest, inertia
    // count) and the dense Hermitian linearization of the quadratic problem
    // at Omega = 0. Each mode's frequency agrees to the solvers' 1e-8; the
    // window is the reported modes and the extra ones asked.
    const ResponseCase c = tester("beam");
    const std::unique_ptr<SpinningModel> beam = spinning_of(c, 3);
    const std::vector<RotatingMode> rest = beam->modes_at_rest(), at_zero = beam->modes_at(0.0);
    REQUIRE(beam->reported() == rest.size());
    REQUIRE(rest.size() >= 6);
    REQUIRE(at_zero.size() == rest.size() + 3);
    for (size_t i = 0; i < rest.size(); ++i) {
        INFO("mode " << i + 1 << ": " << rest[i].frequency_hz << " Hz");
        CHECK(at_zero[i].frequency_hz == Approx(rest[i].frequency_hz).epsilon(1e-8));
        CHECK(at_zero[i].label.type == rest[i].label.type);
    }
    CHECK(beam->n_dofs() > 0);
    CHECK_FALSE(beam->label_new_track());
    CHECK_FALSE(beam->block_modes_at());
    CHECK_FALSE(beam->damped_partners());
    CHECK(beam->zero_frequency_pencils() == nullptr);
    CHECK(beam->notes().front().find("rotation at the beam level") == 0);
}

TEST_CASE(
    "The harmonic level's spinning model: one wave number's modes, the label of a new track and the damped "
    "partners are those of the whole solve",
    "[rotation][campbell][model][damping]") {
    const ResponseCase c = tester("harmonic", "loss_factor = 0.04");
    const std::unique_ptr<SpinningModel> harmonic = spinning_of(c, 2);
    const std::vector<RotatingMode> rest = harmonic->modes_at_rest();
    REQUIRE(harmonic->reported() == 6);
    REQUIRE(harmonic->label_new_track());
    REQUIRE(harmonic->block_modes_at());
    REQUIRE(harmonic->damped_partners());
    CHECK(harmonic->zero_frequency_pencils() == nullptr);  // a body of revolution: the stationary frame
    const double f_rot = 2000.0 / 60;
    const std::vector<RotatingMode> spinning = harmonic->modes_at(f_rot);
    REQUIRE(spinning.size() >= 6);
    // Unlabelled at speed; the label of a new track is the one the labelled solve at rest gives.
    CHECK(spinning.front().label.dominant_share == 0);  // ModeLabel's default
    for (const RotatingMode& m : harmonic->modes_at(0.0)) {
        const RotatingMode* labelled = nullptr;
        for (const RotatingMode& r : rest)
            if (r.block == m.block && std::abs(r.frequency_hz - m.frequency_hz) < 1e-9 * r.frequency_hz) labelled = &r;
        REQUIRE(labelled != nullptr);
        CHECK(labelled->label.dominant_share > 0);
        CHECK(harmonic->label_new_track()(m).type == labelled->label.type);
    }
    // One wave number alone gives the same frequencies as the whole solve.
    const RotatingMode& first = spinning.front();
    const std::vector<RotatingMode> block = harmonic->block_modes_at()(f_rot, first.block);
    REQUIRE(!block.empty());
    CHECK(block.front().frequency_hz == Approx(first.frequency_hz).epsilon(1e-9));
    // A uniform loss factor at rest: zeta = sin(atan(eta) / 2) for every mode
    // (eigensolve/damped_modes.hpp), to the 1e-6 of test_campbell_damping.cpp.
    const std::vector<std::optional<DampedPartner>> partners =
        harmonic->damped_partners()(0.0, {rest.begin(), rest.begin() + 6});
    REQUIRE(partners.size() == 6);
    for (const std::optional<DampedPartner>& p : partners) {
        REQUIRE(p);
        CHECK(std::abs(p->damping_ratio - std::sin(std::atan(0.04) / 2)) < 1e-6);
    }
}

TEST_CASE("A level that cannot spin refuses its spinning model with the reason", "[rotation][campbell][model]") {
    const ResponseCase c = tester("coupled");
    CHECK_THROWS_AS(spinning_of(c, 0), InputError);
    CHECK_THROWS_WITH(spinning_of(c, 0), Catch::Contains("spinning.toml: [rotation] at model = \"coupled\"") &&
                                             Catch::Contains("expected model = \"beam\", \"harmonic\" or \"solid\""));
}
