// `coremodal batch`: the pieces (summary values, tables) and the real program
// on a folder with two good and one broken case.
#include "analyses/batch/batch.hpp"
#include "output/batch_report.hpp"

#include <catch2/catch.hpp>

#include <sys/wait.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace coremodal;
namespace fs = std::filesystem;

namespace {

struct Output {
    int exit_code = -1;
    std::string text;  // stdout and stderr
};

Output run_program(const std::string& arguments) {
    const std::string command = std::string("'") + COREMODAL_BINARY + "' " + arguments + " 2>&1";
    Output out;
    FILE* pipe = popen(command.c_str(), "r");
    REQUIRE(pipe);
    char buf[4096];
    for (std::size_t n; (n = std::fread(buf, 1, sizeof buf, pipe)) > 0;) out.text.append(buf, n);
    const int status = pclose(pipe);
    out.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return out;
}

std::string read_file(const fs::path& p) {
    std::ifstream f(p);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

void write_file(const fs::path& p, const std::string& text) {
    std::ofstream f(p);
    f << text;
}

// A short clamped 76x15 tube on the smallest mesh: about a second per run.
std::string tiny_case(const std::string& name, const std::string& length, const std::string& extra = "") {
    return "name = \"" + name + "\"\n"
           "[core]\ninner_diameter = \"76 mm\"\nwall = \"15 mm\"\nlength = \"" + length + "\"\n"
           "material = \"paperboard_core\"\n"
           "[supports]\ntype = \"clamped\"\n[supports.left]\nlength = \"50 mm\"\n"
           "[analysis]\nmodes = 4\n" + extra +
           "[mesh]\nthrough_wall = 1\naround = 8\nalong = 4\n";
}

const char* kSummary = R"({
    "beam" : { "ends" : "clamped-clamped", "fe_first_bending_hz" : 35.5, "fe_mode_index" : 1,
               "fe_over_timoshenko" : 0.9, "timoshenko_hz" : 39.44 },
    "case" : {
        "assumptions" : [ "a \"quoted\" \u00e9 sentence", "x" ],
        "core" : { "inner_diameter" : 0.1505, "outer_diameter" : 0.1821, "length" : 4.32 },
        "name" : "rest roll",
        "rest_paper" : { "outer_diameter" : 0.2021 },
        "supports" : { "clamps" : [ { "name" : "left", "z_end" : 0.3 } ], "type" : "clamped" }
    },
    "chuck" : { "chuck_factor" : 0.8125, "f1_hz" : 35.5 },
    "modes" : [ { "frequency_hz" : 1.5e1, "index" : 1 } ],
    "speeds" : { "dp_m" : 0.2021, "f1_hz" : 35.5,
                 "safe_web_speed" : [ { "safe" : 0.7, "v_safe_m_s" : 15.777 }, { "safe" : 0.8, "v_safe_m_s" : 18.031 } ] },
    "verification" : { "complete" : true, "missing" : null, "shift" : -2.5E-3 }
}
)";

}  // namespace

TEST_CASE("read_batch_summary refuses a summary that is not JSON, saying so", "[batch]") {
    BatchCase c;
    CHECK_THROWS_WITH(read_batch_summary(c, "{\"beam\": {\"fe_first_bending_hz\": 1},}"),
                      Catch::Contains("invalid JSON"));
    CHECK_THROWS_WITH(read_batch_summary(c, "{\"beam\": 1"), Catch::Contains("invalid JSON"));
    CHECK_THROWS_WITH(read_batch_summary(c, ""), Catch::Contains("invalid JSON"));
    // Values of a kind it does not expect count as absent, not as errors.
    CHECK_NOTHROW(read_batch_summary(c, R"({"beam": {"fe_first_bending_hz": 1}, "case": {"supports": "x"}})"));
}

TEST_CASE("read_batch_summary takes f1, the beam ratio, k and the 0.7 safe speed as summary.json gives them",
          "[batch]") {
    BatchCase c;
    read_batch_summary(c, kSummary);
    REQUIRE(c.f1_hz);
    CHECK(*c.f1_hz == Approx(35.5));
    CHECK(*c.fe_over_timoshenko == Approx(0.9));
    CHECK(*c.chuck_factor == Approx(0.8125));
    CHECK(*c.diameter_m == Approx(0.2021));  // speeds.dp_m, not recomputed
    REQUIRE(c.v_safe_m_s);
    CHECK(*c.v_safe_m_s == 15.777);  // the 0.7 row, not the 0.8 one

    SECTION("no speeds in the summary (free-free, or no bending mode): no safe speed") {
        std::string s = kSummary;
        s.replace(s.find("\"speeds\""), 8, "\"nothing\"");
        BatchCase d;
        read_batch_summary(d, s);
        CHECK(d.f1_hz);
        CHECK_FALSE(d.v_safe_m_s);
        CHECK_FALSE(d.diameter_m);
    }
    SECTION("no bending mode found (written as null since issue 11) leaves f1 empty") {
        BatchCase d;
        read_batch_summary(d, R"({"beam": {"fe_first_bending_hz": null, "fe_over_timoshenko": null}, "case": {}})");
        CHECK_FALSE(d.f1_hz);
        CHECK_FALSE(d.fe_over_timoshenko);
        CHECK_FALSE(d.v_safe_m_s);
        CHECK_FALSE(d.chuck_factor);
    }
    SECTION("no bending mode found (written as 0 before) leaves f1 empty") {
        BatchCase d;
        read_batch_summary(d, R"({"beam": {"fe_first_bending_hz": 0, "fe_over_timoshenko": 0}, "case": {}})");
        CHECK_FALSE(d.f1_hz);
        CHECK_FALSE(d.fe_over_timoshenko);
        CHECK_FALSE(d.v_safe_m_s);
    }
    CHECK_THROWS_WITH(read_batch_summary(c, "{}"), Catch::Contains("beam.fe_first_bending_hz"));
}

TEST_CASE("batch_case_files takes every *.toml of a folder, sorted, and refuses missing paths", "[batch]") {
    const fs::path dir = fs::temp_directory_path() / ("coremodal-batch-files-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir);
    for (const char* name : {"b.toml", "a.toml", "notes.txt"}) write_file(dir / name, "");
    const auto files = batch_case_files({dir.string(), (dir / "b.toml").string()});
    REQUIRE(files.size() == 3);
    CHECK(fs::path(files[0]).filename() == "a.toml");
    CHECK(fs::path(files[1]).filename() == "b.toml");
    CHECK(fs::path(files[2]).filename() == "b.toml");
    CHECK_THROWS_WITH(batch_case_files({(dir / "missing.toml").string()}), Catch::Contains("missing.toml"));
    fs::remove(dir / "a.toml");
    fs::remove(dir / "b.toml");
    CHECK_THROWS_WITH(batch_case_files({dir.string()}), Catch::Contains("no *.toml"));
    fs::remove_all(dir);
}

TEST_CASE("case_has_mesh_file tells cases with their own mesh (no --mesh for them)", "[batch]") {
    const std::string cases = std::string(COREMODAL_SOURCE_DIR) + "/cases/";
    CHECK(case_has_mesh_file(cases + "04-user-mesh-76x15.toml"));
    CHECK_FALSE(case_has_mesh_file(cases + "02-clamped-76x15.toml"));
    CHECK_FALSE(case_has_mesh_file(cases + "no-such-case.toml"));
    CHECK(is_winder_file(cases + "11-two-drum-winder.toml"));  // run with `coremodal winder`
    CHECK_FALSE(is_winder_file(cases + "02-clamped-76x15.toml"));
    CHECK(is_selection_file(cases + "18-core-selection.toml"));  // run with `coremodal select`
    CHECK_FALSE(is_selection_file(cases + "11-two-drum-winder.toml"));
    CHECK(is_traction_file(cases + "19-grooved-idler-traction.toml"));  // run with `coremodal traction`
    CHECK_FALSE(is_traction_file(cases + "02-clamped-76x15.toml"));
}

TEST_CASE("batch tables: CSV quotes error messages, Markdown escapes bars", "[batch]") {
    BatchCase ok;
    ok.name = "good";
    ok.file = "cases/good.toml";
    ok.ok = true;
    ok.f1_hz = 35.5;
    ok.fe_over_timoshenko = 0.9;
    ok.chuck_factor = 0.8125;
    ok.diameter_m = 0.2;
    ok.v_safe_m_s = 0.7 * M_PI * 0.2 * 35.5;
    ok.time_s = 1.25;
    BatchCase bad;
    bad.name = "bad";
    bad.file = "cases/bad.toml";
    bad.error = "error: x, \"y\" | z";
    const std::string csv = batch_csv({ok, bad});
    CHECK(csv.find("good,cases/good.toml,ok,35.5,0.9,0.8125,0.2,15.6") != std::string::npos);
    CHECK(csv.find("bad,cases/bad.toml,failed,,,,,,,0.000,\"error: x, \"\"y\"\" | z\"") != std::string::npos);
    const std::string md = batch_markdown({ok, bad});
    CHECK(md.find("| good | ok | 35.50 | 0.9000 | 0.8125 | 200.0 | 15.61 | 937 | 1.2 |") != std::string::npos);
    CHECK(md.find("error: x, \"y\" \\| z") != std::string::npos);
    CHECK(md.find("0.7 * pi * D * f1") != std::string::npos);
    std::ostringstream console;
    print_batch_table(console, {ok, bad});
    CHECK(console.str().find("FAILED bad: error: x") != std::string::npos);
    CHECK(console.str().find("1 of 2 cases ok, 1 failed") != std::string::npos);
}

TEST_CASE("coremodal batch runs good cases past a broken one and reports it", "[long][batch]") {
    const fs::path dir = fs::temp_directory_path() / ("coremodal-batch-test-" + std::to_string(::getpid()));
    fs::remove_all(dir);
    fs::create_directories(dir / "cases");
    write_file(dir / "cases" / "01-short.toml", tiny_case("short", "0.4 m"));
    write_file(dir / "cases" / "02-longer.toml", tiny_case("longer", "0.5 m"));
    write_file(dir / "cases" / "03-broken.toml", tiny_case("broken", "0.4 m", "colour = \"red\"\n"));
    const fs::path out = dir / "out";

    const Output r = run_program("batch '" + (dir / "cases").string() + "' --output '" + out.string() + "' --jobs 2");
    INFO(r.text);
    CHECK(r.exit_code != 0);
    CHECK(fs::exists(out / "01-short" / "summary.json"));
    CHECK(fs::exists(out / "02-longer" / "summary.json"));
    CHECK_FALSE(fs::exists(out / "03-broken"));
    CHECK(read_file(out / "03-broken.log").find("unknown key 'colour'") != std::string::npos);
    // Console: a progress line per case and the broken case named with its error.
    CHECK(r.text.find("[3/3]") != std::string::npos);
    CHECK(r.text.find("03-broken  FAILED: error:") != std::string::npos);
    CHECK(r.text.find("FAILED 03-broken: error:") != std::string::npos);
    CHECK(r.text.find("2 of 3 cases ok, 1 failed") != std::string::npos);

    std::istringstream csv(read_file(out / "batch.csv"));
    std::vector<std::string> rows;
    for (std::string line; std::getline(csv, line);) rows.push_back(line);
    REQUIRE(rows.size() == 4);  // header and 3 cases, in file order
    CHECK(rows[0].rfind("case,file,status,f1_hz,", 0) == 0);
    CHECK(rows[1].rfind("01-short,", 0) == 0);
    CHECK(rows[1].find(",ok,") != std::string::npos);
    CHECK(rows[2].rfind("02-longer,", 0) == 0);
    CHECK(rows[2].find(",ok,") != std::string::npos);
    CHECK(rows[3].rfind("03-broken,", 0) == 0);
    CHECK(rows[3].find(",failed,") != std::string::npos);
    CHECK(rows[3].find("unknown key 'colour'") != std::string::npos);
    // The good rows carry f1 and v_safe = 0.7 pi D f1 with D = 106 mm.
    BatchCase short_case;
    read_batch_summary(short_case, read_file(out / "01-short" / "summary.json"));
    REQUIRE(short_case.f1_hz);
    CHECK(*short_case.v_safe_m_s == Approx(0.7 * M_PI * 0.106 * *short_case.f1_hz));
    CHECK(read_file(out / "batch.md").find("| 03-broken | FAILED |") != std::string::npos);
    fs::remove_all(dir);
}

TEST_CASE("coremodal batch --help exits 0; no cases is an error", "[batch]") {
    const Output help = run_program("batch --help");
    CHECK(help.exit_code == 0);
    CHECK(help.text.find("--jobs") != std::string::npos);
    const Output missing = run_program("batch /nonexistent/folder");
    CHECK(missing.exit_code != 0);
    CHECK(missing.text.find("no such case file or folder") != std::string::npos);
}
