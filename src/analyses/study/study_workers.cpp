#include "analyses/study/study_workers.hpp"

#include "common/child_process.hpp"
#include "common/error.hpp"
#include "common/petsc_handle.hpp"
#include "common/signals.hpp"
#include "output/text_file.hpp"

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
#include <thread>


namespace coremodal {
namespace fs = std::filesystem;

namespace {

constexpr const char* kRecordHeader = "coremodal-study-point 1";

std::string exact(double v) {
    char text[40];
    std::snprintf(text, sizeof text, "%.17g", v);
    return text;
}

std::string one_line(std::string s) {
    for (char& c : s)
        if (c == '\n' || c == '\r') c = ' ';
    return s;
}

}  // namespace

std::string point_record(const StudyPoint& p) {
    std::ostringstream out;
    out << kRecordHeader << "\nok " << (p.ok ? 1 : 0) << "\ntime_s " << exact(p.time_s) << "\nmodel_level "
        << (p.model_level.empty() ? "-" : p.model_level) << "\nn_dofs " << p.n_dofs << "\n";
    if (p.f1_hz) out << "f1_hz " << exact(*p.f1_hz) << "\n";
    if (!p.ok) out << "error " << one_line(p.error) << "\n";
    out << "modes " << p.modes.size() << "\n";
    for (const ModeSummary& m : p.modes) {
        out << m.index << " " << exact(m.frequency_hz) << " " << m.label.type << " " << m.label.n << " " << m.label.m
            << " " << exact(m.label.dominant_share) << " " << m.signature.size();
        for (double v : m.signature) out << " " << exact(v);
        out << "\n";
    }
    return out.str();
}

void read_point_record(const std::string& text, StudyPoint& p) {
    std::istringstream in(text);
    std::string line;
    if (!std::getline(in, line) || line != kRecordHeader) throw std::runtime_error("not a study point record");
    while (std::getline(in, line)) {
        std::istringstream row(line);
        std::string key;
        row >> key;
        if (key == "ok") {
            int ok = 0;
            row >> ok;
            p.ok = ok == 1;
        } else if (key == "time_s") {
            row >> p.time_s;
        } else if (key == "model_level") {
            row >> p.model_level;
        } else if (key == "n_dofs") {
            row >> p.n_dofs;
        } else if (key == "f1_hz") {
            double f1 = 0;
            row >> f1;
            p.f1_hz = f1;
        } else if (key == "error") {
            std::getline(row >> std::ws, p.error);
        } else if (key == "modes") {
            size_t n = 0;
            row >> n;
            for (size_t i = 0; i < n; ++i) {
                if (!std::getline(in, line)) throw std::runtime_error("study point record: missing modes");
                std::istringstream m(line);
                ModeSummary s;
                size_t n_signature = 0;
                m >> s.index >> s.frequency_hz >> s.label.type >> s.label.n >> s.label.m >> s.label.dominant_share >>
                    n_signature;
                s.signature.resize(n_signature);
                for (double& v : s.signature) m >> v;
                if (!m) throw std::runtime_error("study point record: bad mode line");
                p.modes.push_back(std::move(s));
            }
        } else {
            throw std::runtime_error("study point record: unknown line '" + line + "'");
        }
        if (!row && key != "error") throw std::runtime_error("study point record: bad line '" + line + "'");
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
        const fs::path record = folder / ("point-" + std::to_string(i + 1) + ".txt");
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

}  // namespace

void run_points_in_children(const CaseSweep& sweep, const std::vector<int>& todo, unsigned jobs,
                            const std::string& program, std::vector<StudyPoint>& points,
                            const std::function<void(int)>& finished) {
    const fs::path folder = fs::temp_directory_path() / ("coremodal-study-" + std::to_string(::getpid()));
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

int run_worker_point(const WorkerPoint& w) {
    const CaseSweep sweep = CaseSweep::read(w.case_file, w.table, w.mesh_level);
    if (w.point < 0 || w.point >= sweep.n_points())
        throw InputError("--worker-point " + std::to_string(w.point) + " is not a point of " + w.case_file);
    StudyPoint p;
    p.index = w.point;
    try {
        run_point(sweep.scene(w.point), p);
    } catch (const InputError& e) {
        p.error = e.what();
    }
    if (mpi_rank() == 0) write_text_file(w.output, point_record(p));
    return 0;
}

}  // namespace coremodal
