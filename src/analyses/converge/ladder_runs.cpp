#include "analyses/converge/ladder_runs.hpp"

#include "common/format.hpp"
#include "common/petsc_handle.hpp"
#include "modes/label_tracking.hpp"
#include "scene/mesh_levels.hpp"

#include <algorithm>

namespace coremodal {

std::optional<LevelRun> choose_mode_count(const Scene& scene, const ModelLadder& ladder, const ConvergeOptions& o,
                                          int& n_modes, std::ostream& progress, std::vector<std::string>& notes) {
    if (o.n_modes || scene.analysis.f_max_hz) return std::nullopt;
    const bool root = mpi_rank() == 0;
    for (;;) {
        LevelRun run = measured_run(ladder, ladder.steps.front(), n_modes);
        int found = root ? has_mode_type(run.modes, "ovalling") : 0;
        MPI_Bcast(&found, 1, MPI_INT, 0, PETSC_COMM_WORLD);  // labels live on rank 0
        if (found) return run;
        if (n_modes >= kMaxModesForOvalling) {
            notes.push_back("no ovalling mode among the first " + std::to_string(n_modes) +
                            " modes at the coarsest level: the study tracks the others");
            return run;
        }
        const int more = std::min(2 * n_modes, kMaxModesForOvalling);
        if (root && !o.quiet)
            progress << "  no ovalling mode among the first " << n_modes << " modes at " << ladder.model << " "
                     << ladder.steps.front().label
                     << ": asking for " << more << std::endl;
        n_modes = more;
    }
}

namespace {

// ", f1 61.4990 Hz, first ovalling 1027.6288 Hz": the role modes of a run, for the progress lines.
std::string role_values(const LevelRun& run) {
    std::string s;
    bool f1 = false, oval = false;
    for (const auto& d : distinct_modes(run.modes)) {
        if (!f1 && d.key.type == "bending") s += ", f1 " + formatted("%.4f", d.frequency_hz) + " Hz", f1 = true;
        if (!oval && d.key.type == "ovalling") s += ", first ovalling " + formatted("%.4f", d.frequency_hz) + " Hz", oval = true;
    }
    return s;
}

// Whether rank 0 says so; every rank gets its answer, so that all run alike.
bool rank0_decides(bool yes) {
    int stop = yes;
    MPI_Bcast(&stop, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    return stop != 0;
}

}  // namespace

LevelResult run_level(const ModelLadder& ladder, std::size_t i, std::optional<LevelRun> first_run,
                      const ConvergeOptions& o, std::ostream& progress) {
    const bool say = mpi_rank() == 0 && !o.quiet;
    const MeshStep& step = ladder.steps[i];
    if (say)
        progress << "  " << ladder.model << " [" << i + 1 << "/" << ladder.steps.size() << "] " << step.label << ":"
                 << std::flush;
    std::vector<LevelRun> runs;
    if (first_run) runs.push_back(std::move(*first_run));
    auto show = [&] {
        if (!say) return;
        if (runs.size() == 1) progress << " " << runs[0].n_dofs << " DOFs,";
        progress << " " << progress_seconds(runs.back().timing_s.total, "%.1f") << " s" << std::flush;
    };
    if (!runs.empty()) show();
    // A slow level is timed once: its run-to-run noise is small against its
    // time, and the study must fit in minutes (bench/results/log.md).
    auto slow = [&] { return rank0_decides(runs.front().timing_s.total > o.repeat_limit_s); };
    // A ladder with a time budget per level (the beam) stops repeating when
    // its runs have used it.
    auto spent = [&] {
        double total = 0;
        for (const auto& r : runs) total += r.timing_s.total;
        return rank0_decides(ladder.level_budget_s > 0 && total >= ladder.level_budget_s);
    };
    const int repeats = ladder.runs_per_level > 0 ? ladder.runs_per_level : o.repeats;
    while (static_cast<int>(runs.size()) < repeats && (runs.empty() || (!slow() && !spent()))) {
        runs.push_back(measured_run(ladder, step, ladder.n_modes));
        if (repeats <= 10 || runs.size() == 1) show();
    }
    if (repeats > 10 && say) progress << " ... " << runs.size() << " runs," << std::flush;
    LevelResult result = summarize_runs(step, runs);
    if (say)
        progress << " -> median " << progress_seconds(result.median_s.total, "%.2f") << " s, "
                 << formatted("%.0f", result.peak_memory_mb) << " MiB" << role_values(runs.front())
                 << (result.complete ? "" : "  [INCOMPLETE: modes missing]") << std::endl;
    return result;
}

NamedLevelCheck run_named_level(const Scene& scene, const std::string& name, const ModelLadder& reference,
                                const ConvergeOptions& o, std::ostream& progress) {
    Scene s = scene;
    s.mesh.along_per_segment.clear();
    apply_mesh_level(s, name);
    NamedLevelCheck check;
    check.name = name;
    check.mesh = mesh_counts_text(s.mesh, s.rest_paper.has_value());
    const bool say = mpi_rank() == 0 && !o.quiet;
    if (say) progress << "  named level " << name << " " << check.mesh << ":" << std::flush;
    MeshStep step;
    step.mesh = s.mesh;
    step.counts = check.mesh;
    step.label = name + " " + check.mesh;
    const LevelRun run = measured_run(reference, step, reference.n_modes);
    check.result = summarize_runs(step, {run});
    if (say)
        progress << " " << run.n_dofs << " DOFs, " << formatted("%.1f", run.timing_s.total) << " s" << role_values(run)
                 << std::endl;
    return check;
}

std::string progress_seconds(double s, const char* format) {
    return s > 0 && s < 0.1 ? formatted("%.2g", s) : formatted(format, s);
}

}  // namespace coremodal
