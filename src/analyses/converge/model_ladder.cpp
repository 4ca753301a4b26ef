#include "analyses/converge/model_ladder.hpp"

#include "analyses/run/run.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/petsc_handle.hpp"
#include "common/stopwatch.hpp"
#include "models/choose.hpp"
#include "scene/level_traits.hpp"

#include <malloc.h>

#include <algorithm>
#include <ctime>

namespace coremodal {
namespace {

// Processor time of this process in seconds (user + system, all its
// threads), to the nanosecond (a beam run takes about a millisecond:
// getrusage's ticks would be too coarse).
double process_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

// PETSc's cumulative event times (main stage, this rank) of the events that
// make up a solve; their differences over a run give SolverBreakdown. An
// event not registered yet (no matrix factored so far) counts 0.
double event_seconds(std::initializer_list<const char*> names) {
    double total = 0;
    for (const char* name : names) {
        PetscLogEvent id = -1;
        PetscEventPerfInfo info{};
        if (PetscLogEventGetId(name, &id) || id < 0) continue;
        if (PetscLogEventGetPerfInfo(0, id, &info)) continue;
        total += info.time;
    }
    return total;
}

SolverBreakdown solver_event_seconds() {
    return {event_seconds({"MatCholFctrSym", "MatCholFctrNum", "MatLUFactorSym", "MatLUFactorNum"}),
            event_seconds({"MatSolve", "MatMatSolve"}), event_seconds({"BVOrthogonalizeV", "BlockOrthogonal"})};
}

// The peak memory of this run, summed over ranks: since `reset` if
// reset_peak_memory() succeeded, else the process's peak so far.
double summed_peak_memory_mb(bool reset) {
    double peak = reset ? peak_memory_since_reset_mb() : peak_memory_mb();
    double sum = 0;
    MPI_Allreduce(&peak, &sum, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    return sum;
}

// What a level needs from converge's options to build its ladder; the
// meshed levels run their steps through run_scene, quiet, writing nothing.
LadderRequest ladder_request(const Scene& scene, const ConvergeOptions& o, std::ostream& progress) {
    LadderRequest r;
    r.unit = o.unit;
    r.first = o.first;
    r.levels = o.levels;
    r.max_dofs = o.max_dofs;
    r.n_modes = o.n_modes.value_or(scene.analysis.n_modes);
    r.modes_given = o.n_modes || scene.analysis.f_max_hz;
    r.repeats_words = std::to_string(o.repeats) + (o.repeats == 1 ? " run" : " runs") +
                      " per level, one when the first takes over " + formatted("%.0f", o.repeat_limit_s) + " s";
    r.run_scene = [](Scene s) {
        RunOptions options;
        options.quiet = true;
        options.write_results = false;
        return run_scene(std::move(s), options);
    };
    if (mpi_rank() == 0 && !o.quiet) r.progress = &progress;
    return r;
}

// The levels asked for, the converge reference (the solid) first, then in
// the order of the enum (beam, harmonic): the first meshed ladder chooses
// the mode count for all (ladder_runs.hpp).
std::vector<ModelChoice> asked_levels(const ConvergeOptions& o) {
    std::vector<ModelChoice> levels;
    for (const std::string& name : o.models) levels.push_back(*parse_model_choice(name));  // checked by run_converge
    std::sort(levels.begin(), levels.end(), [](ModelChoice a, ModelChoice b) {
        const bool ra = level_traits(a).converge_reference, rb = level_traits(b).converge_reference;
        return ra != rb ? ra : static_cast<int>(a) < static_cast<int>(b);
    });
    levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
    return levels;
}

// "converge: NAME (FILE), model levels: solid (4 levels, ...), beam (...)".
void announce(const Scene& scene, const ConvergeOptions& o, const std::vector<ModelLadder>& ladders,
              std::ostream& progress) {
    progress << "converge: " << scene.name << " (" << o.case_file << "), model levels:";
    for (std::size_t i = 0; i < ladders.size(); ++i) progress << (i ? ", " : " ") << ladders[i].plan;
    progress << std::endl;
}

}  // namespace

std::vector<ModelLadder> model_ladders(const Scene& scene, const ConvergeOptions& o, std::ostream& progress,
                                       ConvergeStudy& study) {
    const LadderRequest request = ladder_request(scene, o, progress);
    std::vector<ModelLadder> ladders;
    for (ModelChoice level : asked_levels(o))
        if (auto ladder = make_model_level(level)->converge_ladder(scene, request, study.notes))
            ladders.push_back(std::move(*ladder));
    if (ladders.empty())  // --models beam or harmonic, and that level cannot solve the scene
        throw InputError(o.case_file + ": no model level to run (" + study.notes.back() + ")");
    if (mpi_rank() == 0 && !o.quiet) announce(scene, o, ladders, progress);
    return ladders;
}

LevelRun measured_run(const ModelLadder& ladder, const MeshStep& step, int n_modes) {
    const bool reset = reset_peak_memory();
    const double cpu_start = process_cpu_seconds();
    const SolverBreakdown events_start = solver_event_seconds();
    LevelRun run = ladder.run_once(step, n_modes);
    const SolverBreakdown events_end = solver_event_seconds();
    run.cpu_s = process_cpu_seconds() - cpu_start;
    run.solver_s = {events_end.factor_s - events_start.factor_s, events_end.solve_s - events_start.solve_s,
                    events_end.orthogonalize_s - events_start.orthogonalize_s};
    run.peak_memory_mb = summed_peak_memory_mb(reset);
    malloc_trim(0);
    return run;
}

}  // namespace coremodal
