#include "output/summary.hpp"

#include "output/summary_json.hpp"
#include "output/text_file.hpp"
#include "scene/level_traits.hpp"

#include "beam/iso_test.hpp"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <type_traits>

namespace coremodal {
namespace {

// JSON has no NaN or infinity; a value that is not finite becomes 0 and is
// never expected (every writer input is checked upstream).
double finite(double v) { return std::isfinite(v) ? v : 0.0; }

// `value` where it exists, else null (no bending mode was found).
template <typename Number>
Json value_or_null(bool exists, Number value) {
    if (!exists) return nullptr;
    if constexpr (std::is_floating_point_v<Number>)
        return finite(value);
    else
        return value;
}

Json material_json(const OrthotropicMaterial& m) {
    return Json{{"name", m.name},           {"E_r", m.E_r},           {"E_theta", m.E_theta},
                {"E_z", m.E_z},             {"G_rtheta", m.G_rtheta}, {"G_rz", m.G_rz},
                {"G_thetaz", m.G_thetaz},   {"nu_rtheta", m.nu_rtheta}, {"nu_rz", m.nu_rz},
                {"nu_thetaz", m.nu_thetaz}, {"density", m.density},   {"source", m.source}};
}

const char* support_type_name(SupportKind kind) {
    switch (kind) {
    case SupportKind::free: return "free";
    case SupportKind::clamped: return "clamped";
    case SupportKind::chucks: return "chucks";
    }
    return "";
}

Json bearing_json(const BearingSpec& b) {
    Json t{{"type", b.rigid ? "rigid" : "elastic"}};
    if (b.rigid) return t;
    t["radial_stiffness_n_per_m"] = b.radial_stiffness;
    t["tilting_stiffness_nm_per_rad"] = b.tilting_stiffness;
    if (b.frame_mass) t["frame_mass_kg"] = *b.frame_mass;
    if (b.frame_stiffness) t["frame_stiffness_n_per_m"] = *b.frame_stiffness;
    return t;
}

Json chucks_json(const std::vector<ChuckSpec>& chucks) {
    Json out = Json::array();
    for (const auto& c : chucks) {
        Json expanding = Json::array();
        for (const auto& e : c.expanding)
            expanding.push_back(Json{{"center_m", e.center},
                                     {"width_m", e.width},
                                     {"segments", e.segments},
                                     {"segment_angle_rad", e.segment_angle}});
        Json interface{{"kind", c.interface.kind == InterfaceKind::bonded ? "bonded" : "spring"}};
        if (c.interface.kind == InterfaceKind::spring) {
            interface["expanded"] = c.interface.expanded;
            if (c.interface.contact == ContactKind::one_sided) interface["contact"] = "one-sided";
            interface["normal_stiffness_pa_per_m"] = c.interface.normal_stiffness;
            interface["tangential_stiffness_pa_per_m"] = c.interface.tangential_stiffness;
            if (c.interface.expansion_pressure) interface["expansion_pressure_pa"] = *c.interface.expansion_pressure;
        }
        out.push_back(Json{{"name", c.name},
                           {"inserted_length_m", c.inserted_length},
                           {"body_diameter_m", c.body_diameter},
                           {"shaft_diameter_m", c.shaft_diameter},
                           {"shaft_length_m", c.shaft_length},
                           {"li_m", c.li()},
                           {"material", material_json(c.material)},
                           {"expanding", expanding},
                           {"interface", interface},
                           {"bearing", bearing_json(c.bearing)}});
    }
    return out;
}

// The resolved scene after the case head's name, file and description.
void add_scene(Json& t, const Scene& s) {
    t["model"] = to_string(s.model);
    t["core"] = Json{{"inner_diameter", s.core.inner_diameter},
                     {"outer_diameter", s.core.outer_diameter},
                     {"length", s.core.length},
                     {"material", material_json(s.core.material)}};
    if (s.rest_paper)
        t["rest_paper"] = Json{{"outer_diameter", s.rest_paper->outer_diameter},
                               {"material", material_json(s.rest_paper->material)}};
    Json clamps = Json::array();
    for (const auto& c : s.supports.clamps)
        clamps.push_back(Json{{"name", c.name}, {"z_start", c.z_start}, {"z_end", c.z_end}});
    Json supports{{"type", support_type_name(s.supports.kind)}, {"clamps", clamps}};
    if (!s.supports.chucks.empty()) supports["chucks"] = chucks_json(s.supports.chucks);
    t["supports"] = supports;
    Json mesh{{"level", s.mesh.level},         {"through_wall", s.mesh.n_wall},
              {"through_rest_paper", s.mesh.n_rest_paper}, {"around", s.mesh.n_around},
              {"along", s.mesh.n_along},       {"element", s.mesh.element}};
    if (s.mesh.file) mesh["file"] = *s.mesh.file;
    t["mesh"] = mesh;
    Json analysis{{"modes", s.analysis.n_modes}};
    if (s.analysis.f_max_hz) analysis["band_hz"] = Json::array({s.analysis.f_min_hz.value_or(0.0), *s.analysis.f_max_hz});
    analysis["tolerance"] = s.analysis.tolerance;
    analysis["max_iterations"] = s.analysis.max_iterations;
    t["analysis"] = analysis;
    t["assumptions"] = string_array(s.assumptions);
}

// The speeds of report.md's "Speeds" section (beam/speeds.hpp): I-5 in the
// shape every summary uses, and König's critical speed.
Json speeds_json(const RollSpeeds& v) {
    Json t = safe_web_speed_json(v);
    if (!v.given() || !v.koenig) return t;
    const KoenigSpeeds& k = *v.koenig;
    Json koenig{{"formula", k.formula},         {"span_m", k.span.length_m},
                {"span", k.span.source},        {"experience", k.experience},
                {"f_krit_hz", k.speed.f_krit_hz}, {"v_krit_m_s", k.speed.v_krit_m_s},
                {"v_krit_m_min", 60 * k.speed.v_krit_m_s}};
    if (k.v_krit_large_core_m_s) koenig["v_krit_large_core_m_s"] = *k.v_krit_large_core_m_s;
    t["koenig_critical_speed"] = koenig;
    return t;
}

// The solver's proof, and what was asked against what was found: a model
// with fewer modes than [analysis] modes asks (a small beam network) reports
// all it has, and says so here and in the warnings.
Json verification_json(const RunReport& r) {
    const Verification& v = r.modes.verification;
    Json t{{"max_relative_residual", v.max_relative_residual},
                {"max_orthonormality_error", v.max_orthonormality_error},
                {"check_shift", v.check_shift},
                {"negative_pivots_at_shift", v.negative_pivots_at_shift},
                {"modes_below_shift", v.modes_below_shift},
                {"eigenvalues_below_band", v.eigenvalues_below_band},
                {"complete", v.complete},
                {"modes_requested", value_or_null(!r.scene.analysis.f_max_hz, r.scene.analysis.n_modes)},
                {"modes_reported", static_cast<int64_t>(r.modes.modes.size())}};
    // Only where the solid level's one factor at the predicted edge ran (issue 39).
    if (const auto& p = v.factor_precision)
        t["factor_precision"] = Json{{"used", p->used}, {"asked", p->asked}, {"why", p->why}, {"count", p->count}};
    return t;
}

// The beam comparison; the FE values are null when no bending mode was found.
Json beam_json(const BeamComparison& b) {
    const bool found = b.fe_found();
    return Json{{"span_m", b.span_m},
                {"ends", b.ends},
                {"euler_bernoulli_hz", b.euler_bernoulli_hz},
                {"timoshenko_hz", b.timoshenko_hz},
                {"fe_first_bending_hz", value_or_null(found, b.fe_first_bending_hz)},
                {"fe_mode_index", value_or_null(found, b.fe_mode_index)},
                {"fe_over_timoshenko", value_or_null(found, b.fe_over_timoshenko)},
                {"fe_over_euler_bernoulli", value_or_null(found, b.fe_over_euler_bernoulli)},
                {"fe_missing", found ? Json(nullptr) : Json(b.fe_missing)}};
}

// The chuck factor; f1, f2 (FE) and the factors built on them are null where
// they do not exist (no bending mode, or f2 not computed).
Json chuck_json(const ChuckFactor& k) {
    const bool f1 = k.f1_hz > 0, f2 = k.f2_fe_hz > 0;
    Json t{{"li_m", k.li_m},
           {"free_span_m", k.free_span_m},
           {"f1_hz", value_or_null(f1, k.f1_hz)},
           {"f2_fe_hz", value_or_null(f2, k.f2_fe_hz)},
           {"f2_beam_hz", k.f2_beam_hz},
           {"chuck_factor", value_or_null(f1 && f2, k.chuck_factor)},
           {"chuck_factor_beam", value_or_null(f1, k.chuck_factor_beam)},
           {"span_definition", "free_span = core length - Li_left - Li_right"}};
    if (std::abs(k.li_left_m - k.li_right_m) > 1e-12) {
        t["li_left_m"] = k.li_left_m;
        t["li_right_m"] = k.li_right_m;
    }
    return t;
}

Json mode_json(const Mode& m) {
    const auto& e = m.effective_mass;
    return Json{{"index", m.index},
                {"frequency_hz", finite(m.frequency_hz)},
                {"eigenvalue", finite(m.eigenvalue)},
                {"type", m.label.type},
                {"n", m.label.n},
                {"m", m.label.m},
                {"dominant_share", finite(m.label.dominant_share)},
                {"relative_residual", finite(m.relative_residual)},
                {"effective_mass", Json{{"x_kg", e.x}, {"y_kg", e.y}, {"z_kg", e.z}, {"rz_kgm2", e.rz}}}};
}

}  // namespace

std::string scene_json(const Scene& scene) {
    Json t{{"name", scene.name}, {"file", scene.source_file}, {"description", scene.description}};
    add_scene(t, scene);
    return t.dump(2, ' ', false, nlohmann::json::error_handler_t::replace);
}

void write_summary_json(const std::string& path, const RunReport& r) {
    Json summary = summary_head("run", r.scene.name, r.scene.source_file, r.scene.description);
    add_scene(summary["case"], r.scene);
    summary["effects"] = string_array(r.scene.effects());
    summary["model"] = Json{{"level", to_string(r.model.level)},
                            {"element", r.model.element},
                            {"n_dofs", r.model.n_dofs},
                            {"n_nodes", r.model.n_nodes},
                            {"n_elements", r.model.n_elements},
                            {"n_eliminated_nodes", r.model.n_eliminated_nodes},
                            {"mass_kg", r.model.mass_kg},
                            {"expected_mass_kg", r.model.expected_mass_kg},
                            {"mesh_source", r.model.mesh_source},
                            {"harmonics", r.model.harmonics}};
    Json modes = Json::array();
    for (const auto& m : r.modes.modes) modes.push_back(mode_json(m));
    summary["modes"] = modes;
    summary["verification"] = verification_json(r);
    summary["beam"] = beam_json(r.beam);
    summary["speeds"] = speeds_json(report_speeds(r));
    if (r.chuck) summary["chuck"] = chuck_json(*r.chuck);
    if (const auto iso = iso_flexural_test(r.scene, r.beam.fe_first_bending_hz))
        summary["iso_11093_8"] = Json{{"f_free_hz", iso->f_free_hz},
                                      {"mass_per_length_kg_m", iso->mass_per_length},
                                      {"length_m", iso->length_m},
                                      {"Q", iso->Q},
                                      {"flexural_modulus_pa", iso->flexural_modulus_pa},
                                      {"E_z_pa", iso->E_z_pa},
                                      {"difference", iso->difference},
                                      {"notes", string_array(iso->notes)}};
    if (!r.rigid_comparison.empty()) {
        Json rows = Json::array();
        for (const ModeShift& m : r.rigid_comparison)
            rows.push_back(Json{{"type", m.type},
                                {"n", m.n},
                                {"m", m.m},
                                {"elastic_mode", m.elastic_index},
                                {"elastic_hz", m.elastic_hz},
                                {"rigid_mode", m.rigid_index},
                                {"rigid_hz", m.rigid_hz},
                                {"shift_percent", m.shift_percent()}});
        summary["rigid_comparison"] = rows;
    }
    const auto& t = r.timing_s;
    summary["timing_s"] = Json{{"total", t.total},
                               {"mesh", t.mesh},
                               {"chuck_factor", t.chuck_factor},
                               {"assemble", t.assemble},
                               {"factor_and_solve", t.factor_and_solve},
                               {"classify", t.classify}};
    summary["warnings"] = string_array(r.warnings);
    summary["peak_memory_mb"] = r.peak_memory_mb;
    summary["mpi_ranks"] = r.mpi_ranks;
    write_text_file(path, json_text(summary));
}

void write_modes_csv(const std::string& path, const RunReport& r) {
    std::ostringstream s;
    s << "index,frequency_hz,type,n,m,dominant_share,relative_residual,eff_mass_x_kg,eff_mass_y_kg,"
         "eff_mass_z_kg,eff_mass_rz_kgm2\n";
    s << std::setprecision(10);
    for (const auto& m : r.modes.modes) {
        const auto& e = m.effective_mass;
        s << m.index << ',' << m.frequency_hz << ',' << m.label.type << ',' << m.label.n << ',' << m.label.m << ','
          << m.label.dominant_share << ',' << m.relative_residual << ',' << e.x << ',' << e.y << ',' << e.z << ','
          << e.rz << '\n';
    }
    write_text_file(path, s.str());
}

void print_mode_table(std::ostream& out, const RunReport& r) {
    char line[256];
    out << "\n mode   f [Hz]       type       n   m   share   eff. mass x/y/z [kg]        residual\n";
    out << " ----  -----------  ---------  --  --  -----  --------------------------  --------\n";
    // Effective masses below this share of the model mass are round-off of
    // an exact zero (symmetry) and print as 0 so the table reads at a glance.
    constexpr double kNegligibleMassShare = 1e-9;
    const double negligible = kNegligibleMassShare * r.model.mass_kg;
    auto shown = [negligible](double v) { return v < negligible ? 0.0 : v; };
    for (const auto& m : r.modes.modes) {
        const auto& e = m.effective_mass;
        std::snprintf(line, sizeof line, " %4d  %11.4f  %-9s  %2d  %2d  %5.2f  %8.3g %8.3g %8.3g  %8.1e\n", m.index,
                      m.frequency_hz, m.label.type.c_str(), m.label.n, m.label.m, m.label.dominant_share,
                      shown(e.x), shown(e.y), shown(e.z), m.relative_residual);
        out << line;
    }
}

namespace {

// The verification line: residuals, orthonormality and the inertia count
// (one count, or the independent problems' counts summed).
void print_verification(std::ostream& out, const RunReport& r) {
    const auto& v = r.modes.verification;
    char line[512];
    if (r.scene.analysis.f_max_hz && r.modes.modes.empty())
        out << "\nno modes between " << r.scene.analysis.f_min_hz.value_or(0.0) << " and " << *r.scene.analysis.f_max_hz
            << " Hz: an empty band, proven by the inertia count (as many eigenvalues below its upper edge as below "
               "its lower edge)";
    // Modes accounted for below the shift: found, and counted below a band.
    const std::string counted =
        v.eigenvalues_below_band > 0 ? " and " + std::to_string(v.eigenvalues_below_band) + " counted below the band"
                                     : std::string();
    const long found = v.modes_found_below_shift();
    if (r.model.harmonics.empty())
        std::snprintf(line, sizeof line,
                      "\nverification: max residual %.1e, max |X'MX - I| %.1e, %ld negative pivots below %.4g Hz "
                      "for %ld modes found%s: %s\n",
                      v.max_relative_residual, v.max_orthonormality_error, v.negative_pivots_at_shift,
                      eigenvalue_hz(v.check_shift), found, counted.c_str(), v.complete ? "complete" : "INCOMPLETE");
    else  // one count per harmonic, each at its own shift: summed (pairs twice)
        std::snprintf(line, sizeof line,
                      "\nverification: max residual %.1e, max |X'MX - I| %.1e, %ld negative pivots for %ld modes "
                      "found%s, summed over the %s own counts: %s\n",
                      v.max_relative_residual, v.max_orthonormality_error, v.negative_pivots_at_shift, found,
                      counted.c_str(), level_traits(r.model.level).count_owners,
                      v.complete ? "complete" : "INCOMPLETE");
    out << line;
    if (const auto& p = v.factor_precision)
        out << "factor of K - sigma M: " << p->used << " precision (-factor_precision " << p->asked << ": " << p->why
            << "); count: " << p->count << "\n";
    if (!r.model.harmonics.empty()) out << "harmonics: " << r.model.harmonics << "\n";
}

// The model's mass, the beam formulas and the FE's first bending mode against them.
void print_mass_and_beam(std::ostream& out, const RunReport& r) {
    char line[512];
    std::snprintf(line, sizeof line, "mass: model %.6g kg, from dimensions %.6g kg\n", r.model.mass_kg,
                  r.model.expected_mass_kg);
    out << line;
    const auto& b = r.beam;
    std::snprintf(line, sizeof line, "beam (%s, span %.4g m): Euler-Bernoulli %.4f Hz, Timoshenko %.4f Hz; ",
                  b.ends.c_str(), b.span_m, b.euler_bernoulli_hz, b.timoshenko_hz);
    out << line;
    if (b.fe_found()) {
        std::snprintf(line, sizeof line, "FE first bending (mode %d) %.4f Hz = %.4f x Timoshenko\n", b.fe_mode_index,
                      b.fe_first_bending_hz, b.fe_over_timoshenko);
        out << line;
    } else {
        out << "FE first bending: none, " << b.fe_missing << "\n";
    }
}

// The chuck factor k = f1 / f2 (or why not) and the virtual ISO 11093-8 test.
void print_chuck_factor_and_iso_test(std::ostream& out, const RunReport& r) {
    char line[512];
    const auto& b = r.beam;
    if (r.chuck && !(r.chuck->f1_hz > 0)) {
        out << "chuck factor: not computed, no first bending mode f1 (" << b.fe_missing << ")\n";
    } else if (r.chuck) {
        const ChuckFactor& k = *r.chuck;
        std::snprintf(line, sizeof line,
                      "chuck factor: Li %.4g m (left %.4g, right %.4g), free span L = %.4g m; f1 %.4f Hz, "
                      "f2 free-free over L: FE %.4f Hz, Timoshenko %.4f Hz; k = f1/f2 = %.4f (beam f2: %.4f)\n",
                      k.li_m, k.li_left_m, k.li_right_m, k.free_span_m, k.f1_hz, k.f2_fe_hz, k.f2_beam_hz,
                      k.chuck_factor, k.chuck_factor_beam);
        out << line;
    }
    if (const auto iso = iso_flexural_test(r.scene, b.fe_first_bending_hz)) {
        std::snprintf(line, sizeof line,
                      "virtual ISO 11093-8 test: Ec = %.5g N/mm^2 from f1 %.4f Hz (Q %.5f), E_z put in %.5g N/mm^2: "
                      "%+.2f %%\n",
                      iso->flexural_modulus_pa / 1e6, iso->f_free_hz, iso->Q, iso->E_z_pa / 1e6, 100 * iso->difference);
        out << line;
    }
}

}  // namespace

void print_verification_and_beam(std::ostream& out, const RunReport& r) {
    print_verification(out, r);
    print_mass_and_beam(out, r);
    print_chuck_factor_and_iso_test(out, r);
}

}  // namespace coremodal
