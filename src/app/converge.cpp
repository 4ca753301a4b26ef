#include "app/converge.hpp"
#include "common/format.hpp"

#include "beam/beam_model.hpp"
#include "common/error.hpp"
#include "geometry/tube_section.hpp"
#include "numerics/median.hpp"
#include "numerics/power_law.hpp"
#include "output/csv.hpp"
#include "scene/mesh_levels.hpp"

#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <sstream>

namespace coremodal {
namespace {


std::string counts_text(const MeshSpec& m, bool rest_paper) {
    return std::to_string(m.n_wall) + "/" + (rest_paper ? std::to_string(m.n_rest_paper) : std::string("-")) +
           "/" + std::to_string(m.n_around) + "/" + std::to_string(m.n_along);
}

}  // namespace

// ---- the ladder -------------------------------------------------------------

UnitMesh default_unit(const Scene& scene) {
    UnitMesh unit;
    const double along = std::ceil(double(scene.mesh.n_along) * kUnitElementsAround / scene.mesh.n_around);
    unit.n_along = std::max(kMinElementsAlong, static_cast<int>(along));
    return unit;
}

UnitMesh parse_unit(const std::string& text, const std::string& option) {
    const std::string expected = "; expected WALL/PAPER/AROUND/ALONG element counts of the k = 1 level, e.g. 1/1/8/21";
    std::vector<int> v;
    std::stringstream s(text);
    std::string item;
    while (std::getline(s, item, '/')) {
        std::size_t used = 0;
        int value = 0;
        try {
            value = std::stoi(item, &used);
        } catch (const std::exception&) {
            used = 0;
        }
        if (used == 0 || used != item.size() || value < 1)
            throw InputError(option + " " + text + ": '" + item + "' is not a positive whole number" + expected);
        v.push_back(value);
    }
    if (v.size() != 4) throw InputError(option + " " + text + ": " + std::to_string(v.size()) + " counts" + expected);
    if (v[2] % 4 != 0)
        throw InputError(option + " " + text + ": around = " + std::to_string(v[2]) +
                         " must be a multiple of 4 (8 keeps ovalling pairs degenerate)" + expected);
    return {v[0], v[1], v[2], v[3]};
}

long estimate_dofs(const MeshSpec& m, bool rest_paper) {
    const long r = m.n_wall + (rest_paper ? m.n_rest_paper : 0), t = m.n_around, z = m.n_along;
    if (m.element == "hex27") return 3 * (2 * r + 1) * (2 * t) * (2 * z + 1);
    // Corner nodes, then mid-edge nodes on radial, circumferential and axial edges.
    const long nodes = t * ((r + 1) * (z + 1) + r * (z + 1) + (r + 1) * (z + 1) + (r + 1) * z);
    return 3 * nodes;
}

long estimate_dofs(const Scene& scene, const MeshSpec& mesh) {
    Scene meshed = scene;
    meshed.mesh = mesh;
    const TubeSection section = make_tube_section(meshed);
    MeshSpec tube = mesh;
    tube.n_along = 0;
    for (const AxialSegment& seg : section.segments) tube.n_along += seg.n_elements;
    // Chucks are meshed with hex20 (docs/chucks.md).
    return estimate_dofs(tube, scene.rest_paper.has_value()) + 3 * count_chuck_hex20_nodes(section);
}

UnitMesh fit_unit_to_budget(const Scene& scene, UnitMesh unit, int first, int levels, long max_dofs,
                            std::string& note) {
    note.clear();
    if (max_dofs <= 0 || scene.mesh.file) return unit;
    auto finest_dofs = [&](const UnitMesh& u) {
        return estimate_dofs(scene, refinement_ladder(scene, u, first, levels).back().mesh);
    };
    const int asked = unit.n_along;
    while (finest_dofs(unit) > max_dofs && unit.n_along > kMinUnitElementsAlong) --unit.n_along;
    if (unit.n_along != asked)
        note = "the unit's elements along were lowered from " + std::to_string(asked) + " to " +
               std::to_string(unit.n_along) + " so that the finest level stays within --max-dofs " +
               std::to_string(max_dofs) + " (estimated " + std::to_string(finest_dofs(unit)) + " DOFs)";
    if (finest_dofs(unit) > max_dofs)
        note += std::string(note.empty() ? "" : "; ") + "the finest level (estimated " +
                std::to_string(finest_dofs(unit)) + " DOFs) exceeds --max-dofs " + std::to_string(max_dofs) +
                " even with the fewest elements along; use fewer --levels or a smaller --unit";
    return unit;
}

std::vector<MeshStep> refinement_ladder(const Scene& scene, const UnitMesh& unit, int first, int levels) {
    if (scene.mesh.file)
        throw InputError(scene.source_file + ": [mesh] file = " + *scene.mesh.file +
                         ": converge refines the generated mesh; expected a case without a mesh file");
    if (first < 1) throw InputError("--first " + std::to_string(first) + ": expected a multiple k >= 1");
    if (levels < 3) throw InputError("--levels " + std::to_string(levels) + ": Richardson extrapolation needs at least 3");
    // The unit's axial segments (clamp zones, graded free spans) as the mesher
    // would cut them; every level multiplies each segment's count by k.
    Scene unit_scene = scene;
    unit_scene.mesh.n_wall = unit.n_wall;
    unit_scene.mesh.n_rest_paper = unit.n_rest_paper;
    unit_scene.mesh.n_around = unit.n_around;
    unit_scene.mesh.n_along = unit.n_along;
    unit_scene.mesh.along_per_segment.clear();
    std::vector<int> unit_segments;
    for (const AxialSegment& segment : make_tube_section(unit_scene).segments)
        unit_segments.push_back(segment.n_elements);

    std::vector<MeshStep> steps;
    for (int k = first; k < first + levels; ++k) {
        MeshStep step;
        step.k = k;
        step.h = 1.0 / k;
        step.mesh = scene.mesh;
        step.mesh.level = "converge k=" + std::to_string(k);
        step.mesh.n_wall = k * unit.n_wall;
        step.mesh.n_rest_paper = k * unit.n_rest_paper;
        step.mesh.n_around = k * unit.n_around;
        step.mesh.along_per_segment.clear();
        for (int n : unit_segments) step.mesh.along_per_segment.push_back(k * n);
        step.mesh.n_along = std::accumulate(step.mesh.along_per_segment.begin(), step.mesh.along_per_segment.end(), 0);
        step.counts = counts_text(step.mesh, scene.rest_paper.has_value());
        step.label = "k=" + std::to_string(k) + " " + step.counts;
        steps.push_back(std::move(step));
    }
    return steps;
}

std::vector<MeshStep> beam_refinement_ladder(const Scene& scene, int unit_elements, int levels) {
    if (unit_elements < 1) throw InputError("beam unit: " + std::to_string(unit_elements) + " elements: expected at least 1");
    if (levels < 3) throw InputError("--levels " + std::to_string(levels) + ": Richardson extrapolation needs at least 3");
    std::vector<MeshStep> steps;
    for (int i = 0, k = 1; i < levels; ++i, k *= 2) {
        BeamModelOptions options;
        options.core_elements = unit_elements;
        options.refine = k;
        const BeamNetwork net = build_beam_network(scene, options);
        MeshStep step;
        step.k = k;
        step.h = 1.0 / k;
        step.mesh = scene.mesh;  // unused by the beam
        step.counts = std::to_string(net.beams.front().nodes.size() / 2) + "/" + std::to_string(net.n_elements());
        step.label = "k=" + std::to_string(k) + " " + step.counts;
        steps.push_back(std::move(step));
    }
    return steps;
}

// ---- one level's runs -------------------------------------------------------

LevelResult summarize_runs(const MeshStep& step, const std::vector<LevelRun>& runs) {
    COREMODAL_ASSERT(!runs.empty());
    LevelResult r;
    r.step = step;
    r.n_dofs = runs.front().n_dofs;
    r.runs = static_cast<int>(runs.size());
    r.modes = runs.front().modes;
    auto med = [&](double Timing::*part) {
        std::vector<double> v;
        for (const auto& run : runs) v.push_back(run.timing_s.*part);
        return median(v);
    };
    r.median_s = {.mesh = med(&Timing::mesh),
                  .assemble = med(&Timing::assemble),
                  .factor_and_solve = med(&Timing::factor_and_solve),
                  .classify = med(&Timing::classify),
                  .chuck_factor = med(&Timing::chuck_factor),
                  .total = med(&Timing::total)};
    std::vector<double> cpu;
    for (const auto& run : runs) cpu.push_back(run.cpu_s);
    r.median_cpu_s = median(cpu);
    auto med_solver = [&](double SolverBreakdown::*part) {
        std::vector<double> v;
        for (const auto& run : runs) v.push_back(run.solver_s.*part);
        return median(v);
    };
    r.median_solver_s = {med_solver(&SolverBreakdown::factor_s), med_solver(&SolverBreakdown::solve_s),
                         med_solver(&SolverBreakdown::orthogonalize_s)};
    for (const auto& run : runs) {
        r.peak_memory_mb = std::max(r.peak_memory_mb, run.peak_memory_mb);
        r.complete = r.complete && run.complete;
        // Every run solves the same mesh: the frequencies must agree.
        for (std::size_t i = 0; i < std::min(run.modes.size(), r.modes.size()); ++i) {
            const double a = run.modes[i].frequency_hz, b = r.modes[i].frequency_hz;
            if (std::max(a, b) > 0) r.max_repeat_spread = std::max(r.max_repeat_spread, std::abs(a - b) / std::max(a, b));
        }
    }
    return r;
}

// ---- tracking ---------------------------------------------------------------

namespace {

// The extrapolation from the finest levels that all have the mode, and each
// level's error against its f0.
void extrapolate(TrackedMode& t, const std::vector<LevelResult>& levels) {
    std::vector<double> h, f;
    for (std::size_t i = levels.size(); i-- > 0 && t.frequency_hz[i];) {
        h.insert(h.begin(), levels[i].step.h);
        f.insert(f.begin(), *t.frequency_hz[i]);
    }
    if (f.size() >= 3) t.richardson = richardson(h, f);
    for (const auto& value : t.frequency_hz)
        t.relative_error.push_back(value && t.richardson
                                       ? std::optional<double>(std::abs(*value - t.richardson->f0) /
                                                               std::abs(t.richardson->f0))
                                       : std::nullopt);
}

}  // namespace

std::vector<TrackedMode> track_modes(const std::vector<LevelResult>& levels) {
    std::vector<std::vector<DistinctMode>> distinct;
    for (const auto& level : levels) distinct.push_back(distinct_modes(level.modes));
    std::vector<TrackedMode> tracked;
    for (LabelTrack& track : track_by_label(distinct, kModeRoles)) {
        TrackedMode t;
        t.key = std::move(track.key);
        t.role = std::move(track.role);
        t.frequency_hz = std::move(track.frequency_hz);
        extrapolate(t, levels);
        tracked.push_back(std::move(t));
    }
    return tracked;
}

// ---- the study --------------------------------------------------------------

ModelStudy analyse_levels(std::string model, std::string ladder_note, std::vector<LevelResult> levels) {
    ModelStudy s;
    s.model = std::move(model);
    s.ladder_note = std::move(ladder_note);
    s.levels = std::move(levels);
    s.modes = track_modes(s.levels);
    // The coarsest level's time is mostly fixed costs (start-up, gmsh): leave
    // it out of the scaling fit when there are enough levels without it.
    const std::size_t skip = s.levels.size() >= 3 ? 1 : 0;
    std::vector<double> dofs, time, memory;
    for (std::size_t i = skip; i < s.levels.size(); ++i) {
        dofs.push_back(double(s.levels[i].n_dofs));
        time.push_back(s.levels[i].median_s.total);
        memory.push_back(s.levels[i].peak_memory_mb);
    }
    s.time_exponent = power_law_exponent(dofs, time);
    s.memory_exponent = power_law_exponent(dofs, memory);
    return s;
}

std::optional<std::size_t> first_level_within(const TrackedMode& mode, double target) {
    if (!mode.richardson) return std::nullopt;
    const double f0 = std::abs(mode.richardson->f0);
    const double uncertainty = mode.richardson->f0_uncertainty.value_or(0.0) / f0;
    for (std::size_t i = 0; i < mode.relative_error.size(); ++i)
        if (mode.relative_error[i] && *mode.relative_error[i] + uncertainty <= target) return i;
    return std::nullopt;
}

std::optional<TargetPrediction> predict_level_for(const ModelStudy& model, const TrackedMode& mode, double target) {
    if (!mode.richardson || !mode.richardson->extrapolated || !mode.richardson->asymptotic || model.levels.empty())
        return std::nullopt;
    const Richardson& r = *mode.richardson;
    const double f0 = std::abs(r.f0);
    const double room = target - r.f0_uncertainty.value_or(0.0) / f0;
    const double finest_error = r.error_estimate / f0;
    if (room <= 0 || finest_error <= 0) return std::nullopt;
    const LevelResult& finest = model.levels.back();
    TargetPrediction p;
    p.k = finest.step.k * std::pow(finest_error / room, 1.0 / r.order);
    p.n_dofs = double(finest.n_dofs) * std::pow(p.k / finest.step.k, model.refined_dimensions);
    if (model.time_exponent)
        p.time_s = finest.median_s.total * std::pow(p.n_dofs / double(finest.n_dofs), *model.time_exponent);
    return p;
}

// ---- model error ---------------------------------------------------------------

namespace {

const ModelStudy* find_model(const std::vector<ModelStudy>& models, const std::string& name) {
    for (const auto& m : models)
        if (m.model == name) return &m;
    return nullptr;
}

const TrackedMode* find_role(const ModelStudy& m, const std::string& role) {
    for (const auto& t : m.modes)
        if (t.role == role) return &t;
    return nullptr;
}

}  // namespace

std::vector<ModelError> model_errors(const std::vector<ModelStudy>& models) {
    std::vector<ModelError> out;
    const ModelStudy* solid = find_model(models, "solid");
    if (!solid) return out;
    for (const auto& m : models) {
        if (m.model == "solid") continue;
        for (const auto& [role, type] : kModeRoles) {
            const TrackedMode* a = find_role(m, role);
            const TrackedMode* b = find_role(*solid, role);
            if (!a || !b || !a->richardson || !b->richardson) continue;
            const Richardson &ra = *a->richardson, &rb = *b->richardson;
            ModelError e;
            e.model = m.model;
            e.role = role;
            e.id = a->key.text();
            e.solid_id = b->key.text();
            e.f0_hz = ra.f0;
            e.solid_f0_hz = rb.f0;
            e.relative = (ra.f0 - rb.f0) / rb.f0;
            e.known_to = (ra.error_estimate + ra.f0_uncertainty.value_or(0.0)) / std::abs(ra.f0) +
                         (rb.error_estimate + rb.f0_uncertainty.value_or(0.0)) / std::abs(rb.f0);
            out.push_back(std::move(e));
        }
    }
    return out;
}

std::vector<std::optional<double>> error_against_solid(const TrackedMode& mode, const std::vector<ModelStudy>& models) {
    const ModelStudy* solid = find_model(models, "solid");
    const TrackedMode* reference = solid && !mode.role.empty() ? find_role(*solid, mode.role) : nullptr;
    if (!reference || !reference->richardson) return {};
    const double f0 = reference->richardson->f0;
    std::vector<std::optional<double>> out;
    for (const auto& f : mode.frequency_hz)
        out.push_back(f ? std::optional<double>(std::abs(*f - f0) / std::abs(f0)) : std::nullopt);
    return out;
}

// ---- writers ----------------------------------------------------------------

namespace {

const TrackedMode* role_mode(const ModelStudy& m, const std::string& role) {
    for (const auto& t : m.modes)
        if (t.role == role) return &t;
    return nullptr;
}

std::string opt(const std::optional<double>& v, const char* format = "%.10g") { return v ? formatted(format, *v) : ""; }

toml::table timing_table(const Timing& t) {
    return toml::table{{"mesh", t.mesh},
                       {"assemble", t.assemble},
                       {"factor_and_solve", t.factor_and_solve},
                       {"classify", t.classify},
                       {"total", t.total}};
}

toml::table richardson_table(const Richardson& r) {
    toml::table t{{"extrapolated", r.extrapolated},
                  {"order", r.order},
                  {"f0_hz", r.f0},
                  {"error_estimate_hz", r.error_estimate},
                  {"relative_error_estimate", r.error_estimate / std::abs(r.f0)},
                  {"asymptotic", r.asymptotic},
                  {"note", r.note}};
    if (r.previous_order) t.insert("previous_order", *r.previous_order);
    if (r.previous_f0) t.insert("previous_f0_hz", *r.previous_f0);
    if (r.f0_uncertainty) t.insert("f0_uncertainty_hz", *r.f0_uncertainty);
    return t;
}

std::string percent(double fraction) {
    if (fraction >= 0.1) return formatted("%.0f %%", fraction * 100);
    if (fraction >= 0.01) return formatted("%.1f %%", fraction * 100);
    if (fraction >= 1e-3) return formatted("%.2f %%", fraction * 100);
    return formatted("%.2g %%", fraction * 100);
}

// Seconds for the tables: two decimals, one from 10 s; below 0.01 s (a beam
// level takes about a millisecond) two significant digits.
std::string seconds(double s) {
    if (s >= 10) return formatted("%.1f", s);
    if (s >= 0.01 || s <= 0) return formatted("%.2f", s);
    return formatted("%.2g", s);
}

// Timing columns of the CSV: six significant digits (beam levels take ~1e-3 s).
std::string csv_seconds(double s) { return formatted("%.6g", s); }

std::string role_title(const std::string& role) {
    if (role == "f1") return "f1 (first bending)";
    if (role.empty()) return "";
    return "first " + role;
}

}  // namespace

std::string converge_csv(const ConvergeStudy& study) {
    std::ostringstream s;
    s << "model,k,mesh,h,dofs,runs,mesh_s,assemble_s,factor_and_solve_s,classify_s,total_s,cpu_s,factorizations_s,"
         "triangular_solves_s,orthogonalization_s,peak_memory_mb,"
         "mode,role,type,n,m,occurrence,frequency_hz,extrapolated_hz,error_estimate_hz,observed_order,asymptotic,"
         "relative_error,relative_error_vs_solid\n";
    for (const auto& model : study.models) {
        std::vector<std::vector<std::optional<double>>> vs_solid;
        for (const auto& mode : model.modes)
            vs_solid.push_back(model.model == "solid" ? std::vector<std::optional<double>>()
                                                      : error_against_solid(mode, study.models));
        for (std::size_t i = 0; i < model.levels.size(); ++i) {
            const LevelResult& l = model.levels[i];
            const Timing& t = l.median_s;
            for (std::size_t j = 0; j < model.modes.size(); ++j) {
                const TrackedMode& mode = model.modes[j];
                s << model.model << ',' << l.step.k << ',' << l.step.counts << ','
                  << formatted("%.6g", l.step.h) << ',' << l.n_dofs << ',' << l.runs << ',' << csv_seconds(t.mesh) << ','
                  << csv_seconds(t.assemble) << ',' << csv_seconds(t.factor_and_solve) << ','
                  << csv_seconds(t.classify) << ',' << csv_seconds(t.total) << ',' << csv_seconds(l.median_cpu_s)
                  << ',' << csv_seconds(l.median_solver_s.factor_s) << ',' << csv_seconds(l.median_solver_s.solve_s)
                  << ',' << csv_seconds(l.median_solver_s.orthogonalize_s) << ',' << formatted("%.1f", l.peak_memory_mb)
                  << ',' << csv_field(mode.key.text()) << ',' << mode.role << ',' << mode.key.type << ','
                  << mode.key.n << ',' << mode.key.m << ',' << mode.key.occurrence << ','
                  << opt(mode.frequency_hz[i]) << ',';
                if (mode.richardson) {
                    const Richardson& r = *mode.richardson;
                    s << formatted("%.10g", r.f0) << ',' << formatted("%.4g", r.error_estimate) << ','
                      << (r.extrapolated ? formatted("%.4g", r.order) : std::string()) << ','
                      << (r.asymptotic ? "yes" : "no");
                } else {
                    s << ",,,";
                }
                s << ',' << opt(mode.relative_error[i], "%.4g") << ','
                  << (vs_solid[j].empty() ? std::string() : opt(vs_solid[j][i], "%.4g")) << '\n';
            }
        }
    }
    return s.str();
}

std::string converge_json(const ConvergeStudy& study) {
    toml::array models;
    for (const auto& model : study.models) {
        toml::array levels, modes;
        for (const auto& l : model.levels)
            levels.push_back(toml::table{{"k", l.step.k},
                                         {"h", l.step.h},
                                         {"mesh", l.step.counts},
                                         {"n_dofs", l.n_dofs},
                                         {"runs", l.runs},
                                         {"timing_s", timing_table(l.median_s)},
                                         {"cpu_s", l.median_cpu_s},
                                         {"solver_s", toml::table{{"factorizations", l.median_solver_s.factor_s},
                                                                  {"triangular_solves", l.median_solver_s.solve_s},
                                                                  {"orthogonalization", l.median_solver_s.orthogonalize_s}}},
                                         {"peak_memory_mb", l.peak_memory_mb},
                                         {"complete", l.complete},
                                         {"repeat_spread", l.max_repeat_spread}});
        for (const auto& mode : model.modes) {
            const auto vs_solid = model.model == "solid" ? std::vector<std::optional<double>>()
                                                         : error_against_solid(mode, study.models);
            toml::array values;
            for (std::size_t i = 0; i < model.levels.size(); ++i) {
                if (!mode.frequency_hz[i]) continue;
                toml::table v{{"level", static_cast<int64_t>(i)}, {"frequency_hz", *mode.frequency_hz[i]}};
                if (mode.relative_error[i]) v.insert("relative_error", *mode.relative_error[i]);
                if (!vs_solid.empty() && vs_solid[i]) v.insert("error_vs_solid", *vs_solid[i]);
                values.push_back(v);
            }
            toml::table t{{"id", mode.key.text()}, {"type", mode.key.type},         {"n", mode.key.n},
                          {"m", mode.key.m},       {"occurrence", mode.key.occurrence}, {"role", mode.role},
                          {"values", values}};
            if (mode.richardson) t.insert("richardson", richardson_table(*mode.richardson));
            modes.push_back(t);
        }
        toml::table m{{"model", model.model},
                      {"ladder", model.ladder_note},
                      {"refined_dimensions", model.refined_dimensions},
                      {"levels", levels},
                      {"modes", modes}};
        if (model.model == "beam")
            m.insert("timing_parts", "mesh: building the beam network; factor_and_solve: assembly, eigensolve and "
                                     "inertia count (assemble is inside it, 0 here); classify: labels and effective "
                                     "masses");
        if (model.model == "harmonic")
            m.insert("timing_parts", "mesh: the r-z section and its revolution (for naming the modes); assemble and "
                                     "factor_and_solve: summed over the wave numbers n (eigensolves and inertia "
                                     "counts); n_dofs: the largest one-harmonic problem");
        toml::array unseen;
        for (const auto& [role, why] : model.unseen_roles) unseen.push_back(toml::table{{"role", role}, {"reason", why}});
        m.insert("not_in_model", unseen);
        if (model.time_exponent) m.insert("time_exponent", *model.time_exponent);
        if (model.memory_exponent) m.insert("memory_exponent", *model.memory_exponent);
        models.push_back(m);
    }
    toml::array errors;
    for (const ModelError& e : model_errors(study.models))
        errors.push_back(toml::table{{"model", e.model},
                                     {"role", e.role},
                                     {"id", e.id},
                                     {"solid_id", e.solid_id},
                                     {"f0_hz", e.f0_hz},
                                     {"solid_f0_hz", e.solid_f0_hz},
                                     {"model_error", e.relative},
                                     {"known_to", e.known_to}});
    toml::array checks;
    const ModelStudy* solid = find_model(study.models, "solid");
    for (const auto& c : study.checks) {
        toml::array modes;
        for (const auto& d : distinct_modes(c.result.modes)) {
            toml::table v{{"id", d.key.text()}, {"frequency_hz", d.frequency_hz}};
            if (solid)
                for (const auto& t : solid->modes)
                    if (t.key == d.key && t.richardson) {
                        v.insert("relative_error", std::abs(d.frequency_hz - t.richardson->f0) / t.richardson->f0);
                        v.insert("role", t.role);
                    }
            modes.push_back(v);
        }
        checks.push_back(toml::table{{"name", c.name},
                                     {"mesh", c.mesh},
                                     {"n_dofs", c.result.n_dofs},
                                     {"timing_s", timing_table(c.result.median_s)},
                                     {"peak_memory_mb", c.result.peak_memory_mb},
                                     {"modes", modes}});
    }
    toml::array notes;
    for (const auto& n : study.notes) notes.push_back(n);
    toml::table root{{"program", "coremodal " COREMODAL_VERSION},
                     {"case", study.case_name},
                     {"source_file", study.source_file},
                     {"n_modes", study.n_modes},
                     {"repeats", study.repeats},
                     {"repeat_limit_s", study.repeat_limit_s},
                     {"total_time_s", study.total_time_s},
                     {"ladder_time_s", study.ladder_time_s},
                     {"load_average", toml::array{study.load_start, study.load_end}},
                     {"n_cores", study.n_cores},
                     {"models", models},
                     {"model_errors", errors},
                     {"checks", checks},
                     {"notes", notes}};
    std::ostringstream s;
    s << toml::json_formatter{root} << "\n";
    return s.str();
}

namespace {

void markdown_levels(std::ostringstream& s, const ModelStudy& m) {
    const TrackedMode* f1 = role_mode(m, "f1");
    const TrackedMode* oval = role_mode(m, "ovalling");
    // The beam builds a network instead of a mesh and assembles inside its
    // solve (problem by problem): its columns say so.
    const bool beam = m.model == "beam";
    if (beam)
        s << "| k | elements (core/network) | DOFs | runs | network [s] | assemble+solve [s] | labels [s] | "
             "total [s] | CPU [s] | peak memory [MiB] |";
    else
        s << "| k | mesh (wall/paper/around/along) | DOFs | runs | mesh [s] | assemble [s] | factor+solve [s] | "
             "total [s] | CPU [s] | peak memory [MiB] |";
    if (f1) s << " f1 [Hz] | error f1 |";
    if (oval) s << " ovalling [Hz] | error ovalling |";
    s << "\n|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|";
    if (f1) s << "---:|---:|";
    if (oval) s << "---:|---:|";
    s << "\n";
    for (std::size_t i = 0; i < m.levels.size(); ++i) {
        const LevelResult& l = m.levels[i];
        const Timing& t = l.median_s;
        s << "| " << l.step.k << " | " << l.step.counts << " | " << l.n_dofs << " | " << l.runs << " | "
          << seconds(t.mesh) << " | " << (beam ? seconds(t.factor_and_solve) : seconds(t.assemble)) << " | "
          << (beam ? seconds(t.classify) : seconds(t.factor_and_solve)) << " | " << seconds(t.total) << " | "
          << seconds(l.median_cpu_s) << " | " << formatted("%.0f", l.peak_memory_mb) << " |";
        for (const TrackedMode* t : {f1, oval}) {
            if (!t) continue;
            s << ' ' << opt(t->frequency_hz[i], "%.4f") << " | "
              << (t->relative_error[i] ? percent(*t->relative_error[i]) : std::string("–")) << " |";
        }
        s << "\n";
        if (!l.complete) s << "\n(k = " << l.step.k << ": the inertia count found missing modes)\n";
    }
}

void markdown_extrapolation(std::ostringstream& s, const ModelStudy& m) {
    s << "\n| mode | role | finest [Hz] | extrapolated f0 [Hz] | error estimate | f0 known to | order p | "
         "asymptotic | note |\n|---|---|---:|---:|---:|---:|---:|---|---|\n";
    for (const auto& t : m.modes) {
        s << "| " << t.key.text() << " | " << role_title(t.role) << " | " << opt(t.frequency_hz.back(), "%.4f")
          << " | ";
        if (!t.richardson) {
            s << "– | – | – | – | – | missing at some level (labels differ) |\n";
            continue;
        }
        const Richardson& r = *t.richardson;
        s << formatted("%.4f", r.f0) << " | " << percent(r.error_estimate / std::abs(r.f0)) << " | "
          << (r.f0_uncertainty ? percent(*r.f0_uncertainty / std::abs(r.f0)) : std::string("–")) << " | "
          << (r.extrapolated ? formatted("%.2f", r.order) : std::string("–")) << " | " << (r.asymptotic ? "yes" : "no")
          << " | " << r.note << " |\n";
    }
    for (const auto& [role, why] : m.unseen_roles)
        if (!role_mode(m, role)) s << "| – | " << role_title(role) << " | – | not in this model | – | – | – | – | " << why << " |\n";
    s << "\nerror estimate = |f(finest) − f0| / f0; \"f0 known to\" = |f0 − f0 of the triple one level coarser| / f0.\n";
}

void markdown_targets(std::ostringstream& s, const ModelStudy& m) {
    s << "\n| mode | target | cheapest level reaching it | DOFs | time [s] |\n|---|---:|---|---:|---:|\n";
    for (const std::string role : {"f1", "ovalling"}) {
        const TrackedMode* t = role_mode(m, role);
        if (!t) continue;
        for (double target : kAccuracyTargets) {
            s << "| " << role_title(role) << " | " << percent(target) << " | ";
            const auto i = first_level_within(*t, target);
            if (i) {
                const LevelResult& l = m.levels[*i];
                s << l.step.label << " | " << l.n_dofs << " | " << seconds(l.median_s.total) << " |\n";
            } else if (const auto p = predict_level_for(m, *t, target)) {
                s << "none of the ladder; predicted k ≈ " << formatted("%.1f", p->k) << " | ≈ " << formatted("%.3g", p->n_dofs)
                  << " | " << (p->time_s ? "≈ " + formatted("%.3g", *p->time_s) : std::string("–")) << " |\n";
            } else {
                s << "none of the ladder (not asymptotic, or below what f0 is known to) | – | – |\n";
            }
        }
    }
    s << "\nA level reaches a target when its error against f0 plus the uncertainty of f0 is within it. "
         "Predictions extend the observed order and time scaling beyond the ladder (uniform refinement).\n";
}

void markdown_cost(std::ostringstream& s, const ModelStudy& m) {
    if (m.levels.empty()) return;
    const LevelResult& l = m.levels.back();
    const Timing& t = l.median_s;
    const double total = t.total > 0 ? t.total : 1;
    if (m.model == "beam") {
        s << "\nWhere the time goes at the finest level (" << l.step.label << ", " << l.n_dofs << " DOFs, median of "
          << l.runs << " runs): building the beam network " << seconds(t.mesh) << " s (" << percent(t.mesh / total)
          << "), assembly, eigensolve and inertia count " << seconds(t.factor_and_solve) << " s ("
          << percent(t.factor_and_solve / total) << "), labels and effective masses " << seconds(t.classify) << " s ("
          << percent(t.classify / total) << "); total " << seconds(t.total) << " s. Peak memory "
          << formatted("%.0f", l.peak_memory_mb) << " MiB is the whole process's resident set (PETSc, the "
          << "solid ladder's freed heap): the beam itself needs well under a MiB.\n";
        if (m.time_exponent) s << "\nObserved scaling over the levels after the coarsest: time ~ DOFs^"
                               << formatted("%.2f", *m.time_exponent) << ".\n";
        return;
    }
    if (m.model == "harmonic")
        s << "\nHarmonic level: mesh = the r–z section and its revolution (for naming the modes); assembly and "
             "factorization and solve sum over the wave numbers n solved or counted; DOFs = the largest one-harmonic "
             "problem.\n";
    s << "\nWhere the time goes at the finest level (" << l.step.label << ", " << l.n_dofs << " DOFs, median of "
      << l.runs << (l.runs == 1 ? " run" : " runs") << "): mesh " << seconds(t.mesh) << " s ("
      << percent(t.mesh / total) << "), assembly " << seconds(t.assemble) << " s (" << percent(t.assemble / total)
      << "), factorization and solve " << seconds(t.factor_and_solve) << " s (" << percent(t.factor_and_solve / total)
      << "), classification " << seconds(t.classify) << " s (" << percent(t.classify / total) << "); total "
      << seconds(t.total) << " s, peak memory " << formatted("%.0f", l.peak_memory_mb) << " MiB.\n";
    const SolverBreakdown& b = l.median_solver_s;
    if (b.factor_s + b.solve_s + b.orthogonalize_s > 0) {
        const double rest = std::max(0.0, t.factor_and_solve - b.factor_s - b.solve_s - b.orthogonalize_s);
        s << "\nInside factorization and solve (PETSc event log): factorizations " << seconds(b.factor_s) << " s ("
          << percent(b.factor_s / total) << " of the total), triangular solves " << seconds(b.solve_s) << " s ("
          << percent(b.solve_s / total) << "), orthogonalization of the Krylov basis " << seconds(b.orthogonalize_s)
          << " s (" << percent(b.orthogonalize_s / total) << "), the rest of the eigensolver (M products, projected "
          << "problem, residual checks) " << seconds(rest) << " s (" << percent(rest / total) << ").\n";
    }
    if (m.time_exponent && m.memory_exponent)
        s << "\nObserved scaling over the levels after the coarsest: time ~ DOFs^" << formatted("%.2f", *m.time_exponent)
          << ", peak memory ~ DOFs^" << formatted("%.2f", *m.memory_exponent) << ".\n";
}

// The harmonic level against the solid level by level: at equal k both mesh
// the same r–z section, so the difference is exactly the solid's
// circumferential discretization error at that level (the solid is the
// stiffer: a positive difference).
void markdown_same_section(std::ostringstream& s, const ModelStudy& harmonic, const ModelStudy& solid) {
    bool header = false;
    for (const std::string role : {"f1", "ovalling"}) {
        const TrackedMode* h = role_mode(harmonic, role);
        const TrackedMode* so = role_mode(solid, role);
        if (!h || !so) continue;
        for (std::size_t i = 0; i < solid.levels.size(); ++i)
            for (std::size_t j = 0; j < harmonic.levels.size(); ++j) {
                if (harmonic.levels[j].step.k != solid.levels[i].step.k || !so->frequency_hz[i] || !h->frequency_hz[j])
                    continue;
                if (!header) {
                    s << "\nLevel by level on the same section: the difference is the solid's own circumferential "
                         "discretization error at that level (its level k has " << solid.levels[i].step.mesh.n_around / solid.levels[i].step.k
                      << " × k elements around). It stiffens the solid; but the solid's quadratic arcs only approximate "
                         "the circle, so where that error is tiny (bending) the difference can take either sign at the "
                         "10⁻⁴ level:\n\n| mode | k | solid [Hz] | harmonic [Hz] | (solid − harmonic) / harmonic |\n"
                         "|---|---:|---:|---:|---:|\n";
                    header = true;
                }
                const double fs = *so->frequency_hz[i], fh = *h->frequency_hz[j];
                s << "| " << role_title(role) << " | " << solid.levels[i].step.k << " | " << formatted("%.4f", fs)
                  << " | " << formatted("%.4f", fh) << " | " << formatted("%+.3g", 100 * (fs - fh) / fh) << " % |\n";
            }
    }
}

// One line per role: where each model level converges and how far apart.
void markdown_model_errors(std::ostringstream& s, const ConvergeStudy& study) {
    const ModelStudy* solid = find_model(study.models, "solid");
    if (!solid) return;
    const std::vector<ModelError> errors = model_errors(study.models);
    for (const auto& m : study.models) {
        if (m.model == "solid") continue;
        const bool harmonic = m.model == "harmonic";
        s << "\n## Model error: " << m.model << " against solid\n\n";
        if (harmonic)
            s << "The harmonic level solves the solid's own r–z section (level k meshes the same section as the "
                 "solid's level k) exactly in theta. The difference between the two extrapolated values is therefore "
                 "not a modelling error: it is the part of the solid's circumferential discretization error that its "
                 "extrapolation did not remove (the solid refines around together with the section), plus both "
                 "extrapolations' noise; ideally it is zero. A difference within what both are known to is agreement; "
                 "where the harmonic f0 is better known, it is the better value of the two.\n\n";
        else
            s << "Each level converges to its own model's answer; the difference between the two extrapolated values "
                 "is the model error, which no refinement of the " << m.model << " removes.\n\n";
        const char* error_words = harmonic ? "difference " : "model error ";
        for (const auto& [role, type] : kModeRoles) {
            const TrackedMode* own = role_mode(m, role);
            const TrackedMode* ref = role_mode(*solid, role);
            const auto e = std::find_if(errors.begin(), errors.end(),
                                        [&](const ModelError& x) { return x.model == m.model && x.role == role; });
            s << "- " << role_title(role) << ": ";
            if (e != errors.end()) {
                s << m.model << " level converges to " << formatted("%.4f", e->f0_hz) << " Hz (" << e->id
                  << "), the solid to " << formatted("%.4f", e->solid_f0_hz) << " Hz (" << e->solid_id
                  << "): " << error_words << formatted("%+.3g", 100 * e->relative) << " % (both extrapolations known to "
                  << percent(e->known_to) << ")\n";
                continue;
            }
            const auto unseen = std::find_if(m.unseen_roles.begin(), m.unseen_roles.end(),
                                             [&](const auto& u) { return u.first == role; });
            if (unseen != m.unseen_roles.end()) {
                s << "not in this model (" << unseen->second << ")";
                if (ref && ref->richardson) s << "; the solid converges to " << formatted("%.4f", ref->richardson->f0) << " Hz";
                s << "\n";
            } else if (!own || !own->richardson) {
                s << "the " << m.model << " level has no extrapolated value (not among its modes, or not tracked at "
                     "every level)\n";
            } else {
                s << m.model << " level converges to " << formatted("%.4f", own->richardson->f0)
                  << " Hz; the solid has no extrapolated value (not among its modes)\n";
            }
        }
        if (harmonic) markdown_same_section(s, m, *solid);
    }
}

}  // namespace

std::string converge_markdown(const ConvergeStudy& study, const std::string& plot_note) {
    std::ostringstream s;
    s << "# Convergence study: " << study.case_name << "\n\n";
    s << "Case file `" << study.source_file << "`; modes asked per run:";
    for (std::size_t i = 0; i < study.models.size(); ++i)
        s << (i ? ", " : " ") << study.models[i].model << " " << study.models[i].n_modes;
    s << "; timings are medians of the runs in each table's \"runs\" column (" << study.repeats
      << " per solid or harmonic level, one for a level whose first run took longer than " << formatted("%.0f", study.repeat_limit_s)
      << " s; " << kBeamRunsPerLevel << " per beam level, whose runs take about a millisecond, or as many as fit in "
      << formatted("%g", kBeamLevelBudget) << " s). Model levels: ";
    for (std::size_t i = 0; i < study.models.size(); ++i) s << (i ? ", " : "") << study.models[i].model;
    s << ". Ladders: " << seconds(study.ladder_time_s) << " s; whole study (with named-level checks): "
      << seconds(study.total_time_s) << " s on " << study.n_cores
      << " cores, load average " << formatted("%.1f", study.load_start) << " at the start and "
      << formatted("%.1f", study.load_end) << " at the end (a load above the number of cores means other processes "
      << "shared the machine and the wall times are longer than on an idle one; CPU time is less affected).\n";
    for (const auto& m : study.models) {
        s << "\n## Model level: " << m.model << "\n\n" << m.ladder_note << "\n\n";
        markdown_levels(s, m);
        s << "\n### Extrapolated frequencies (Richardson, three finest levels)\n";
        markdown_extrapolation(s, m);
        s << "\n### Accuracy targets\n";
        markdown_targets(s, m);
        s << "\n### Cost\n";
        markdown_cost(s, m);
    }
    markdown_model_errors(s, study);
    if (!study.checks.empty()) {
        s << "\n## Named mesh levels against the extrapolated values (solid)\n\n"
             "| level | mesh (wall/paper/around/along) | DOFs | total [s] | peak memory [MiB] | f1 [Hz] | error f1 | "
             "ovalling [Hz] | error ovalling |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
        const ModelStudy* solid = find_model(study.models, "solid");
        for (const auto& c : study.checks) {
            s << "| " << c.name << " | " << c.mesh << " | " << c.result.n_dofs << " | "
              << seconds(c.result.median_s.total) << " | " << formatted("%.0f", c.result.peak_memory_mb) << " |";
            const auto distinct = distinct_modes(c.result.modes);
            for (const std::string role : {"f1", "ovalling"}) {
                const TrackedMode* t = solid ? role_mode(*solid, role) : nullptr;
                const DistinctMode* d = nullptr;
                if (t)
                    for (const auto& x : distinct)
                        if (x.key == t->key) d = &x;
                if (!d || !t->richardson) {
                    s << " – | – |";
                    continue;
                }
                s << ' ' << formatted("%.4f", d->frequency_hz) << " | "
                  << percent(std::abs(d->frequency_hz - t->richardson->f0) / t->richardson->f0) << " |";
            }
            s << "\n";
        }
    }
    if (!study.notes.empty()) {
        s << "\n## Notes\n\n";
        for (const auto& n : study.notes) s << "- " << n << "\n";
    }
    s << "\n## Error against time\n\n";
    if (plot_note.empty())
        s << "![relative error of f1 and of the first ovalling mode against run time](error_vs_time.png)\n";
    else
        s << "(no picture: " << plot_note << ")\n";
    return s.str();
}

}  // namespace coremodal
