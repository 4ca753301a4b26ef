// Time per evaluation of the beam model (bench/results/log.md):
//
//   build/coremodal_bench_beam [--repeats N] [--modes M] [--elements E] CASE.toml...
//
// Any case file runs at the beam level here (its `model` key is ignored);
// --modes replaces every case's [analysis] modes, --elements the core
// element count (BeamModelOptions::core_elements, default 30).
//
// For each case: the median, 10th and 90th percentile wall-clock time of
// solve_beam_model (build, assemble, solve, label; no file I/O) over N runs
// after a warm-up, for the case's [analysis] modes and for the first bending
// pair only (modes = 2, what a study of f1 needs); and the median CPU time of
// this thread, which a machine shared with other jobs inflates less than the
// wall clock (time spent descheduled is not counted). No PETSc, no MPI.
#include "beam/beam_model.hpp"
#include "scene/case_file.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>
#include <vector>

using namespace coremodal;

namespace {

constexpr int kWarmUp = 50;

struct Times {
    double p10, median, p90;  // wall clock, ms
    double cpu_median;        // this thread's CPU time, ms
};

double thread_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * t.tv_sec + 1e-6 * t.tv_nsec;
}

double quantile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    return v[static_cast<size_t>(q * (v.size() - 1))];
}

Times time_evaluations(const Scene& scene, const BeamModelOptions& options, int repeats) {
    for (int i = 0; i < kWarmUp; ++i) solve_beam_model(scene, options);
    std::vector<double> wall, cpu;
    for (int i = 0; i < repeats; ++i) {
        const double cpu_start = thread_cpu_ms();
        const auto start = std::chrono::steady_clock::now();
        const BeamModelResult r = solve_beam_model(scene, options);
        wall.push_back(std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
        cpu.push_back(thread_cpu_ms() - cpu_start);
        if (r.modes.empty()) std::abort();
    }
    return {quantile(wall, 0.1), quantile(wall, 0.5), quantile(wall, 0.9), quantile(cpu, 0.5)};
}

double first_bending_hz(const BeamModelResult& r) {
    for (const BeamMode& m : r.modes)
        if (m.label.type == "bending") return m.frequency_hz;
    return 0;
}

}  // namespace

int run(int argc, char** argv) {
    int repeats = 2000, modes = 0;
    BeamModelOptions options;
    std::vector<std::string> files;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--repeats" && i + 1 < argc) repeats = std::atoi(argv[++i]);
        else if (a == "--modes" && i + 1 < argc) modes = std::atoi(argv[++i]);
        else if (a == "--elements" && i + 1 < argc) options.core_elements = std::atoi(argv[++i]);
        else if (a == "-h" || a == "--help") {
            std::printf("usage: coremodal_bench_beam [--repeats N] [--modes N] [--elements N] CASE.toml...\n"
                        "Times the beam model level's evaluation of each case (bench/results/log.md).\n");
            return 0;
        } else files.push_back(a);
    }
    std::printf("%-40s %5s %5s %8s | %28s | %8s | %s\n", "case", "DOFs", "modes", "f1 [Hz]",
                "wall p10 / median / p90 [ms]", "CPU [ms]", "modes = 2: wall / CPU [ms]");
    for (const std::string& file : files) {
        Scene scene = parse_case_file(file);
        if (modes > 0) scene.analysis.n_modes = modes;
        const BeamModelResult r = solve_beam_model(scene, options);
        const Times all = time_evaluations(scene, options, repeats);
        scene.analysis.n_modes = 2;
        const Times pair = time_evaluations(scene, options, repeats);
        std::printf("%-40s %5ld %5zu %8.4f | %8.3f / %7.3f / %7.3f | %8.3f | %7.3f / %.3f\n", scene.name.c_str(),
                    r.n_dofs, r.modes.size(), first_bending_hz(r), all.p10, all.median, all.p90, all.cpu_median,
                    pair.median, pair.cpu_median);
    }
    return 0;
}

int main(int argc, char** argv) {
    try {
        return run(argc, argv);
    } catch (const std::exception& e) {
        std::fprintf(stderr, "coremodal_bench_beam: %s\n", e.what());
        return 2;
    }
}
