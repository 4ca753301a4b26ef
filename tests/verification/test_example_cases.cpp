// Regression runs of the example cases in cases/, at the coarse mesh level so
// the suite stays fast. Each pins the physics the case's tutorial describes;
// reference frequencies were computed at the default mesh level and the
// tolerances cover the coarse mesh's discretisation error (measured: < 0.4 %
// with the axial mesh graded towards the clamp edges).
#include "analyses/response/response.hpp"
#include "analyses/run/run.hpp"
#include "analyses/study/study.hpp"
#include "scene/case_sweep.hpp"
#include "scene/response_spec.hpp"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>

using namespace coremodal;

namespace {

RunReport run_example(const std::string& name) {
    RunOptions options;
    options.case_file = std::string(COREMODAL_SOURCE_DIR) + "/cases/" + name;
    options.quiet = true;
    options.write_results = false;
    options.mesh_level = "coarse";
    return run_case(options);
}

void check_verified(const RunReport& r) {
    CHECK(r.modes.verification.complete);
    CHECK(r.modes.verification.max_relative_residual < 1e-8);
    CHECK(r.modes.verification.max_orthonormality_error < 1e-8);
    // Coarse quadratic arcs (16 around) lose a^4/30 ~ 5e-5 of the section.
    CHECK(r.model.mass_kg == Approx(r.model.expected_mass_kg).epsilon(1e-4));
}

}  // namespace

TEST_CASE("Case 01: the ISO 11093-8 free-free core test has 6 rigid modes and bends at Timoshenko's frequency",
          "[cases]") {
    const auto r = run_example("01-iso-free-free-76x15.toml");
    check_verified(r);
    for (int i = 0; i < 6; ++i) CHECK(r.modes.modes[i].label.type == "rigid");
    CHECK(r.modes.modes[6].label.type == "bending");
    // Default mesh: 133.36 Hz, 1.0012 x Timoshenko (a long free tube is a beam).
    CHECK(r.beam.fe_first_bending_hz == Approx(133.36).epsilon(0.01));
    CHECK(r.beam.fe_over_timoshenko == Approx(1.0).epsilon(0.01));
}

TEST_CASE("Case 02: a core clamped over 70 mm bends well below the clamped beam of its free span", "[cases]") {
    const auto r = run_example("02-clamped-76x15.toml");
    check_verified(r);
    CHECK(r.modes.modes[0].label.type == "bending");
    // Default mesh: 61.44 Hz = 0.889 x Timoshenko: the shear-soft wall lets a
    // short clamp rotate (docs/validation/models.md: physics, not an error).
    CHECK(r.beam.fe_first_bending_hz == Approx(61.44).epsilon(0.01));
    CHECK(r.beam.fe_over_timoshenko < 0.95);
}

TEST_CASE("Case 03: the 4.32 m rotogravure rest roll's first bending", "[cases]") {
    const auto r = run_example("03-rest-roll-150x15.8-4320.toml");
    check_verified(r);
    CHECK(r.modes.modes[0].label.type == "bending");
    CHECK(r.modes.modes[1].label.type == "bending");  // the degenerate partner
    // Default mesh: 32.11 Hz (Timoshenko over the 3.72 m span: 35.43 Hz).
    CHECK(r.beam.fe_first_bending_hz == Approx(32.11).epsilon(0.01));
    CHECK(r.beam.span_m == Approx(3.72));
}

TEST_CASE("Case 08: 110 mm expanding chucks hold a 76 mm roll at k ~ 0.77, below rigid clamps", "[cases][chucks]") {
    RunOptions options;
    options.case_file = std::string(COREMODAL_SOURCE_DIR) + "/cases/08-news-chucks-76x15-2200.toml";
    options.quiet = true;
    options.write_results = false;
    options.mesh_level = "coarse";
    options.compare_rigid = true;
    const RunReport r = run_case(options);
    check_verified(r);
    REQUIRE(r.chuck);
    // Default mesh: f1 55.03 Hz, f2 (FE, free-free over 2.06 m) 71.63 Hz, k 0.768.
    CHECK(r.chuck->f1_hz == Approx(55.03).epsilon(0.01));
    CHECK(r.chuck->f2_fe_hz == Approx(71.63).epsilon(0.01));
    CHECK(r.chuck->chuck_factor == Approx(0.768).epsilon(0.01));
    CHECK(r.chuck->free_span_m == Approx(2.06));
    // A rigid clamp is the limit of a stiff, massless chuck: the elastic
    // chuck can only lower the first bending frequency (Rayleigh).
    REQUIRE_FALSE(r.rigid_comparison.empty());
    CHECK(r.rigid_comparison[0].type == "bending");
    CHECK(r.rigid_comparison[0].shift_percent() < -5);
}

TEST_CASE("Case 10: three 60-degree segments hold less than a band", "[cases][chucks]") {
    const auto r = run_example("10-segmented-chuck-76x15-2200.toml");
    check_verified(r);
    REQUIRE(r.chuck);
    // Default mesh: 50.44 Hz, k 0.704 (the band of case 08: 55.03 Hz).
    CHECK(r.chuck->f1_hz == Approx(50.44).epsilon(0.01));
    CHECK(r.chuck->f1_hz < 55.03);
    // Three-fold symmetry keeps the bending pair degenerate; the mesh is only
    // four-fold symmetric, so the pair splits by the discretisation (1.2e-5
    // on the coarse mesh).
    CHECK(r.modes.modes[1].frequency_hz == Approx(r.modes.modes[0].frequency_hz).epsilon(1e-4));
}

TEST_CASE("Case 15: the web stiffens Ilomaki's rest roll along its own direction only", "[cases][web]") {
    // The coupled level (auto) on the coarse mesh, against the same roll with
    // the web cut and against the beam level. Across the web the string
    // T / s = 250 N/m^2 is 1/1300 of the stretch E t / s: that member stays
    // at the web-cut frequency. Along it the web adds k_d / m per unit length
    // to omega^2 whatever holds the roll's ends, so the rise of f^2 is the
    // same at the beam level, whose stiffer chucks put its web-cut roll 6 %
    // higher (measured, default mesh: 1372.3 against 1371.0 Hz^2); 2 %
    // covers the levels' different mode shapes near the chucks.
    const RunReport r = run_example("15-rest-roll-on-web-76x15-2211.toml");
    check_verified(r);
    REQUIRE(r.model.level == ModelChoice::coupled);
    const std::vector<std::string> effects = r.scene.effects();
    CHECK(std::find(effects.begin(), effects.end(), "web") != effects.end());
    RunOptions quiet;
    quiet.quiet = true;
    quiet.write_results = false;
    quiet.chuck_factor_by_fe = false;
    Scene cut = r.scene, beam = r.scene;
    cut.web.reset();
    cut.model = ModelChoice::harmonic;
    beam.model = ModelChoice::beam;
    const RunReport c = run_scene(cut, quiet), b = run_scene(beam, quiet);
    const double across = r.modes.modes[0].frequency_hz, along = r.modes.modes[1].frequency_hz;
    const double f_cut = c.modes.modes[0].frequency_hz;
    INFO("coupled: web cut " << f_cut << " Hz, on the web " << across << " and " << along << " Hz; beam "
                             << b.modes.modes[0].frequency_hz << " and " << b.modes.modes[1].frequency_hz << " Hz");
    CHECK(f_cut == Approx(48.8).epsilon(0.005));  // the fitted rest paper (default mesh: 48.80 Hz)
    CHECK(across == Approx(f_cut).epsilon(1e-3));
    CHECK(r.modes.modes[0].effective_mass.y > 100 * r.modes.modes[0].effective_mass.x);  // the web leaves along x
    CHECK(r.modes.modes[1].effective_mass.x > 100 * r.modes.modes[1].effective_mass.y);
    const double rise = along * along - across * across;
    const double beam_rise = std::pow(b.modes.modes[1].frequency_hz, 2) - std::pow(b.modes.modes[0].frequency_hz, 2);
    CHECK(rise == Approx(beam_rise).epsilon(0.02));
}

TEST_CASE("Case 13: the bowed rotogravure rest roll reaches +-5 mm only at its order-1 resonance", "[cases][response]") {
    const ResponseCase c = parse_response_case(std::string(COREMODAL_SOURCE_DIR) +
                                               "/cases/13-rest-roll-response-150x15.8-4320.toml");
    REQUIRE(c.response);
    const ResponseResult r = run_forced_response(c.scene, *c.response);
    // The tutorial's numbers (docs/how-to/response.md): one order-1 peak of the
    // first bending pair, 5.155 mm at 16.74 m/s; the limit at 16.70 m/s.
    REQUIRE(r.peaks.size() == 1);
    CHECK(r.peaks[0].order == 1);
    CHECK(r.peaks[0].mode.type == "bending");
    CHECK(r.peaks[0].amplitude_m == Approx(5.155e-3).epsilon(0.01));
    CHECK(r.peaks[0].web_speed_m_s == Approx(16.74).epsilon(0.005));
    REQUIRE(r.safe.reached);
    CHECK(r.safe.web_speed_m_s == Approx(16.70).epsilon(0.005));
    REQUIRE(r.speeds_at_rest.given());
    CHECK(r.speeds_at_rest.safe[0].v_safe_m_s == Approx(11.69).epsilon(0.005));
    CHECK(r.checks.direct_max_relative < 1e-8);
    CHECK(r.checks.truncation_max_relative < 1e-2);
}

TEST_CASE("Case 13 at the harmonic level: the same peak at the same fraction of its own first bending frequency",
          "[cases][response][harmonic]") {
    ResponseCase c = parse_response_case(std::string(COREMODAL_SOURCE_DIR) +
                                         "/cases/13-rest-roll-response-150x15.8-4320.toml");
    REQUIRE(c.response);
    c.scene.model = ModelChoice::harmonic;
    const ResponseResult r = run_forced_response(c.scene, *c.response);
    // docs/validation/response.md, "The three levels on one scene": f1
    // 25.789 Hz (beam 26.308), the peak 5.444 mm at 16.41 m/s (beam 5.155 mm
    // at 16.74 m/s: 0.980 of the speed, as f1), the limit at 16.34 m/s.
    REQUIRE(r.level == ModelChoice::harmonic);
    REQUIRE(r.peaks.size() == 1);
    CHECK(r.peaks[0].order == 1);
    CHECK(r.peaks[0].mode.type == "bending");
    CHECK(r.speeds_at_rest.f1_hz == Approx(25.789).epsilon(1e-4));
    CHECK(r.peaks[0].web_speed_m_s / 16.74 == Approx(r.speeds_at_rest.f1_hz / 26.308).epsilon(2e-3));
    CHECK(r.peaks[0].amplitude_m == Approx(5.444e-3).epsilon(0.01));
    REQUIRE(r.safe.reached);
    CHECK(r.safe.web_speed_m_s == Approx(16.34).epsilon(0.005));
    CHECK(r.checks.truncation_max_relative < 1e-2);  // against the direct solve: the truncation's effect
    CHECK(r.checks.direct_max_relative < 1e-2);
}

TEST_CASE("Case 14: the study of case 13's rest paper gives the amplitude-based safe speed of docs/how-to/response.md",
          "[cases][response][study]") {
    const CaseSweep sweep = CaseSweep::read(std::string(COREMODAL_SOURCE_DIR) + "/cases/14-study-response-safe-speed.toml",
                                            "study");
    std::ostringstream progress;
    const StudyResult result = run_sweep(sweep, {true}, progress);
    REQUIRE(result.n_failed() == 0);
    REQUIRE(result.points.size() == 5);
    // docs/how-to/response.md's table, "by hand" and from the study alike: 5 mm of
    // paper stays below +-5 mm (peak 4.78 mm); 10, 20, 40, 80 mm reach it at
    // 16.70, 16.72, 17.61, 20.54 m/s; I-5 x 0.7 is 11.89 ... 14.69 m/s.
    const StudyResponse& thin = *result.points[0].response;
    CHECK_FALSE(thin.limit_reached);
    CHECK(thin.max_amplitude_m == Approx(4.78e-3).epsilon(0.01));
    CHECK(*thin.v_i5_07_m_s == Approx(11.89).epsilon(0.005));
    const double limit_at[] = {16.70, 16.72, 17.61, 20.54};
    for (size_t i = 1; i < 5; ++i) {
        REQUIRE(result.points[i].response);
        REQUIRE(result.points[i].response->v_limit_m_s);
        CHECK(*result.points[i].response->v_limit_m_s == Approx(limit_at[i - 1]).epsilon(0.005));
    }
    CHECK(*result.points[4].response->v_i5_07_m_s == Approx(14.69).epsilon(0.005));
    CHECK(*result.points[4].response->v_koenig_m_s == Approx(35.18).epsilon(0.005));
}
