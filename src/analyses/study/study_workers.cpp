#include "analyses/study/study_workers.hpp"

#include "common/child_process.hpp"
#include "common/error.hpp"
#include "common/petsc_handle.hpp"
#include "common/process_folders.hpp"
#include "common/signals.hpp"

#include <nlohmann/json.hpp>

#include <signal.h>
#include <sys/prctl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <thread>


namespace coremodal {
namespace fs = std::filesystem;

namespace {

// The record's "format": a file with another tag is not a point record.
constexpr const char* kRecordFormat = "coremodal-study-point";
constexpr int kRecordVersion = 1;

nlohmann::json mode_json(const ModeSummary& m) {
    return {{"index", m.index},
            {"frequency_hz", m.frequency_hz},
            {"type", m.label.type},
            {"n", m.label.n},
            {"m", m.label.m},
            {"dominant_share", m.label.dominant_share},
            {"signature", m.signature}};
}

ModeSummary mode_from_json(const nlohmann::json& j) {
    ModeSummary m;
    m.index = j.at("index").get<int>();
    m.frequency_hz = j.at("frequency_hz").get<double>();
    m.label.type = j.at("type").get<std::string>();
    m.label.n = j.at("n").get<int>();
    m.label.m = j.at("m").get<int>();
    m.label.dominant_share = j.at("dominant_share").get<double>();
    m.signature = j.at("signature").get<Signature>();
    return m;
}

void put(nlohmann::json& j, const char* key, const std::optional<double>& v) {
    if (v) j[key] = *v;
}
std::optional<double> take(const nlohmann::json& j, const char* key) {
    return j.contains(key) ? std::optional<double>(j.at(key).get<double>()) : std::nullopt;
}

// A point's forced response (StudyResponse); absent values stay absent.
nlohmann::json response_json(const StudyResponse& r) {
    nlohmann::json j = {{"limit_m", r.limit_m},
                        {"max_web_speed_m_s", r.max_web_speed_m_s},
                        {"limit_reached", r.limit_reached},
                        {"below_range", r.below_range},
                        {"max_amplitude_m", r.max_amplitude_m},
                        {"max_amplitude_web_speed_m_s", r.max_amplitude_web_speed_m_s}};
    put(j, "v_limit_m_s", r.v_limit_m_s);
    put(j, "implied_factor", r.implied_factor);
    put(j, "v_i5_07_m_s", r.v_i5_07_m_s);
    put(j, "v_i5_08_m_s", r.v_i5_08_m_s);
    put(j, "v_koenig_m_s", r.v_koenig_m_s);
    return j;
}

StudyResponse response_from_json(const nlohmann::json& j) {
    StudyResponse r;
    r.limit_m = j.at("limit_m").get<double>();
    r.max_web_speed_m_s = j.at("max_web_speed_m_s").get<double>();
    r.limit_reached = j.at("limit_reached").get<bool>();
    r.below_range = j.at("below_range").get<bool>();
    r.max_amplitude_m = j.at("max_amplitude_m").get<double>();
    r.max_amplitude_web_speed_m_s = j.at("max_amplitude_web_speed_m_s").get<double>();
    r.v_limit_m_s = take(j, "v_limit_m_s");
    r.implied_factor = take(j, "implied_factor");
    r.v_i5_07_m_s = take(j, "v_i5_07_m_s");
    r.v_i5_08_m_s = take(j, "v_i5_08_m_s");
    r.v_koenig_m_s = take(j, "v_koenig_m_s");
    return r;
}

}  // namespace

std::string point_record(const StudyPoint& p) {
    nlohmann::json modes = nlohmann::json::array();
    for (const ModeSummary& m : p.modes) modes.push_back(mode_json(m));
    nlohmann::json j = {{"format", kRecordFormat}, {"version", kRecordVersion}, {"ok", p.ok},
                        {"time_s", p.time_s},      {"model_level", p.model_level}, {"n_dofs", p.n_dofs},
                        {"error", p.error},        {"modes", modes}};
    if (p.f1_hz) j["f1_hz"] = *p.f1_hz;
    if (p.response) j["response"] = response_json(*p.response);
    // Doubles are written with the shortest text that reads back to the same bits.
    return j.dump(1) + "\n";
}

void read_point_record(const std::string& text, StudyPoint& p) {
    nlohmann::json j;
    try {
        j = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        throw std::runtime_error(std::string("not a study point record (invalid JSON): ") + e.what());
    }
    if (!j.is_object() || j.value("format", "") != kRecordFormat)
        throw std::runtime_error(std::string("not a study point record (no \"format\": \"") + kRecordFormat + "\")");
    try {
        if (j.at("version").get<int>() != kRecordVersion)
            throw std::runtime_error("version " + j.at("version").dump() + ", expected " +
                                     std::to_string(kRecordVersion));
        p.ok = j.at("ok").get<bool>();
        p.time_s = j.at("time_s").get<double>();
        p.model_level = j.at("model_level").get<std::string>();
        p.n_dofs = j.at("n_dofs").get<long>();
        p.error = j.at("error").get<std::string>();
        if (j.contains("f1_hz")) p.f1_hz = j.at("f1_hz").get<double>();
        if (j.contains("response")) p.response = response_from_json(j.at("response"));
        for (const nlohmann::json& m : j.at("modes")) p.modes.push_back(mode_from_json(m));
    } catch (const std::exception& e) {  // a missing key or a value of the wrong kind
        throw std::runtime_error(std::string("study point record: ") + e.what());
    }
}

namespace {

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

struct Child {
    const CaseSweep& sweep;
    const std::string& program;
    std::vector<std::string>& env;
    fs::path folder;

    // Runs point i in a child; fills the point from its record, or its failure.
    void run(int i, StudyPoint& p) const {
        const fs::path record = folder / ("point-" + std::to_string(i + 1) + ".json");
        const fs::path log = folder / ("point-" + std::to_string(i + 1) + ".log");
        std::error_code ec;  // "/proc/self/exe" names the program by a link: show its target in ps
        const fs::path real = fs::read_symlink(program, ec);
        std::vector<std::string> args = {ec ? program : real.string(),
                                         "study",
                                         sweep.case_file(),
                                         "--worker-table",
                                         sweep.table(),
                                         "--worker-point",
                                         std::to_string(i),
                                         "--worker-output",
                                         record.string(),
                                         "--quiet"};
        if (!sweep.options().mesh_level.empty()) args.insert(args.end(), {"--mesh", sweep.options().mesh_level});
        if (!sweep.options().model.empty()) args.insert(args.end(), {"--model", sweep.options().model});
        const ChildExit child = run_child(program, args, env, log);
        if (!child.started()) {
            p.error = "cannot start " + program + ": " + std::strerror(child.spawn_error);
            return;
        }
        const int status = child.status;
        const double wall = child.wall_s;
        read_outcome(status, record, log, p);
        p.time_s = wall;  // the child's whole life: start-up included
    }

    static void read_outcome(int status, const fs::path& record, const fs::path& log, StudyPoint& p) {
        const std::string why = first_error_line(read_file(log));
        if (WIFSIGNALED(status)) {
            p.error = "crashed: signal " + std::to_string(WTERMSIG(status)) + " (" + strsignal(WTERMSIG(status)) +
                      ")" + (why.empty() ? "" : ": " + why);
            return;
        }
        if (!fs::exists(record)) {
            p.error = why.empty() ? "the worker wrote no result (exit code " +
                                        std::to_string(WIFEXITED(status) ? WEXITSTATUS(status) : -1) + ")"
                                  : why;
            return;
        }
        try {
            read_point_record(read_file(record), p);
        } catch (const std::exception& e) {
            p.ok = false;
            p.error = record.string() + ": " + e.what();
        }
    }
};

// The scratch folder of the study run by process `pid`, and the prefix of
// every study's: a killed study's is removed by the next (common/process_folders.hpp).
constexpr std::string_view kScratchPrefix = "coremodal-study-";
fs::path scratch_folder(pid_t pid) { return process_folder(fs::temp_directory_path(), kScratchPrefix, pid); }

}  // namespace

void run_points_in_children(const CaseSweep& sweep, const std::vector<int>& todo, unsigned jobs,
                            const std::string& program, std::vector<StudyPoint>& points,
                            const std::function<void(int)>& finished) {
    remove_folders_of_dead_processes(fs::temp_directory_path(), kScratchPrefix);
    const fs::path folder = scratch_folder(::getpid());
    remove_on_interrupt(folder);  // the workers' records: scratch, removed however the study ends
    fs::remove_all(folder);
    fs::create_directories(folder);
    std::vector<std::string> env = child_environment(/*single_threaded=*/true);
    const Child child{sweep, program, env, folder};
    std::atomic<size_t> next{0};
    std::mutex lock;
    auto worker = [&] {
        for (size_t k; (k = next++) < todo.size();) {
            const int i = todo[k];
            child.run(i, points[static_cast<size_t>(i)]);
            std::lock_guard<std::mutex> guard(lock);
            finished(i);
        }
    };
    std::vector<std::thread> threads;
    for (unsigned j = 0; j < jobs; ++j) threads.emplace_back(worker);
    for (auto& t : threads) t.join();
    std::error_code ignored;
    fs::remove_all(folder, ignored);
    keep_on_interrupt(folder);
}

StudyPoint run_worker_point(const WorkerPoint& w) {
    // A worker ends with its study: a study killed with SIGKILL cannot stop
    // it, so the kernel sends it SIGTERM (common/signals.hpp) when the
    // study's thread that started it is gone. If the study died before this
    // line, the worker has a new parent already and stops at once.
    const pid_t study = ::getppid();
    ::prctl(PR_SET_PDEATHSIG, SIGTERM);
    if (::getppid() != study || !coremodal_running(study))
        throw SolveError("the study that started this worker has ended");
    const CaseSweep sweep = CaseSweep::read(w.case_file, w.table, w.mesh_level).with_model(w.model);
    if (w.point < 0 || w.point >= sweep.n_points())
        throw InputError("--worker-point " + std::to_string(w.point) + " is not a point of " + w.case_file);
    StudyPoint p;
    p.index = w.point;
    try {
        ResponseCase c = sweep.response_case(w.point);
        run_point(std::move(c.scene), p, response_of_point(w.table, std::move(c.response)));
    } catch (const InputError& e) {
        p.error = e.what();
    }
    return p;
}

}  // namespace coremodal
