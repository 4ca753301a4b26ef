#include "analyses/converge/converge.hpp"

#include "analyses/converge/ladder_runs.hpp"
#include "analyses/converge/model_ladder.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/petsc_handle.hpp"
#include "common/stopwatch.hpp"
#include "common/warnings.hpp"
#include "scene/level_traits.hpp"
#include "scene/case_file.hpp"
#include "scene/mesh_levels.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <thread>

namespace coremodal {
namespace {

// The 1-minute load average (0 when unknown).
double load_average() {
    double load[1] = {0};
    return getloadavg(load, 1) == 1 ? load[0] : 0.0;
}

void check_options(const ConvergeOptions& o) {
    if (o.repeats < 1) throw InputError("--repeats " + std::to_string(o.repeats) + ": expected at least 1");
    if (o.n_modes && *o.n_modes < 1) throw InputError("--modes " + std::to_string(*o.n_modes) + ": expected at least 1");
    for (const auto& name : o.check_levels)
        if (!find_mesh_level(name))
            throw InputError("--check-levels " + name + ": unknown mesh level; expected coarse, default, fine or very_fine");
    const std::string valid = "expected solid, harmonic, beam (comma-separated, any of them)";
    if (o.models.empty()) throw InputError("--models: no model level; " + valid);
    bool reference = false;  // the solid's ladder, whose meshes the named mesh levels are
    for (const auto& name : o.models) {
        const auto level = parse_model_choice(name);
        if (!level || *level == ModelChoice::automatic || !level_traits(*level).converge_ladder)
            throw InputError("--models " + name + ": unknown model level; " + valid);
        reference = reference || level_traits(*level).converge_reference;
    }
    if (!o.check_levels.empty() && !reference)
        throw InputError("--check-levels: named mesh levels are solid meshes; add solid to --models");
}

// Every level of every ladder, coarse to fine, then each ladder's analysis.
// How many modes each solid and harmonic run asks for (enough to hold the
// first ovalling mode) is found first, on the solid's coarsest level, or on
// the harmonic's when the solid is not run; that coarsest run counts as the
// level's first.
void run_ladders(const Scene& scene, std::vector<ModelLadder>& ladders, const ConvergeOptions& o, int& n_modes,
                 std::ostream& progress, ConvergeStudy& study) {
    std::optional<LevelRun> first_run;
    std::optional<ModelChoice> first_run_model;
    for (const auto& ladder : ladders)
        if (level_traits(ladder.model).meshed) {
            first_run = choose_mode_count(scene, ladder, o, n_modes, progress, study.notes);
            first_run_model = ladder.model;
            break;
        }
    study.n_modes = n_modes;
    for (auto& ladder : ladders)
        if (level_traits(ladder.model).meshed) ladder.n_modes = n_modes;
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
}

// The converge reference's ladder (the solid's: check_options requires it
// with --check-levels).
const ModelLadder& reference_ladder(const std::vector<ModelLadder>& ladders) {
    const auto it = std::find_if(ladders.begin(), ladders.end(),
                                 [](const ModelLadder& l) { return level_traits(l.model).converge_reference; });
    COREMODAL_ASSERT(it != ladders.end());
    return *it;
}

// Notes on levels whose modes are not all proven present, or whose repeated
// runs disagree beyond round-off.
void add_level_notes(ConvergeStudy& study) {
    for (const auto& m : study.models)
        for (const auto& l : m.levels) {
            if (!l.complete)
                study.notes.push_back(m.model + " " + l.step.label + ": the inertia count found modes missing");
            if (l.max_repeat_spread > 1e-8)
                study.notes.push_back(m.model + " " + l.step.label + ": repeated runs differ by " +
                                      formatted("%.1e", l.max_repeat_spread) + " in frequency");
        }
}

}  // namespace

ConvergeStudy run_converge(const ConvergeOptions& o, std::ostream& progress) {
    Stopwatch clock;
    const bool root = mpi_rank() == 0;
    check_options(o);

    // PETSc's event log (cheap) splits the solver time into factorizations,
    // triangular solves and orthogonalization; -log_view may have started it.
    PetscBool logging = PETSC_FALSE;
    PetscLogIsActive(&logging);
    if (!logging) PetscLogDefaultBegin();

    // 1. The scene and its model levels; the results folder checked before any work.
    const Scene scene = parse_case_file(o.case_file);
    print_warnings(scene.warnings);
    const std::filesystem::path out = o.output_dir ? std::filesystem::path(*o.output_dir)
                                                   : std::filesystem::path("results") / (scene.name + "-converge");
    if (o.write_results && o.claim) o.claim(out, o);
    ConvergeStudy study;
    study.load_start = load_average();
    study.n_cores = static_cast<int>(std::thread::hardware_concurrency());
    study.case_name = scene.name;
    study.source_file = o.case_file;
    study.repeats = o.repeats;
    study.repeat_limit_s = o.repeat_limit_s;
    int n_modes = o.n_modes.value_or(scene.analysis.n_modes);
    std::vector<ModelLadder> ladders = model_ladders(scene, o, progress, study);

    // 2. The number of modes, then every level of every ladder and the analysis.
    run_ladders(scene, ladders, o, n_modes, progress, study);
    study.ladder_time_s = clock.seconds();

    // 3. Named mesh levels, for choosing the default.
    for (const auto& name : o.check_levels)
        study.checks.push_back(run_named_level(scene, name, reference_ladder(ladders), o, progress));
    add_level_notes(study);
    study.total_time_s = clock.seconds();
    study.load_end = load_average();

    // 4. Write (rank 0): numbers first, then the picture, then the report.
    if (root && o.write) o.write(study, out, o, progress);
    return study;
}

}  // namespace coremodal
