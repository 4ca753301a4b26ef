// `coremodal fit` (analyses/fit): known parameters recovered from synthetic
// measurements made by coremodal itself; an unidentifiable pair flagged; bad
// input named with file:line.
#include "analyses/fit/fit.hpp"

#include "analyses/sensitivity/sensitivity.hpp"
#include "common/error.hpp"
#include "output/fit_report.hpp"

#include <catch2/catch.hpp>

// Last: <signal.h> (in program_run) defines si_value, a parameter name in scene/units.hpp.
#include "support/program_run.hpp"
#include "support/tiny_case.hpp"

#include <filesystem>

using namespace coremodal;

namespace {

// An ISO 11093-8 free-hanging sample, solved at the beam level (a free tube:
// the beam represents its low bending modes).
const std::string kIsoCase = coremodal::testing::iso_sample_case("beam", 16);

// A scratch folder holding the sample as iso.toml.
struct IsoFolder : coremodal::testing::TempDir {
    IsoFolder() : TempDir("fit") { write("iso.toml", kIsoCase); }
};

// The frequencies of the sample with E_z and G_thetaz set: what a lab would measure.
std::vector<double> synthetic_hz(const std::string& case_file, double E_z, double G_thetaz) {
    const CaseParameters c = CaseParameters::read(case_file, {"core.material.E_z", "core.material.G_thetaz"});
    SensitivityOptions o;
    o.chuck_factor = false;
    const SensitivityResult r = eigen_sensitivities(c, {E_z, G_thetaz}, o);
    std::vector<double> f;
    // Free–free bending modes: m = 2, 3, 4 axial nodes.
    for (int m = 2; m <= 4; ++m) f.push_back(r.find(ModeKey{"bending", 1, m, 1})->frequency_hz);
    return f;
}

std::string measurements(const std::string& parameters, const std::vector<double>& f) {
    std::string text = "parameters = " + parameters + "\n";
    for (int m = 2; m <= 4; ++m)
        text += "[[measurement]]\ncase = \"iso.toml\"\nmode = \"bending n=1 m=" + std::to_string(m) +
                "\"\nfrequency = \"" + std::to_string(f[m - 2]) + " Hz\"\nuncertainty = \"0.1 Hz\"\n";
    return text;
}

}  // namespace

TEST_CASE("fit: the ISO recipe recovers E_z and G_thetaz from three free-free bending modes", "[fit]") {
    const IsoFolder dir;
    const std::string case_file = (dir.path / "iso.toml").string();
    // The truth: a wall stiffer along the core and softer in shear than the library's 6.5 / 1.8 GPa.
    constexpr double E_true = 5.2e9, G_true = 0.9e9;
    const std::vector<double> f = synthetic_hz(case_file, E_true, G_true);
    const FitInput in = parse_fit_input(measurements(R"(["core.material.E_z", "core.material.G_thetaz"])", f),
                                        (dir.path / "m.toml").string());
    const FitOutcome out = run_fit(in);
    REQUIRE(out.converged);
    CHECK(out.parameters[0].value == Approx(E_true).epsilon(0.01));
    CHECK(out.parameters[1].value == Approx(G_true).epsilon(0.01));
    REQUIRE(out.parameters[0].uncertainty);
    REQUIRE(out.parameters[1].uncertainty);
    // 0.1 Hz on ~130-800 Hz: E_z to a fraction of a per cent, the shear modulus
    // (a few per cent of the frequencies) much less well.
    CHECK(*out.parameters[0].uncertainty / E_true < 0.01);
    CHECK(*out.parameters[1].uncertainty / G_true > *out.parameters[0].uncertainty / E_true);
    CHECK(out.chi2 < 1e-6);
    for (const FittedMeasurement& m : out.measurements) CHECK(m.model_hz == Approx(m.measurement.frequency_hz).epsilon(1e-6));
    // The calibrated case reads back with the fitted values.
    REQUIRE(out.cases.size() == 1);
    CHECK(out.cases[0].calibrated_text.find("E_z") != std::string::npos);
    CHECK(fit_report_markdown(in, out, {"iso-fitted.toml"}).find("## Residuals") != std::string::npos);
}

TEST_CASE("fit: stiffness and density from frequencies alone are flagged as not separable", "[fit]") {
    const IsoFolder dir;
    const std::string case_file = (dir.path / "iso.toml").string();
    const std::vector<double> f = synthetic_hz(case_file, 5.2e9, 1.8e9);
    // f depends on E/ρ (and weakly, through the shear share, on E/G): E_z, G_thetaz and
    // the density scaled together leave every frequency unchanged.
    const FitInput in = parse_fit_input(
        measurements(R"(["core.material.E_z", "core.material.G_thetaz", "core.material.density"])", f),
        (dir.path / "m.toml").string());
    const FitOutcome out = run_fit(in);
    bool flagged = false;
    for (const std::string& w : out.warnings)
        flagged = flagged || (w.find("cannot separate") != std::string::npos && w.find("density") != std::string::npos);
    CHECK(flagged);
    CHECK_FALSE(out.parameters[2].uncertainty);
}

TEST_CASE("fit: bad measurements files are named with file, line and key", "[fit]") {
    const IsoFolder dir;
    const std::string path = (dir.path / "m.toml").string();
    CHECK_THROWS_WITH(parse_fit_input("parameters = [\"core.material.E_z\"]\n[[measurement]]\ncase = \"iso.toml\"\n"
                                      "mode = \"bending n=1\"\nfrequency = \"100 Hz\"\n", path),
                      Catch::Contains("m.toml:4:8") && Catch::Contains("mode"));
    CHECK_THROWS_WITH(parse_fit_input("parameters = [\"core.material.E_z\"]\n[[measurement]]\ncase = \"iso.toml\"\n"
                                      "mode = \"bending n=1 m=0\"\nfrequency = \"100 mm\"\n", path),
                      Catch::Contains("m.toml:5:13") && Catch::Contains("frequency"));
    CHECK_THROWS_WITH(parse_fit_input("parameters = [\"core.material.E_z\"]\nmeasurments = 1\n", path),
                      Catch::Contains("m.toml:2:1") && Catch::Contains("unknown key 'measurments'"));
    // A key no case has, named where the measurements file gives it.
    const FitInput in = parse_fit_input("parameters = [\"core.material.E_q\"]\n[[measurement]]\ncase = \"iso.toml\"\n"
                                        "mode = \"bending n=1 m=2\"\nfrequency = \"100 Hz\"\n", path);
    CHECK_THROWS_WITH(run_fit(in), Catch::Contains("m.toml:1:15") && Catch::Contains("E_q"));
    // A mode the case does not show.
    const FitInput in2 = parse_fit_input("parameters = [\"core.material.E_z\"]\n[[measurement]]\ncase = \"iso.toml\"\n"
                                         "mode = \"torsion n=0 m=7\"\nfrequency = \"100 Hz\"\n", path);
    CHECK_THROWS_WITH(run_fit(in2), Catch::Contains("m.toml:2:1") && Catch::Contains("torsion n=0 m=7"));
}

TEST_CASE("fit: the field validation's measurements and cases read (docs/validation/models.md)", "[fit]") {
    const std::string dir = std::string(COREMODAL_SOURCE_DIR) + "/cases/validation/";
    const FitInput in = read_fit_input(dir + "ilomaki-table1.toml");
    REQUIRE(in.measurements.size() == 2);
    CHECK(in.measurements[0].frequency_hz == Approx(39.06));
    CHECK(in.measurements[1].frequency_hz == Approx(37.11));
    const CaseParameters stand = CaseParameters::read(dir + "ilomaki-table1-stand.toml", {"supports.left.normal_stiffness"});
    CHECK(stand.values()[0] == Approx(50 * (0.6e6 + 20e3) / 1e-3));  // the library law at 6 bar
    for (const char* c : {"predict-07-expanded", "predict-07-not-expanded", "predict-08-expanded", "predict-08-not-expanded"})
        CHECK_NOTHROW(CaseParameters::read(dir + c + ".toml", {"supports.left.normal_stiffness"}));
}
