// Degenerate requests (issue 11, defect 4), tried as a new user would: each
// gave silent nonsense or a crash before. A tiny core, an empty or absurd
// band, more modes than a beam network has, a chuck with zero clearance, a
// modulus written without its unit: each now gives a right answer that says
// what it is, or a clear refusal, quickly.
#include "support/program_run.hpp"

#include <catch2/catch.hpp>

#include <chrono>
#include <filesystem>
#include <regex>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using namespace coremodal::testing;

namespace {

// A free steel tube 76 x 15 mm; the tests set its length, level and analysis.
std::string tube(const std::string& length, const std::string& model, const std::string& analysis,
                 const std::string& supports = "") {
    return "name = \"tube\"\nmodel = \"" + model + "\"\n\n[core]\ninner_diameter = \"76 mm\"\nwall = \"15 mm\"\n"
           "length = \"" + length + "\"\nmaterial = { E = \"210 GPa\", nu = 0.3, density = \"7850 kg/m^3\" }\n\n" +
           supports + "[analysis]\n" + analysis + "\n\n[mesh]\naround = 8\nthrough_wall = 1\nalong = 4\n";
}

const std::string kClamped = "[supports]\ntype = \"clamped\"\n\n[supports.left]\nlength = \"40 mm\"\n\n";

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

int count_of(const std::string& text, const std::string& part) {
    int n = 0;
    for (size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1)) ++n;
    return n;
}

// The modes array of a summary.json text (its entries hold no brackets).
std::string modes_of(const std::string& json) {
    const size_t start = json.find("\"modes\": [");
    return start == std::string::npos ? "" : json.substr(start, json.find(']', start) - start);
}

// Every "key" : value of a JSON text, as written.
std::vector<std::string> json_values(const std::string& json, const std::string& key) {
    std::vector<std::string> values;
    const std::regex pattern("\"" + key + "\": (null|true|false|\"[^\"]*\"|-?[0-9.eE+-]+)");
    for (auto it = std::sregex_iterator(json.begin(), json.end(), pattern); it != std::sregex_iterator(); ++it)
        values.push_back((*it)[1]);
    return values;
}

struct Result {
    Run run;
    std::string summary, report;
};

Result run_case(const TempDir& dir, const std::string& text, const std::string& extra = "") {
    dir.write("case.toml", text);
    fs::remove_all(dir.path / "out");
    Result r;
    r.run = run_coremodal(dir, "run case.toml --output out --no-plots" + extra);
    r.summary = slurp(dir.path / "out" / "summary.json");
    r.report = slurp(dir.path / "out" / "report.md");
    return r;
}

}  // namespace

TEST_CASE("A 10 um core: the beam level answers with warnings, the 3D levels say why they cannot; "
          "no vector::_M_range_check", "[app][degenerate]") {
    TempDir dir("tiny");
    const std::string plausibility = "case.toml:7:10: [core] length = 1e-05 m is outside the plausible range";
    const Result beam = run_case(dir, tube("10 um", "beam", "modes = 8"));
    INFO(beam.run.out << beam.run.err);
    CHECK(beam.run.exit_code == 0);
    CHECK(contains(beam.run.err, plausibility));
    CHECK(contains(beam.run.err, "is less than the outer diameter"));
    CHECK(json_values(beam.summary, "complete") == std::vector<std::string>{"true"});
    // A disc 10 um thick and 106 mm across: its plate modes lie within the
    // round-off of its stiffness matrix (harmonic: rigid modes cannot be told
    // apart; solid: the factor meets a zero pivot). A clear refusal, nothing written.
    for (const char* level : {"harmonic", "solid"}) {
        INFO(level);
        const Result r = run_case(dir, tube("10 um", level, "modes = 8"));
        INFO(r.run.out << r.run.err);
        CHECK(r.run.exit_code != 0);
        CHECK_FALSE(contains(r.run.err, "range_check"));
        CHECK(contains(r.run.err, plausibility));
        CHECK(contains(r.run.err, "double precision"));
        CHECK(contains(r.run.err, "expected a body at least about a hundredth as long as its diameter"));
        CHECK_FALSE(fs::exists(dir.path / "out"));
    }
}

TEST_CASE("A 1 mm free core at the beam level: six rigid modes at 0 Hz, the rest elastic", "[app][degenerate]") {
    TempDir dir("short-beam");
    const Result r = run_case(dir, tube("1 mm", "beam", "modes = 10"));
    INFO(r.run.out << r.run.err);
    REQUIRE(r.run.exit_code == 0);
    const std::vector<std::string> types = json_values(modes_of(r.summary), "type");
    const std::vector<std::string> f = json_values(modes_of(r.summary), "frequency_hz");
    REQUIRE(types.size() == f.size());
    REQUIRE(types.size() >= 7);
    for (int i = 0; i < 6; ++i) {
        CHECK(types[i] == "\"rigid\"");
        // Before: 1-3 Hz, the round-off of a shift at -0.1 x (2 pi 300 MHz)^2.
        CHECK(std::stod(f[i]) < 1e-3 * std::stod(f[6]));
    }
    for (size_t i = 6; i < types.size(); ++i) CHECK(types[i] != "\"rigid\"");
    CHECK(contains(r.run.err, "is less than the outer diameter"));
}

TEST_CASE("A band below the first mode is empty: no modes, complete, exit 0, and null where f1 would be",
          "[app][degenerate]") {
    TempDir dir("empty-band");
    for (const char* level : {"solid", "harmonic", "beam"}) {
        INFO(level);
        const Result r = run_case(dir, tube("0.5 m", level, "band = [\"0 Hz\", \"1 Hz\"]", kClamped));
        INFO(r.run.out << r.run.err);
        REQUIRE(r.run.exit_code == 0);
        CHECK(contains(r.run.out, "no modes between 0 and 1 Hz"));
        CHECK_FALSE(contains(r.run.out, "INCOMPLETE"));
        CHECK_FALSE(contains(r.run.out, "mode 0"));
        CHECK(json_values(r.summary, "complete") == std::vector<std::string>{"true"});
        CHECK(json_values(r.summary, "fe_first_bending_hz") == std::vector<std::string>{"null"});
        CHECK(json_values(r.summary, "fe_over_timoshenko") == std::vector<std::string>{"null"});
        CHECK(json_values(r.summary, "fe_missing") == std::vector<std::string>{"\"no modes between 0 and 1 Hz\""});
        CHECK(contains(r.report, "no modes between 0 and 1 Hz"));
    }
}

TEST_CASE("A band between the rigid modes and the first elastic one is empty, proven by two counts",
          "[app][degenerate]") {
    // Free-free: six rigid modes at 0 Hz lie below the band's lower edge, the
    // first elastic one (1.4 kHz) above its upper edge.
    TempDir dir("gap-band");
    const Result r = run_case(dir, tube("0.5 m", "solid", "band = [\"50 Hz\", \"100 Hz\"]"));
    INFO(r.run.out << r.run.err);
    REQUIRE(r.run.exit_code == 0);
    CHECK(contains(r.run.out, "no modes between 50 and 100 Hz"));
    CHECK(json_values(r.summary, "eigenvalues_below_band") == std::vector<std::string>{"6"});
    CHECK(json_values(r.summary, "negative_pivots_at_shift") == std::vector<std::string>{"6"});
    CHECK(json_values(r.summary, "complete") == std::vector<std::string>{"true"});
}

TEST_CASE("A band far above what the mesh resolves is refused at once, saying what to change", "[app][degenerate]") {
    TempDir dir("far-band");
    for (const char* level : {"solid", "harmonic"}) {
        INFO(level);
        const auto start = std::chrono::steady_clock::now();
        const Result r = run_case(dir, tube("0.5 m", level, "band = [1e9, 2e9]"));
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        INFO(r.run.out << r.run.err);
        CHECK(r.run.exit_code != 0);
        CHECK(contains(r.run.err, "coremodal: error: case.toml: "));
        CHECK(contains(r.run.err, "[analysis] band = [1e+09 Hz, 2e+09 Hz] reaches above every eigenvalue"));
        CHECK(contains(r.run.err, "lower the upper edge"));
        CHECK_FALSE(fs::exists(dir.path / "out"));
        CHECK(seconds < 60);  // minutes before, then "the band is too wide"
    }
}

TEST_CASE("Too few modes for a bending mode: null and the reason, not \"mode 0 0.0000 Hz\"", "[app][degenerate]") {
    TempDir dir("no-bending");
    const Result r = run_case(dir, tube("0.5 m", "harmonic", "modes = 6"));
    INFO(r.run.out << r.run.err);
    REQUIRE(r.run.exit_code == 0);
    CHECK(contains(r.run.out, "FE first bending: none, no bending mode among the 6 modes found (6 rigid); ask for more modes"));
    CHECK(json_values(r.summary, "fe_mode_index") == std::vector<std::string>{"null"});
    CHECK(json_values(r.summary, "fe_missing") ==
          std::vector<std::string>{"\"no bending mode among the 6 modes found (6 rigid); ask for more modes\""});
}

TEST_CASE("The beam level says when it has fewer modes than were asked", "[app][degenerate]") {
    TempDir dir("many-modes");
    const Result r = run_case(dir, tube("0.5 m", "beam", "modes = 10000"));
    INFO(r.run.err);
    REQUIRE(r.run.exit_code == 0);
    CHECK(count_of(r.run.err, "asks for more modes than the beam model has") == 1);
    CHECK(json_values(r.summary, "modes_requested") == std::vector<std::string>{"10000"});
    const std::vector<std::string> reported = json_values(r.summary, "modes_reported");
    REQUIRE(reported.size() == 1);
    CHECK(std::stoi(reported[0]) < 10000);
    CHECK(std::stoi(reported[0]) == static_cast<int>(json_values(r.summary, "index").size()));
    CHECK(contains(r.summary, "asks for more modes than the beam model has"));
}

TEST_CASE("A modulus written without its unit is warned about once, with the unit it probably meant",
          "[app][degenerate]") {
    TempDir dir("bare-modulus");
    std::string text = tube("0.5 m", "beam", "modes = 8");
    text.replace(text.find("E = \"210 GPa\""), std::string("E = \"210 GPa\"").size(), "E = 210");
    const Result r = run_case(dir, text);
    INFO(r.run.err);
    REQUIRE(r.run.exit_code == 0);  // a warning, not an error
    CHECK(count_of(r.run.err, "[core.material] E = 210 Pa is outside the plausible range") == 1);
    CHECK(contains(r.run.err, "case.toml:8:18:"));
    CHECK(contains(r.run.err, "did you mean \"210 GPa\"?"));
    CHECK(contains(r.summary, "E = 210 Pa is outside the plausible range"));
}

TEST_CASE("check and study say the case's warnings too, once each", "[app][degenerate]") {
    TempDir dir("warned-study");
    std::string text = tube("0.5 m", "beam", "modes = 8");
    text.replace(text.find("E = \"210 GPa\""), std::string("E = \"210 GPa\"").size(), "E = 210");
    dir.write("case.toml", text + "\n[study]\nparameters = [{ key = \"core.length\", values = "
                                              "[\"0.5 m\", \"0.6 m\", \"0.7 m\"] }]\n");
    for (const std::string command : {"check case.toml", "study case.toml --jobs 1 --no-plots --quiet"}) {
        const Run r = run_coremodal(dir, command);
        INFO(command << ": " << r.err);
        CHECK(r.exit_code == 0);
        CHECK(count_of(r.err, "[core.material] E = 210 Pa is outside the plausible range") == 1);
    }
}

TEST_CASE("A chuck with zero clearance runs at every level and tends to a vanishing clearance", "[app][degenerate]") {
    // Before: the reader took clearance = "0 mm" and the mesher failed with
    // "no physical surface 'interface_left_chuck'".
    TempDir dir("zero-clearance");
    const auto roll = [](const std::string& level, const std::string& clearance, const std::string& interface) {
        return "name = \"chucks\"\nmodel = \"" + level +
               "\"\n\n[core]\ninner_diameter = \"76 mm\"\nwall = \"15 mm\"\nlength = \"1 m\"\n"
               "material = \"paperboard_core\"\n\n[supports]\ntype = \"chucks\"\n\n[supports.left]\n"
               "inserted_length = \"110 mm\"\nclearance = \"" + clearance + "\"\ninterface = \"" + interface +
               "\"\n\n[[supports.left.expanding]]\ncenter = \"80 mm\"\nwidth = \"60 mm\"\n\n"
               "[analysis]\nmodes = 2\n\n[mesh]\nlevel = \"coarse\"\n";
    };
    const auto f1 = [&](const std::string& level, const std::string& clearance, const std::string& interface) {
        const Result r = run_case(dir, roll(level, clearance, interface));
        INFO(level << ", clearance " << clearance << ", " << interface << ": " << r.run.out << r.run.err);
        REQUIRE(r.run.exit_code == 0);
        const std::vector<std::string> f = json_values(modes_of(r.summary), "frequency_hz");
        REQUIRE(!f.empty());
        return std::stod(f[0]);
    };
    for (const char* interface : {"bonded", "spring"})
        for (const char* level : {"solid", "harmonic", "beam"}) {
            INFO(level << ", " << interface);
            // 0.02 mm of clearance moves the first bending mode by about 1e-4.
            CHECK(f1(level, "0 mm", interface) == Approx(f1(level, "0.02 mm", interface)).epsilon(5e-4));
        }
}
