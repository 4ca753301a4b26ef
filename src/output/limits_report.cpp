#include "output/limits_report.hpp"

#include "common/format.hpp"
#include "common/join.hpp"
#include "output/csv.hpp"
#include "output/summary_json.hpp"
#include "output/text_file.hpp"

#include <sstream>

namespace coremodal {
namespace {

std::string speed_2f(double v) { return formatted("%.2f", v); }

Criterion criterion(size_t i) { return static_cast<Criterion>(i); }

std::string limits_rows(const LimitsResult& r) {
    std::string out = "diameter_mm,added,f1_hz,chuck_factor";
    for (int i = 0; i < kCriteria; ++i) {
        const std::string id = criterion_id(criterion(i));
        out += "," + id + "_m_s," + id + "_low_m_s," + id + "_high_m_s";
    }
    out += ",governing,safe_m_s,safe_low_m_s,safe_high_m_s\n";
    for (const LimitsPoint& p : r.points) {
        out += ten_digits(p.diameter_m * kMmPerM) + "," + (p.added ? "1" : "0") + "," + ten_digits(p.f1_hz) + "," +
               (p.chuck_factor ? ten_digits(*p.chuck_factor) : "");
        for (const CriterionSpeed& c : p.criteria) {
            const bool band = c.given || c.band_low_m_s > 0;
            out += "," + (c.given ? ten_digits(c.web_speed_m_s) : "") + "," + (band ? ten_digits(c.band_low_m_s) : "") +
                   "," + (band ? ten_digits(c.band_high_m_s) : "");
        }
        out += "," + csv_field(criterion_id(criterion(p.governing))) + "," + ten_digits(p.safe_m_s) + "," +
               ten_digits(p.safe_low_m_s) + "," + ten_digits(p.safe_high_m_s) + "\n";
    }
    return out;
}

std::string amplitude_rows(const LimitsResult& r) {
    std::string out = "diameter_mm,web_speed_m_s,amplitude_mm\n";
    for (const LimitsPoint& p : r.points)
        for (const auto& [v, a] : p.amplitude)
            out += ten_digits(p.diameter_m * kMmPerM) + "," + ten_digits(v) + "," + ten_digits(a * kMmPerM) + "\n";
    return out;
}

// Where the verdict mixes levels (a coupled scene): " (I-5 x0.7: coupled;
// ...)", else empty.
std::string criteria_levels(const LimitsResult& r) {
    if (r.points.empty()) return "";
    std::vector<std::string> out;
    for (const CriterionSpeed& c : r.points.front().criteria)
        if (!c.level.empty()) out.push_back(std::string(criterion_name(c.criterion)) + ": " + c.level);
    return out.empty() ? "" : " (" + join(out, "; ") + ")";
}

Json criterion_json(const CriterionSpeed& c) {
    Json t{{"id", criterion_id(c.criterion)},
           {"name", criterion_name(c.criterion)},
           {"given", c.given},
           {"limiting", c.limits}};
    if (c.given) t["web_speed_m_s"] = c.web_speed_m_s;
    if (c.given || c.band_low_m_s > 0) t["band_m_s"] = Json::array({c.band_low_m_s, c.band_high_m_s});
    if (!c.note.empty()) t["note"] = c.note;
    if (!c.level.empty()) t["level"] = c.level;
    return t;
}

Json point_json(const LimitsPoint& p) {
    Json criteria = Json::array(), peaks = Json::array();
    for (const CriterionSpeed& c : p.criteria) criteria.push_back(criterion_json(c));
    for (const ResponsePeak& k : p.peaks)
        peaks.push_back(Json{{"order", k.order},
                             {"web_speed_m_s", k.web_speed_m_s},
                             {"amplitude_mm", k.amplitude_m * kMmPerM},
                             {"mode_frequency_hz", k.mode_frequency_hz}});
    Json t{{"diameter_mm", p.diameter_m * kMmPerM},
           {"added_where_fast", p.added},
           {"band_sampled", p.band_sampled},
           {"f1_hz", p.f1_hz},
           {"criteria", criteria},
           {"governing", criterion_id(criterion(p.governing))},
           {"safe_web_speed_m_s", p.safe_m_s},
           {"safe_band_m_s", Json::array({p.safe_low_m_s, p.safe_high_m_s})},
           {"order1_mode", p.order1_mode},
           {"peaks", peaks}};
    if (p.chuck_factor) t["chuck_factor"] = Json{{"k", *p.chuck_factor}, {"f2_hz", p.f2_hz}};
    return t;
}

std::string summary_json(const Scene& scene, const LimitsResult& r) {
    Json points = Json::array(), inputs = Json::array();
    for (const LimitsPoint& p : r.points) points.push_back(point_json(p));
    for (const UncertainInput& i : r.inputs) {
        Json t{{"name", i.name}, {"range", i.range}, {"source", i.source}, {"applies", i.applies}};
        if (i.applies)
            t["samples"] = Json{{"low", i.low}, {"high", i.high}, {"unit", i.what}};
        else
            t["why_not"] = i.why_not;
        inputs.push_back(t);
    }
    const Verdict& v = r.verdict;
    Json verdict{{"line", verdict_line(r)},
                 {"safe_web_speed_m_s", v.speed_m_s},
                 {"roll_change_diameter_mm", v.diameter_m * kMmPerM},
                 {"governed_by", v.governed_by},
                 {"at_diameter_mm", v.at_diameter_m * kMmPerM},
                 {"band_m_s", Json::array({v.band_low_m_s, v.band_high_m_s})}};
    if (r.change)
        verdict["target"] = Json{{"web_speed_m_s", r.change->target_m_s},
                                 {"never_safe", r.change->never_safe},
                                 {"change_needed", r.change->needed},
                                 {"change_diameter_mm", r.change->diameter_m * kMmPerM},
                                 {"margin_at_full_roll_m_s", r.change->margin_m_s}};
    // The same head as every command's summary.json (output/summary_json.hpp).
    Json t = summary_head("limits", scene.name, scene.source_file, scene.description);
    t["model"] = Json{{"level", to_string(r.level)}, {"solves", r.n_solves}};
    t["verdict"] = verdict;
    t["inputs"] = Json{{"damping", r.damping_summary},
                       {"bow_mm", r.bow_m * kMmPerM},
                       {"limit_mm", r.limit_m * kMmPerM},
                       {"band", r.band},
                       {"uncertain", inputs}};
    t["points"] = points;
    t["warnings"] = string_array(r.warnings);
    t["notes"] = string_array(r.notes);
    t["assumptions"] = string_array(r.assumptions);
    t["timing_s"] = Json{{"total", r.seconds}};
    return json_text(t);
}

std::string cell(const CriterionSpeed& c, bool band) {
    if (!c.given) return "—";
    std::string s = speed_2f(c.web_speed_m_s);
    if (band) s += " (" + speed_2f(c.band_low_m_s) + "–" + speed_2f(c.band_high_m_s) + ")";
    return s;
}

std::string verdict_table(const LimitsResult& r) {
    std::ostringstream out;
    out << "| D (mm) | f1 (Hz) | k |";
    for (int i = 0; i < kCriteria; ++i) out << " " << criterion_name(criterion(i)) << " |";
    out << " governing | safe (m/s) |\n|---:|---:|---:|";
    for (int i = 0; i < kCriteria; ++i) out << "---:|";
    out << "---|---:|\n";
    for (const LimitsPoint& p : r.points) {
        out << "| " << formatted("%.1f", p.diameter_m * kMmPerM) << (p.added ? "*" : "") << " | "
            << formatted("%.2f", p.f1_hz) << " | " << (p.chuck_factor ? formatted("%.3f", *p.chuck_factor) : "—")
            << " |";
        for (const CriterionSpeed& c : p.criteria) out << " " << cell(c, r.band) << " |";
        out << " " << criterion_name(criterion(p.governing)) << " | **" << speed_2f(p.safe_low_m_s) << "** ("
            << speed_2f(p.safe_m_s) << ", " << speed_2f(p.safe_low_m_s) << "–" << speed_2f(p.safe_high_m_s)
            << ") |\n";
    }
    return out.str();
}

}  // namespace

void write_limits_tables(const std::filesystem::path& dir, const Scene& scene, const LimitsResult& result) {
    write_text_file(dir / "limits.csv", limits_rows(result));
    write_text_file(dir / "amplitude.csv", amplitude_rows(result));
    write_text_file(dir / "summary.json", summary_json(scene, result));
}

std::string limits_report_markdown(const Scene& scene, const LimitsResult& r, const std::vector<std::string>& pngs,
                                   const std::string& plot_problem) {
    std::ostringstream out;
    out << "# How fast may " << scene.name << " run: " << verdict_line(r) << "\n\n";
    out << "Every criterion at each rest-roll diameter (web speeds in m/s; in "
           "brackets the band from the uncertain "
           "inputs below; * a diameter added where the verdict changes fast). "
           "The safe speed is the conservative end "
           "(bold), then the point value and the band. Level: "
        << to_string(r.level) << criteria_levels(r) << ".\n\n";
    out << verdict_table(r) << "\n";
    for (const std::string& png : pngs) out << "![web speed against rest-roll diameter](" << png << ")\n\n";
    if (pngs.empty()) out << "(No picture: " << plot_problem << ")\n\n";
    if (!r.warnings.empty()) {
        out << "## Warnings\n\n";
        for (const std::string& w : r.warnings) out << "- " << w << "\n";
        out << "\n";
    }
    out << "## The uncertain inputs (the band)\n\n| input | range | source | "
           "sampled |\n|---|---|---|---|\n";
    for (const UncertainInput& i : r.inputs)
        out << "| " << i.name << " | " << i.range << " | " << i.source << " | "
            << (i.applies ? "yes" : "no: " + i.why_not) << " |\n";
    out << "\nA measured first resonance of the roll in its stand narrows the "
           "band: fit the stand to it with "
           "`coremodal fit` and run the verdict on the fitted case "
           "(docs/how-to/limits.md, \"Narrowing the band\").\n\n";
    out << "## Assumptions\n\n";
    for (const std::string& a : r.assumptions) out << "- " << a << "\n";
    out << "\n## Notes\n\n";
    for (const std::string& n : r.notes) out << "- " << n << "\n";
    out << "\nDamping: " << r.damping_summary << ". Tables: limits.csv, amplitude.csv (the mid-span orbit against "
        << "web speed at every diameter), summary.json. " << r.n_solves << " solves in "
        << minutes_or_seconds(r.seconds) << ".\n";
    return out.str();
}

std::string limits_console_summary(const Scene& scene, const LimitsResult& r) {
    std::ostringstream out;
    out << "limits: " << scene.name << ": " << r.points.size() << " rest-roll diameters at the " << to_string(r.level)
        << " level, " << r.n_solves << " solves, " << minutes_or_seconds(r.seconds) << "\n";
    out << "  D (mm)   f1 (Hz)  governing              safe (m/s)  band (m/s)\n";
    for (const LimitsPoint& p : r.points)
        out << "  " << formatted("%6.1f", p.diameter_m * kMmPerM) << "  " << formatted("%8.3f", p.f1_hz) << "  "
            << criterion_name(criterion(p.governing))
            << std::string(23 - std::string(criterion_name(criterion(p.governing))).size(), ' ')
            << formatted("%10.2f", p.safe_m_s) << "  " << speed_2f(p.safe_low_m_s) << "-" << speed_2f(p.safe_high_m_s)
            << (p.equivalent_f1_hz
                    ? "  (f1 of the axisymmetric equivalent " + formatted("%.3f", *p.equivalent_f1_hz) + " Hz)"
                    : std::string())
            << "\n";
    if (!criteria_levels(r).empty()) out << "  levels" << criteria_levels(r) << "\n";
    for (const std::string& a : r.assumptions)
        if (a.rfind("axisymmetric equivalent", 0) == 0) out << "  assumed: " << a << "\n";
    for (const std::string& w : r.warnings) out << "  warning: " << w << "\n";
    return out.str();
}

}  // namespace coremodal
