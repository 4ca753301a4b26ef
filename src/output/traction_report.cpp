// traction.csv, summary.json and report.md of `coremodal traction`.
#include "output/traction_report.hpp"

#include "common/format.hpp"
#include "output/csv.hpp"
#include "output/summary_json.hpp"
#include "output/text_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <sstream>

namespace coremodal {
namespace {

std::string um(double m) { return significant(m * 1e6, 4) + " µm"; }
std::string speed_or_none(double v) { return std::isfinite(v) ? significant(v, 3) + " m/s" : "none (a massless web)"; }
std::string deg(double rad) { return significant(rad * 180.0 / std::numbers::pi, 4) + "°"; }
bool grooved(const TractionSpec& s) { return s.grooves.shape != GrooveShape::none; }

std::string join_lines(const std::vector<std::string>& v) {
    std::string out;
    for (size_t i = 0; i < v.size(); ++i) out += (i ? "; " : "") + v[i];
    return out;
}

// One CSV line from its fields (numbers, fixed words and csv_field text).
std::string row(const std::vector<std::string>& fields) {
    std::string out;
    for (size_t i = 0; i < fields.size(); ++i) {
        if (i) out += ',';
        out += fields[i];
    }
    out += '\n';
    return out;
}

std::string csv_rows(const TractionSweep& s) {
    std::vector<std::string> header = {"web_speed_m_s",       "tension_N_m",  "air_pressure_Pa",  "wrap_pressure_Pa",
                                       "contact_pressure_Pa", "air_share",    "p_star",           "h_star",
                                       "traction_N_m",        "capstan_traction_N_m", "effective_friction",
                                       "theta_star",          "b_star",       "contact",          "valid"};
    if (s.plain) header.insert(header.end(), {"plain_traction_N_m", "plain_effective_friction"});
    header.push_back("violations");
    std::string out = row(header);
    for (size_t i = 0; i < s.points.size(); ++i) {
        const TractionPoint& p = s.points[i];
        std::vector<std::string> fields = {ten_digits(p.web_speed),
                                           ten_digits(p.tension),
                                           ten_digits(p.air_pressure),
                                           ten_digits(p.wrap_pressure),
                                           ten_digits(p.contact_pressure),
                                           ten_digits(p.air_share),
                                           ten_digits(p.p_star),
                                           ten_digits(p.h_star),
                                           ten_digits(p.traction),
                                           ten_digits(p.capstan_traction),
                                           ten_digits(p.effective_friction),
                                           optional_number(p.theta_star),
                                           optional_number(p.b_star),
                                           p.contact ? "true" : "false",
                                           p.valid ? "true" : "false"};
        if (s.plain)
            fields.insert(fields.end(), {ten_digits(s.plain->traction[i]), ten_digits(s.plain->effective_friction[i])});
        fields.push_back(csv_field(join_lines(p.violations)));
        out += row(fields);
    }
    return out;
}

Json roller_json(const TractionSpec& s) {
    const Grooves& g = s.grooves;
    Json grooves{{"shape", groove_shape_name(g.shape)}};
    if (grooved(s)) {
        grooves["depth_m"] = g.depth;
        grooves["width_m"] = g.width;
        grooves["pitch_m"] = g.pitch;
        grooves["land_width_m"] = g.land_width();
        grooves["land_fraction"] = g.land_fraction();
        if (g.shape == GrooveShape::circular) grooves["tool_radius_m"] = g.tool_radius;
    }
    Json web{{"tension_N_m", s.tension}, {"thickness_m", s.web_thickness}, {"density_kg_m3", s.web_density},
             {"roughness_m", s.web_roughness}};
    if (s.web_modulus) web["modulus_Pa"] = *s.web_modulus;
    if (s.web_poisson) web["poisson"] = *s.web_poisson;
    Json out{{"radius_m", s.roller_radius}, {"wrap_rad", s.wrap},
             {"wrap_deg", s.wrap * 180.0 / std::numbers::pi}, {"roughness_m", s.roller_roughness},
             {"grooves", grooves}, {"friction", s.friction}, {"air_viscosity_Pa_s", s.air_viscosity},
             {"web", web}};
    if (s.tension_difference) out["tension_difference_N_m"] = *s.tension_difference;
    return out;
}

Json point_json(const TractionPoint& p) {
    Json t{{"web_speed_m_s", p.web_speed},
           {"tension_N_m", p.tension},
           {"air_pressure_Pa", p.air_pressure},
           {"wrap_pressure_Pa", p.wrap_pressure},
           {"contact_pressure_Pa", p.contact_pressure},
           {"air_share", p.air_share},
           {"p_star", p.p_star},
           {"h_star", p.h_star},
           {"traction_N_m", p.traction},
           {"capstan_traction_N_m", p.capstan_traction},
           {"effective_friction", p.effective_friction},
           {"contact", p.contact},
           {"valid", p.valid}};
    // theta* is infinite on lands without asperities: JSON has no infinity, so a string.
    if (p.theta_star) {
        if (std::isfinite(*p.theta_star))
            t["theta_star"] = *p.theta_star;
        else
            t["theta_star"] = "infinite";
    }
    if (p.b_star) t["b_star"] = *p.b_star;
    t["violations"] = string_array(p.violations);
    return t;
}

std::string summary_json(const TractionCase& tc, const TractionSweep& s, double seconds) {
    Json points = Json::array();
    for (const TractionPoint& p : s.points) points.push_back(point_json(p));
    Json clearance{{"asperity_height_m", s.clearance.asperity_height},
                   {"effective_clearance_m", s.clearance.clearance}};
    if (s.clearance.groove_depth_eff) clearance["groove_depth_eff_m"] = *s.clearance.groove_depth_eff;
    // Not "speeds": that key is a roll's I-5 speeds in every summary.json.
    Json speeds{{"zero_traction_m_s", s.zero_traction_speed}};
    if (std::isfinite(s.centripetal_limit_speed)) speeds["centripetal_limit_m_s"] = s.centripetal_limit_speed;
    if (s.slip_speed) speeds["slip_m_s"] = *s.slip_speed;
    // The same head as every command's summary.json (output/summary_json.hpp).
    Json t = summary_head("traction", tc.name, tc.source_file, tc.description);
    t["source"] = kRiceGansCitation;
    t["roller"] = roller_json(tc.spec);
    t["clearance"] = clearance;
    t["traction_speeds"] = speeds;
    if (s.plain) {
        Json plain{{"clearance_m", s.plain->clearance}, {"zero_traction_speed_m_s", s.plain->zero_traction_speed}};
        if (const std::optional<double> gain = groove_speed_gain(s)) plain["groove_speed_gain"] = *gain;
        t["plain_roller"] = plain;
    }
    t["validity"] = Json{{"theta_star_max", kMaxThetaStar},
                         {"b_star_max", kMaxBStar},
                         {"local_flow_error_max", kMaxLocalFlowError},
                         {"points", s.points.size()},
                         {"points_invalid", s.n_invalid},
                         {"points_without_contact", s.n_no_contact}};
    t["defaults_used"] = string_array(tc.assumptions);
    t["model_assumptions"] = string_array(traction_model_assumptions(tc.spec));
    t["warnings"] = string_array(tc.warnings);
    t["points"] = points;
    t["timing_s"] = Json{{"total", seconds}};
    return json_text(t);
}

// The rows report.md shows: all of a short sweep, else about 21 evenly spread
// (the first and last included); traction.csv has them all.
std::vector<size_t> shown_rows(size_t n) {
    constexpr size_t kMaxRows = 21;
    std::vector<size_t> rows;
    if (n <= kMaxRows) {
        for (size_t i = 0; i < n; ++i) rows.push_back(i);
        return rows;
    }
    for (size_t k = 0; k < kMaxRows; ++k) rows.push_back(k * (n - 1) / (kMaxRows - 1));
    return rows;
}

std::string optional_cell(const std::optional<double>& v) {
    if (!v) return "–";
    return std::isfinite(*v) ? significant(*v, 3) : "∞";
}

void clearance_section(std::ostringstream& md, const TractionSpec& spec, const TractionSweep& s) {
    const Grooves& g = spec.grooves;
    md << "## Effective clearance\n\n";
    md << "- asperity engagement height α = √(α_r² + α_w²) = √(" << um(spec.roller_roughness) << "² + "
       << um(spec.web_roughness) << "²) = **" << um(s.clearance.asperity_height) << "** (eq. 6)\n";
    switch (g.shape) {
        case GrooveShape::none:
            md << "- plain roller: h_eff = α = **" << um(s.clearance.clearance) << "**\n";
            break;
        case GrooveShape::sine:
            md << "- sine grooves " << um(g.depth) << " deep (crest to trough; the sine's amplitude is G_D/2), "
               << um(g.width) << " wide, pitch " << um(g.pitch) << ": h_eff from eq. 8 over one pitch (eq. 16 with "
               << "lands of α) = **" << um(s.clearance.clearance) << "**\n";
            break;
        case GrooveShape::circular:
        case GrooveShape::rectangular:
            md << "- " << groove_shape_name(g.shape) << " grooves G_D = " << um(g.depth) << ", G_W = " << um(g.width)
               << ", pitch " << um(g.pitch) << " (land L_W = " << um(g.land_width())
               << ", L_F = " << significant(g.land_fraction(), 3) << ")"
               << (g.shape == GrooveShape::circular ? ", tool radius " + um(g.tool_radius) : std::string()) << "\n";
            md << "- effective groove depth G_Deff = **" << um(*s.clearance.groove_depth_eff) << "** (eq. "
               << (g.shape == GrooveShape::circular ? "18" : "17") << ")\n";
            md << "- h_eff from eq. 8 over one pitch (eq. 19 with α on lands and grooves) = **"
               << um(s.clearance.clearance) << "**\n";
            break;
    }
    md << "\n";
}

void speeds_section(std::ostringstream& md, const TractionSpec& spec, const TractionSweep& s) {
    md << "## Speeds\n\n";
    md << "- **zero-traction speed " << speed_or_none(s.zero_traction_speed)
       << "**: the air carries the whole wrap pressure T/R (P* = 1, h* = 1); faster, the web floats on the roller "
          "and slips under any tension difference\n";
    if (s.slip_speed)
        md << "- **slip speed " << speed_or_none(*s.slip_speed) << "** for a tension difference of "
           << significant(*spec.tension_difference, 4) << " N/m"
           << (*s.slip_speed > 0
                   ? ""
                   : " (the roller cannot carry it even at rest: T_0 (1 - e^(-f θ)) = " +
                         significant(spec.tension * (1 - std::exp(-spec.friction * spec.wrap)), 4) + " N/m)")
           << "\n";
    md << "- centripetal limit " << speed_or_none(s.centripetal_limit_speed)
       << " (T_0 = c ρ V², the web no longer wraps)\n";
    if (s.plain) {
        md << "- the same roller without grooves (h_eff = α = " << um(s.plain->clearance) << "): ";
        if (const std::optional<double> gain = groove_speed_gain(s))
            md << "zero traction at " << speed_or_none(s.plain->zero_traction_speed) << "; **the grooves raise it "
               << significant(*gain, 3) << "×**\n";
        else
            md << "no clearance for the air at all: no traction at any speed above 0; the grooves give all of it\n";
    }
    md << "\n";
}

void curve_section(std::ostringstream& md, const TractionSweep& s) {
    md << "## Traction against web speed\n\n";
    md << "| V_w [m/s] | T [N/m] | P_a [Pa] | P* | h* | ΔT [N/m] | f_e | θ* | B* |"
       << (s.plain ? " plain ΔT [N/m] |" : "") << " valid |\n";
    md << "|---|---|---|---|---|---|---|---|---|" << (s.plain ? "---|" : "") << "---|\n";
    for (size_t i : shown_rows(s.points.size())) {
        const TractionPoint& p = s.points[i];
        md << "| " << significant(p.web_speed, 4) << " | " << significant(p.tension, 4) << " | "
           << significant(p.air_pressure, 4) << " | " << significant(p.p_star, 3) << " | "
           << significant(p.h_star, 3) << " | " << significant(p.traction, 4) << " | "
           << significant(p.effective_friction, 3) << " | " << optional_cell(p.theta_star) << " | "
           << optional_cell(p.b_star) << " |";
        if (s.plain) md << " " << significant(s.plain->traction[i], 4) << " |";
        md << " " << (p.valid ? (p.contact ? "yes" : "yes (no contact)") : "**no**") << " |\n";
    }
    md << "\nAll " << s.points.size() << " speeds: `traction.csv`.\n\n";
}

void validity_section(std::ostringstream& md, const TractionSpec& spec, const TractionSweep& s) {
    md << "## Validity (the paper's limits)\n\n";
    md << "- P* = P_a/(T/R) (eq. 10) and h* = h/h_eff (eq. 9): at 1 the web loses contact and traction is 0 (eq. 11); "
       << s.n_no_contact << " of " << s.points.size() << " speeds are there\n";
    if (grooved(spec)) {
        double theta_max = 0, b_max = 0;
        for (const TractionPoint& p : s.points) {
            if (p.theta_star) theta_max = std::max(theta_max, *p.theta_star);
            if (p.b_star) b_max = std::max(b_max, *p.b_star);
        }
        const double aspect = std::pow(spec.grooves.depth / spec.grooves.width, 2);
        md << "- θ* < " << kMaxThetaStar << " (eq. 20, high wrap: the air leaves the lands in time): largest θ* "
           << (std::isfinite(theta_max) ? significant(theta_max, 3) : "∞") << " (where the web touches)\n";
        md << "- B* < " << kMaxBStar << " (eq. 21, the web is rigid across a groove): largest B* "
           << significant(b_max, 3) << "\n";
        md << "- (G_D/G_W)² = " << significant(aspect, 3) << " (eq. 8's local flow, error of this order; flagged above "
           << kMaxLocalFlowError << ")\n";
    } else {
        md << "- θ* and B* (eqs. 20, 21) are the paper's limits for grooved rollers; a plain roller needs only the "
              "continuous air path through its roughness valleys (the paper's shot-blasted roller 15, whose valleys "
              "are isolated, is not predicted)\n";
    }
    if (s.n_invalid == 0) {
        md << "\n**Every point is within the paper's limits.**\n\n";
    } else {
        md << "\n**" << s.n_invalid << " of " << s.points.size() << " points are outside the paper's limits**; the "
           << "first: " << join_lines(std::find_if(s.points.begin(), s.points.end(), [](const TractionPoint& p) {
                                          return !p.valid;
                                      })->violations)
           << ".\n\n";
    }
}

// The roller as TOML for a person (`coremodal check`): the keys of summary.json's
// `roller`, numbers to 10 significant digits (88, not 87.99999999999999).
void toml_lines(std::ostream& out, const Json& table, const std::string& prefix) {
    for (const auto& [key, value] : table.items()) {
        if (value.is_object()) continue;
        out << key << " = " << (value.is_number_float() ? significant(value.get<double>(), 10) : value.dump()) << "\n";
    }
    for (const auto& [key, value] : table.items())
        if (value.is_object()) {
            out << "\n[" << prefix << key << "]\n";
            toml_lines(out, value, prefix + key + ".");
        }
}

}  // namespace

void write_traction_tables(const std::filesystem::path& dir, const TractionCase& tc, const TractionSweep& sweep,
                           double seconds) {
    write_text_file(dir / "traction.csv", csv_rows(sweep));
    write_text_file(dir / "summary.json", summary_json(tc, sweep, seconds));
}

std::string traction_report_markdown(const TractionCase& tc, const TractionSweep& s, const std::vector<std::string>& pngs,
                                     const std::string& plot_problem) {
    const TractionSpec& spec = tc.spec;
    std::ostringstream md;
    md << "# Web-to-roller traction: " << tc.name << "\n\n";
    if (!tc.description.empty()) md << tc.description << "\n\n";
    md << "Model: " << kRiceGansCitation << " (docs/how-to/traction.md); case file `" << tc.source_file << "`.\n\n";
    md << "## Roller and web\n\n";
    md << "| R | θ | T_0 | f | μ | c | ρ |\n|---|---|---|---|---|---|---|\n";
    md << "| " << significant(spec.roller_radius * 1e3, 4) << " mm | " << deg(spec.wrap) << " | "
       << significant(spec.tension, 4) << " N/m | " << significant(spec.friction, 3) << " | "
       << significant(spec.air_viscosity, 3) << " Pa·s | " << um(spec.web_thickness) << " | "
       << significant(spec.web_density, 4) << " kg/m³ |\n\n";
    clearance_section(md, spec, s);
    speeds_section(md, spec, s);
    if (!pngs.empty()) {
        for (const std::string& png : pngs) md << "![" << png << "](" << png << ")\n\n";
    } else {
        md << "(No picture: " << plot_problem << ".)\n\n";
    }
    curve_section(md, s);
    validity_section(md, spec, s);
    md << "## Assumptions\n\n";
    for (const std::string& a : traction_model_assumptions(spec)) md << "- " << a << "\n";
    md << "\nDefaults used (not in the file):\n\n";
    for (const std::string& a : tc.assumptions) md << "- `" << a << "`\n";
    if (tc.assumptions.empty()) md << "- none\n";
    if (!tc.warnings.empty()) {
        md << "\nWarnings:\n\n";
        for (const std::string& w : tc.warnings) md << "- " << w << "\n";
    }
    return md.str();
}

std::string traction_check_text(const TractionCase& tc) {
    const TractionSpec& spec = tc.spec;
    std::ostringstream out;
    toml_lines(out, roller_json(spec), "");
    const EffectiveClearance h = effective_clearance(spec);
    out << "effective clearance h_eff " << um(h.clearance) << " (asperities " << um(h.asperity_height) << ")"
        << "; zero-traction speed " << speed_or_none(zero_traction_speed(spec));
    if (spec.tension_difference) out << "; slip speed " << speed_or_none(slip_speed(spec, *spec.tension_difference));
    out << "\n"
        << spec.web_speeds.size() << " web speeds from " << speed_or_none(spec.web_speeds.front()) << " to "
        << speed_or_none(spec.web_speeds.back()) << "\ndefaults used (not in the file):\n";
    for (const std::string& a : tc.assumptions) out << "  " << a << "\n";
    if (tc.assumptions.empty()) out << "  none\n";
    return out.str();
}

std::string traction_console_summary(const TractionCase& tc, const TractionSweep& s) {
    std::ostringstream out;
    const TractionSpec& spec = tc.spec;
    out << "traction: " << (grooved(spec) ? groove_shape_name(spec.grooves.shape) + std::string("-grooved") : "plain")
        << " roller R " << significant(spec.roller_radius * 1e3, 4)
        << " mm, wrap " << deg(spec.wrap) << ", T_0 " << significant(spec.tension, 4) << " N/m, f "
        << significant(spec.friction, 3) << "; h_eff " << um(s.clearance.clearance) << "\n";
    out << "  zero-traction speed " << speed_or_none(s.zero_traction_speed);
    if (s.slip_speed)
        out << "; slips under " << significant(*spec.tension_difference, 4) << " N/m at "
            << speed_or_none(*s.slip_speed);
    if (const std::optional<double> gain = groove_speed_gain(s))
        out << "; the grooves raise it " << significant(*gain, 3) << "x over the plain roller ("
            << speed_or_none(s.plain->zero_traction_speed) << ")";
    out << "\n";
    const TractionPoint& first = s.points.front();
    const TractionPoint& last = s.points.back();
    out << "  f_e " << significant(first.effective_friction, 3) << " at " << speed_or_none(first.web_speed) << " to "
        << significant(last.effective_friction, 3) << " at " << speed_or_none(last.web_speed) << "; " << s.n_invalid
        << " of " << s.points.size() << " points outside the paper's validity limits\n";
    return out.str();
}

}  // namespace coremodal
