#include "output/campbell_report.hpp"

#include "common/format.hpp"
#include "modes/tracking.hpp"  // label_text
#include "output/csv.hpp"
#include "output/i5_speeds.hpp"
#include "output/summary_json.hpp"
#include "output/text_file.hpp"
#include "scene/level_traits.hpp"

#include <algorithm>
#include <map>
#include <optional>
#include <cstdio>
#include <sstream>

namespace coremodal {
namespace {

std::string whirl_word(Whirl w) { return w == Whirl::none ? "" : whirl_name(w); }

// A value that may be absent (a rigid mode's damping): empty then.
std::string num_or_empty(const std::optional<double>& v) { return v ? ten_digits(*v) : ""; }

std::string campbell_rows(const CampbellResult& r) {
    std::string out = "speed_rpm,speed_hz,track,frequency_hz,whirl,label,relative_residual";
    out += r.damped ? ",damped_frequency_hz,damping_ratio\n" : "\n";  // only with [damping]
    for (const CampbellPoint& p : r.points)
        for (const CampbellMode& m : p.modes) {
            out += ten_digits(p.speed_hz * kRpmPerHz) + "," + ten_digits(p.speed_hz) + "," + std::to_string(m.track) +
                   "," + ten_digits(m.frequency_hz) + "," + whirl_word(m.whirl) + "," + csv_field(label_text(m.label)) +
                   "," + ten_digits(m.relative_residual);
            if (r.damped) out += "," + num_or_empty(m.damped_frequency_hz) + "," + num_or_empty(m.damping_ratio);
            out += "\n";
        }
    return out;
}

// [damping]: what entered, the lowest ratio of every track over the sweep
// and where, and the damped modes' largest residual.
Json damping_json(const CampbellResult& r) {
    Json tracks = Json::array();
    std::map<int, std::pair<const CampbellMode*, double>> lowest;  // track: mode, speed (Hz)
    for (const CampbellPoint& p : r.points)
        for (const CampbellMode& m : p.modes) {
            if (!m.damping_ratio) continue;
            auto [it, fresh] = lowest.try_emplace(m.track, &m, p.speed_hz);
            if (!fresh && *m.damping_ratio < *it->second.first->damping_ratio) it->second = {&m, p.speed_hz};
        }
    for (const auto& [track, low] : lowest)
        tracks.push_back(Json{{"track", track},
                              {"label", label_text(low.first->label)},
                              {"lowest_damping_ratio", *low.first->damping_ratio},
                              {"at_speed_rpm", low.second * kRpmPerHz},
                              {"damped_frequency_hz", *low.first->damped_frequency_hz}});
    return Json{{"terms", string_array(r.damping)},
                {"critical_speeds", "undamped"},
                {"tracks", tracks},
                {"max_relative_residual", r.max_damped_residual}};
}

std::string critical_rows(const CampbellResult& r) {
    std::string out = "order,speed_rpm,speed_hz,frequency_hz,web_speed_m_s,track,whirl,label,refined,"
                      "interpolated_speed_rpm,source\n";
    for (const WhirlCrossing& c : r.critical)
        out += std::to_string(c.order) + "," + ten_digits(c.speed_hz * kRpmPerHz) + "," + ten_digits(c.speed_hz) + "," +
               ten_digits(c.frequency_hz) + "," + ten_digits(c.web_speed_m_s) + "," + std::to_string(c.track) + "," +
               whirl_word(c.whirl) + "," + csv_field(label_text(c.label)) + "," + (c.refined ? "true" : "false") + "," +
               ten_digits(c.interpolated_speed_hz * kRpmPerHz) + "," + crossing_source_name(c.source) + "\n";
    return out;
}

Json critical_json(const WhirlCrossing& c, const CampbellResult& r) {
    Json t{{"order", c.order},          {"speed_rpm", c.speed_hz * kRpmPerHz},
                       {"speed_hz", c.speed_hz},    {"frequency_hz", c.frequency_hz},
                       {"web_speed_m_s", c.web_speed_m_s}, {"track", c.track},
                       {"whirl", whirl_word(c.whirl)}, {"label", label_text(c.label)},
                       {"refined", c.refined}, {"interpolated_speed_rpm", c.interpolated_speed_hz * kRpmPerHz},
                       {"source", crossing_source_name(c.source)}};
    if (r.operating_hz)
        t["inside_operating_range"] = c.speed_hz >= (*r.operating_hz)[0] && c.speed_hz <= (*r.operating_hz)[1];
    return t;
}

// I-5 at rest in the shape every summary uses, and the first order-1 critical speed.
Json speeds_json(const CampbellResult& r) {
    Json t = safe_web_speed_json(r.speeds_at_rest);
    if (!r.speeds_at_rest.given()) return t;
    if (const WhirlCrossing* c = r.first_order_one()) t["first_order_1_critical"] = critical_json(*c, r);
    return t;
}

std::string summary_json(const Scene& scene, const RotationSpec& rotation, const CampbellResult& r) {
    Json speeds = Json::array(), critical = Json::array(), orders = Json::array();
    for (const CampbellPoint& p : r.points) speeds.push_back(p.speed_hz * kRpmPerHz);
    for (const WhirlCrossing& c : r.critical) critical.push_back(critical_json(c, r));
    for (int k : r.excitation_orders) orders.push_back(k);
    Json t = summary_head("campbell", scene.name, scene.source_file, scene.description);
    t["model"] = Json{{"level", to_string(r.level)}, {"dofs", r.n_dofs}, {"solver", r.solver}};
    t["effects"] = string_array(r.effects);
    t["notes"] = string_array(r.notes);
    t["rotation"] = Json{{"speeds_rpm", speeds},
                         {"excitation_orders", orders},
                         {"roll_outer_diameter_m", r.roll_outer_diameter},
                         {"from_web_speed", r.from_web_speed},
                         {"centrifugal_stiffening_requested", rotation.centrifugal_stiffening},
                         {"sweep_end", r.sweep_end}};
    if (r.operating_hz)
        t["rotation"]["operating_speeds_rpm"] = Json{(*r.operating_hz)[0] * kRpmPerHz, (*r.operating_hz)[1] * kRpmPerHz};
    t["critical_speeds"] = critical;
    t["speeds"] = speeds_json(r);
    t["verification"] =
        Json{{"max_relative_residual", r.max_relative_residual}, {"complete", true}, {"completeness", r.completeness}};
    if (r.damped) t["damping"] = damping_json(r);
    t["timing_s"] = Json{{"total", r.solve_seconds}};
    return json_text(t);
}

// "critical speed X rpm inside the operating range" for each one there, or
// that none is; nothing without an operating range.
std::string operating_range_lines(const CampbellResult& r) {
    if (!r.operating_hz) return "";
    const auto [low, high] = *r.operating_hz;
    const std::string range = rpm(low) + " to " + rpm(high);
    std::string out;
    for (const WhirlCrossing* c : r.inside_operating_range())
        out += "- WARNING: critical speed " + rpm(c->speed_hz) + " inside the operating range " + range + " (order " +
               std::to_string(c->order) + ", " + significant(c->frequency_hz, 5) + " Hz" +
               (c->whirl == Whirl::none ? "" : " " + whirl_word(c->whirl)) + ")\n";
    if (out.empty()) out = "- no critical speed inside the operating range " + range + "\n";
    // The sweep may stop short (sweep_end): above its last speed nothing is known.
    if (r.points.back().speed_hz < high)
        out += "- the sweep ends at " + rpm(r.points.back().speed_hz) + ", below the operating range's top: critical "
               "speeds above it are not known\n";
    return out;
}

bool from_sweep(const WhirlCrossing& c) { return c.source == CrossingSource::sweep; }

std::string refinement_sentence(const CampbellResult& r) {
    const long swept = std::count_if(r.critical.begin(), r.critical.end(), from_sweep);
    const long exact = static_cast<long>(r.critical.size()) - swept;
    const std::string pencil = exact == 0 ? "" : std::to_string(exact) + " critical speeds from the pencil of zero "
                                                 "rotating-frame frequency (exact, counted by inertia; see the notes).\n\n";
    if (swept == 0) return pencil;
    const long refined = std::count_if(r.critical.begin(), r.critical.end(),
                                       [](const WhirlCrossing& c) { return from_sweep(c) && c.refined; });
    std::string out = pencil + "Critical speeds of the sweep: " + std::to_string(refined) + " of " + std::to_string(swept) +
                      " refined by solving inside the sweep's bracket until it is narrower than " +
                      significant(kCrossingSpeedTolerance, 1) + " of the speed";
    if (refined < swept) out += "; the others are linear interpolations (the track was lost inside the bracket)";
    return out + ".\n\n";
}

std::string critical_table(const CampbellResult& r) {
    if (r.critical.empty()) return "No excitation line crosses a natural frequency within the sweep.\n";
    std::string out = "| order | speed | web speed at Dp | frequency | whirl | mode (at rest) | from |\n"
                      "|---|---|---|---|---|---|---|\n";
    for (const WhirlCrossing& c : r.critical)
        out += "| " + std::to_string(c.order) + " | " + rpm(c.speed_hz) + " | " + significant(c.web_speed_m_s, 4) +
               " m/s | " + significant(c.frequency_hz, 5) + " Hz | " + whirl_word(c.whirl) + " | " +
               label_text(c.label) + " | " + (from_sweep(c) ? "sweep" : "pencil (exact)") + " |\n";
    return out;
}

// The modes at the last speed: with one speed (`run`), the modes at that speed.
std::string last_speed_table(const CampbellResult& r) {
    const CampbellPoint& p = r.points.back();
    std::string out = "| mode | track | frequency | whirl | mode at rest | relative residual |";
    out += r.damped ? " damped frequency | damping ratio |\n|---|---|---|---|---|---|---|---|\n" : "\n|---|---|---|---|---|---|\n";
    for (size_t i = 0; i < p.modes.size(); ++i) {
        const CampbellMode& m = p.modes[i];
        out += "| " + std::to_string(i + 1) + " | " + std::to_string(m.track) + " | " + significant(m.frequency_hz, 6) +
               " Hz | " + whirl_word(m.whirl) + " | " + label_text(m.label) + " | " + significant(m.relative_residual, 2) +
               " |";
        if (r.damped)
            out += m.damping_ratio ? " " + significant(*m.damped_frequency_hz, 6) + " Hz | " + significant(*m.damping_ratio, 4) + " |"
                                   : " | (rigid) |";
        out += "\n";
    }
    return out;
}

// [damping]: which damping entered and how (empty without).
std::string damping_lines(const CampbellResult& r) {
    if (!r.damped) return "";
    std::string out = "Damping ([damping]; campbell.csv's damping_ratio and damped_frequency_hz columns; largest "
                      "relative residual of a damped mode " + significant(r.max_damped_residual, 2) + "):\n\n";
    for (const std::string& line : r.damping) out += "- " + line + "\n";
    return out + "\n";
}

std::string safe_speed_lines(const CampbellResult& r) {
    std::string out = i5_speed_lines(r.speeds_at_rest);
    if (!r.speeds_at_rest.given()) return out;
    if (const WhirlCrossing* c = r.first_order_one())
        out += "- first order-1 critical speed: " + rpm(c->speed_hz) + " = " + significant(c->web_speed_m_s, 4) +
               " m/s web speed (" + whirl_word(c->whirl) + ", " + label_text(c->label) + ")\n";
    else
        out += "- no order-1 critical speed within the sweep\n";
    return out;
}

}  // namespace

void write_campbell_tables(const std::filesystem::path& dir, const Scene& scene, const RotationSpec& rotation,
                           const CampbellResult& result) {
    write_text_file(dir / "campbell.csv", campbell_rows(result));
    write_text_file(dir / "critical_speeds.csv", critical_rows(result));
    write_text_file(dir / "summary.json", summary_json(scene, rotation, result));
}

std::string campbell_report_markdown(const Scene& scene, const CampbellResult& r, const std::vector<std::string>& pngs,
                                     const std::string& plot_problem) {
    std::ostringstream out;
    out << "# Campbell diagram: " << scene.name << "\n\n";
    if (!scene.description.empty()) out << scene.description << "\n\n";
    out << level_traits(r.level).title << " level, " << r.n_dofs << " DOFs (" << r.solver << "); " << r.points.size() << " speeds from " << rpm(r.points.front().speed_hz)
        << " to " << rpm(r.points.back().speed_hz) << "; excitation orders";
    for (int k : r.excitation_orders) out << " " << k;
    if (r.operating_hz) out << "; operating range " << rpm((*r.operating_hz)[0]) << " to " << rpm((*r.operating_hz)[1]);
    out << "; Dp = " << significant(r.roll_outer_diameter * 1e3, 4) << " mm. Effects:";
    for (const std::string& e : r.effects) out << " " << e;
    out << ".\n\n";
    for (const std::string& n : r.notes) out << "- " << n << "\n";
    out << "\n" << damping_lines(r);
    out << "## Critical speeds\n\nEvery crossing of an excitation line f = k f_rot with a natural frequency "
           "(between the sweep's speeds, refined by solving inside the bracket; in co-rotating coordinates also the exact "
           "speeds of zero rotating-frame frequency, \"pencil\"), as rotation speed and as web speed v = pi Dp f_rot.\n\n"
        << critical_table(r) << "\n" << operating_range_lines(r) << safe_speed_lines(r) << "\n";
    out << "## Modes at " << rpm(r.points.back().speed_hz) << "\n\n" << last_speed_table(r) << "\n";
    out << "## Diagram\n\n";
    for (const std::string& png : pngs) out << "![" << png << "](" << png << ")\n\n";
    if (pngs.empty()) out << "No picture: " << plot_problem << ".\n\n";
    out << "## Verification\n\nLargest relative residual of the quadratic problem "
           "||(K + i w W G - w^2 M) x|| / ((||K|| + w W ||G|| + w^2 ||M||) ||x||) over every mode at every speed: "
        << significant(r.max_relative_residual, 2)
        << ". Complete: " << r.completeness << ". Modes are followed from speed to speed by MAC, starting at rest.\n\n"
        << refinement_sentence(r)
        << "Tables: campbell.csv (speed, tracked mode, frequency, whirl), critical_speeds.csv, summary.json. Solve "
        << minutes_or_seconds(r.solve_seconds) << ".\n";
    return out.str();
}

std::string campbell_console_summary(const Scene& scene, const CampbellResult& r) {
    std::ostringstream out;
    out << "campbell: " << scene.name << ": " << r.points.size() << " speeds, " << r.critical.size()
        << " critical speeds, max residual " << significant(r.max_relative_residual, 2) << "\n";
    for (const WhirlCrossing& c : r.critical)
        out << "  order " << c.order << ": " << rpm(c.speed_hz) << " (" << significant(c.web_speed_m_s, 4) << " m/s)  "
            << significant(c.frequency_hz, 5) << " Hz " << whirl_word(c.whirl) << " " << label_text(c.label)
            << (from_sweep(c) ? "" : " (pencil, exact)") << "\n";
    if (!r.sweep_end.empty()) out << "  " << r.sweep_end << "\n";
    if (r.damped) {
        out << "  damped modes (campbell.csv damping_ratio; critical speeds undamped):\n";
        for (const std::string& line : r.damping) out << "    " << line << "\n";
    }
    out << operating_range_lines(r) << safe_speed_lines(r);
    return out.str();
}

}  // namespace coremodal
