// The tables, summary.json, report.md and console steps of `coremodal durability`.
#include "output/durability_report.hpp"

#include "common/format.hpp"
#include "output/summary_json.hpp"
#include "output/text_file.hpp"

#include <cmath>
#include <sstream>

namespace coremodal {
namespace {

constexpr const char* kPaper = "M. Ilomäki, \"On the durability of cores and rest roll dynamics\"";

std::string g(double v, int digits = 5) { return significant(v, digits); }
double pow10(double v) { return std::pow(10.0, v); }
std::string unit(const DurabilityData& d) { return " " + d.weight_unit; }
std::string weight_column(const DurabilityData& d) { return d.weight_name + "_" + d.weight_unit; }

std::string points_csv(const DurabilityData& d, const DurabilityAnalysis& a) {
    std::ostringstream out;
    out << "line,cycles," << weight_column(d) << ",fit_" << d.weight_unit << ",log10_residual\n";
    for (std::size_t i = 0; i < d.cycles.size(); ++i)
        out << d.lines[i] << "," << g(d.cycles[i], 10) << "," << g(d.weights[i], 10) << ","
            << g(a.fit.weight(d.cycles[i]), 8) << "," << g(a.fit.log_residuals[i], 8) << "\n";
    return out.str();
}

std::string probability_column(double p, const DurabilityData& d) { return "P_" + g(p, 6) + "_" + d.weight_unit; }

std::string curves_csv(const DurabilityData& d, const DurabilityAnalysis& a) {
    std::ostringstream out;
    const std::string u = d.weight_unit;
    out << "cycles,fit_" << u << ",confidence_lower_" << u << ",confidence_upper_" << u << ",prediction_lower_" << u
        << ",prediction_upper_" << u << ",confident_mean_" << u;
    for (const ProbabilityLimit& l : a.limits) out << "," << probability_column(l.probability, d);
    out << "\n";
    for (double x : a.curve_cycles) {
        const Band c = confidence_band(a.fit, x, a.confidence), p = prediction_band(a.fit, x, a.confidence);
        out << g(x, 8) << "," << g(a.fit.weight(x), 8) << "," << g(pow10(c.lower), 8) << "," << g(pow10(c.upper), 8)
            << "," << g(pow10(p.lower), 8) << "," << g(pow10(p.upper), 8) << ","
            << g(pow10(confident_mean_log_weight(a.fit, x, a.confidence)), 8);
        for (const ProbabilityLimit& l : a.limits)
            out << "," << g(pow10(reduced_log_weight(a.fit, x, a.confidence, l.probability)), 8);
        out << "\n";
    }
    return out.str();
}

std::string allowed_csv(const DurabilityData& d, const DurabilityAnalysis& a) {
    std::ostringstream out;
    out << "cycles";
    for (const ProbabilityLimit& l : a.limits) out << "," << probability_column(l.probability, d);
    out << "\n";
    for (std::size_t i = 0; i < a.table_cycles.size(); ++i) {
        out << g(a.table_cycles[i]);
        for (const ProbabilityLimit& l : a.limits) out << "," << g(l.allowed_weights[i], 6);
        out << "\n";
    }
    return out.str();
}

Json band_json(const Band& b) { return Json::array({b.lower, b.upper}); }

std::string summary_json(const DurabilityData& d, const DurabilityAnalysis& a, double seconds) {
    Json limits = Json::array();
    for (const ProbabilityLimit& l : a.limits)
        limits.push_back(Json{{"failure_probability", l.probability},
                              {"lambda", l.factors.lambda},
                              {"safety_factor", l.factors.log_space},
                              {"relative_deviation", l.factors.relative_deviation},
                              {"safety_factor_eq30", l.factors.paper_eq30},
                              {"allowed_weights", l.allowed_weights}});
    const PowerLawFit& f = a.fit;
    // The same head as every command's summary.json (output/summary_json.hpp);
    // the data file is the case.
    Json j = summary_head("durability", std::filesystem::path(d.source).stem().string(), d.source,
                          "winding-unwinding simulator results, " + std::to_string(f.n) + " points, test chuck " +
                              g(d.chuck_length_m * 1e3, 4) + " mm " + d.chuck_type);
    j["source"] = kPaper;
    j["data"] = Json{{"file", d.source},
                     {"points", f.n},
                     {"chuck_length_m", d.chuck_length_m},
                     {"chuck_type", d.chuck_type},
                     {"weight", d.weight_name},
                     {"weight_unit", d.weight_unit},
                     {"weight_unit_newton", d.weight_unit_newton}};
    j["fit"] = Json{{"b0", f.b0},
                    {"b1", f.b1},
                    {"log10_b0", f.log_b0},
                    {"s_log", f.s_log},
                    {"degrees_of_freedom", f.degrees_of_freedom()},
                    {"mean_log10_cycles", f.mean_log_x},
                    {"sxx", f.sxx},
                    {"intervals", Json{{"b1", band_json(a.intervals.b1)},
                                       {"log10_b0", band_json(a.intervals.log_b0)},
                                       {"s_log", band_json(a.intervals.s_log)}}}};
    j["confidence"] = Json{{"level", a.confidence}, {"t2", a.t2}, {"h1", a.h1}, {"upper_s_log", a.upper_sd_log}};
    j["table_cycles"] = a.table_cycles;
    j["limits"] = limits;
    j["timing_s"] = Json{{"total", seconds}};
    return json_text(j);
}

}  // namespace

void write_durability_tables(const std::filesystem::path& dir, const DurabilityData& data,
                             const DurabilityAnalysis& a, double seconds) {
    write_text_file(dir / "points.csv", points_csv(data, a));
    write_text_file(dir / "curves.csv", curves_csv(data, a));
    write_text_file(dir / "allowed_weights.csv", allowed_csv(data, a));
    write_text_file(dir / "summary.json", summary_json(data, a, seconds));
}

std::vector<std::string> durability_steps(const DurabilityData& d, const DurabilityAnalysis& a) {
    const PowerLawFit& f = a.fit;
    const int dof = f.degrees_of_freedom();
    const std::string pct = g(100 * a.confidence, 4) + " %";
    std::vector<std::string> steps = {
        "1. data: " + std::to_string(f.n) + " points from " + d.source + ", " + d.weight_name + " in " + d.weight_unit +
            ", test chuck " + g(d.chuck_length_m * 1e3, 4) + " mm " + d.chuck_type,
        "2. power-law fit y = b0 x^b1 in log10-log10 ({16}-{20}): b0 = " + g(f.b0) + unit(d) + ", b1 = " + g(f.b1),
        "3. residuals in log10 y ({21} taken in log y), S_log = " + g(f.s_log) + " ({24}, n - 2 = " +
            std::to_string(dof) + " degrees of freedom)",
        "4. mean at confidence C = " + pct + " ({22}, {23}): t2 = " + g(a.t2) + " (Student's t, " +
            std::to_string(dof) + " degrees of freedom), at the centroid log10 y lowered by " +
            g(a.t2 * f.s_log / std::sqrt(f.n)),
        "5. upper standard deviation at C = " + pct + " ({25}, {26}): h1 = " + g(a.h1) + " (chi-squared, " +
            std::to_string(dof) + " degrees of freedom), S_C = sqrt((n-2)/h1) S_log = " + g(a.upper_sd_log)};
    std::string lambdas = "6. lambda from the failure probability ({27}):";
    std::string reduced = "7. reduced curves log10 y_R = log10 y_C + lambda S_C ({28}, {32}), safety factor " +
                          std::string("10^(-lambda S_C) ({30}: 1/(1 + lambda S_Crel), S_Crel = ln10 S_C = ") +
                          g(a.limits.empty() ? 0 : a.limits[0].factors.relative_deviation, 4) + "):";
    for (const ProbabilityLimit& l : a.limits) {
        lambdas += " P = " + g(l.probability) + ": " + formatted("%.3f", l.factors.lambda) + ";";
        reduced += " P = " + g(l.probability) + ": " + formatted("%.3f", l.factors.log_space) + " (" +
                   (l.factors.paper_eq30 > 0 ? formatted("%.3f", l.factors.paper_eq30) : std::string("none")) + ");";
    }
    lambdas.pop_back();
    reduced.pop_back();
    steps.push_back(lambdas);
    steps.push_back(reduced);
    std::string table = "8. allowed " + d.weight_name + " at " + g(a.table_cycles.back()) + " cycles:";
    for (const ProbabilityLimit& l : a.limits)
        table += " P = " + g(l.probability) + ": " + g(l.allowed_weights.back(), 4) + unit(d) + ";";
    table.pop_back();
    steps.push_back(table);
    return steps;
}

std::string durability_report_markdown(const DurabilityData& d, const DurabilityAnalysis& a,
                                       const std::vector<std::string>& pngs, const std::string& plot_problem) {
    const PowerLawFit& f = a.fit;
    std::ostringstream md;
    md << "# Core durability: " << d.source << "\n\n"
       << "The statistics of " << kPaper << ", equations {16}-{32}, as docs/how-to/durability.md reads them: "
       << "the fit and every spread in log10 of the weight, n - 2 degrees of freedom.\n\n"
       << "## Steps\n\n";
    for (const std::string& s : durability_steps(d, a)) md << "- " << s << "\n";
    md << "\n## The fit\n\n| quantity | value | " << g(100 * a.confidence, 4) << " % interval |\n|---|---|---|\n"
       << "| b0 (" << d.weight_unit << " at 1 cycle) | " << g(f.b0) << " | " << g(pow10(a.intervals.log_b0.lower))
       << " - " << g(pow10(a.intervals.log_b0.upper)) << " |\n"
       << "| b1 | " << g(f.b1) << " | " << g(a.intervals.b1.lower) << " - " << g(a.intervals.b1.upper) << " |\n"
       << "| S_log | " << g(f.s_log) << " | " << g(a.intervals.s_log.lower) << " - " << g(a.intervals.s_log.upper)
       << " |\n\n"
       << "Test chuck: " << g(d.chuck_length_m * 1e3, 4) << " mm, " << d.chuck_type
       << ". The weights below hold for cores on this chuck; `coremodal select` scales them to a stand's chuck.\n\n";
    md << "## Allowed " << d.weight_name << " [" << d.weight_unit << "]\n\n| cycles |";
    for (const ProbabilityLimit& l : a.limits) md << " P = " << g(l.probability) << " |";
    md << "\n|---|";
    for (std::size_t i = 0; i < a.limits.size(); ++i) md << "---|";
    md << "\n";
    for (std::size_t i = 0; i < a.table_cycles.size(); ++i) {
        md << "| " << g(a.table_cycles[i]) << " |";
        for (const ProbabilityLimit& l : a.limits) md << " " << g(l.allowed_weights[i], 4) << " |";
        md << "\n";
    }
    md << "\n| P | lambda ({27}) | safety factor 10^(-lambda S_C) | {30} with S_Crel = " << g(a.limits.empty() ? 0 : a.limits[0].factors.relative_deviation, 4)
       << " |\n|---|---|---|---|\n";
    for (const ProbabilityLimit& l : a.limits)
        md << "| " << g(l.probability) << " | " << formatted("%.3f", l.factors.lambda) << " | "
           << formatted("%.3f", l.factors.log_space) << " | "
           << (l.factors.paper_eq30 > 0 ? formatted("%.3f", l.factors.paper_eq30) : std::string("not positive"))
           << " |\n";
    md << "\n## Picture\n\n";
    for (const std::string& p : pngs) md << "![" << p << "](" << p << ")\n";
    if (pngs.empty()) md << "No picture: " << plot_problem << "\n";
    md << "\nFiles: points.csv (data, fit, log10 residuals), curves.csv (fit, limits, reduced curves), "
          "allowed_weights.csv, summary.json.\n";
    return md.str();
}

}  // namespace coremodal
