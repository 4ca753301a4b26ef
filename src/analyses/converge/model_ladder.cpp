#include "analyses/converge/model_ladder.hpp"

#include "models/beam/beam_level.hpp"
#include "analyses/run/run.hpp"
#include "models/choose.hpp"
#include "beam/beam_model.hpp"
#include "common/format.hpp"
#include "common/petsc_handle.hpp"
#include "common/stopwatch.hpp"
#include "modes/label_tracking.hpp"

#include <malloc.h>

#include <algorithm>
#include <ctime>
#include <stdexcept>

namespace coremodal {
namespace {

// ---- measuring a run --------------------------------------------------------

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

// ---- running one level once ---------------------------------------------------

// One run of a meshed model level (solid or harmonic) on one mesh of its
// ladder. Freed memory is handed back to the system afterwards so that a
// level does not inherit the previous level's heap. For the harmonic level
// (the same r-z section as the solid's level; n_around only sets the
// revolved mesh the modes are shown and named on) n_dofs is the largest
// one-harmonic problem's, and the timings sum over the harmonics.
LevelRun run_meshed_once(const Scene& scene, ModelChoice model, const MeshSpec& mesh, int n_modes) {
    Scene s = scene;
    s.model = model;  // the case may name another level for its runs; this ladder is `model`'s
    s.mesh = mesh;
    s.analysis.n_modes = n_modes;
    RunOptions options;
    options.quiet = true;
    options.write_results = false;
    const bool reset = reset_peak_memory();
    const double cpu_start = process_cpu_seconds();
    const SolverBreakdown events_start = solver_event_seconds();
    RunReport report = run_scene(std::move(s), options);
    const SolverBreakdown events_end = solver_event_seconds();
    LevelRun run;
    run.n_dofs = report.model.n_dofs;
    run.timing_s = report.timing_s;
    run.cpu_s = process_cpu_seconds() - cpu_start;
    run.solver_s = {events_end.factor_s - events_start.factor_s, events_end.solve_s - events_start.solve_s,
                    events_end.orthogonalize_s - events_start.orthogonalize_s};
    run.peak_memory_mb = summed_peak_memory_mb(reset);
    run.complete = report.modes.verification.complete;
    run.modes = std::move(report.modes.modes);
    for (Mode& m : run.modes) std::vector<double>().swap(m.shape);
    malloc_trim(0);
    return run;
}

// One run of the beam model at refinement k of the unit. Every rank solves
// the same small problem (serial Eigen, no PETSc). Timing: `mesh` is building
// the network, `factor_and_solve` assembly, eigensolve and inertia count (the
// beam assembles problem by problem inside its solve: `assemble` stays 0),
// `classify` the labels, `total` the whole call.
LevelRun run_beam_once(const Scene& scene, const MeshStep& step, int unit_elements, int n_modes) {
    Scene s = scene;
    s.analysis.n_modes = n_modes;
    BeamModelOptions options;
    options.core_elements = unit_elements;
    options.refine = step.k;
    const bool reset = reset_peak_memory();
    const double cpu_start = process_cpu_seconds();
    Stopwatch clock;
    const BeamModelResult beam = solve_beam_model(s, options);
    LevelRun run;
    run.timing_s.total = clock.seconds();
    run.cpu_s = process_cpu_seconds() - cpu_start;
    run.timing_s.mesh = beam.timing_s.build;
    run.timing_s.factor_and_solve = beam.timing_s.solve;
    run.timing_s.classify = beam.timing_s.classify;
    run.n_dofs = beam.n_dofs;
    run.peak_memory_mb = summed_peak_memory_mb(reset);
    run.complete = beam.verification.complete;
    for (std::size_t i = 0; i < beam.modes.size(); ++i) run.modes.push_back(report_mode(beam.modes[i], int(i) + 1));
    return run;
}

// ---- the ladders ----------------------------------------------------------------

// The unit of the solid ladder (and of the harmonic ladder, which shares its
// levels): --unit as given, or the default unit fitted to --max-dofs at the
// solid's --levels. `budget_note` says what the bound changed.
UnitMesh solid_unit(const Scene& scene, const ConvergeOptions& o, std::string& budget_note) {
    budget_note.clear();
    if (o.unit) return parse_unit(*o.unit, "--unit");  // the user's unit is taken as given
    return fit_unit_to_budget(scene, default_unit(scene), o.first, o.levels, o.max_dofs, budget_note);
}

// "1/1/8/21 (...; along per axial segment 2+2+13+2+2)": the unit of a ladder as its steps multiply it.
std::string unit_text(const Scene& scene, const UnitMesh& unit, const MeshStep& first) {
    std::string segments;
    for (int n : first.mesh.along_per_segment) {
        if (!segments.empty()) segments += "+";
        segments += std::to_string(n / first.k);
    }
    const std::string paper = scene.rest_paper ? std::to_string(unit.n_rest_paper) : std::string("-");
    return std::to_string(unit.n_wall) + "/" + paper + "/" + std::to_string(unit.n_around) + "/" +
           std::to_string(first.mesh.n_along / first.k) + " (through the wall / through the rest paper / around / "
           "along; along per axial segment " + segments + ")";
}

// The modes asked per beam run: --modes or the case's as given (or a band);
// otherwise doubled on the coarsest level until it shows the first torsion
// and axial modes, up to kMaxModesForOvalling. Either way the coarsest level
// is run once, so that a scene the beam cannot solve throws here.
int beam_mode_count(const Scene& scene, const ModelLadder& ladder, const ConvergeOptions& o, std::ostream& progress) {
    int n_modes = ladder.n_modes;
    const MeshStep& coarsest = ladder.steps.front();
    if (o.n_modes || scene.analysis.f_max_hz) {
        run_beam_once(scene, coarsest, kBeamUnitElements, n_modes);  // can it solve the scene?
        return n_modes;
    }
    for (;;) {
        const LevelRun run = run_beam_once(scene, coarsest, kBeamUnitElements, n_modes);
        if ((has_mode_type(run.modes, "torsion") && has_mode_type(run.modes, "axial")) ||
            n_modes >= kMaxModesForOvalling)
            return n_modes;
        const int more = std::min(2 * n_modes, kMaxModesForOvalling);
        if (mpi_rank() == 0 && !o.quiet)
            progress << "  beam: no torsion or no axial mode among the first " << n_modes << " modes at "
                     << coarsest.label << ": asking for " << more << std::endl;
        n_modes = more;
    }
}

std::string beam_ladder_note(const Scene& scene) {
    std::string shafts;
    if (scene.supports.kind == SupportKind::chucks) shafts = ", every chuck shaft";
    return "Ladder: level k has k times the elements of the unit beam mesh (" + std::to_string(kBeamUnitElements) +
           " three-node Timoshenko elements along the core, at least two per gap between support edges) in every "
           "such gap" + shafts + ", so h = 1/k exactly (k = 1, 2, 4, ..., ratio 2 between levels). Elements: the "
           "core's / the whole network's. Each level runs " + std::to_string(kBeamRunsPerLevel) +
           " times (about a millisecond each), or as often as fits in " + formatted("%g", kBeamLevelBudget) +
           " s: times are medians. Network = building the beam network; assemble+solve = assembly, eigensolve and "
           "inertia count; labels = labels and effective masses.";
}

}  // namespace

LevelRun run_solid_once(const Scene& scene, const MeshSpec& mesh, int n_modes) {
    return run_meshed_once(scene, ModelChoice::solid, mesh, n_modes);
}

ModelLadder solid_ladder(const Scene& scene, const ConvergeOptions& o, const int& n_modes) {
    std::string budget_note;
    const UnitMesh unit = solid_unit(scene, o, budget_note);
    ModelLadder ladder;
    ladder.model = ModelChoice::solid;
    ladder.steps = refinement_ladder(scene, unit, o.first, o.levels);
    const long finest = estimate_dofs(scene, ladder.steps.back().mesh);
    if (o.unit && o.max_dofs > 0 && finest > o.max_dofs)
        budget_note = "the finest level (estimated " + std::to_string(finest) + " DOFs) exceeds --max-dofs " +
                      std::to_string(o.max_dofs) + "; --unit was taken as given";
    ladder.note = "Ladder: level k has k times the elements of the unit mesh " +
                  unit_text(scene, unit, ladder.steps.front()) + " in every direction and in every axial segment, so h = 1/k "
                  "exactly (ratios (k+1)/k between levels; graded segments keep their size ratio). Hexahedra " +
                  scene.mesh.element + (budget_note.empty() ? "." : "; " + budget_note + ".");
    ladder.run_once = [&scene, &n_modes](const MeshStep& step) { return run_solid_once(scene, step.mesh, n_modes); };
    return ladder;
}

std::optional<ModelLadder> harmonic_ladder(const Scene& scene, const ConvergeOptions& o, const int& n_modes,
                                           std::ostream& progress, std::vector<std::string>& notes) {
    if (const auto why = why_not_axisymmetric(scene)) {
        const std::string note = "harmonic model level skipped: " + *why;
        notes.push_back(note);
        if (mpi_rank() == 0 && !o.quiet) progress << "  " << note << std::endl;
        return std::nullopt;
    }
    std::string budget_note;
    const UnitMesh unit = solid_unit(scene, o, budget_note);
    ModelLadder ladder;
    ladder.model = ModelChoice::harmonic;
    ladder.refined_dimensions = 2;
    ladder.steps = refinement_ladder(scene, unit, o.first, o.levels + kHarmonicExtraLevels);
    ladder.note = "Ladder (r–z section only; exact in theta): level k meshes the r–z section of the solid's level k "
                  "(unit " + unit_text(scene, unit, ladder.steps.front()) + ", h = 1/k) in quad8 cells and solves one "
                  "eigenproblem per circumferential wave number n, so it has no circumferential discretization; it "
                  "runs the solid's levels and " + std::to_string(kHarmonicExtraLevels) + " finer ones (k up to " +
                  std::to_string(ladder.steps.back().k) + "), not bound by --max-dofs. Around only sets the revolved "
                  "mesh the modes are named on. DOFs: the largest one-harmonic problem; assemble and factor+solve "
                  "sum over the harmonics (with their inertia counts)" +
                  (budget_note.empty() ? "." : "; the unit is the solid's: " + budget_note + ".");
    ladder.run_once = [&scene, &n_modes](const MeshStep& step) {
        return run_meshed_once(scene, ModelChoice::harmonic, step.mesh, n_modes);
    };
    return ladder;
}

std::optional<ModelLadder> beam_ladder(const Scene& scene, const ConvergeOptions& o, std::ostream& progress,
                                       std::vector<std::string>& notes) {
    ModelLadder ladder;
    ladder.model = ModelChoice::beam;
    ladder.runs_per_level = kBeamRunsPerLevel;
    ladder.level_budget_s = kBeamLevelBudget;
    ladder.refined_dimensions = 1;
    ladder.unseen_roles = {{"ovalling", "a beam's cross-sections are rigid: no ovalling, n >= 2"},
                           {"breathing", "a beam's cross-sections are rigid: no breathing, n = 0 radial"}};
    ladder.n_modes = o.n_modes.value_or(scene.analysis.n_modes);
    try {
        ladder.steps = beam_refinement_ladder(scene, kBeamUnitElements, kBeamLevels);
        ladder.n_modes = beam_mode_count(scene, ladder, o, progress);
    } catch (const std::runtime_error& e) {  // InputError, SolveError: the beam cannot solve this scene
        notes.push_back("beam model level skipped: " + std::string(e.what()));
        if (mpi_rank() == 0 && !o.quiet) progress << "  beam model level skipped: " << e.what() << std::endl;
        return std::nullopt;
    }
    ladder.note = beam_ladder_note(scene);
    ladder.run_once = [&scene, modes = ladder.n_modes](const MeshStep& step) {
        return run_beam_once(scene, step, kBeamUnitElements, modes);
    };
    return ladder;
}

}  // namespace coremodal
