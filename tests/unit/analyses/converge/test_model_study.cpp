// What the levels of one model level say (analyses/converge/model_study.hpp):
// modes tracked by label across levels and extrapolated, the cheapest level
// within a target, and where the ladder would have to go beyond its end.
#include "analyses/converge/model_study.hpp"

#include "support/converge_levels.hpp"
#include "support/test_modes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

using namespace coremodal;
using coremodal::testing::level;
using coremodal::testing::mode;

TEST_CASE("Modes are tracked by label, not by index, across levels", "[converge]") {
    // The dense ovalling family swaps order between meshes (m = 1 below m = 0
    // on the coarse mesh); the torsion mode drops below the second bending pair.
    std::vector<LevelResult> levels;
    const double f0_bend = 61.3, f0_oval = 430.0, f0_tors = 150.0;
    for (int k = 1; k <= 4; ++k) {
        const double e = std::pow(1.0 / k, 4);
        std::vector<Mode> modes = {mode(1, f0_bend + 2 * e, "bending", 1, 0), mode(2, f0_bend + 2 * e, "bending", 1, 0)};
        if (k == 1) {
            modes.push_back(mode(3, 170.0, "bending", 1, 3));
            modes.push_back(mode(4, 170.0, "bending", 1, 3));
            modes.push_back(mode(5, f0_tors + 40 * e, "torsion", 0, 0));
        } else {
            modes.push_back(mode(3, f0_tors + 40 * e, "torsion", 0, 0));
            modes.push_back(mode(4, 170.0 - e, "bending", 1, 3));
            modes.push_back(mode(5, 170.0 - e, "bending", 1, 3));
        }
        const Mode m0 = mode(6, f0_oval + 100 * e, "ovalling", 2, 0);
        const Mode m1 = mode(7, f0_oval + 0.5 + (k == 1 ? 80 : 100) * e, "ovalling", 2, 1);
        if (k == 1) modes.insert(modes.end(), {m1, m0});
        else modes.insert(modes.end(), {m0, m1});
        if (k == 4) modes.push_back(mode(8, 900.0, "axial", 0, 0));  // only the finest level reaches it
        levels.push_back(level(k, modes));
    }
    const auto tracked = track_modes(levels);
    auto find = [&](const std::string& type, int m) -> const TrackedMode* {
        for (const auto& t : tracked)
            if (t.key.type == type && t.key.m == m) return &t;
        return nullptr;
    };
    const TrackedMode* f1 = find("bending", 0);
    const TrackedMode* oval = find("ovalling", 0);
    const TrackedMode* tors = find("torsion", 0);
    const TrackedMode* axial = find("axial", 0);
    REQUIRE(f1);
    REQUIRE(oval);
    REQUIRE(tors);
    CHECK(f1->role == "f1");
    CHECK(oval->role == "ovalling");
    CHECK(tors->role == "torsion");
    REQUIRE(f1->richardson);
    CHECK(f1->richardson->f0 == Approx(f0_bend).epsilon(1e-10));
    CHECK(f1->richardson->order == Approx(4).epsilon(1e-6));
    REQUIRE(oval->richardson);
    CHECK(oval->richardson->f0 == Approx(f0_oval).epsilon(1e-10));
    CHECK(*oval->frequency_hz[0] == Approx(f0_oval + 100));  // the m = 0 value, although second at k = 1
    REQUIRE(tors->richardson);
    CHECK(tors->richardson->f0 == Approx(f0_tors).epsilon(1e-10));
    // A role mode that only the finest level has is listed, without extrapolation.
    REQUIRE(axial);
    CHECK(axial->role == "axial");
    CHECK_FALSE(axial->richardson);
    CHECK_FALSE(axial->frequency_hz[0]);
    // Relative errors against f0, and the cheapest level within each target.
    REQUIRE(f1->relative_error[1]);
    CHECK(*f1->relative_error[1] == Approx(2 * std::pow(0.5, 4) / f0_bend).epsilon(1e-6));
    const auto within = first_level_within(*f1, 1e-3);  // errors 3.3e-2, 2.0e-3, 4.0e-4, 1.3e-4
    REQUIRE(within);
    CHECK(*within == 2);
    CHECK_FALSE(first_level_within(*f1, 1e-5));
}

TEST_CASE("Time and memory scale as power laws of the DOFs, the coarsest level left out", "[converge]") {
    std::vector<LevelResult> levels;
    for (int k = 1; k <= 4; ++k) levels.push_back(level(k, {mode(1, 61.3 + std::pow(1.0 / k, 4), "bending", 1, 0)}));
    levels[0].median_s.total = 1e3;  // start-up costs of the coarsest level: not in the fit
    const ModelStudy m = analyse_levels(ModelChoice::solid, "", levels);
    REQUIRE(m.time_exponent);
    CHECK(*m.time_exponent == Approx(1.0).epsilon(1e-9));  // time ~ k^3, DOFs ~ k^3
    REQUIRE(m.memory_exponent);
    CHECK(*m.memory_exponent == Approx(2.0 / 3).epsilon(1e-9));  // memory ~ k^2
    CHECK(find_role(m, "f1") == &m.modes.at(0));
    CHECK_FALSE(find_role(m, "ovalling"));
}

TEST_CASE("A target beyond the ladder is predicted from the observed order and time scaling", "[converge]") {
    std::vector<LevelResult> levels;
    for (int k = 1; k <= 4; ++k) {
        const double e = std::pow(1.0 / k, 4);
        levels.push_back(level(k, {mode(1, 100 + 10 * e, "ovalling", 2, 0)}));
    }
    const ModelStudy m = analyse_levels(ModelChoice::solid, "", levels);
    const TrackedMode& oval = m.modes.at(0);
    REQUIRE(oval.richardson);
    // Finest error 10/256/100 = 3.9e-4: 1e-4 needs k = 4 (3.9)^(1/4) = 5.59.
    const auto p = predict_level_for(m, oval, 1e-4);
    REQUIRE(p);
    CHECK(p->k == Approx(4 * std::pow(10.0 / 256 / 100 / 1e-4, 0.25)).epsilon(1e-6));
    CHECK(p->n_dofs == Approx(64000 * std::pow(p->k / 4, 3)).epsilon(1e-9));
    REQUIRE(p->time_s);
    CHECK(*p->time_s == Approx(1.2 * std::pow(p->k, 3)).epsilon(1e-6));  // time ~ DOFs here
}
