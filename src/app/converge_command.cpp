// `coremodal converge CASE.toml`: what accuracy costs in time. Runs a
// refinement ladder for every model level the scene allows, times each level
// (median of repeated runs), tracks the modes across levels by label,
// extrapolates their frequencies (Richardson, observed order) and writes
// converge.csv, converge.json, converge.md and error_vs_time.png.
#include "app/commands.hpp"
#include "common/format.hpp"
#include "app/converge.hpp"
#include "app/run_beam.hpp"
#include "app/run_case.hpp"
#include "app/run_harmonic.hpp"
#include "beam/beam_model.hpp"
#include "common/error.hpp"
#include "common/petsc_handle.hpp"
#include "common/stopwatch.hpp"
#include "output/python_plots.hpp"
#include "output/results_folder.hpp"
#include "output/text_file.hpp"
#include "scene/case_file.hpp"
#include "scene/mesh_levels.hpp"

#include <malloc.h>
#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <thread>

namespace coremodal {
namespace {


// ---- 1. model levels and their ladders ---------------------------------------

// Processor time of this process so far (user + system, all its threads).
double cpu_seconds() {
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    auto s = [](const timeval& t) { return double(t.tv_sec) + 1e-6 * double(t.tv_usec); };
    return s(usage.ru_utime) + s(usage.ru_stime);
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
            event_seconds({"MatSolve"}), event_seconds({"BVOrthogonalizeV"})};
}

// The 1-minute load average (0 when unknown).
double load_average() {
    double load[1] = {0};
    return getloadavg(load, 1) == 1 ? load[0] : 0.0;
}

// One run of a meshed model level ("solid" or "harmonic") on one mesh of its
// ladder. The peak memory is the process's peak during this run (summed over
// ranks); freed memory is handed back to the system afterwards so that a
// level does not inherit the previous level's heap.
LevelRun run_meshed_once(const Scene& scene, const std::string& model, const MeshSpec& mesh, int n_modes) {
    Scene s = scene;
    s.model = model;  // the case may name another level for its runs; this ladder is `model`'s
    s.mesh = mesh;
    s.analysis.n_modes = n_modes;
    RunOptions options;
    options.quiet = true;
    options.write_results = false;
    const bool reset = reset_peak_memory();
    const double cpu_start = cpu_seconds();
    const SolverBreakdown events_start = solver_event_seconds();
    RunReport report = run_scene(std::move(s), options);
    const SolverBreakdown events_end = solver_event_seconds();
    LevelRun run;
    run.n_dofs = report.model.n_dofs;
    run.timing_s = report.timing_s;
    run.cpu_s = cpu_seconds() - cpu_start;
    run.solver_s = {events_end.factor_s - events_start.factor_s, events_end.solve_s - events_start.solve_s,
                    events_end.orthogonalize_s - events_start.orthogonalize_s};
    double peak = reset ? peak_memory_since_reset_mb() : peak_memory_mb();
    MPI_Allreduce(&peak, &run.peak_memory_mb, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    run.complete = report.modes.verification.complete;
    run.modes = std::move(report.modes.modes);
    for (Mode& m : run.modes) std::vector<double>().swap(m.shape);
    malloc_trim(0);
    return run;
}

LevelRun run_solid_once(const Scene& scene, const MeshSpec& mesh, int n_modes) {
    return run_meshed_once(scene, "solid", mesh, n_modes);
}

// The harmonic level on the same MeshSpec: the same r-z section as the solid
// of that level (n_around only sets the revolved mesh the modes are shown and
// named on). n_dofs is the largest one-harmonic problem's; the timings sum
// over the harmonics (assemble: all assemblies; factor_and_solve: every
// eigensolve and inertia count).
LevelRun run_harmonic_once(const Scene& scene, const MeshSpec& mesh, int n_modes) {
    return run_meshed_once(scene, "harmonic", mesh, n_modes);
}

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
    for (int n : first.mesh.along_per_segment) segments += (segments.empty() ? "" : "+") + std::to_string(n / first.k);
    const std::string paper = scene.rest_paper ? std::to_string(unit.n_rest_paper) : std::string("-");
    return std::to_string(unit.n_wall) + "/" + paper + "/" + std::to_string(unit.n_around) + "/" +
           std::to_string(first.mesh.n_along / first.k) + " (through the wall / through the rest paper / around / "
           "along; along per axial segment " + segments + ")";
}

ModelLadder solid_ladder(const Scene& scene, const ConvergeOptions& o, const int& n_modes) {
    std::string budget_note;
    const UnitMesh unit = solid_unit(scene, o, budget_note);
    ModelLadder ladder;
    ladder.model = "solid";
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

// The harmonic model level: the solid's unit and levels k = first ... plus
// kHarmonicExtraLevels finer ones (a harmonic run costs ~1 % of the solid's
// on the same section), not bound by --max-dofs (its DOFs are those of one 2D
// problem). Level k meshes exactly the r-z section of the solid's level k.
// A scene that is not axisymmetric is skipped with the reason in the notes,
// as the beam skips what it cannot solve.
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
    ladder.model = "harmonic";
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
    ladder.run_once = [&scene, &n_modes](const MeshStep& step) { return run_harmonic_once(scene, step.mesh, n_modes); };
    return ladder;
}

// Processor time of this process in seconds, to the nanosecond (a beam run
// takes about a millisecond: getrusage's ticks would be too coarse).
double process_cpu_seconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
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
    double peak = reset ? peak_memory_since_reset_mb() : peak_memory_mb();
    MPI_Allreduce(&peak, &run.peak_memory_mb, 1, MPI_DOUBLE, MPI_SUM, PETSC_COMM_WORLD);
    run.complete = beam.verification.complete;
    for (std::size_t i = 0; i < beam.modes.size(); ++i) run.modes.push_back(report_mode(beam.modes[i], int(i) + 1));
    return run;
}

bool has_type(const std::vector<Mode>& modes, const std::string& type) {
    for (const auto& d : distinct_modes(modes))
        if (d.key.type == type) return true;
    return false;
}

// The beam model level: kBeamLevels levels of the unit beam mesh (h = 1/k,
// k = 1, 2, 4, ...), each run kBeamRunsPerLevel times. The modes asked per
// run start from --modes or the case's and double (up to
// kMaxModesForOvalling) until the coarsest level shows the first torsion and
// axial modes, as the solid's do for ovalling. A scene the beam model cannot
// solve is skipped with its reason in the notes, not an error.
std::optional<ModelLadder> beam_ladder(const Scene& scene, const ConvergeOptions& o, std::ostream& progress,
                                       std::vector<std::string>& notes) {
    ModelLadder ladder;
    ladder.model = "beam";
    ladder.runs_per_level = kBeamRunsPerLevel;
    ladder.level_budget_s = kBeamLevelBudget;
    ladder.refined_dimensions = 1;
    ladder.unseen_roles = {{"ovalling", "a beam's cross-sections are rigid: no ovalling, n >= 2"},
                           {"breathing", "a beam's cross-sections are rigid: no breathing, n = 0 radial"}};
    ladder.n_modes = o.n_modes.value_or(scene.analysis.n_modes);
    const bool say = mpi_rank() == 0 && !o.quiet;
    try {
        ladder.steps = beam_refinement_ladder(scene, kBeamUnitElements, kBeamLevels);
        if (!o.n_modes && !scene.analysis.f_max_hz)
            for (;;) {
                const LevelRun run = run_beam_once(scene, ladder.steps.front(), kBeamUnitElements, ladder.n_modes);
                if ((has_type(run.modes, "torsion") && has_type(run.modes, "axial")) ||
                    ladder.n_modes >= kMaxModesForOvalling)
                    break;
                const int more = std::min(2 * ladder.n_modes, kMaxModesForOvalling);
                if (say)
                    progress << "  beam: no torsion or no axial mode among the first " << ladder.n_modes
                             << " modes at " << ladder.steps.front().label << ": asking for " << more << std::endl;
                ladder.n_modes = more;
            }
        else
            run_beam_once(scene, ladder.steps.front(), kBeamUnitElements, ladder.n_modes);  // can it solve the scene?
    } catch (const std::runtime_error& e) {  // InputError, SolveError: the beam cannot solve this scene
        notes.push_back("beam model level skipped: " + std::string(e.what()));
        if (say) progress << "  beam model level skipped: " << e.what() << std::endl;
        return std::nullopt;
    }
    std::string shafts;
    if (scene.supports.kind == SupportKind::chucks) shafts = ", every chuck shaft";
    ladder.note = "Ladder: level k has k times the elements of the unit beam mesh (" +
                  std::to_string(kBeamUnitElements) + " three-node Timoshenko elements along the core, at least " +
                  "two per gap between support edges) in every such gap" + shafts + ", so h = 1/k exactly (k = 1, 2, 4, "
                  "..., ratio 2 between levels). Elements: the core's / the whole network's. Each level runs " +
                  std::to_string(kBeamRunsPerLevel) + " times (about a millisecond each), or as often as fits in " +
                  formatted("%g", kBeamLevelBudget) + " s: times are medians. Network = "
                  "building the beam network; assemble+solve = assembly, eigensolve and inertia count; labels = "
                  "labels and effective masses.";
    ladder.run_once = [&scene, modes = ladder.n_modes](const MeshStep& step) {
        return run_beam_once(scene, step, kBeamUnitElements, modes);
    };
    return ladder;
}

// ---- 2. the number of modes -------------------------------------------------

bool has_ovalling(const std::vector<Mode>& modes) {
    for (const auto& d : distinct_modes(modes))
        if (d.key.type == "ovalling") return true;
    return false;
}

// The study reports on the first ovalling mode, which beam theory cannot see;
// it often lies above the case's own request (case 03: mode 17). Doubles
// n_modes on the coarsest level (cheap) until an ovalling mode shows, up to
// kMaxModesForOvalling. Returns the last coarsest run, which counts as that
// level's first run; nothing when the count is given (--modes, a band).
std::optional<LevelRun> choose_mode_count(const Scene& scene, const ModelLadder& ladder, const ConvergeOptions& o,
                                          int& n_modes, std::ostream& progress, std::vector<std::string>& notes) {
    if (o.n_modes || scene.analysis.f_max_hz) return std::nullopt;
    const bool root = mpi_rank() == 0;
    for (;;) {
        LevelRun run = ladder.run_once(ladder.steps.front());
        int found = root ? has_ovalling(run.modes) : 0;
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

// ---- 3. running a ladder ------------------------------------------------------

// Seconds in the progress lines; a beam run (~1e-3 s) gets two significant digits.
std::string progress_seconds(double s, const char* format) {
    return s > 0 && s < 0.1 ? formatted("%.2g", s) : formatted(format, s);
}

std::string role_values(const LevelRun& run) {
    std::string s;
    bool f1 = false, oval = false;
    for (const auto& d : distinct_modes(run.modes)) {
        if (!f1 && d.key.type == "bending") s += ", f1 " + formatted("%.4f", d.frequency_hz) + " Hz", f1 = true;
        if (!oval && d.key.type == "ovalling") s += ", first ovalling " + formatted("%.4f", d.frequency_hz) + " Hz", oval = true;
    }
    return s;
}

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
    // time, and the study must fit in minutes (docs/performance.md). The
    // decision is rank 0's, so that every rank runs alike.
    auto slow = [&] {
        int stop = runs.front().timing_s.total > o.repeat_limit_s;
        MPI_Bcast(&stop, 1, MPI_INT, 0, PETSC_COMM_WORLD);
        return stop != 0;
    };
    // A ladder with a time budget per level (the beam) stops repeating when
    // its runs have used it; again rank 0 decides.
    auto spent = [&] {
        double total = 0;
        for (const auto& r : runs) total += r.timing_s.total;
        int stop = ladder.level_budget_s > 0 && total >= ladder.level_budget_s;
        MPI_Bcast(&stop, 1, MPI_INT, 0, PETSC_COMM_WORLD);
        return stop != 0;
    };
    const int repeats = ladder.runs_per_level > 0 ? ladder.runs_per_level : o.repeats;
    while (static_cast<int>(runs.size()) < repeats && (runs.empty() || (!slow() && !spent()))) {
        runs.push_back(ladder.run_once(step));
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

NamedLevelCheck run_named_level(const Scene& scene, const std::string& name, int n_modes, const ConvergeOptions& o,
                                std::ostream& progress) {
    Scene s = scene;
    s.mesh.along_per_segment.clear();
    apply_mesh_level(s, name);
    NamedLevelCheck check;
    check.name = name;
    check.mesh = std::to_string(s.mesh.n_wall) + "/" +
                 (s.rest_paper ? std::to_string(s.mesh.n_rest_paper) : std::string("-")) + "/" +
                 std::to_string(s.mesh.n_around) + "/" + std::to_string(s.mesh.n_along);
    const bool say = mpi_rank() == 0 && !o.quiet;
    if (say) progress << "  named level " << name << " " << check.mesh << ":" << std::flush;
    MeshStep step;
    step.mesh = s.mesh;
    step.counts = check.mesh;
    step.label = name + " " + check.mesh;
    const LevelRun run = run_solid_once(scene, s.mesh, n_modes);
    check.result = summarize_runs(step, {run});
    if (say)
        progress << " " << run.n_dofs << " DOFs, " << formatted("%.1f", run.timing_s.total) << " s" << role_values(run)
                 << std::endl;
    return check;
}

// ---- 4. the results folder, with its picture ----------------------------------

void write_study(const ConvergeStudy& study, const std::filesystem::path& out, bool force, bool quiet,
                 std::ostream& progress) {
    ResultsFolder folder(out, force);
    write_text_file(folder.file("converge.csv"), converge_csv(study));
    write_text_file(folder.file("converge.json"), converge_json(study));
    const std::string plot_note =
        run_python_plot("converge-plot", std::filesystem::path(folder.file("converge.json")).parent_path(), {"--quiet"});
    if (!plot_note.empty()) std::cerr << "coremodal: warning: no error_vs_time.png: " << plot_note << std::endl;
    write_text_file(folder.file("converge.md"), converge_markdown(study, plot_note));
    folder.commit();
    if (!quiet) progress << "results: " << out.string() << " (converge.md, converge.csv, converge.json"
                         << (plot_note.empty() ? ", error_vs_time.png" : "") << ")" << std::endl;
}

void print_summary(const ConvergeStudy& study, std::ostream& out) {
    for (const auto& m : study.models) {
        out << "\n" << m.model << ": extrapolated frequencies (three finest levels)\n";
        for (const auto& t : m.modes) {
            if (t.role.empty() || !t.richardson) continue;
            const Richardson& r = *t.richardson;
            char line[256];
            std::snprintf(line, sizeof line, "  %-10s %-24s f0 %12.4f Hz  error of finest %9.2e  order %s  %s\n",
                          t.role.c_str(), t.key.text().c_str(), r.f0, r.error_estimate / std::abs(r.f0),
                          r.extrapolated ? formatted("%.2f", r.order).c_str() : "-",
                          r.asymptotic ? "asymptotic" : "NOT asymptotic");
            out << line;
        }
        for (const std::string role : {"f1", "ovalling"})
            for (const auto& t : m.modes) {
                if (t.role != role) continue;
                out << "  " << role << " within";
                for (double target : kAccuracyTargets) {
                    const auto i = first_level_within(t, target);
                    out << "  " << formatted("%g", target * 100) << " %: ";
                    if (i) {
                        out << m.levels[*i].step.label << " (" << progress_seconds(m.levels[*i].median_s.total, "%.1f")
                            << " s)";
                    } else if (const auto p = predict_level_for(m, t, target)) {
                        out << "not in the ladder (k ~ " << formatted("%.1f", p->k) << ", ~" << formatted("%.2g", p->n_dofs)
                            << " DOFs" << (p->time_s ? ", ~" + formatted("%.2g", *p->time_s) + " s" : std::string()) << ")";
                    } else {
                        out << "not in the ladder";
                    }
                }
                out << "\n";
            }
    }
    const std::vector<ModelError> errors = model_errors(study.models);
    for (const ModelError& e : errors)
        out << "\nmodel error, " << e.model << " " << e.role << ": " << e.model << " converges to "
            << formatted("%.4f", e.f0_hz) << " Hz, the solid to " << formatted("%.4f", e.solid_f0_hz) << " Hz: "
            << formatted("%+.3g", 100 * e.relative) << " %";
    if (!errors.empty()) out << "\n";
    out << "\nladders " << formatted("%.1f", study.ladder_time_s) << " s, whole study " << formatted("%.1f", study.total_time_s)
        << " s" << std::endl;
}

bool wants_model(const ConvergeOptions& o, const std::string& model) {
    return std::find(o.models.begin(), o.models.end(), model) != o.models.end();
}

}  // namespace

// ---- 5. the study, in order ------------------------------------------------------

ConvergeStudy run_converge(const ConvergeOptions& o, std::ostream& progress) {
    Stopwatch clock;
    const bool root = mpi_rank() == 0;
    if (o.repeats < 1) throw InputError("--repeats " + std::to_string(o.repeats) + ": expected at least 1");
    if (o.n_modes && *o.n_modes < 1) throw InputError("--modes " + std::to_string(*o.n_modes) + ": expected at least 1");
    for (const auto& name : o.check_levels)
        if (!find_mesh_level(name))
            throw InputError("--check-levels " + name + ": unknown mesh level; expected coarse, default, fine or very_fine");
    const std::string valid = "expected solid, harmonic, beam (comma-separated, any of them)";
    if (o.models.empty()) throw InputError("--models: no model level; " + valid);
    for (const auto& name : o.models)
        if (name != "solid" && name != "beam" && name != "harmonic")
            throw InputError("--models " + name + ": unknown model level; " + valid);
    if (!o.check_levels.empty() && !wants_model(o, "solid"))
        throw InputError("--check-levels: named mesh levels are solid meshes; add solid to --models");

    // PETSc's event log (cheap) splits the solver time into factorizations,
    // triangular solves and orthogonalization; -log_view may have started it.
    PetscBool logging = PETSC_FALSE;
    PetscLogIsActive(&logging);
    if (!logging) PetscLogDefaultBegin();

    // 1. The scene and its model levels; the results folder checked before any work.
    const Scene scene = parse_case_file(o.case_file);
    const std::filesystem::path out = o.output_dir ? std::filesystem::path(*o.output_dir)
                                                   : std::filesystem::path("results") / (scene.name + "-converge");
    if (o.write_results) prepare_output(out, o.force);
    ConvergeStudy study;
    study.load_start = load_average();
    study.n_cores = static_cast<int>(std::thread::hardware_concurrency());
    study.case_name = scene.name;
    study.source_file = o.case_file;
    study.repeats = o.repeats;
    study.repeat_limit_s = o.repeat_limit_s;
    int n_modes = o.n_modes.value_or(scene.analysis.n_modes);
    const bool want_solid = wants_model(o, "solid"), want_beam = wants_model(o, "beam"),
               want_harmonic = wants_model(o, "harmonic");
    std::vector<ModelLadder> ladders;
    if (want_solid) ladders.push_back(solid_ladder(scene, o, n_modes));
    if (root && !o.quiet) {
        progress << "converge: " << scene.name << " (" << o.case_file << "), model levels:";
        if (want_solid)
            progress << " solid (" << o.levels << " levels, " << o.repeats << (o.repeats == 1 ? " run" : " runs")
                     << " per level, one when the first takes over " << formatted("%.0f", o.repeat_limit_s) << " s)";
        if (want_beam)
            progress << (want_solid ? "," : "") << " beam (" << kBeamLevels << " levels, " << kBeamRunsPerLevel
                     << " runs per level)";
        if (want_harmonic)
            progress << (want_solid || want_beam ? "," : "") << " harmonic (" << o.levels + kHarmonicExtraLevels
                     << " levels, r-z section only)";
        progress << std::endl;
    }
    if (want_beam)
        if (auto beam = beam_ladder(scene, o, progress, study.notes)) ladders.push_back(std::move(*beam));
    if (want_harmonic)
        if (auto harmonic = harmonic_ladder(scene, o, n_modes, progress, study.notes))
            ladders.push_back(std::move(*harmonic));
    if (ladders.empty())  // --models beam or harmonic, and that level cannot solve the scene
        throw InputError(o.case_file + ": no model level to run (" + study.notes.back() + ")");

    // 2. How many modes each solid and harmonic run asks for (enough to hold
    //    the first ovalling mode), found on the solid's coarsest level, or on
    //    the harmonic's when the solid is not run. That coarsest run counts as
    //    the level's first.
    std::optional<LevelRun> first_run;
    std::string first_run_model;
    for (const auto& ladder : ladders)
        if (ladder.model == "solid" || ladder.model == "harmonic") {
            first_run = choose_mode_count(scene, ladder, o, n_modes, progress, study.notes);
            first_run_model = ladder.model;
            break;
        }
    study.n_modes = n_modes;
    for (auto& ladder : ladders)
        if (ladder.model == "solid" || ladder.model == "harmonic") ladder.n_modes = n_modes;

    // 3. Every level of every ladder, coarse to fine, then the analysis.
    for (auto& ladder : ladders) {
        std::vector<LevelResult> levels;
        for (std::size_t i = 0; i < ladder.steps.size(); ++i) {
            std::optional<LevelRun> reuse;
            if (i == 0 && ladder.model == first_run_model) reuse = std::move(first_run);
            levels.push_back(run_level(ladder, i, std::move(reuse), o, progress));
        }
        ModelStudy model = analyse_levels(ladder.model, ladder.note, std::move(levels));
        model.n_modes = ladder.n_modes;
        model.refined_dimensions = ladder.refined_dimensions;
        model.unseen_roles = ladder.unseen_roles;
        study.models.push_back(std::move(model));
    }

    study.ladder_time_s = clock.seconds();

    // 4. Named mesh levels, for choosing the default.
    for (const auto& name : o.check_levels) study.checks.push_back(run_named_level(scene, name, n_modes, o, progress));

    for (const auto& m : study.models)
        for (const auto& l : m.levels) {
            if (!l.complete)
                study.notes.push_back(m.model + " " + l.step.label + ": the inertia count found modes missing");
            if (l.max_repeat_spread > 1e-8)
                study.notes.push_back(m.model + " " + l.step.label + ": repeated runs differ by " +
                                      formatted("%.1e", l.max_repeat_spread) + " in frequency");
        }
    study.total_time_s = clock.seconds();
    study.load_end = load_average();

    // 5. Write (rank 0): numbers first, then the picture, then the report.
    if (root && o.write_results) write_study(study, out, o.force, o.quiet, progress);
    if (root && !o.quiet) print_summary(study, progress);
    return study;
}

Command add_converge_command(CLI::App& app) {
    auto options = std::make_shared<ConvergeOptions>();
    auto output = std::make_shared<std::string>();
    auto unit = std::make_shared<std::string>();
    auto n_modes = std::make_shared<int>(0);
    CLI::App* cmd = app.add_subcommand(
        "converge",
        "What accuracy costs in time: a mesh refinement ladder per model level, timed (median of repeated runs), "
        "modes tracked by label, Richardson-extrapolated frequencies with error estimates, error-vs-time plot");
    cmd->add_option("case", options->case_file, "case file (TOML) with a generated mesh")->required();
    cmd->add_option("-o,--output", *output,
                    "results folder (default results/<case name>-converge): converge.md, converge.csv, "
                    "converge.json, error_vs_time.png; replaces only an earlier coremodal result, which is kept as "
                    "<folder>.previous (docs/results.md)");
    cmd->add_flag("--force", options->force,
                  "remove the earlier result at --output instead of keeping it as .previous");
    cmd->add_option("--levels", options->levels, "levels of the ladder, k = first ... first + levels - 1 (at least 3)")
        ->capture_default_str()
        ->check(CLI::Range(3, 12));
    cmd->add_option("--first", options->first, "multiple k of the coarsest level")->capture_default_str()->check(
        CLI::Range(1, 64));
    cmd->add_option("--unit", *unit,
                    "element counts of the k = 1 mesh, WALL/PAPER/AROUND/ALONG (default: 1/1/8 and along keeping the "
                    "case's element aspect)");
    cmd->add_option("--repeats", options->repeats, "runs per level; the median time is reported")
        ->capture_default_str()
        ->check(CLI::Range(1, 100));
    cmd->add_option("--repeat-limit", options->repeat_limit_s, "seconds: a level whose first run is slower runs once")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--max-dofs", options->max_dofs,
                    "bound on the finest level's DOFs: the default unit's elements along are lowered to stay "
                    "within it (0: no bound; an explicit --unit is taken as given)")
        ->capture_default_str()
        ->check(CLI::NonNegativeNumber);
    cmd->add_option("--modes", *n_modes,
                    "modes per run (default: the case's, doubled until the coarsest level shows an ovalling mode)")
        ->check(CLI::Range(1, 10000));
    cmd->add_option("--check-levels", options->check_levels,
                    "named mesh levels (coarse, default, fine, very_fine) to run once and compare with the "
                    "extrapolated frequencies")
        ->delimiter(',');
    cmd->add_option("--models", options->models,
                    "model levels to run, comma-separated: solid, harmonic, beam (default all three; the harmonic "
                    "level is skipped for a scene that is not axisymmetric, the beam for one it cannot solve, with "
                    "the reason in converge.md)")
        ->delimiter(',');
    cmd->add_flag("-q,--quiet", options->quiet, "no progress lines or summary");
    cmd->footer("Model levels: solid, harmonic and beam. Solid level k refines the unit mesh k times in every direction "
                "(h = 1/k; --levels, --first, --unit, --max-dofs, --repeats apply to it); the harmonic ladder (r-z "
                "section only; exact in theta) meshes the same section as the solid's level k and goes two levels "
                "finer (--levels + 2), not bound by --max-dofs; the beam ladder is its own: "
                "5 levels of 4, 8, 16, 32, 64 three-node Timoshenko elements along the core (every gap between "
                "support edges refined alike), each level run 200 times or for 1 s (median time). The three finest levels of "
                "each give the Richardson extrapolation and its observed order, the level before them checks that "
                "order; converge.md sets the beam's and the harmonic's extrapolated frequencies against the solid's "
                "(for the beam the model error; for the harmonic, exact in theta on the same section, what is left "
                "of the solid's circumferential discretization error). "
                "PETSc/SLEPc options pass through as for `run`. See docs/accuracy-vs-cost.md.");
    auto run = [options, output, unit, n_modes] {
        if (!output->empty()) options->output_dir = *output;
        if (!unit->empty()) options->unit = *unit;
        if (*n_modes > 0) options->n_modes = *n_modes;
        run_converge(*options, std::cout);
        return 0;
    };
    return {cmd, run, true};
}

}  // namespace coremodal
