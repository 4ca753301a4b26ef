#include "output/response_report.hpp"

#include "common/format.hpp"
#include "modes/tracking.hpp"  // label_text
#include "output/csv.hpp"
#include "output/i5_speeds.hpp"
#include "output/summary_json.hpp"
#include "output/text_file.hpp"
#include "scene/level_traits.hpp"

#include <algorithm>
#include <sstream>

namespace coremodal {
namespace {

std::string m_s(double v) { return significant(v, 4) + " m/s"; }

std::string response_rows(const ResponseResult& r) {
    std::string out = "web_speed_m_s,speed_rpm,speed_hz,probe,position_m,amplitude_mm";
    for (int k : r.orders) out += ",order_" + std::to_string(k) + "_mm";
    out += "\n";
    for (const ResponsePoint& p : r.points)
        for (size_t i = 0; i < r.probes.size(); ++i) {
            out += ten_digits(p.web_speed_m_s) + "," + ten_digits(p.speed_hz * kRpmPerHz) + "," +
                   ten_digits(p.speed_hz) + "," + csv_field(r.probes[i].name) + "," + ten_digits(r.probes[i].z_m) +
                   "," + ten_digits(p.probes[i].total_m * kMmPerM);
            for (double a : p.probes[i].per_order_m) out += "," + ten_digits(a * kMmPerM);
            out += "\n";
        }
    return out;
}

std::string peak_rows(const ResponseResult& r) {
    std::string out = "order,web_speed_m_s,speed_rpm,speed_hz,excitation_hz,amplitude_mm,mode,mode_frequency_hz\n";
    for (const ResponsePeak& p : r.peaks)
        out += std::to_string(p.order) + "," + ten_digits(p.web_speed_m_s) + "," + ten_digits(p.speed_hz * kRpmPerHz) +
               "," + ten_digits(p.speed_hz) + "," + ten_digits(p.excitation_hz) + "," +
               ten_digits(p.amplitude_m * kMmPerM) + "," + csv_field(label_text(p.mode)) + "," +
               ten_digits(p.mode_frequency_hz) + "\n";
    return out;
}

Json peak_json(const ResponsePeak& p) {
    return Json{{"order", p.order},
                {"web_speed_m_s", p.web_speed_m_s},
                {"speed_rpm", p.speed_hz * kRpmPerHz},
                {"excitation_hz", p.excitation_hz},
                {"amplitude_mm", p.amplitude_m * kMmPerM},
                {"mode", label_text(p.mode)},
                {"mode_frequency_hz", p.mode_frequency_hz}};
}

// I-5 at rest in the shape every summary uses, and the speed at which the
// amplitude reaches the limit.
Json speeds_json(const ResponseResult& r) {
    Json t = safe_web_speed_json(r.speeds_at_rest);
    t["limit_mm"] = (r.limit_m * kMmPerM);
    t["probe"] = (r.probes.front().name);
    Json amplitude{{"reached", r.safe.reached}};
    if (r.safe.reached) {
        amplitude["below_range"] = (r.safe.below_range);
        amplitude["web_speed_m_s"] = (r.safe.web_speed_m_s);
        amplitude["speed_rpm"] = (r.safe.speed_hz * kRpmPerHz);
        amplitude["implied_safe_factor"] = (r.safe.implied_factor);
    }
    t["from_amplitude_limit"] = (amplitude);
    return t;
}

// [damping] as given, and the ratio each kept mode took (and from what).
Json damping_json(const ResponseResult& r) {
    const DampingSpec& d = r.damping;
    Json t{{"model", d.rayleigh ? "rayleigh" : "modal"}, {"source", d.source}, {"summary", r.damping_summary}};
    if (d.rayleigh) t["rayleigh"] = (Json{{"alpha_per_s", d.rayleigh->alpha}, {"beta_s", d.rayleigh->beta}});
    else t["ratio"] = (d.ratio);
    Json families = Json::object();
    for (const DampingSpec::FamilyRatio& f : d.families) families[f.family] = (f.ratio);
    t["families"] = (families);
    for (const DampingValue& v : r.damping_values) t[Json::json_pointer(v.path)] = v.value;  // only when the case names them
    Json given = Json::array(), kept = Json::array();
    for (const DampingSpec::ModeRatio& m : d.modes) given.push_back(Json{{"mode", m.mode}, {"ratio", m.ratio}});
    t["modes"] = (given);
    for (const ModeDamping& m : r.mode_damping) {
        Json rest = Json::array();
        for (int k : m.rest_modes) rest.push_back(k);
        Json mode{{"modes_at_rest", rest}, {"label", label_text(m.label)}, {"frequency_hz", m.frequency_hz},
                  {"zeta", m.zeta}, {"from", m.from}};
        for (const DampingValue& v : m.values) mode[Json::json_pointer(v.path)] = v.value;
        kept.push_back(mode);
    }
    t["kept_modes"] = (kept);
    return t;
}

// The columns the kept modes' own damping values make (each path once, in
// the order first met), and one mode's cells (0 where it has none).
std::vector<DampingValue> value_columns(const std::vector<ModeDamping>& modes) {
    std::vector<DampingValue> out;
    for (const ModeDamping& m : modes)
        for (const DampingValue& v : m.values)
            if (std::none_of(out.begin(), out.end(), [&](const DampingValue& c) { return c.path == v.path; })) out.push_back(v);
    return out;
}
std::string value_cells(const ModeDamping& m, const std::vector<DampingValue>& columns) {
    std::string out;
    for (const DampingValue& c : columns) out += " " + significant(m.value_of(c.path), 4) + " |";
    return out;
}

// The kept modes' damping as a table for people.
std::string damping_table(const ResponseResult& r) {
    const std::vector<DampingValue> columns = value_columns(r.mode_damping);
    std::string out = "| lateral mode | mode at rest | label | f at rest | zeta | from |", rule = "\n|---|---|---|---|---|---|";
    for (const DampingValue& c : columns) out += " " + c.heading + " |", rule += "---|";
    out += rule + "\n";
    for (size_t j = 0; j < r.mode_damping.size(); ++j) {
        const ModeDamping& m = r.mode_damping[j];
        std::string rest;
        for (int k : m.rest_modes) rest += (rest.empty() ? "" : ", ") + std::to_string(k);
        out += "| " + std::to_string(j + 1) + " | " + (rest.empty() ? "-" : rest) + " | " + label_text(m.label) + " | " +
               significant(m.frequency_hz, 5) + " Hz | " + significant(m.zeta, 4) + " | " + m.from + " |" +
               value_cells(m, columns) + "\n";
    }
    return out;
}

Json inputs_json(const ResponseSetup& setup, const ResponseResult& r) {
    const ExcitationSpec& x = setup.excitation;
    Json probes = Json::array(), orders = Json::array();
    for (const ResponseRange::Probe& p : r.probes) probes.push_back(Json{{"name", p.name}, {"z_m", p.z_m}});
    for (size_t k = 0; k < r.orders.size(); ++k) {
        Json sources = Json::array();
        for (const std::string& s : r.order_sources[k]) sources.push_back(s);
        orders.push_back(Json{{"order", r.orders[k]}, {"sources", sources}});
    }
    return Json{{"damping", damping_json(r)},
                {"excitation", Json{{"bow_mm", x.bow_m * kMmPerM},
                                    {"bow_shape", bow_shape_name(x.bow_shape)},
                                    {"unbalance_kg_m", x.unbalance_kg_m},
                                    {"eccentricity_mm", x.eccentricity_m * kMmPerM},
                                    {"ovality_mm", x.ovality_m * kMmPerM},
                                    {"gravity", x.gravity},
                                    {"ovality_stiffness_split", r.ovality_split},
                                    {"static_sag_mm", r.sag_m * kMmPerM}}},
                {"orders", orders},
                {"probes", probes},
                {"roll_outer_diameter_m", r.roll_outer_diameter},
                {"from_web_speed", r.from_web_speed}};
}

std::string summary_json(const Scene& scene, const ResponseSetup& setup, const ResponseResult& r) {
    Json peaks = Json::array();
    for (const ResponsePeak& p : r.peaks) peaks.push_back(peak_json(p));
    const ResponseChecks& c = r.checks;
    Json t = summary_head("response", scene.name, scene.source_file, scene.description);
    t["model"] = Json{{"level", to_string(r.level)}, {"dofs", r.n_dofs}, {"solver", r.solver}};
    t["effects"] = string_array(r.effects);
    t["notes"] = string_array(r.notes);
    t["assumptions"] = string_array(r.assumptions);
    t["inputs"] = inputs_json(setup, r);
    t["max_amplitude_mm"] = r.max_amplitude_m * kMmPerM;
    t["max_amplitude_web_speed_m_s"] = r.max_amplitude_web_speed_m_s;
    t["peaks"] = peaks;
    t["speeds"] = speeds_json(r);
    t["verification"] = Json{{"modes_all", c.n_modes_all},
                             {"modes_used", c.n_modes_used},
                             {"cutoff_hz", c.cutoff_hz},
                             {"speeds_checked", c.speeds_checked},
                             {"truncation_max_relative", c.truncation_max_relative},
                             {"direct_max_relative", c.direct_max_relative},
                             {"reference", c.complete_basis ? "complete basis" : "direct solve"}};
    t["timing_s"] = Json{{"total", r.solve_seconds}};
    return json_text(t);
}

std::string peak_table(const ResponseResult& r) {
    if (r.peaks.empty()) return "No resonance peak within the range.\n";
    std::string out = "| order | web speed | rotation | excitation | amplitude | mode (at rest) |\n|---|---|---|---|---|---|\n";
    for (const ResponsePeak& p : r.peaks)
        out += "| " + std::to_string(p.order) + " | " + m_s(p.web_speed_m_s) + " | " + rpm(p.speed_hz) + " | " +
               significant(p.excitation_hz, 5) + " Hz | " + millimetres(p.amplitude_m) + " | " + label_text(p.mode) +
               ", " + significant(p.mode_frequency_hz, 5) + " Hz |\n";
    return out;
}

std::string safe_speed_lines(const ResponseResult& r) {
    std::string out;
    const AmplitudeSafeSpeed& s = r.safe;
    const std::string limit = "+-" + millimetres(r.limit_m) + " at " + r.probes.front().name;
    if (!s.reached)
        out += "- amplitude limit " + limit + ": not reached up to " + m_s(r.points.back().web_speed_m_s) +
               " (largest " + millimetres(r.max_amplitude_m) + " at " + m_s(r.max_amplitude_web_speed_m_s) + ")\n";
    else if (s.below_range)
        out += "- amplitude limit " + limit + ": already exceeded at the first speed, " + m_s(s.web_speed_m_s) + "\n";
    else
        out += "- safe web speed from the amplitude limit " + limit + ": " + m_s(s.web_speed_m_s) + " (" +
               rpm(s.speed_hz) + "; implied I-5 factor " + formatted("%.3f", s.implied_factor) + ")\n";
    return out + i5_speed_lines(r.speeds_at_rest);
}

std::string inputs_lines(const ResponseSetup& setup, const ResponseResult& r) {
    std::ostringstream out;
    out << "- damping: " << r.damping_summary << "\n";
    for (size_t k = 0; k < r.orders.size(); ++k) {
        out << "- order " << r.orders[k] << ":";
        for (const std::string& s : r.order_sources[k]) out << " " << s;
        out << "\n";
    }
    const ExcitationSpec& x = setup.excitation;
    if (x.bow_m > 0)
        out << "- bow " << millimetres(x.bow_m) << " at mid-core, shape " << bow_shape_name(x.bow_shape) << "\n";
    if (x.unbalance_kg_m > 0)
        out << "- unbalance " << significant(x.unbalance_kg_m * kMmPerM, 4) << " kg*mm at mid-core\n";
    if (x.eccentricity_m > 0) out << "- rest roll eccentricity " << millimetres(x.eccentricity_m) << "\n";
    if (x.ovality_m > 0)
        out << "- ovality " << millimetres(x.ovality_m)
            << " (D_max - D_min): stiffness split eps = " << significant(r.ovality_split, 3) << "\n";
    if (x.gravity)
        out << "- static sag under gravity at " << r.probes.front().name << ": " << millimetres(r.sag_m) << "\n";
    return out.str();
}

}  // namespace

void write_response_tables(const std::filesystem::path& dir, const Scene& scene, const ResponseSetup& setup,
                           const ResponseResult& result) {
    write_text_file(dir / "response.csv", response_rows(result));
    write_text_file(dir / "peaks.csv", peak_rows(result));
    write_text_file(dir / "summary.json", summary_json(scene, setup, result));
}

std::string response_report_markdown(const Scene& scene, const ResponseSetup& setup, const ResponseResult& r,
                                     const std::vector<std::string>& pngs, const std::string& plot_problem) {
    std::ostringstream out;
    out << "# Forced response: " << scene.name << "\n\n";
    if (!scene.description.empty()) out << scene.description << "\n\n";
    out << level_traits(r.level).response_heading << r.n_dofs << " lateral DOFs; " << r.points.size() << " speeds from "
        << m_s(r.points.front().web_speed_m_s) << " to " << m_s(r.points.back().web_speed_m_s) << " web speed ("
        << rpm(r.points.front().speed_hz) << " to " << rpm(r.points.back().speed_hz)
        << ", Dp = " << significant(r.roll_outer_diameter * kMmPerM, 4) << " mm). Effects:";
    for (const std::string& e : r.effects) out << " " << e;
    out << ".\n\n" << inputs_lines(setup, r) << "\n";
    for (const std::string& n : r.notes) out << "- " << n << "\n";
    out << "\n## Safe web speed\n\n" << safe_speed_lines(r) << "\n";
    out << "## Resonance peaks\n\nLargest amplitude at " << r.probes.front().name << ": "
        << millimetres(r.max_amplitude_m) << " at " << m_s(r.max_amplitude_web_speed_m_s)
        << ". Peaks (refined between the sweep's speeds):\n\n"
        << peak_table(r) << "\n";
    out << "## Amplitude against web speed\n\n";
    for (const std::string& png : pngs) out << "![" << png << "](" << png << ")\n\n";
    if (pngs.empty()) out << "No picture: " << plot_problem << ".\n\n";
    out << "## Damping of the kept modes\n\n" << damping_table(r) << "\n";
    out << "## Assumptions\n\n";
    for (const std::string& a : r.assumptions) out << "- " << a << "\n";
    const ResponseChecks& c = r.checks;
    out << "\n## Verification\n\nAt " << c.speeds_checked << " speeds (" << kCheckSpeeds << " of the sweep and every "
        << "peak): the truncated sum (" << c.n_modes_used << " of " << c.n_modes_all << " modes, up to "
        << significant(c.cutoff_hz, 4) << " Hz, with the static part of the others) differs from the "
        << (c.complete_basis ? "complete basis" : "direct solve") << " by " << significant(c.truncation_max_relative, 2)
        << " (relative, amplitude at " << r.probes.front().name << "); the "
        << (c.complete_basis ? "complete basis" : "truncated sum") << " differs from the direct solve of "
        << level_traits(r.level).response_equation
        << " by " << significant(c.direct_max_relative, 2) << " (relative norm)"
        << (c.complete_basis ? "" : ": both are the truncation's effect (no complete basis of a mesh)") << ".\n\n"
        << "Tables: response.csv (per speed and probe), peaks.csv, summary.json. Solve "
        << minutes_or_seconds(r.solve_seconds) << ".\n";
    return out.str();
}

std::string response_console_summary(const Scene& scene, const ResponseResult& r) {
    std::ostringstream out;
    out << "response: " << scene.name << ": " << r.points.size() << " speeds, " << r.peaks.size() << " peaks, largest "
        << millimetres(r.max_amplitude_m) << " at " << m_s(r.max_amplitude_web_speed_m_s) << "\n";
    for (const ResponsePeak& p : r.peaks)
        out << "  peak order " << p.order << ": " << m_s(p.web_speed_m_s) << " (" << rpm(p.speed_hz) << ")  "
            << millimetres(p.amplitude_m) << "  " << label_text(p.mode) << " " << significant(p.mode_frequency_hz, 5)
            << " Hz\n";
    out << safe_speed_lines(r);
    out << "  checks: truncation " << significant(r.checks.truncation_max_relative, 2) << ", direct "
        << significant(r.checks.direct_max_relative, 2) << "\n";
    return out.str();
}

}  // namespace coremodal
