// winder.csv, crossings.csv, response.csv and summary.json of `coremodal winder`.
#include "output/summary_json.hpp"

#include "common/format.hpp"
#include "output/text_file.hpp"
#include "output/winder_report.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <sstream>

namespace coremodal {
namespace {

// One CSV line (the fields are numbers and fixed words: nothing to quote).
std::string row(std::initializer_list<std::string> fields) {
    std::string out;
    bool first = true;
    for (const std::string& f : fields) {
        if (!first) out += ',';
        out += f;
        first = false;
    }
    out += '\n';
    return out;
}

std::string mode_rows(const WinderSweepResult& r) {
    std::string out =
        "roll_diameter_m,mode,frequency_hz,type,track,share_drums,share_rolls,share_rider,damping_ratio,mac_previous,"
        "ambiguous\n";
    for (const SweepPoint& p : r.points)
        for (const SweepMode& m : p.modes) {
            const auto& share = m.kinetic_share;
            out += row({ten_digits(p.roll_diameter), std::to_string(m.index), ten_digits(m.frequency_hz),
                        body_kind_name(m.type), std::to_string(m.track), ten_digits(share[0]), ten_digits(share[1]),
                        ten_digits(share[2]), ten_digits(m.damping_ratio),
                        m.mac_previous ? ten_digits(*m.mac_previous) : "", m.ambiguous ? "true" : "false"});
        }
    return out;
}

std::string crossing_rows(const WinderSweepResult& r) {
    std::string out =
        "roll_diameter_m,harmonic,harmonic_frequency_hz,track,mode_frequency_hz,type,damping_ratio,x_over_f_m_per_n\n";
    for (const Crossing& c : r.crossings)
        out += row({ten_digits(c.roll_diameter), std::to_string(c.harmonic), ten_digits(c.frequency_hz),
                    std::to_string(c.track), ten_digits(c.mode_frequency_hz), body_kind_name(c.type),
                    ten_digits(c.damping_ratio), ten_digits(c.resonance_response)});
    return out;
}

std::string response_rows(const WinderScene& s, const WinderSweepResult& r) {
    std::string out = "roll_diameter_m,harmonic,frequency_hz,x_over_f_m_per_n\n";
    for (const SweepPoint& p : r.points)
        for (size_t k = 0; k < p.harmonic_response.size(); ++k) {
            const int h = static_cast<int>(k) + 1;
            out += row({ten_digits(p.roll_diameter), std::to_string(h),
                        ten_digits(roll_harmonic_hz(h, s.web_speed, p.roll_diameter)),
                        ten_digits(p.harmonic_response[k])});
        }
    return out;
}

toml::table scene_json(const WinderScene& s) {
    const WinderDrums& d = s.drums;
    const WinderRolls& r = s.rolls;
    const WinderRider& rd = s.rider;
    toml::table drums{{"outer_diameter_m", d.outer_diameter}, {"wall_m", d.wall}, {"length_m", d.length},
                      {"gap_m", d.gap}, {"material", d.material},
                      {"bearing_stiffness_vertical_n_m", d.bearing_stiffness_vertical},
                      {"bearing_stiffness_horizontal_n_m", d.bearing_stiffness_horizontal}, {"elements", d.elements}};
    // The drum nips' line load: given, or from each roll's equilibrium at each diameter.
    if (d.line_load) drums.insert("line_load_n_m", *d.line_load);
    else drums.insert("line_load_n_m", "equilibrium");
    toml::table rolls{{"count", r.count}, {"width_m", r.width}, {"gap_m", r.gap},
                      {"core_inner_diameter_m", r.core_inner_diameter}, {"core_outer_diameter_m", r.core_outer_diameter},
                      {"core_material", r.core_material}, {"paper_material", r.paper_material},
                      {"paper_density_kg_m3", r.paper_density}, {"radial_modulus_pa", r.radial_modulus},
                      {"poisson", r.poisson}, {"model", roll_model_name(r.model)},
                      {"diameter_start_m", r.diameter_start}, {"diameter_end_m", r.diameter_end}};
    toml::table rider{{"outer_diameter_m", rd.outer_diameter}, {"wall_m", rd.wall}, {"length_m", rd.length},
                      {"material", rd.material}, {"support_stiffness_n_m", rd.support_stiffness},
                      {"line_load_n_m", rd.line_load}, {"elements", rd.elements}};
    toml::table damping{{"drums", s.damping.drums}, {"nips", s.damping.nips}, {"rider", s.damping.rider}};
    toml::table sweep{{"points", s.sweep.points}, {"harmonics", s.sweep.harmonics},
                      {"max_frequency_hz", s.sweep.max_frequency},
                      {"response_drum", drum_side_name(s.sweep.response_drum)},
                      {"response_direction", direction_name(s.sweep.response_direction)}};
    return toml::table{{"web_speed_m_s", s.web_speed}, {"drums", drums}, {"rolls", rolls}, {"rider", rider},
                       {"damping", damping}, {"sweep", sweep}};
}

Json nip_json(const Nip& n, double line_load) {
    return Json{{"line_load_n_m", line_load}, {"half_width_m", n.half_width}, {"deflection_m", n.deflection},
                       {"stiffness_n_m2", n.stiffness_per_length}};
}

Json point_json(const SweepPoint& p) {
    Json estimate{{"drum_alone_hz", p.estimate.drum_alone_hz},
                         {"isotropic_bearings", p.estimate.isotropic},
                         {"nip_modal_stiffness", p.estimate.nip_modal_stiffness}};
    const char* names[kDrumFamilies] = {"symmetric", "antisymmetric"};
    for (int f = 0; f < kDrumFamilies; ++f) {
        const auto& e = p.estimate.family[f];
        estimate[names[f]] = Json{{"estimate_hz", e.drum_hz}, {"other_root_hz", e.roll_hz},
                                               {"heavy_roll_hz", e.heavy_roll_hz}, {"roll_bounce_hz", e.roll_bounce_hz},
                                               {"model_hz", e.model_hz}, {"model_participation", e.model_participation}};
    }
    const Verification& v = p.verification;
    return Json{{"roll_diameter_m", p.roll_diameter},
                {"nip_angle_deg", p.state.geometry.nip_angle * 180 / M_PI},
                {"roll_mass_per_width_kg_m", p.state.roll_mass_per_width},
                {"drum_nip", nip_json(p.state.drum_nip, p.state.drum_line_load)},
                {"rider_nip", nip_json(p.state.rider_nip, p.state.rider_line_load)},
                {"modes", static_cast<int64_t>(p.modes.size())},
                {"estimate", estimate},
                {"verification", Json{{"max_relative_residual", v.max_relative_residual},
                                      {"max_orthonormality_error", v.max_orthonormality_error},
                                      {"check_shift_hz", eigenvalue_hz(v.check_shift)},
                                      {"negative_pivots", v.negative_pivots_at_shift},
                                      {"complete", v.complete}}}};
}

// The resolved scene (a TOML table: winder_scene_description prints it as
// TOML) as JSON, keys in the table's order.
Json to_json(const toml::node& node) {
    if (const toml::table* t = node.as_table()) {
        Json out = Json::object();
        for (const auto& [key, value] : *t) out[std::string(key.str())] = to_json(value);
        return out;
    }
    if (const toml::array* a = node.as_array()) {
        Json out = Json::array();
        for (const toml::node& value : *a) out.push_back(to_json(value));
        return out;
    }
    if (const auto* v = node.as_string()) return v->get();
    if (const auto* v = node.as_integer()) return v->get();
    if (const auto* v = node.as_floating_point()) return number_or_null(v->get());
    if (const auto* v = node.as_boolean()) return v->get();
    return nullptr;  // dates and times: none in a winder scene
}

std::string summary_json(const WinderScene& s, const WinderSweepResult& r) {
    Json points = Json::array(), crossings = Json::array();
    for (const SweepPoint& p : r.points) points.push_back(point_json(p));
    for (const Crossing& c : r.crossings)
        crossings.push_back(Json{{"roll_diameter_m", c.roll_diameter}, {"harmonic", c.harmonic},
                                 {"harmonic_frequency_hz", c.frequency_hz}, {"track", c.track},
                                 {"mode_frequency_hz", c.mode_frequency_hz}, {"type", body_kind_name(c.type)},
                                 {"damping_ratio", c.damping_ratio}, {"x_over_f_m_per_n", c.resonance_response}});
    Json t = summary_head("winder", s.name, s.source_file, s.description);
    t["scene"] = to_json(scene_json(s));
    t["defaults_used"] = string_array(s.defaults);
    t["model"] = Json{{"level", "beam"},
                      {"rolls", roll_model_name(s.rolls.model)},
                      {"dofs", r.n_dofs},
                      {"motion", "bending only (ux, uy, rx, ry); no rotation (gyroscopic) terms"}};
    t["points"] = points;
    t["crossings"] = crossings;
    t["timing_s"] = Json{{"total", r.time_s}};
    return json_text(t);
}

}  // namespace

std::string winder_scene_description(const WinderScene& scene) {
    std::ostringstream out;
    constexpr auto flags = toml::toml_formatter::default_flags | toml::format_flags::relaxed_float_precision;
    out << toml::toml_formatter{scene_json(scene), flags} << "\n\ndefaults used (not in the file):\n";
    for (const auto& d : scene.defaults) out << "  " << d << "\n";
    if (scene.defaults.empty()) out << "  none\n";
    return out.str();
}

void write_winder_tables(const std::filesystem::path& dir, const WinderScene& scene, const WinderSweepResult& result) {
    write_text_file(dir / "winder.csv", mode_rows(result));
    write_text_file(dir / "crossings.csv", crossing_rows(result));
    write_text_file(dir / "response.csv", response_rows(scene, result));
    write_text_file(dir / "summary.json", summary_json(scene, result));
}

}  // namespace coremodal
