#include "analyses/batch/batch.hpp"

#include "common/child_process.hpp"
#include "common/error.hpp"
#include "scene/toml_text.hpp"

#include <nlohmann/json.hpp>
#include <toml++/toml.h>

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <thread>
#include <utility>


namespace coremodal {
namespace fs = std::filesystem;
namespace {

// ---- child processes ---------------------------------------------------------

std::string read_text(const std::string& path) {
    std::ifstream f(path, std::ios::binary);
    std::ostringstream s;
    s << f.rdbuf();
    return s.str();
}

std::string program_name(const std::string& program) {
    std::error_code ec;
    const fs::path real = fs::read_symlink(program, ec);
    return ec ? program : real.string();
}

void run_one(BatchCase& c, const BatchOptions& o, std::vector<std::string>& env) {
    const bool winder = is_winder_file(c.file), selection = is_selection_file(c.file);
    const bool traction = !winder && !selection && is_traction_file(c.file);
    const bool fit = !winder && !selection && !traction && is_fit_file(c.file);
    const char* command = winder ? "winder" : selection ? "select" : traction ? "traction" : fit ? "fit" : "run";
    std::vector<std::string> args = {program_name(o.program), command, c.file, "--output", c.result_dir, "--quiet"};
    if (!o.plots) args.push_back("--no-plots");
    if (winder) c.note = "a two-drum winder (coremodal winder): its frequencies and crossings are in its report.md";
    if (selection) c.note = "a core selection (coremodal select): its chart and verdicts are in its report.md";
    if (traction) c.note = "a roller's traction (coremodal traction): its speeds are in its report.md";
    if (fit) c.note = "a fit's measurements (coremodal fit): the fitted parameters are in its report.md";
    if (o.mesh_level) {
        if (winder || selection || traction || fit)
            c.note += std::string("; ") + (traction ? "closed forms" : fit ? "the measured cases' own meshes" : "a beam model") +
                      ": --mesh " + *o.mesh_level + " not applied";
        else if (case_has_mesh_file(c.file))
            c.note = "own mesh file: --mesh " + *o.mesh_level + " not applied";
        else
            args.insert(args.end(), {"--mesh", *o.mesh_level});
    }
    const ChildExit child = run_child(o.program, args, env, c.log_file);
    if (!child.started()) {
        c.error = "cannot start " + args[0] + ": " + std::strerror(child.spawn_error);
        return;
    }
    const int status = child.status;
    c.time_s = child.wall_s;

    const std::string message = first_error_line(read_text(c.log_file));
    if (WIFSIGNALED(status)) {
        c.error = "crashed: signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) + ")";
        if (!message.empty()) c.error += ": " + message;
        return;
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) {
        c.error = !message.empty() ? message
                                   : "exit code " + std::to_string(WEXITSTATUS(status)) + " without a message";
        return;
    }
    const fs::path summary = fs::path(c.result_dir) / "summary.json";
    if (!fs::exists(summary)) {
        c.error = "finished without writing " + summary.string();
        return;
    }
    if (winder || traction) {  // no f1 or safe speed of one roll: the answer is in the command's own report
        c.ok = true;
        return;
    }
    try {
        read_batch_summary(c, read_text(summary.string()));
        c.ok = true;
    } catch (const std::exception& e) {
        c.error = summary.string() + ": " + e.what();
    }
}

}  // namespace

void read_batch_summary(BatchCase& c, const std::string& summary_json) {
    nlohmann::json root;
    try {
        root = nlohmann::json::parse(summary_json);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::runtime_error(std::string("invalid JSON: ") + e.what());
    }
    // The value at a dotted path of object keys ("beam.fe_first_bending_hz"); nullptr when absent.
    auto find = [&](const std::string& path) -> const nlohmann::json* {
        const nlohmann::json* v = &root;
        std::istringstream keys(path);
        for (std::string key; std::getline(keys, key, '.');) {
            if (!v->is_object() || !v->contains(key)) return nullptr;
            v = &(*v)[key];
        }
        return v;
    };
    auto number = [&](const std::string& path) -> std::optional<double> {
        const nlohmann::json* v = find(path);
        if (!v || !v->is_number() || !std::isfinite(v->get<double>())) return std::nullopt;
        return v->get<double>();
    };
    if (!find("beam.fe_first_bending_hz")) throw std::runtime_error("no beam.fe_first_bending_hz");
    // The writer stores null when no bending mode was found among the modes (0 before).
    const auto f1 = number("beam.fe_first_bending_hz");
    c.f1_hz = f1 && *f1 > 0 ? f1 : std::nullopt;
    const auto ratio = number("beam.fe_over_timoshenko");
    c.fe_over_timoshenko = ratio && *ratio > 0 ? ratio : std::nullopt;
    // The speeds as the run gave them (summary.json "speeds", beam/speeds.hpp):
    // none for a free-free case or one without a bending mode.
    c.diameter_m = number("speeds.dp_m");
    c.v_safe_m_s.reset();
    if (const nlohmann::json* safe = find("speeds.safe_web_speed"); safe && safe->is_array())
        for (const nlohmann::json& row : *safe)
            if (row.is_object() && row.value("safe", 0.0) == kBatchSafeFactor && row.contains("v_safe_m_s") &&
                row["v_safe_m_s"].is_number())
                c.v_safe_m_s = row["v_safe_m_s"].get<double>();
    const auto k = number("chuck.chuck_factor");
    c.chuck_factor = k && *k > 0 ? k : std::nullopt;
}

namespace {
// The parsed case file, or an empty table when it cannot be read (its run
// then reports why).
toml::table case_table_or_empty(const std::string& case_file) {
    try {
        return parse_toml_text(read_input_file(case_file, "case file"), case_file);
    } catch (const std::exception&) {
        return {};
    }
}
}  // namespace

bool case_has_mesh_file(const std::string& case_file) {
    return case_table_or_empty(case_file)["mesh"]["file"].is_string();
}

bool is_winder_file(const std::string& case_file) { return case_table_or_empty(case_file).contains("winder"); }

bool is_selection_file(const std::string& case_file) {
    return case_table_or_empty(case_file).contains("selection");
}

bool is_fit_file(const std::string& case_file) {
    const toml::table t = case_table_or_empty(case_file);
    return !t.contains("core") && (t.contains("measurement") || t.contains("parameters"));
}

bool is_traction_file(const std::string& case_file) {
    const toml::table t = case_table_or_empty(case_file);
    return t.contains("traction") && !t.contains("core");
}

std::vector<std::string> batch_case_files(const std::vector<std::string>& inputs) {
    std::vector<std::string> files;
    for (const auto& input : inputs) {
        std::error_code ec;
        if (fs::is_directory(input, ec)) {
            std::vector<std::string> found;
            for (const auto& entry : fs::directory_iterator(input, ec))
                if (entry.path().extension() == ".toml" && !fs::is_directory(entry.path(), ec))
                    found.push_back(entry.path().string());
            if (ec) throw InputError("cannot read folder " + input + ": " + ec.message());
            if (found.empty()) throw InputError("no *.toml case files in folder " + input);
            std::sort(found.begin(), found.end());
            files.insert(files.end(), found.begin(), found.end());
        } else if (fs::exists(input, ec)) {
            files.push_back(input);
        } else {
            throw InputError("no such case file or folder: " + input);
        }
    }
    if (files.empty()) throw InputError("no case files given");
    return files;
}

std::vector<BatchCase> batch_cases(const BatchOptions& o) {
    const auto files = batch_case_files(o.inputs);

    // One result folder per case, named by the file stem; a stem seen before
    // (the same name in two folders) gets -2, -3, ...
    std::vector<BatchCase> cases;
    std::map<std::string, int> seen;
    for (const auto& f : files) {
        BatchCase c;
        c.file = f;
        const std::string stem = fs::path(f).stem().string();
        const int n = ++seen[stem];
        c.name = n == 1 ? stem : stem + "-" + std::to_string(n);
        c.result_dir = (fs::path(o.output_dir) / c.name).string();
        c.log_file = (fs::path(o.output_dir) / (c.name + ".log")).string();
        cases.push_back(std::move(c));
    }
    return cases;
}

std::vector<std::string> batch_folder_contents(const std::vector<BatchCase>& cases) {
    std::vector<std::string> contents = {"batch.csv", "batch.md"};
    for (const BatchCase& c : cases) {
        contents.push_back(c.name + "/");
        contents.push_back(c.name + ".log");
    }
    return contents;
}

void run_batch(std::vector<BatchCase>& cases, const BatchOptions& o, std::ostream& progress) {
    unsigned jobs = o.jobs ? o.jobs : std::max(1u, std::thread::hardware_concurrency());
    jobs = std::min<unsigned>(jobs, static_cast<unsigned>(cases.size()));
    std::vector<std::string> env = child_environment(jobs > 1);

    progress << "batch: " << cases.size() << (cases.size() == 1 ? " case, " : " cases, ") << jobs
             << " at a time, results in " << o.output_dir << std::endl;

    std::size_t width = 0;
    for (const auto& c : cases) width = std::max(width, c.name.size());
    std::atomic<std::size_t> next{0};
    std::mutex lock;
    std::size_t finished = 0;
    auto worker = [&] {
        for (std::size_t i; (i = next++) < cases.size();) {
            BatchCase& c = cases[i];
            try {
                run_one(c, o, env);
            } catch (const std::exception& e) {
                c.ok = false;
                c.error = e.what();
            }
            std::lock_guard<std::mutex> guard(lock);
            char head[64], time[64];
            std::snprintf(head, sizeof head, "[%zu/%zu] ", ++finished, cases.size());
            std::snprintf(time, sizeof time, "%.1f s", c.time_s);
            progress << head << c.name << std::string(width - c.name.size(), ' ')
                     << (c.ok ? "  ok " + std::string(time) : "  FAILED: " + c.error + "  (" + time + ")")
                     << (c.note.empty() ? "" : "  [" + c.note + "]") << std::endl;
        }
    };
    std::vector<std::thread> threads;
    for (unsigned j = 0; j < jobs; ++j) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
}


}  // namespace coremodal
