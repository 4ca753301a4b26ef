// [traction]: one roller under the web, for Rice & Gans' traction model
// (traction/traction_model.hpp, scene/traction_case.hpp, docs/how-to/traction.md).
// Every mistake stops the reader with file:line:col, the key and what is
// expected; what the model cannot take (a zero clearance, a groove wider
// than its tool cuts, a speed at which the web's own inertia takes its whole
// tension) is refused here, before any number is computed.
#include "scene/case_reader.hpp"
#include "scene/case_table.hpp"
#include "scene/traction_case.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "scene/toml_text.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>

namespace coremodal::case_reading {

namespace {

const std::vector<std::string_view> kGrooveShapes = {"none", "sine", "circular", "rectangular"};
const std::vector<std::string_view> kGrooveKeys = {"groove_depth", "groove_width", "groove_pitch", "tool_radius"};
constexpr const char* kSpeedsExpected =
    "one of web_speed = \"5 m/s\" or web_speeds = [\"0 m/s\", \"8 m/s\"] (with points = 41, or a list), or "
    "neither (0 to 1.25 x the zero-traction speed)";

GrooveShape shape_of(std::string_view name) {
    if (name == "sine") return GrooveShape::sine;
    if (name == "circular") return GrooveShape::circular;
    if (name == "rectangular") return GrooveShape::rectangular;
    return GrooveShape::none;
}

std::string um(double m) { return significant(m * 1e6, 4) + " um"; }

}  // namespace

Grooves CaseReader::read_grooves(const Section& t) const {
    Grooves g;
    g.shape = shape_of(choice(t, "grooves", kGrooveShapes).value_or("none"));
    if (g.shape == GrooveShape::none) {
        for (std::string_view key : kGrooveKeys)
            if (const toml::node* n = get(t, key))
                fail(*n, echo(t, key, *n) + " describes grooves, but the roller has none; expected grooves = "
                                            "\"sine\", \"circular\" or \"rectangular\" with it, or no groove keys");
        return g;
    }
    const std::string shape = groove_shape_name(g.shape);
    g.depth = required(t, "groove_depth", "the groove depth G_D with grooves = \"" + shape + "\", e.g. \"36 um\"");
    g.pitch = required(t, "groove_pitch",
                       "the groove pitch 1/N with grooves = \"" + shape + "\", e.g. \"254 um\" (3937 per metre)");
    if (const std::optional<double> w = quantity(t, "groove_width")) {
        g.width = *w;
    } else if (g.shape == GrooveShape::sine) {
        g.width = g.pitch;  // the paper's eq. 16: a sine over the whole surface, no flat land
    } else {
        required(t, "groove_width", "the groove width G_W at the land with grooves = \"" + shape + "\", e.g. \"175 um\"");
    }
    if (g.width > g.pitch)
        fail(*get(t, "groove_width"), name_of(t, "groove_width") + " = " + um(g.width) + " is wider than " +
                                          name_of(t, "groove_pitch") + " = " + um(g.pitch) +
                                          "; expected a groove no wider than the pitch (the land is pitch - width)");
    if (g.shape != GrooveShape::circular) {
        if (const toml::node* n = get(t, "tool_radius"))
            fail(*n, echo(t, "tool_radius", *n) + " is for circular grooves; expected grooves = \"circular\" with "
                                                  "it, or no tool_radius");
        return g;
    }
    g.tool_radius = required(t, "tool_radius", "the radius of the tool that cut the grooves, e.g. \"127 um\"");
    const toml::node* where = get(t, "tool_radius");
    if (g.depth > g.tool_radius)
        fail(*get(t, "groove_depth"), name_of(t, "groove_depth") + " = " + um(g.depth) + " is deeper than " +
                                          name_of(t, "tool_radius") + " = " + um(g.tool_radius) +
                                          "; a round tool cuts a circular segment at most its radius deep");
    const double chord = 2.0 * std::sqrt(g.depth * (2.0 * g.tool_radius - g.depth));
    if (g.width > chord * (1.0 + 1e-9))
        fail(*(get(t, "groove_width") ? get(t, "groove_width") : where),
             name_of(t, "groove_width") + " = " + um(g.width) + " is wider than the " + um(chord) +
                 " a tool of radius " + um(g.tool_radius) + " cuts " + um(g.depth) +
                 " deep; expected a width at most 2 sqrt(G_D (2 r_tool - G_D))");
    return g;
}

std::optional<TractionSpec> CaseReader::read_traction(const Section& top, std::vector<std::string>& assumptions) const {
    const std::optional<Section> t = section(top, "traction", "traction");
    if (!t) return std::nullopt;
    TractionSpec spec;
    spec.roller_radius = required(*t, "roller_radius", "the roller's radius R, e.g. roller_radius = \"50 mm\"");
    spec.wrap = required(*t, "wrap", "the web's wrap angle on the roller, e.g. wrap = \"90 deg\"");
    spec.tension = required(*t, "tension", "the web tension per unit width (high side), e.g. tension = \"350 N/m\"");
    spec.friction = required(*t, "friction", "the static coefficient of friction of web on roller, e.g. friction = 0.3");
    spec.roller_roughness = required(*t, "roller_roughness",
                                     "the roller's asperity engagement height alpha_r, e.g. \"2.6 um\" (docs/how-to/traction.md)");
    spec.web_roughness = required(*t, "web_roughness", "the web's asperity engagement height alpha_w, e.g. \"1.1 um\"");
    spec.grooves = read_grooves(*t);
    if (const std::optional<double> mu = quantity(*t, "air_viscosity")) {
        spec.air_viscosity = *mu;
    } else {
        assumptions.push_back("[traction] air_viscosity = 1.81e-5 Pa*s: air at room temperature (Rice & Gans, "
                              "Table 3); 1.7-2.0e-5 Pa*s from 0 to 100 C");
    }
    spec.web_thickness = required(*t, "web_thickness", "the web's thickness c, e.g. \"100 um\"");
    spec.web_density = required(*t, "web_density", "the web's density rho, e.g. \"800 kg/m^3\"");
    spec.web_modulus = quantity(*t, "web_modulus");
    spec.web_poisson = quantity(*t, "web_poisson");
    if (spec.grooves.shape != GrooveShape::none) {  // B* {21} is one of the validity limits of a grooved roller
        required(*t, "web_modulus", "the web's Young's modulus with grooves (the thin-web limit B*, eq. 21), "
                                    "e.g. \"5 GPa\"");
        required(*t, "web_poisson", "the web's Poisson ratio with grooves (B*, eq. 21), e.g. 0.3");
    }
    spec.tension_difference = quantity(*t, "tension_difference");

    const toml::node* one = get(*t, "web_speed");
    const toml::node* list = get(*t, "web_speeds");
    if (one && list)
        fail(*list, echo(*t, "web_speeds", *list) + " and " + echo(*t, "web_speed", *one) +
                        " are both given; expected " + kSpeedsExpected);
    if (const toml::node* points = get(*t, "points"); points && !list)
        fail(*points, echo(*t, "points", *points) + " goes with web_speeds = [first, last]; expected " +
                          kSpeedsExpected);
    if (one) spec.web_speeds = {*quantity(*t, "web_speed")};
    if (list) spec.web_speeds = read_speed_list(*t, "web_speeds", Dimension::speed);
    check_traction(*t, spec);
    return spec;
}

void CaseReader::check_traction(const Section& t, const TractionSpec& spec) const {
    if (!(effective_clearance(spec).clearance > 0))
        fail(t.table->source(),
             t.display + (spec.grooves.shape == GrooveShape::none
                              ? " roller_roughness = 0 and web_roughness = 0 on a plain roller"
                              : " grooves and asperities too small to count") +
                 ": the effective clearance h_eff is zero and the air film has no gap to flow in (eq. 5 gives no "
                 "finite pressure); expected an asperity engagement height above 0, or grooves");
    const double limit = centripetal_limit_speed(spec);
    const toml::node* speeds = get(t, "web_speed") ? get(t, "web_speed") : get(t, "web_speeds");
    for (double v : spec.web_speeds)
        if (v >= limit)
            fail(*speeds, name_of(t, speeds == get(t, "web_speed") ? "web_speed" : "web_speeds") + ": " +
                              significant(v, 4) + " m/s is at or above " + significant(limit, 3) + " m/s" +
                              ", where the web's centripetal term c rho V^2 takes its whole tension (T = T_0 - c "
                              "rho V^2 = 0) and it no longer wraps the roller; expected speeds below it");
}

std::optional<TractionSpec> CaseReader::traction(const toml::table& root, std::vector<std::string>& assumptions) const {
    const Section top{&root, "", ""};
    return read_traction(top, assumptions);
}

void CaseReader::check_top_level(const toml::table& root) const { open(root, "", ""); }

}  // namespace coremodal::case_reading

namespace coremodal {
namespace {

// Keys a file for `coremodal traction` alone may hold; any other makes it a
// roll's case, read (and checked) whole.
bool traction_only(const toml::table& root) {
    for (const auto& [key, value] : root)
        if (key.str() != "name" && key.str() != "description" && key.str() != "traction") return false;
    return true;
}

std::vector<double> default_speeds(const TractionSpec& spec) {
    const double zero = zero_traction_speed(spec);
    // Past the zero-traction speed, but short of the centripetal limit.
    const double last = std::min(kDefaultSpeedSpan * zero, 0.5 * (zero + centripetal_limit_speed(spec)));
    std::vector<double> out(kDefaultSpeedPoints);
    for (int i = 0; i < kDefaultSpeedPoints; ++i) out[i] = last * i / (kDefaultSpeedPoints - 1);
    return out;
}

TractionCase read_document(const toml::table& root, const std::string& path) {
    TractionCase out;
    out.source_file = path;
    out.has_roll = !traction_only(root);
    case_reading::CaseReader reader(path);
    if (out.has_roll) {
        out.warnings = parse_case_table(root, path).warnings;  // the whole scene, [traction] included
    } else {
        reader.check_top_level(root);
    }
    std::optional<TractionSpec> spec = reader.traction(root, out.assumptions);
    COREMODAL_ASSERT(spec);
    if (!out.has_roll) out.warnings = reader.warnings();
    out.speeds_given = !spec->web_speeds.empty();
    if (!out.speeds_given) {
        spec->web_speeds = default_speeds(*spec);
        out.assumptions.push_back("[traction] web_speeds: " + std::to_string(kDefaultSpeedPoints) +
                                  " speeds from 0 to " + significant(spec->web_speeds.back(), 3) + " m/s" +
                                  " (the file gives none: 0 to 1.25 x the zero-traction speed)");
    }
    out.spec = std::move(*spec);
    out.name = root["name"].value<std::string>().value_or(std::filesystem::path(path).stem().string());
    out.description = root["description"].value<std::string>().value_or("");
    return out;
}

}  // namespace

std::optional<TractionCase> read_traction_case_text(std::string_view text, const std::string& path) {
    const toml::table root = parse_toml_input(text, path, "a valid TOML case file (docs/reference/case-files.md)");
    if (!root.get("traction")) return std::nullopt;
    try {
        return read_document(root, path);
    } catch (const InputError& e) {  // a key echoed in a message: the user's characters
        throw InputError(restore_characters(e.what()));
    }
}

std::optional<TractionCase> read_traction_case(const std::string& path) {
    return read_traction_case_text(read_input_file(path, "case file"), path);
}

}  // namespace coremodal
