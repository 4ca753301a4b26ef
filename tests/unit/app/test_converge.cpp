// `coremodal converge`, the pieces without a solver: tracking modes by label,
// the refinement ladder, a level's runs and the report writers (Richardson,
// medians and power laws: tests/unit/numerics/).
#include "app/converge.hpp"

#include "app/batch.hpp"  // json_number, json_string: read back converge.json
#include "common/error.hpp"
#include "geometry/tube_section.hpp"
#include "scene/case_file.hpp"

#include "support/test_modes.hpp"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

using namespace coremodal;
using coremodal::testing::mode;

namespace {

LevelResult level(int k, std::vector<Mode> modes) {
    LevelResult l;
    l.step.k = k;
    l.step.h = 1.0 / k;
    l.step.counts = std::to_string(k) + "/" + std::to_string(k) + "/" + std::to_string(8 * k) + "/" +
                    std::to_string(10 * k);
    l.step.label = "k=" + std::to_string(k) + " " + l.step.counts;
    l.n_dofs = 1000L * k * k * k;
    l.runs = 3;
    l.median_s = {.mesh = 0.01 * k, .assemble = 0.1 * k, .factor_and_solve = 1.0 * k * k * k, .classify = 0.01,
                  .total = 1.2 * k * k * k};
    l.peak_memory_mb = 100.0 * k * k;
    l.modes = std::move(modes);
    return l;
}

std::string cases(const std::string& name) { return std::string(COREMODAL_SOURCE_DIR) + "/cases/" + name; }

}  // namespace

TEST_CASE("The median of repeated runs", "[converge]") {
    MeshStep step;
    LevelRun a, b, c;
    a.timing_s = {.mesh = 0.1, .assemble = 1.0, .factor_and_solve = 10.0, .classify = 0.2, .total = 11.3};
    b.timing_s = {.mesh = 0.2, .assemble = 1.2, .factor_and_solve = 30.0, .classify = 0.2, .total = 31.6};  // disturbed
    c.timing_s = {.mesh = 0.1, .assemble = 1.1, .factor_and_solve = 11.0, .classify = 0.2, .total = 12.4};
    a.peak_memory_mb = 500, b.peak_memory_mb = 520, c.peak_memory_mb = 510;
    a.modes = b.modes = c.modes = {mode(1, 32.1, "bending", 1, 0)};
    const LevelResult r = summarize_runs(step, {a, b, c});
    CHECK(r.runs == 3);
    CHECK(r.median_s.factor_and_solve == 11.0);
    CHECK(r.median_s.total == 12.4);
    CHECK(r.peak_memory_mb == 520);
    CHECK(r.max_repeat_spread == 0);
}

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

TEST_CASE("The ladder refines every direction and every axial segment by k", "[converge]") {
    const Scene scene = parse_case_file(cases("03-rest-roll-150x15.8-4320.toml"));
    const UnitMesh unit = parse_unit("1/1/8/11", "--unit");
    const auto steps = refinement_ladder(scene, unit, 1, 4);
    REQUIRE(steps.size() == 4);
    const auto& unit_segments = steps[0].mesh.along_per_segment;
    REQUIRE(unit_segments.size() == 5);  // end, clamp, free span, clamp, end
    for (const auto& s : steps) {
        CAPTURE(s.label);
        CHECK(s.h == Approx(1.0 / s.k));
        CHECK(s.mesh.n_wall == s.k);
        CHECK(s.mesh.n_rest_paper == s.k);
        CHECK(s.mesh.n_around == 8 * s.k);
        for (std::size_t i = 0; i < unit_segments.size(); ++i)
            CHECK(s.mesh.along_per_segment[i] == s.k * unit_segments[i]);
        // The mesher takes the counts as given.
        Scene refined = scene;
        refined.mesh = s.mesh;
        const TubeSection section = make_tube_section(refined);
        for (std::size_t i = 0; i < section.segments.size(); ++i)
            CHECK(section.segments[i].n_elements == s.mesh.along_per_segment[i]);
    }
    CHECK(steps[3].label == "k=4 4/4/32/" + std::to_string(steps[3].mesh.n_along));

    SECTION("The default unit keeps the case's axial element aspect") {
        const UnitMesh d = default_unit(scene);
        CHECK(d.n_wall == 1);
        CHECK(d.n_around == kUnitElementsAround);
        CHECK(d.n_along == (scene.mesh.n_along * 8 + scene.mesh.n_around - 1) / scene.mesh.n_around);
    }
}

TEST_CASE("Bad ladder input is refused with the option and what is expected", "[converge]") {
    CHECK_THROWS_WITH(parse_unit("1/1/8", "--unit"), Catch::Contains("--unit 1/1/8: 3 counts"));
    CHECK_THROWS_WITH(parse_unit("1/x/8/10", "--unit"), Catch::Contains("'x' is not a positive whole number"));
    CHECK_THROWS_WITH(parse_unit("1/1/10/10", "--unit"), Catch::Contains("multiple of 4"));
    CHECK_THROWS_WITH(parse_unit("1/0/8/10", "--unit"), Catch::Contains("expected WALL/PAPER/AROUND/ALONG"));
    const Scene free_core = parse_case_file(cases("01-iso-free-free-76x15.toml"));
    CHECK_THROWS_WITH(refinement_ladder(free_core, UnitMesh{1, 1, 8, 10}, 1, 2), Catch::Contains("at least 3"));
    const Scene user_mesh = parse_case_file(cases("04-user-mesh-76x15.toml"));
    CHECK_THROWS_AS(refinement_ladder(user_mesh, UnitMesh{1, 1, 8, 10}, 1, 4), InputError);
    CHECK_THROWS_WITH(refinement_ladder(user_mesh, UnitMesh{1, 1, 8, 10}, 1, 4),
                      Catch::Contains("converge refines the generated mesh"));
}

TEST_CASE("The report files hold every level and tracked mode", "[converge]") {
    std::vector<LevelResult> levels;
    for (int k = 1; k <= 4; ++k) {
        const double e = std::pow(1.0 / k, 4);
        levels.push_back(level(k, {mode(1, 61.3 + e, "bending", 1, 0), mode(2, 61.3 + e, "bending", 1, 0),
                                   mode(3, 430 + 50 * e, "ovalling", 2, 0)}));
    }
    ConvergeStudy study;
    study.case_name = "synthetic";
    study.source_file = "synthetic.toml";
    study.n_modes = 3;
    study.repeats = 3;
    study.repeat_limit_s = 30;
    study.models.push_back(analyse_levels("solid", "unit 1/1/8/10", levels));
    study.total_time_s = 99;

    const std::string csv = converge_csv(study);
    std::istringstream lines(csv);
    int n = 0;
    for (std::string line; std::getline(lines, line);) ++n;
    CHECK(n == 1 + 4 * 2);  // header + levels x tracked modes
    CHECK_THAT(csv, Catch::StartsWith("model,k,mesh,h,dofs,runs,"));
    CHECK_THAT(csv, Catch::Contains("solid,4,4/4/32/40,0.25,64000,3,"));

    const std::string json = converge_json(study);
    CHECK(json_string(json, "case") == "synthetic");
    CHECK(*json_number(json, "total_time_s") == Approx(99));

    const std::string md = converge_markdown(study, "");
    CHECK_THAT(md, Catch::Contains("# Convergence study: synthetic"));
    CHECK_THAT(md, Catch::Contains("| f1 (first bending) | 1.0 % | k=2"));
    CHECK_THAT(md, Catch::Contains("| f1 (first bending) | 0.10 % | k=3"));
    CHECK_THAT(md, Catch::Contains("![relative error"));
    CHECK_THAT(converge_markdown(study, "python3 missing"), Catch::Contains("(no picture: python3 missing)"));
    CHECK(study.models[0].time_exponent);
    CHECK(*study.models[0].time_exponent == Approx(1.0).epsilon(1e-9));  // time ~ k^3, DOFs ~ k^3
}

TEST_CASE("The DOF estimate of a tube mesh and the study's cost bound", "[converge]") {
    const Scene rest_roll = parse_case_file(cases("03-rest-roll-150x15.8-4320.toml"));
    MeshSpec m = rest_roll.mesh;
    m.n_wall = 4, m.n_rest_paper = 4, m.n_around = 32, m.n_along = 104;
    // Measured: 346,944 DOFs after eliminating the clamped nodes (docs/accuracy-vs-cost.md).
    CHECK(estimate_dofs(m, true) == 351936);
    CHECK(estimate_dofs(m, true) > 346944);
    CHECK(estimate_dofs(m, true) < 1.02 * 346944);

    SECTION("A chuck scene counts its chuck bodies and shafts") {
        // Measured: case 07 at the default level has 247,788 DOFs (the two
        // frame masses' nodes, 6 DOFs, are not in the estimate).
        const Scene chucks = parse_case_file(cases("07-rotogravure-chucks-150x15.8-4320.toml"));
        CHECK(estimate_dofs(chucks, chucks.mesh) == 247788 - 6);
    }
    SECTION("A long rest roll's unit is shortened along until the finest level fits") {
        std::string note;
        const UnitMesh unit = fit_unit_to_budget(rest_roll, default_unit(rest_roll), 1, 4, 200000, note);
        CHECK(unit.n_along < default_unit(rest_roll).n_along);
        CHECK(estimate_dofs(refinement_ladder(rest_roll, unit, 1, 4).back().mesh, true) <= 200000);
        CHECK_THAT(note, Catch::Contains("lowered from 21 to"));
    }
    SECTION("A scene that fits keeps its unit; no bound keeps every unit") {
        const Scene free_core = parse_case_file(cases("01-iso-free-free-76x15.toml"));
        std::string note;
        CHECK(fit_unit_to_budget(free_core, default_unit(free_core), 1, 4, 200000, note).n_along ==
              default_unit(free_core).n_along);
        CHECK(note.empty());
        CHECK(fit_unit_to_budget(rest_roll, default_unit(rest_roll), 1, 4, 0, note).n_along == 21);
    }
    SECTION("A bound that cannot be met says so") {
        std::string note;
        fit_unit_to_budget(rest_roll, default_unit(rest_roll), 1, 4, 1000, note);
        CHECK_THAT(note, Catch::Contains("exceeds --max-dofs 1000"));
    }
}

TEST_CASE("A target beyond the ladder is predicted from the observed order and time scaling", "[converge]") {
    std::vector<LevelResult> levels;
    for (int k = 1; k <= 4; ++k) {
        const double e = std::pow(1.0 / k, 4);
        levels.push_back(level(k, {mode(1, 100 + 10 * e, "ovalling", 2, 0)}));
    }
    const ModelStudy m = analyse_levels("solid", "", levels);
    const TrackedMode& oval = m.modes.at(0);
    REQUIRE(oval.richardson);
    // Finest error 10/256/100 = 3.9e-4: 1e-4 needs k = 4 (3.9)^(1/4) = 5.59.
    const auto p = predict_level_for(m, oval, 1e-4);
    REQUIRE(p);
    CHECK(p->k == Approx(4 * std::pow(10.0 / 256 / 100 / 1e-4, 0.25)).epsilon(1e-6));
    CHECK(p->n_dofs == Approx(64000 * std::pow(p->k / 4, 3)).epsilon(1e-9));
    REQUIRE(p->time_s);
    CHECK(*p->time_s == Approx(1.2 * std::pow(p->k, 3)).epsilon(1e-6));  // time ~ DOFs here
    const std::string md = [&] {
        ConvergeStudy study;
        study.models.push_back(m);
        return converge_markdown(study, "");
    }();
    CHECK_THAT(md, Catch::Contains("predicted k ≈ 5.6"));
}

TEST_CASE("The beam ladder doubles the elements in every gap between support edges", "[converge][beam]") {
    const Scene scene = parse_case_file(cases("03-rest-roll-150x15.8-4320.toml"));
    const auto steps = beam_refinement_ladder(scene, kBeamUnitElements, kBeamLevels);
    REQUIRE(steps.size() == static_cast<std::size_t>(kBeamLevels));
    REQUIRE(kBeamLevels >= 4);
    // Unit: 4 elements along the core; the gaps (overhang, clamp zone, free
    // span, clamp zone, overhang) get max(2, round(4 gap / Lc)) = 2, 2, 3, 2, 2.
    CHECK(steps[0].counts == "11/11");
    for (std::size_t i = 0; i < steps.size(); ++i) {
        const int k = 1 << i;
        CAPTURE(steps[i].label);
        CHECK(steps[i].k == k);
        CHECK(steps[i].h == Approx(1.0 / k));
        CHECK(steps[i].counts == std::to_string(11 * k) + "/" + std::to_string(11 * k));
        CHECK(steps[i].label == "k=" + std::to_string(k) + " " + steps[i].counts);
    }
    // Chucks: the chuck beams (body on the core's stations, shaft) refine too.
    const Scene chucked = parse_case_file(cases("07-rotogravure-chucks-150x15.8-4320.toml"));
    const auto chuck_steps = beam_refinement_ladder(chucked, kBeamUnitElements, 3);
    const auto elements = [](const MeshStep& s) { return std::stoi(s.counts.substr(s.counts.find('/') + 1)); };
    CHECK(elements(chuck_steps[1]) == 2 * elements(chuck_steps[0]));
    CHECK(elements(chuck_steps[2]) == 4 * elements(chuck_steps[0]));
    CHECK_THROWS_WITH(beam_refinement_ladder(scene, kBeamUnitElements, 2), Catch::Contains("at least 3"));
}

TEST_CASE("Model error: a beam level's extrapolated values against the solid's, role by role", "[converge][beam]") {
    std::vector<LevelResult> solid_levels, beam_levels;
    for (int k = 1; k <= 4; ++k) {
        const double e = std::pow(1.0 / k, 4);
        solid_levels.push_back(level(k, {mode(1, 61.3 + e, "bending", 1, 0), mode(2, 61.3 + e, "bending", 1, 0),
                                         mode(3, 200 + 3 * e, "torsion", 0, 0), mode(4, 430 + 50 * e, "ovalling", 2, 0)}));
    }
    for (int k = 1; k <= 16; k *= 2) {
        const double e = std::pow(1.0 / k, 4);
        LevelResult l = level(k, {mode(1, 62.0 + e, "bending", 1, 0), mode(2, 62.0 + e, "bending", 1, 0),
                                  mode(3, 199 + 2 * e, "torsion", 0, 0)});
        l.n_dofs = 48L * k;
        l.median_s.total = 1e-3 * k;
        beam_levels.push_back(std::move(l));
    }
    ConvergeStudy study;
    study.case_name = "synthetic";
    study.source_file = "synthetic.toml";
    study.models.push_back(analyse_levels("solid", "solid ladder", solid_levels));
    study.models.push_back(analyse_levels("beam", "beam ladder", beam_levels));
    study.models[1].refined_dimensions = 1;
    study.models[1].unseen_roles = {{"ovalling", "rigid cross-sections"}};

    const std::vector<ModelError> errors = model_errors(study.models);
    REQUIRE(errors.size() == 2);  // f1 and torsion: the beam has no ovalling
    CHECK(errors[0].role == "f1");
    CHECK(errors[0].f0_hz == Approx(62.0).epsilon(1e-9));
    CHECK(errors[0].solid_f0_hz == Approx(61.3).epsilon(1e-9));
    CHECK(errors[0].relative == Approx(0.7 / 61.3).epsilon(1e-7));
    CHECK(errors[1].role == "torsion");
    CHECK(errors[1].relative == Approx(-1.0 / 200).epsilon(1e-7));

    // Each beam level against the solid's f0: it levels off at the model error.
    const TrackedMode* beam_f1 = nullptr;
    for (const auto& t : study.models[1].modes)
        if (t.role == "f1") beam_f1 = &t;
    REQUIRE(beam_f1);
    const auto vs_solid = error_against_solid(*beam_f1, study.models);
    REQUIRE(vs_solid.size() == 5);
    CHECK(*vs_solid.back() == Approx((62.0 + std::pow(1.0 / 16, 4) - 61.3) / 61.3));
    CHECK(error_against_solid(*beam_f1, {study.models[1]}).empty());  // no solid level, nothing to set against

    // Predictions scale the beam's DOFs with k, not k^3.
    const auto p = predict_level_for(study.models[1], *beam_f1, 1e-9);
    REQUIRE(p);
    CHECK(p->n_dofs == Approx(48 * p->k).epsilon(1e-9));

    const std::string md = converge_markdown(study, "");
    CHECK_THAT(md, Catch::Contains("## Model level: beam"));
    CHECK_THAT(md, Catch::Contains("| k | elements (core/network) | DOFs | runs | network [s] |"));
    CHECK_THAT(md, Catch::Contains("| – | first ovalling | – | not in this model |"));
    CHECK_THAT(md, Catch::Contains("## Model error: beam against solid"));
    CHECK_THAT(md, Catch::Contains("- f1 (first bending): beam level converges to 62.0000 Hz (bending n=1 m=0), the "
                                   "solid to 61.3000 Hz (bending n=1 m=0): model error +1.14 %"));
    CHECK_THAT(md, Catch::Contains("- first ovalling: not in this model (rigid cross-sections); the solid converges to "
                                   "430.0000 Hz"));
    CHECK_THAT(md, Catch::Contains("0.001 |"));  // a beam level's time (1e-3 s) is not rounded to 0.00
    const std::string csv = converge_csv(study);
    CHECK_THAT(csv, Catch::Contains(",relative_error,relative_error_vs_solid\n"));
    CHECK_THAT(csv, Catch::Contains("beam,16,"));
    const std::string json = converge_json(study);
    CHECK_THAT(json, Catch::Contains("\"model_errors\""));
    CHECK_THAT(json, Catch::Contains("\"error_vs_solid\""));
    CHECK_THAT(json, Catch::Contains("\"not_in_model\""));
}
