// The case-file key table: one row per key, declared once (issue 34: "case-file
// keys in one table"): its table, kind, unit, range and plausible range
// (scene/case_key_ranges.hpp), and its words, the default as a user writes it
// and a one-line description (KeyText), which the JSON Schema
// (scene/case_json_schema.cpp) and the docs show. docs/reference/case-files.md is
// the long form of the same text. Each schema table's title is here too.
#include "scene/case_key_ranges.hpp"
#include "scene/case_schema.hpp"

#include <cmath>
#include <initializer_list>

namespace coremodal {
namespace {

using namespace key_ranges;

KeySpec length_key(std::string_view table, std::string_view key, double max, PlausibleRange plausible = {}) {
    return {table, key, ValueKind::quantity, Dimension::length, 0.0, max, true, plausible};
}
KeySpec modulus_key(std::string_view key, double typical) {
    return {"material", key, ValueKind::quantity, Dimension::pressure, 0.0, kMaxModulus, true,
            {kMinPlausibleModulus, kMaxPlausibleModulus, typical, kModulusWhy}};
}
KeySpec poisson_key(std::string_view key) {
    // The admissible range depends on the moduli (Jones 1999, ch. 2); the whole
    // material is checked with why_not_admissible.
    return {"material", key, ValueKind::quantity, Dimension::dimensionless};
}
KeySpec integer_key(std::string_view table, std::string_view key, double min, double max) {
    return {table, key, ValueKind::integer, Dimension::dimensionless, min, max};
}
KeySpec plain_key(std::string_view table, std::string_view key, ValueKind kind) {
    return {table, key, kind};
}

// One row of the key table: the value's spec and its words, side by side.
struct KeyRow {
    KeySpec spec;
    KeyText text;
};
std::vector<KeySpec> with_text(std::initializer_list<KeyRow> rows) {
    std::vector<KeySpec> out;
    out.reserve(rows.size());
    for (const KeyRow& row : rows) {
        out.push_back(row.spec);
        out.back().text = row.text;
    }
    return out;
}

}  // namespace

const std::vector<KeySpec>& case_schema() {
    static const std::vector<KeySpec> schema = with_text({
        {plain_key("", "name", ValueKind::text),
         {"the file name without .toml", "case name, used in output file names and summaries; a name, not a path (no '/', not \"\", \".\" or \"..\")"}},
        {plain_key("", "description", ValueKind::text),
         {"\"\"", "free text, echoed in the summary"}},
        {plain_key("", "model", ValueKind::text),
         {"\"solid\"", "model level: 3D solid, axisymmetric-harmonic section, coupled harmonics (segmented chucks), auto, or Timoshenko beam network (run --model overrides it)", "solid harmonic coupled auto beam"}},
        {plain_key("", "core", ValueKind::table),
         {"required (a file for `coremodal traction` alone needs only [traction])", "the paperboard core"}},
        {plain_key("", "rest_paper", ValueKind::table),
         {"none: a bare core", "paper still wound on the core, over its full length"}},
        {plain_key("", "supports", ValueKind::table),
         {"none: free-free", "how the core is held: free, rigid clamps or elastic chucks"}},
        {plain_key("", "analysis", ValueKind::table),
         {"the 20 lowest modes", "what to compute: the lowest modes or all modes in a band"}},
        {plain_key("", "mesh", ValueKind::table),
         {"level \"default\"", "mesh refinement, or a gmsh mesh file"}},
        // Read by `coremodal study` and `coremodal calibrate` (scene/case_sweep.hpp,
        // docs/how-to/studies.md, docs/how-to/calibration.md); `coremodal run` ignores them.
        {plain_key("", "study", ValueKind::table),
         {"none", "a sweep over this file's keys, for `coremodal study` (`run` ignores it)"}},
        {plain_key("", "calibration", ValueKind::table),
         {"none", "a sweep whose chuck factors are fitted, for `coremodal calibrate` (`run` ignores it)"}},
        {plain_key("", "rotation", ValueKind::table),
         {"none: the roll stands still", "the roll, chucks and shafts spin: modes at a speed, or a Campbell sweep (`coremodal campbell`)"}},
        {plain_key("", "web", ValueKind::table),
         {"none: no web", "the paper web pulls on the roll along one line of its surface (docs/theory/web.md)"}},
        {plain_key("", "damping", ValueKind::table),
         {"none (needed by [response])", "relative damping of the modes, for the forced response (docs/how-to/response.md)"}},
        {plain_key("", "excitation", ValueKind::table),
         {"none (needed by [response])", "what excites the spinning roll: bow, unbalance, eccentricity, ovality with gravity"}},
        {plain_key("", "response", ValueKind::table),
         {"none: no forced response", "mid-span vibration against web speed and the safe speed from the amplitude limit (`coremodal response`)"}},
        // Read by `coremodal traction` (docs/how-to/traction.md); other commands check it and ignore it.
        {plain_key("", "traction", ValueKind::table),
         {"none: no roller", "web-to-roller traction on one roller, Rice & Gans (`coremodal traction`, docs/how-to/traction.md); other commands check it and ignore it"}},
        {plain_key("", "limits", ValueKind::table),
         {"none: the case's roll down to the bare core", "how fast the roll may run as it unwinds: one verdict (`coremodal limits`, docs/how-to/limits.md)"}},

        {length_key("core", "inner_diameter", kMaxDiameter, kPlausibleDiameter),
         {kRequired, "inner diameter Di of the core, smaller than the outer diameter"}},
        {length_key("core", "outer_diameter", kMaxDiameter, kPlausibleDiameter),
         {"none: give outer_diameter or wall", "outer diameter Do; give exactly one of outer_diameter and wall"}},
        {length_key("core", "wall", kMaxDiameter, kPlausibleWall),
         {"none: give wall or outer_diameter", "wall thickness; Do = Di + 2 wall"}},
        {length_key("core", "length", kMaxLength, kPlausibleCoreLength),
         {kRequired, "full core length Lc"}},
        {plain_key("core", "material", ValueKind::material),
         {"\"paperboard_core\"", "core material: a library name or an inline table (noted as an assumption when left out)"}},

        {length_key("rest_paper", "thickness", kMaxDiameter, kPlausibleRestPaper),
         {"none: give thickness or outer_diameter", "radial thickness of the paper; Dp = Do + 2 thickness"}},
        {length_key("rest_paper", "outer_diameter", kMaxDiameter, kPlausibleDiameter),
         {"none: give outer_diameter or thickness", "outer diameter Dp of the paper, larger than the core's"}},
        {plain_key("rest_paper", "material", ValueKind::material),
         {"\"rest_paper\"", "paper cylinder material: a library name or an inline table"}},

        {plain_key("material", "base", ValueKind::text),
         {"none: every value given", "library material to start from; the other keys replace its values"}},
        {modulus_key("E", kTypicalIsotropic),
         {"from base", "isotropic Young's modulus (G = E / (2 (1 + nu)))"}},
        {poisson_key("nu"),
         {"from base", "isotropic Poisson ratio"}},
        {modulus_key("E_r", kTypicalAcross),
         {"from base", "radial Young's modulus"}},
        {modulus_key("E_theta", kTypicalInPlane),
         {"from base", "circumferential Young's modulus"}},
        {modulus_key("E_z", kTypicalInPlane),
         {"from base", "axial Young's modulus"}},
        {modulus_key("G_rtheta", kTypicalShearAcross),
         {"from base", "shear modulus in the r-theta plane"}},
        {modulus_key("G_rz", kTypicalShearAcross),
         {"from base", "shear modulus in the r-z plane"}},
        {modulus_key("G_thetaz", kTypicalShearInPlane),
         {"from base", "shear modulus in the theta-z plane"}},
        {poisson_key("nu_rtheta"),
         {"from base", "Poisson ratio nu_rtheta = -eps_theta/eps_r under sigma_r; compliance must stay positive definite"}},
        {poisson_key("nu_rz"),
         {"from base", "Poisson ratio nu_rz = -eps_z/eps_r under sigma_r; compliance must stay positive definite"}},
        {poisson_key("nu_thetaz"),
         {"from base", "Poisson ratio nu_thetaz = -eps_z/eps_theta under sigma_theta; compliance must stay positive definite"}},
        {{"material", "density", ValueKind::quantity, Dimension::density, 0.0, kMaxDensity, true, kPlausibleDensity},
         {"from base", "mass density"}},

        {plain_key("supports", "type", ValueKind::text),
         {"\"free\"", "free-free (6 rigid-body modes), rigid clamps on the inner surface, or elastic chucks in a stand", "free clamped chucks"}},
        {plain_key("supports", "left", ValueKind::table),
         {"none: required when clamped or chucks", "clamp zone (type = \"clamped\") or chuck (type = \"chucks\") at the left end, z = 0"}},
        {plain_key("supports", "right", ValueKind::table),
         {"the mirror of left", "clamp zone or chuck at the right end, z = Lc"}},

        {length_key("clamp", "length", kMaxLength),
         {kRequired, "clamped length of the core's inner surface"}},
        {{"clamp", "start", ValueKind::quantity, Dimension::length, 0.0, kMaxLength},
         {"0", "distance from the core end to the zone's end-side edge"}},
        {{"clamp", "center", ValueKind::quantity, Dimension::length, 0.0, kMaxLength},
         {"none: give start or center", "distance from the core end to the zone centre; instead of start"}},

        // [supports.left] / [supports.right] of type = "chucks" (docs/theory/chucks.md).
        {length_key("chuck", "inserted_length", kMaxLength),
         {kRequired, "chuck body length inside the core, at most half the core"}},
        {{"chuck", "clearance", ValueKind::quantity, Dimension::length, 0.0, kMaxDiameter},
         {"\"0.5 mm\"", "radial clearance: body diameter = bore - 2 clearance"}},
        {length_key("chuck", "body_diameter", kMaxDiameter),
         {"from clearance", "chuck body diameter, instead of clearance; smaller than the bore"}},
        {length_key("chuck", "shaft_diameter", kMaxDiameter),
         {"the body diameter", "shaft diameter from the core end to the bearing, at most the body diameter"}},
        {length_key("chuck", "shaft_length", kMaxLength),
         {"\"150 mm\"", "shaft length from the core end to the bearing"}},
        {plain_key("chuck", "material", ValueKind::material),
         {"\"steel\"", "chuck body and shaft material: a library name or an inline table"}},
        {plain_key("chuck", "interface", ValueKind::text),
         {"\"spring\"", "spring layer over the expanding elements, or shared displacements", "spring bonded"}},
        {plain_key("chuck", "expanded", ValueKind::boolean),
         {"true", "false: the chuck was not expanded (the bore rests on the body under gravity)"}},
        {plain_key("chuck", "contact", ValueKind::text),
         {"\"one-sided\" when not expanded, else \"uniform\"", "one-sided: compression-only contact across the clearance, closed where the roll's weight closes it (3D solid level); uniform: the spring layer all around", "uniform one-sided"}},
        {{"chuck", "normal_stiffness", ValueKind::quantity, Dimension::stiffness_per_area, 0.0, kInf, true},
         {"from the expansion pressure", "normal stiffness of the spring layer, instead of expansion_pressure"}},
        {{"chuck", "tangential_stiffness", ValueKind::quantity, Dimension::stiffness_per_area, 0.0, kInf, true},
         {"from the expansion pressure", "tangential stiffness of the spring layer, with normal_stiffness"}},
        {{"chuck", "expansion_pressure", ValueKind::quantity, Dimension::pressure, 0.0, 1e9},
         {"\"6 bar\"", "expansion pressure of the elements; gives the spring layer's stiffness (docs/theory/chucks.md)"}},
        {plain_key("chuck", "expanding", ValueKind::tables),
         {kRequired, "the expanding elements, [[supports.<end>.expanding]], at least one"}},
        {plain_key("chuck", "bearing", ValueKind::table),
         {"none: a rigid bearing", "the bearing at the shaft's end"}},

        {{"expanding", "center", ValueKind::quantity, Dimension::length, 0.0, kMaxLength},
         {kRequired, "axial centre of the element from the core end"}},
        {length_key("expanding", "width", kMaxLength),
         {kRequired, "axial width of the element"}},
        {integer_key("expanding", "segments", 1, 64),
         {"none: a full band", "N segments centred at 0, 360/N, ... degrees instead of a band; needs segment_angle"}},
        {{"expanding", "segment_angle", ValueKind::quantity, Dimension::angle, 0.0, 6.2832, true},
         {"none: required with segments", "angle each segment spans; segments x segment_angle <= 360 deg"}},

        {plain_key("bearing", "type", ValueKind::text),
         {"\"rigid\" (\"elastic\" when radial_stiffness is given)", "rigid or elastic bearing", "rigid elastic"}},
        {{"bearing", "radial_stiffness", ValueKind::quantity, Dimension::stiffness, 0.0, kInf, true},
         {"none: required when elastic", "radial stiffness of an elastic bearing"}},
        {{"bearing", "tilting_stiffness", ValueKind::quantity, Dimension::rotational_stiffness, 0.0, kInf, true},
         {"none: required when elastic", "tilting stiffness of an elastic bearing"}},
        {{"bearing", "frame_mass", ValueKind::quantity, Dimension::mass, 0.0, 1e6, true},
         {"none: no frame", "mass of the stand's frame behind the bearing; needs frame_stiffness"}},
        {{"bearing", "frame_stiffness", ValueKind::quantity, Dimension::stiffness, 0.0, kInf, true},
         {"none: required with frame_mass", "stiffness of the frame to the ground"}},

        {integer_key("analysis", "modes", 1, kMaxModes),
         {"20", "the lowest modes wanted; rigid-body modes count; not with band"}},
        {plain_key("analysis", "band", ValueKind::band),
         {"none: the lowest modes", "all modes in [low, high], e.g. [\"0 Hz\", \"500 Hz\"]; instead of modes"}},
        {{"analysis", "tolerance", ValueKind::quantity, Dimension::dimensionless, 0.0, 0.1, true},
         {"1e-10", "eigensolver relative residual tolerance"}},
        {integer_key("analysis", "max_iterations", 1, 1e7),
         {"500", "eigensolver iteration limit"}},

        {plain_key("mesh", "level", ValueKind::text),
         {"\"default\"", "named refinement (docs/reference/case-scene.md, [mesh])", "coarse default fine very_fine"}},
        {integer_key("mesh", "through_wall", 1, kMaxElementsThrough),
         {"from the level", "elements through the core wall; overrides the level's"}},
        {integer_key("mesh", "through_rest_paper", 1, kMaxElementsThrough),
         {"from the level", "elements through the rest paper; overrides the level's"}},
        {integer_key("mesh", "around", 8, kMaxElementsAround),
         {"from the level", "elements around the circumference, a multiple of 4; overrides the level's"}},
        {integer_key("mesh", "along", 2, 100000),
         {"from the level", "elements along the core; overrides the level's"}},
        {plain_key("mesh", "element", ValueKind::text),
         {"\"hex20\"", "quadratic serendipity (hex20) or Lagrange (hex27) hexahedra", "hex20 hex27"}},
        {plain_key("mesh", "file", ValueKind::text),
         {"none: a generated mesh", "a gmsh .msh file of your own, relative to the case file's folder; excludes the other mesh keys except element"}},

        // [rotation]: the roll spins (docs/how-to/campbell.md).
        {{"rotation", "speed", ValueKind::quantity, Dimension::frequency, 0.0, kMaxRotationHz},
         {"none: give one of speed, speeds, web_speed, web_speeds", "one rotation speed, e.g. \"1200 rpm\" (a plain number is in Hz)"}},
        {plain_key("rotation", "speeds", ValueKind::list),
         {"none: give one of speed, speeds, web_speed, web_speeds", "rotation speeds: a list, or [first, last] with points"}},
        {integer_key("rotation", "points", 2, kMaxRotationPoints),
         {"none: speeds is a list", "number of equally spaced speeds from the first to the last of speeds (or web_speeds)"}},
        {{"rotation", "web_speed", ValueKind::quantity, Dimension::speed, 0.0, kMaxWebSpeed},
         {"none: give one of speed, speeds, web_speed, web_speeds", "one web speed v; f_rot = v / (pi Dp), Dp the roll's outer diameter"}},
        {plain_key("rotation", "web_speeds", ValueKind::list),
         {"none: give one of speed, speeds, web_speed, web_speeds", "web speeds: a list, or [first, last] with points; each f_rot = v / (pi Dp)"}},
        {plain_key("rotation", "excitation_orders", ValueKind::list),
         {"[1, 2]", "orders k of the excitation lines f = k f_rot (1: unbalance, 2: ovality, sag)"}},
        {plain_key("rotation", "operating_speeds", ValueKind::list),
         {"none: no operating range", "[lowest, highest] speed the machine runs at, in the sweep's units and inside it; campbell shades it and flags a critical speed inside"}},
        {plain_key("rotation", "centrifugal_stiffening", ValueKind::boolean),
         {"true", "the centrifugal prestress as geometric stiffness, where the level has a term for it (not at the beam level)"}},

        // [web]: the paper web pulls on the roll along a line (docs/theory/web.md).
        {{"web", "tension", ValueKind::quantity, Dimension::line_force, 0.0, 1e6, true, kPlausibleWebTension},
         {"required", "the web's tension per unit width, e.g. \"300 N/m\""}},
        {{"web", "span", ValueKind::quantity, Dimension::length, 0.0, kMaxLength, true, kPlausibleWebSpan},
         {"required", "free span from the roll's surface to the first guide roller"}},
        {{"web", "angle", ValueKind::quantity, Dimension::angle, -2 * M_PI, 2 * M_PI},
         {"required", "direction the web leaves the roll in, about the roll's axis (0 = +x, 90 deg = +y)"}},
        {{"web", "thickness", ValueKind::quantity, Dimension::length, 0.0, 0.1, true, kPlausibleWebThickness},
         {"required", "the web's thickness"}},
        {{"web", "modulus", ValueKind::quantity, Dimension::pressure, 0.0, kMaxModulus, true, kPlausibleWebModulus},
         {"required", "the web's in-plane modulus along its length (MD)"}},
        {{"web", "shear_modulus", ValueKind::quantity, Dimension::pressure, 0.0, kMaxModulus, true, kPlausibleWebModulus},
         {"0.387 sqrt(E_MD E_CD) with E_CD = E_MD / 2: 0.274 x modulus (Baum et al. 1981)", "the web's in-plane shear modulus"}},

        // [traction]: web-to-roller traction on one roller (Rice & Gans; docs/how-to/traction.md).
        {length_key("traction", "roller_radius", kMaxDiameter, kPlausibleRollerRadius),
         {kRequired, "radius R of the roller the web wraps"}},
        {{"traction", "wrap", ValueKind::quantity, Dimension::angle, 0.0, 2 * M_PI, true},
         {kRequired, "wrap angle theta of the web on the roller, above 0 and at most 360 deg"}},
        {{"traction", "tension", ValueKind::quantity, Dimension::line_force, 0.0, 1e6, true, kPlausibleWebTension},
         {kRequired, "nominal (high-side) web tension per unit width T_0, e.g. \"350 N/m\""}},
        {{"traction", "friction", ValueKind::quantity, Dimension::dimensionless, 0.0, 10.0, true, kPlausibleFriction},
         {kRequired, "static coefficient of friction f of the web on the roller (no air)"}},
        {{"traction", "roller_roughness", ValueKind::quantity, Dimension::length, 0.0, 0.01, false, kPlausibleRoughness},
         {kRequired, "the roller's asperity engagement height alpha_r (Rice et al. 2002; 0 for a polished groove land)"}},
        {{"traction", "web_roughness", ValueKind::quantity, Dimension::length, 0.0, 0.01, false, kPlausibleRoughness},
         {kRequired, "the web's asperity engagement height alpha_w"}},
        {plain_key("traction", "grooves", ValueKind::text),
         {"\"none\"", "the roller's circumferential grooves by cross-section: none (plain roller), sine, circular (a round tool), rectangular", "none sine circular rectangular"}},
        {length_key("traction", "groove_depth", 0.1, kPlausibleGrooveSize),
         {"none: required with grooves", "groove depth G_D, land to bottom (sine: crest to trough)"}},
        {length_key("traction", "groove_width", 0.1, kPlausibleGrooveSize),
         {"none: required for circular and rectangular grooves; sine: the pitch", "groove width G_W at the land; the land is pitch - width"}},
        {length_key("traction", "groove_pitch", 0.1, kPlausibleGrooveSize),
         {"none: required with grooves", "groove to groove, 1/N (3937 grooves per metre: \"254 um\")"}},
        {length_key("traction", "tool_radius", 0.1, kPlausibleGrooveSize),
         {"none: required for circular grooves", "radius r_tool of the tool that cut circular grooves"}},
        {{"traction", "air_viscosity", ValueKind::quantity, Dimension::viscosity, 0.0, 1.0, true, kPlausibleViscosity},
         {"\"1.81e-5 Pa*s\"", "dynamic viscosity mu of the air (Rice & Gans, Table 3)"}},
        {{"traction", "web_thickness", ValueKind::quantity, Dimension::length, 0.0, 0.1, true, kPlausibleWebThickness},
         {kRequired, "web thickness c (the centripetal term c rho V^2 and B*)"}},
        {{"traction", "web_density", ValueKind::quantity, Dimension::density, 0.0, kMaxDensity, true, kPlausibleWebDensity},
         {kRequired, "web density rho (the centripetal term c rho V^2)"}},
        {{"traction", "web_modulus", ValueKind::quantity, Dimension::pressure, 0.0, kMaxModulus, true, kPlausibleWebModulus},
         {"none: required with grooves", "web Young's modulus E (B*, the thin-web limit, eq. 21)"}},
        {{"traction", "web_poisson", ValueKind::quantity, Dimension::dimensionless, 0.0, 0.5, false},
         {"none: required with grooves", "web Poisson ratio nu (B*, eq. 21)"}},
        {{"traction", "tension_difference", ValueKind::quantity, Dimension::line_force, 0.0, 1e6, false},
         {"none", "tension difference the roller must carry (drive or brake): the speed it slips at is reported"}},
        {{"traction", "web_speed", ValueKind::quantity, Dimension::speed, 0.0, kMaxWebSpeed},
         {"none: web_speeds, or 0 to 1.25 x the zero-traction speed", "one web speed V_w (the roller runs with the web)"}},
        {plain_key("traction", "web_speeds", ValueKind::list),
         {"0 to 1.25 x the zero-traction speed, 51 points", "web speeds: a list, or [first, last] with points"}},
        {integer_key("traction", "points", 2, kMaxResponsePoints),
         {"none: web_speeds is a list", "number of equally spaced web speeds from the first to the last of web_speeds"}},

        // [damping], [excitation], [response]: the forced response (docs/how-to/response.md).
        {{"damping", "ratio", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
         {"none: give one of ratio, log_decrement, decay, rayleigh", "relative damping zeta of every elastic mode not named by a family key or modes (cores and rest rolls 0.005-0.02)"}},
        {{"damping", "log_decrement", ValueKind::quantity, Dimension::dimensionless, 0.0, 2 * M_PI, true, kPlausibleLogDecrement},
         {"none: give one of ratio, log_decrement, decay, rayleigh", "logarithmic decrement delta = ln(X0/X1) of a measured decay; zeta = delta / (2 pi) (I-1)"}},
        {plain_key("damping", "decay", ValueKind::table),
         {"none: give one of ratio, log_decrement, decay, rayleigh", "a measured decay { amplitude_ratio = X0/XN, cycles = N }; zeta = ln(X0/XN) / (2 pi N) (I-1)"}},
        {{"decay", "amplitude_ratio", ValueKind::quantity, Dimension::dimensionless, 1.0, 1e6, true},
         {kRequired, "X0/XN: the first amplitude over the amplitude N cycles later, larger than 1"}},
        {{"decay", "cycles", ValueKind::quantity, Dimension::dimensionless, 0.0, 1e4, true},
         {kRequired, "N: the cycles between the two amplitudes"}},
        // Rayleigh's alpha (1/s) and beta (s) as plain SI numbers: no unit
        // names a rate apart from a frequency ("1/s" is 1 Hz here, a cycle
        // per second, which alpha is not).
        {plain_key("damping", "rayleigh", ValueKind::table),
         {"none: give one of ratio, log_decrement, decay, rayleigh", "Rayleigh damping D = alpha M + beta K: { alpha = 0.5, beta = 1e-5 } (1/s, s) or { zeta = 0.01, frequencies = [\"20 Hz\", \"200 Hz\"] }; mode j gets alpha/(2 w_j) + beta w_j/2"}},
        {{"rayleigh", "alpha", ValueKind::quantity, Dimension::dimensionless, 0.0, kInf},
         {"0", "alpha of D = alpha M + beta K, in 1/s (a plain number)"}},
        {{"rayleigh", "beta", ValueKind::quantity, Dimension::dimensionless, 0.0, kInf},
         {"0", "beta of D = alpha M + beta K, in s (a plain number)"}},
        {{"rayleigh", "zeta", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
         {"none: give alpha and beta, or zeta with frequencies", "the relative damping at both frequencies"}},
        {plain_key("rayleigh", "frequencies", ValueKind::list),
         {"none: give alpha and beta, or zeta with frequencies", "two frequencies at which the damping ratio is zeta, e.g. [\"20 Hz\", \"200 Hz\"]"}},
        {{"damping", "bending", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
         {"the base (ratio, ..., rayleigh)", "relative damping of every bending mode (mode label bending)"}},
        {{"damping", "torsion", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
         {"the base (ratio, ..., rayleigh)", "relative damping of every torsion mode (none in the lateral response: beam level, or n = 1 at the harmonic level)"}},
        {{"damping", "axial", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
         {"the base (ratio, ..., rayleigh)", "relative damping of every axial mode (none in the lateral response: beam level, or n = 1 at the harmonic level)"}},
        {{"damping", "breathing", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
         {"the base (ratio, ..., rayleigh)", "relative damping of every breathing mode (solid and harmonic levels)"}},
        {{"damping", "ovalling", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
         {"the base (ratio, ..., rayleigh)", "relative damping of every ovalling mode (solid and harmonic levels)"}},
        {plain_key("damping", "modes", ValueKind::tables),
         {"none", "ratios of single modes: [{ mode = 1, ratio = 0.02 }], mode numbers as in modes.csv of the scene at rest; a degenerate pair shares one ratio"}},
        {integer_key("modes", "mode", 1, kMaxModes),
         {kRequired, "the mode's number among the modes at rest (modes.csv), from 1"}},
        {{"modes", "ratio", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
         {kRequired, "its relative damping zeta (0 to 1)"}},
        // Structural damping: 0 < eta <= 1 for every part, 0 <= eta <= 1 per part (0: a lossless part).
        {{"damping", "loss_factor", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleLossFactor},
         {"none", "structural (hysteretic) damping: the loss factor eta of every part (core, rest paper, chucks), complex stiffness K (1 + i eta); at resonance as zeta = eta / 2; the value is the user's"}},
        {plain_key("damping", "loss_factors", ValueKind::table),
         {"none", "loss factors per part, over loss_factor: { core = 0.03, rest_paper = 0.05, chucks = 0.001 }"}},
        {{"loss_factors", "core", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, false, kPlausibleLossFactor},
         {"[damping] loss_factor", "the core's loss factor eta (0 to 1; 0: lossless)"}},
        {{"loss_factors", "rest_paper", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, false, kPlausibleLossFactor},
         {"[damping] loss_factor", "the rest paper's loss factor eta (0 to 1; 0: lossless)"}},
        {{"loss_factors", "chucks", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, false, kPlausibleLossFactor},
         {"[damping] loss_factor", "both chucks' (steel) loss factor eta (0 to 1; 0: lossless)"}},
        {{"excitation", "bow", ValueKind::quantity, Dimension::length, 0.0, 0.1, false, kPlausibleBow},
         {"0: straight", "straightness deviation of the core at mid-core (ISO 11093-5); the bow turns with the roll (order 1)"}},
        {plain_key("excitation", "bow_shape", ValueKind::text),
         {"\"half_sine\"", "shape of the bow along the core: a half sine over the core length, or the first bending mode at rest", "half_sine first_mode"}},
        {{"excitation", "unbalance", ValueKind::quantity, Dimension::unbalance, 0.0, 100.0, false, kPlausibleUnbalance},
         {"0", "a point unbalance at mid-core (kg*m, e.g. \"2 kg*mm\"): force U Omega^2 turning with the roll (order 1)"}},
        {{"excitation", "eccentricity", ValueKind::quantity, Dimension::length, 0.0, 0.1, false, kPlausibleEccentricity},
         {"0", "the rest paper's mass centre off the axis, uniform along the roll (needs [rest_paper]): order 1"}},
        {{"excitation", "ovality", ValueKind::quantity, Dimension::length, 0.0, 0.1, false, kPlausibleOvality},
         {"0", "roundness deviation of the core, D_max - D_min; with gravity an order-2 load (2 x per revolution)"}},
        {plain_key("excitation", "gravity", ValueKind::boolean),
         {"true", "gravity acts vertically: the static sag, and with ovality the order-2 load"}},
        {plain_key("response", "speeds", ValueKind::list),
         {"none: give speeds or web_speeds", "rotation speeds: a list, or [first, last] with points (above 0)"}},
        {plain_key("response", "web_speeds", ValueKind::list),
         {"none: give speeds or web_speeds", "web speeds: a list, or [first, last] with points; each f_rot = v / (pi Dp)"}},
        {integer_key("response", "points", 2, kMaxResponsePoints),
         {"none: the speeds are a list", "number of equally spaced speeds from the first to the last"}},
        {length_key("response", "limit", 1.0, kPlausibleLimit),
         {"\"5 mm\"", "the amplitude limit at the first probe (semi-major axis of the orbit): the safe speed is where it is first reached"}},
        {plain_key("response", "probes", ValueKind::list),
         {"[\"mid-span\"]", "where the amplitude is reported: \"mid-span\" (the core's middle) or positions from the core's left end"}},

        // [limits]: one verdict over the rest-roll diameters (docs/how-to/limits.md).
        {plain_key("limits", "diameters", ValueKind::list),
         {"[the case's roll, the bare core]", "rest-roll diameters [largest, smallest] the verdict runs over (`coremodal limits`)"}},
        {integer_key("limits", "points", 2, kMaxLimitsPoints),
         {"20", "number of rest-roll diameters (more are added where a criterion changes fast)"}},
        {{"limits", "web_speed", ValueKind::quantity, Dimension::speed, 0.0, kMaxWebSpeed, true},
         {"none: no roll change reported", "the press's target web speed: the rest-roll diameter where the roll must be changed"}},
        {length_key("limits", "limit", 1.0, kPlausibleLimit),
         {"[response] limit, else \"5 mm\"", "the amplitude limit at mid-span (Ilomaki's +-5 mm)"}},
        {plain_key("limits", "band", ValueKind::boolean),
         {"true", "propagate the uncertain inputs' documented ranges into a band beside every speed"}},

        // [study]: a sweep over case-file keys, with the modes tracked by MAC.
        {plain_key("study", "parameters", ValueKind::tables),
         {kRequired, "what to vary, one table per parameter; several make a grid (first slowest)"}},
        {plain_key("study", "mesh", ValueKind::text),
         {"the case's [mesh], else \"coarse\"", "mesh level of every point", "coarse default fine very_fine"}},
        {integer_key("study", "modes", 1, kMaxModes),
         {"the case's [analysis] modes, else 12", "modes of every point"}},
        {{"study", "safe_factor", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true},
         {"0.7", "I-5 safe-speed factor"}},
        {{"study", "web_speed", ValueKind::quantity, Dimension::speed, 0.0, kMaxWebSpeed, true},
         {"none", "the web speed line of Koenig's chart"}},

        // [calibration]: a sweep whose chuck factors are fitted (docs/how-to/calibration.md).
        {plain_key("calibration", "parameters", ValueKind::tables),
         {kRequired, "what to vary, one table per parameter; several make a grid (first slowest)"}},
        {plain_key("calibration", "mesh", ValueKind::text),
         {"the case's [mesh], else \"coarse\"", "mesh level of every point", "coarse default fine very_fine"}},
        {integer_key("calibration", "modes", 1, kMaxModes),
         {"the case's [analysis] modes, else 6", "modes of every point"}},
        {integer_key("calibration", "holdout_every", 2, 1000),
         {"4", "every Nth usable point is held out of the fit"}},
        {{"calibration", "max_error", ValueKind::quantity, Dimension::dimensionless, 0.0, 0.5, true},
         {"0.05", "stated error of I-7 with the fitted k"}},

        // One item of parameters = [...]: key (a dotted path, or a list of
        // paths set together) and either values or a range from/to/steps.
        {plain_key("parameter", "key", ValueKind::text),
         {kRequired, "dotted key path into this file, e.g. \"core.length\", or a list of paths set together"}},
        {plain_key("parameter", "values", ValueKind::list),
         {"none: give values or from/to/steps", "the values, written as the key takes them (\"10 mm\", 6.5e9, \"steel\", true)"}},
        {plain_key("parameter", "from", ValueKind::quantity),
         {"none: give values or from/to/steps", "first value of a range, written as the key takes it"}},
        {plain_key("parameter", "to", ValueKind::quantity),
         {"none: give values or from/to/steps", "last value of a range (included)"}},
        {integer_key("parameter", "steps", 2, kMaxSweepSteps),
         {"none: give values or from/to/steps", "number of values in the range"}},
        {plain_key("parameter", "spacing", ValueKind::text),
         {"\"linear\"", "spacing of the range's values", "linear log"}},
    });
    return schema;
}

const std::vector<TableTitle>& schema_tables() {
    static const std::vector<TableTitle> tables = {
    {"core", "[core]: the paperboard core"},
    {"rest_paper", "[rest_paper]: paper still wound on the core"},
    {"material", "a material table ([core.material], [rest_paper.material], a chuck's material): isotropic (E, nu, "
                 "density) or orthotropic keys, optionally on a library base"},
    {"supports", "[supports]: how the core is held"},
    {"clamp", "[supports.left] / [supports.right] when type = \"clamped\": a rigid clamp zone on the inner surface"},
    {"chuck", "[supports.left] / [supports.right] when type = \"chucks\": an elastic chuck (docs/theory/chucks.md)"},
    {"expanding", "[[supports.<end>.expanding]]: an expanding element of a chuck"},
    {"bearing", "[supports.<end>.bearing]: the chuck's bearing"},
    {"analysis", "[analysis]: what to compute"},
    {"mesh", "[mesh]: mesh refinement or a mesh file"},
    {"study", "[study]: a sweep for `coremodal study` (docs/how-to/studies.md)"},
    {"calibration", "[calibration]: a sweep whose chuck factor is fitted, for `coremodal calibrate`"},
    {"parameter", "an item of parameters: key, and values or from/to/steps"},
    {"rotation", "[rotation]: the roll spins; the modes at a speed or a Campbell sweep (docs/how-to/campbell.md)"},
    {"web", "[web]: the paper web pulls on one line of the roll's surface (docs/theory/web.md)"},
    {"damping", "[damping]: relative damping of the modes for the forced response (docs/how-to/response.md)"},
    {"decay", "[damping] decay: a measured free decay, zeta = ln(X0/XN) / (2 pi N) (I-1)"},
    {"rayleigh", "[damping] rayleigh: D = alpha M + beta K, from alpha and beta or from zeta at two frequencies"},
    {"modes", "[damping] modes: the relative damping of single modes at rest, { mode = 1, ratio = 0.02 }"},
    {"loss_factors", "[damping.loss_factors]: the loss factor eta per part (structural damping, K_p (1 + i eta_p))"},
    {"excitation", "[excitation]: what excites the spinning roll (docs/how-to/response.md)"},
    {"response", "[response]: the forced response against web speed and the safe speed from the amplitude limit"},
    {"limits", "[limits]: one verdict over the rest-roll diameters, for `coremodal limits` (docs/how-to/limits.md)"},
    {"traction", "[traction]: web-to-roller traction on one roller, Rice & Gans (`coremodal traction`, docs/how-to/traction.md)"},
};
    return tables;
}

}  // namespace coremodal
