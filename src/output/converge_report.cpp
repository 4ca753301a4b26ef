#include "output/converge_report.hpp"

#include "common/format.hpp"
#include "output/csv.hpp"
#include "output/python_plots.hpp"
#include "output/results_folder.hpp"
#include "output/summary_json.hpp"
#include "output/text_file.hpp"

#include <cmath>
#include <cstdint>
#include <iostream>
#include <sstream>

namespace coremodal {
namespace {

// Timing columns of the CSV: six significant digits (beam levels take ~1e-3 s).
std::string csv_seconds(double s) { return formatted("%.6g", s); }

// The level's columns of a converge.csv row, up to peak_memory_mb.
std::string csv_level_cells(const std::string& model, const LevelResult& l) {
    const Timing& t = l.median_s;
    std::ostringstream s;
    s << model << ',' << l.step.k << ',' << l.step.counts << ',' << formatted("%.6g", l.step.h) << ',' << l.n_dofs
      << ',' << l.runs << ',' << csv_seconds(t.mesh) << ',' << csv_seconds(t.assemble) << ','
      << csv_seconds(t.factor_and_solve) << ',' << csv_seconds(t.classify) << ',' << csv_seconds(t.total) << ','
      << csv_seconds(l.median_cpu_s) << ',' << csv_seconds(l.median_solver_s.factor_s) << ','
      << csv_seconds(l.median_solver_s.solve_s) << ',' << csv_seconds(l.median_solver_s.orthogonalize_s) << ','
      << formatted("%.1f", l.peak_memory_mb);
    return s.str();
}

// A tracked mode's columns of the row of level i, from mode to relative_error_vs_solid.
std::string csv_mode_cells(const TrackedMode& mode, std::size_t i, const std::vector<std::optional<double>>& vs_solid) {
    std::ostringstream s;
    s << csv_field(mode.key.text()) << ',' << mode.role << ',' << mode.key.type << ',' << mode.key.n << ','
      << mode.key.m << ',' << mode.key.occurrence << ',' << optional_number(mode.frequency_hz[i]) << ',';
    if (mode.richardson) {
        const Richardson& r = *mode.richardson;
        s << formatted("%.10g", r.f0) << ',' << formatted("%.4g", r.error_estimate) << ','
          << (r.extrapolated ? formatted("%.4g", r.order) : std::string()) << ',' << (r.asymptotic ? "yes" : "no");
    } else {
        s << ",,,";
    }
    s << ',' << optional_number(mode.relative_error[i], "%.4g") << ','
      << (vs_solid.empty() ? std::string() : optional_number(vs_solid[i], "%.4g"));
    return s.str();
}

// Each tracked mode's error against the solid's f0 per level (empty for the solid itself).
std::vector<std::optional<double>> vs_solid(const ModelStudy& model, const TrackedMode& mode,
                                            const ConvergeStudy& study) {
    return model.traits.reference ? std::vector<std::optional<double>>() : error_against_solid(mode, study.models);
}

}  // namespace

std::string converge_csv(const ConvergeStudy& study) {
    std::ostringstream s;
    s << "model,k,mesh,h,dofs,runs,mesh_s,assemble_s,factor_and_solve_s,classify_s,total_s,cpu_s,factorizations_s,"
         "triangular_solves_s,orthogonalization_s,peak_memory_mb,"
         "mode,role,type,n,m,occurrence,frequency_hz,extrapolated_hz,error_estimate_hz,observed_order,asymptotic,"
         "relative_error,relative_error_vs_solid\n";
    for (const auto& model : study.models) {
        std::vector<std::vector<std::optional<double>>> errors;
        for (const auto& mode : model.modes) errors.push_back(vs_solid(model, mode, study));
        for (std::size_t i = 0; i < model.levels.size(); ++i) {
            const std::string level = csv_level_cells(model.model, model.levels[i]);
            for (std::size_t j = 0; j < model.modes.size(); ++j)
                s << level << ',' << csv_mode_cells(model.modes[j], i, errors[j]) << '\n';
        }
    }
    return s.str();
}

namespace {

Json timing_table(const Timing& t) {
    return Json{{"mesh", t.mesh},
                       {"assemble", t.assemble},
                       {"factor_and_solve", t.factor_and_solve},
                       {"classify", t.classify},
                       {"total", t.total}};
}

Json richardson_table(const Richardson& r) {
    Json t{{"extrapolated", r.extrapolated},
                  {"order", r.order},
                  {"f0_hz", r.f0},
                  {"error_estimate_hz", r.error_estimate},
                  {"relative_error_estimate", r.error_estimate / std::abs(r.f0)},
                  {"asymptotic", r.asymptotic},
                  {"note", r.note}};
    if (r.previous_order) t["previous_order"] = (*r.previous_order);
    if (r.previous_f0) t["previous_f0_hz"] = (*r.previous_f0);
    if (r.f0_uncertainty) t["f0_uncertainty_hz"] = (*r.f0_uncertainty);
    return t;
}

Json level_table(const LevelResult& l) {
    return Json{{"k", l.step.k},
                       {"h", l.step.h},
                       {"mesh", l.step.counts},
                       {"n_dofs", l.n_dofs},
                       {"runs", l.runs},
                       {"timing_s", timing_table(l.median_s)},
                       {"cpu_s", l.median_cpu_s},
                       {"solver_s", Json{{"factorizations", l.median_solver_s.factor_s},
                                                {"triangular_solves", l.median_solver_s.solve_s},
                                                {"orthogonalization", l.median_solver_s.orthogonalize_s}}},
                       {"peak_memory_mb", l.peak_memory_mb},
                       {"complete", l.complete},
                       {"repeat_spread", l.max_repeat_spread}};
}

Json mode_table(const ModelStudy& model, const TrackedMode& mode, const ConvergeStudy& study) {
    const auto errors = vs_solid(model, mode, study);
    Json values = Json::array();
    for (std::size_t i = 0; i < model.levels.size(); ++i) {
        if (!mode.frequency_hz[i]) continue;
        Json v{{"level", static_cast<int64_t>(i)}, {"frequency_hz", *mode.frequency_hz[i]}};
        if (mode.relative_error[i]) v["relative_error"] = (*mode.relative_error[i]);
        if (!errors.empty() && errors[i]) v["error_vs_solid"] = (*errors[i]);
        values.push_back(v);
    }
    Json t{{"id", mode.key.text()}, {"type", mode.key.type},         {"n", mode.key.n},
                  {"m", mode.key.m},       {"occurrence", mode.key.occurrence}, {"role", mode.role},
                  {"values", values}};
    if (mode.richardson) t["richardson"] = (richardson_table(*mode.richardson));
    return t;
}

Json model_table(const ModelStudy& model, const ConvergeStudy& study) {
    Json levels = Json::array(), modes = Json::array();
    for (const auto& l : model.levels) levels.push_back(level_table(l));
    for (const auto& mode : model.modes) modes.push_back(mode_table(model, mode, study));
    Json m{{"model", model.model},
                  {"ladder", model.ladder_note},
                  {"refined_dimensions", model.refined_dimensions},
                  {"levels", levels},
                  {"modes", modes}};
    if (!model.traits.timing_parts.empty()) m["timing_parts"] = model.traits.timing_parts;
    Json unseen = Json::array();
    for (const auto& [role, why] : model.unseen_roles) unseen.push_back(Json{{"role", role}, {"reason", why}});
    m["not_in_model"] = (unseen);
    if (model.time_exponent) m["time_exponent"] = (*model.time_exponent);
    if (model.memory_exponent) m["memory_exponent"] = (*model.memory_exponent);
    return m;
}

Json model_errors_array(const ConvergeStudy& study) {
    Json errors = Json::array();
    for (const ModelError& e : model_errors(study.models))
        errors.push_back(Json{{"model", e.model},
                                     {"role", e.role},
                                     {"id", e.id},
                                     {"solid_id", e.solid_id},
                                     {"f0_hz", e.f0_hz},
                                     {"solid_f0_hz", e.solid_f0_hz},
                                     {"model_error", e.relative},
                                     {"known_to", e.known_to}});
    return errors;
}

Json checks_array(const ConvergeStudy& study) {
    Json checks = Json::array();
    const ModelStudy* solid = find_reference(study.models);
    for (const auto& c : study.checks) {
        Json modes = Json::array();
        for (const auto& d : distinct_modes(c.result.modes)) {
            Json v{{"id", d.key.text()}, {"frequency_hz", d.frequency_hz}};
            if (solid)
                for (const auto& t : solid->modes)
                    if (t.key == d.key && t.richardson) {
                        v["relative_error"] = (std::abs(d.frequency_hz - t.richardson->f0) / t.richardson->f0);
                        v["role"] = (t.role);
                    }
            modes.push_back(v);
        }
        checks.push_back(Json{{"name", c.name},
                                     {"mesh", c.mesh},
                                     {"n_dofs", c.result.n_dofs},
                                     {"timing_s", timing_table(c.result.median_s)},
                                     {"peak_memory_mb", c.result.peak_memory_mb},
                                     {"modes", modes}});
    }
    return checks;
}

}  // namespace

std::string converge_json(const ConvergeStudy& study) {
    Json models = Json::array();
    for (const auto& model : study.models) models.push_back(model_table(model, study));
    Json root = summary_head("converge", study.case_name, study.source_file, "");
    root["n_modes"] = study.n_modes;
    root["repeats"] = study.repeats;
    root["repeat_limit_s"] = study.repeat_limit_s;
    root["timing_s"] = Json{{"total", study.total_time_s}, {"ladder", study.ladder_time_s}};
    root["load_average"] = Json::array({study.load_start, study.load_end});
    root["n_cores"] = study.n_cores;
    root["models"] = models;
    root["model_errors"] = model_errors_array(study);
    root["checks"] = checks_array(study);
    root["notes"] = string_array(study.notes);
    return json_text(root);
}

void write_converge_results(const ConvergeStudy& study, const std::filesystem::path& out, const ConvergeWriting& how,
                            std::ostream& progress) {
    ResultsFolder folder(out, how.force);
    write_text_file(folder.file("converge.csv"), converge_csv(study));
    write_text_file(folder.file("converge.json"), converge_json(study));
    const std::string plot_note = how.plots ? run_python_plot("converge-plot", folder.dir(), {"--quiet"})
                                            : "switched off (--no-plots)";
    if (!plot_note.empty() && how.plots) std::cerr << "coremodal: warning: no error_vs_time.png: " << plot_note << std::endl;
    write_text_file(folder.file("converge.md"), converge_markdown(study, plot_note));
    folder.commit();
    if (!how.quiet) progress << "results: " << out.string() << " (converge.md, converge.csv, converge.json"
                         << (plot_note.empty() ? ", error_vs_time.png" : "") << ")" << std::endl;
}

}  // namespace coremodal
