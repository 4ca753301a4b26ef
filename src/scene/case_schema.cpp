#include "scene/case_schema.hpp"

#include "common/join.hpp"
#include "scene/units.hpp"

#include <algorithm>
#include <cmath>
#include <cctype>

namespace coremodal {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Upper bounds that catch unit slips (a plain 76 is 76 m, not 76 mm) rather
// than physics: no core or rest roll comes near them.
constexpr double kMaxDiameter = 5.0;  // m
constexpr double kMaxLength = 50.0;   // m
constexpr double kMaxModulus = 1e13;  // Pa, above diamond
constexpr double kMaxDensity = 1e5;   // kg/m^3, above osmium
constexpr int kMaxModes = 10000;
constexpr int kMaxElementsThrough = 100;
constexpr int kMaxElementsAround = 4096;
constexpr double kMaxWebSpeed = 100.0;  // m/s; presses run up to ~20 m/s
constexpr int kMaxSweepSteps = 10000;
// 1000 Hz = 60 000 rpm: ten times a rotation tester's 4000 rpm and far above
// any press roll (a 76 mm core at 30 m/s turns at 7500 rpm); a larger value
// is a unit slip (a plain number is in Hz, not rpm).
constexpr double kMaxRotationHz = 1000.0;
constexpr int kMaxRotationPoints = 1000;
// [response]: a dense reduced solve per speed is cheap, but 10 000 points is
// already a 1 mm/s step over a press's whole range.
constexpr int kMaxResponsePoints = 10000;
// [limits]: each diameter is a forced response and a Campbell sweep; 200
// diameters is already a step of a millimetre over a whole unwind.
constexpr int kMaxLimitsPoints = 200;
// Relative damping of cores and rest rolls: 0.005-0.02 (Ilomäki,
// I-1...4); 1 is critical damping, above which nothing oscillates.
constexpr PlausibleRange kPlausibleDampingRatio{1e-3, 0.2, 0.01, "cores and rest rolls: 0.005-0.02 (Ilomäki I-1...I-4; docs/reference/references.md)"};
// A material's loss factor (loss tangent tan delta, effects/damping.hpp):
// no published range for cores is built in, the value is the user's; the
// band catches slips (2 for 2 %): metals ~1e-4-1e-3, paper and polymers of
// order 1e-2-1e-1 (Nashif, Jones & Henderson, Vibration Damping, 1985, ch. 2).
// Above 1 the loss modulus exceeds the storage modulus: no roll part.
constexpr PlausibleRange kPlausibleLossFactor{1e-4, 0.2, 0.03, "loss factors of solids: ~1e-4 (steel) to ~0.1 (paper, polymers); the value is the user's"};
// The same as a logarithmic decrement, delta = 2 pi zeta (I-1).
constexpr PlausibleRange kPlausibleLogDecrement{6e-3, 1.3, 0.06, "2 pi times 0.001-0.2 (cores and rest rolls: 0.03-0.13)"};
// Straightness deviations of cores (ISO 11093-5) are tenths of a millimetre
// per metre; a bowed rest roll a few millimetres. Roundness deviations alike.
// Zero is a perfect roll (the default), so the ranges start at 0: they catch
// the slip that matters, a plain 0.5 read as 0.5 m.
constexpr PlausibleRange kPlausibleBow{0.0, 20e-3, 0.5e-3, "core straightness deviations are ~0.1-5 mm (ISO 11093-5)"};
constexpr PlausibleRange kPlausibleOvality{0.0, 10e-3, 0.3e-3, "core roundness deviations are ~0.1-2 mm (ISO 11093-5)"};
constexpr PlausibleRange kPlausibleEccentricity{0.0, 20e-3, 0.5e-3, "an eccentric rest roll: ~0.1-5 mm"};
// Unbalance: balancing grades put a 100 kg roll at ~1e-3-1e-2 kg m.
constexpr PlausibleRange kPlausibleUnbalance{0.0, 1.0, 2e-3, "rolls and cores: ~0.1-100 g m (balancing grades, ISO 21940)"};
// [web] (docs/theory/web.md): running tensions of printing and converting webs are
// ~100-1000 N/m (Roisum, The Mechanics of Web Handling, TAPPI 1998), a guide
// roller sits tens of centimetres to a few metres from the roll, papers and
// boards are 30 um to ~1 mm thick, and paper's in-plane moduli are a few GPa
// (MD 2-10 GPa: Niskanen, Paper Physics, 2nd ed., ch. 5).
constexpr PlausibleRange kPlausibleWebTension{5.0, 20e3, 300.0, "running web tensions are ~100-1000 N/m (Roisum 1998)"};
constexpr PlausibleRange kPlausibleWebSpan{0.02, 20.0, 1.0, "roll surface to the first guide roller: ~0.1-5 m"};
constexpr PlausibleRange kPlausibleWebThickness{10e-6, 3e-3, 80e-6, "papers and boards are ~30 um to ~1 mm thick"};
constexpr PlausibleRange kPlausibleWebModulus{0.2e9, 30e9, 5e9, "paper's in-plane moduli are ~2-10 GPa (Niskanen, Paper Physics)"};
// [traction] (docs/how-to/traction.md): Rice & Gans' rollers are 50 mm in radius,
// their grooves 36-43 um deep and 254 um apart (3937 per metre), their
// asperity engagement heights 0.4-26 um, their friction 0.13-0.55 (Tables 1-3
// of "A simple model to predict web-to-roller traction"); idler rollers of
// presses are ~25-300 mm in radius. Air's viscosity is 1.7-2.0e-5 Pa s from
// 0 to 100 C (1.81e-5 at room temperature, their Table 3).
constexpr PlausibleRange kPlausibleRollerRadius{5e-3, 1.0, 0.05, "web-handling rollers are ~25-300 mm in radius"};
constexpr PlausibleRange kPlausibleGrooveSize{5e-6, 10e-3, 200e-6,
                                              "roller grooves are tens of um to a few mm (Rice & Gans: 36-254 um)"};
constexpr PlausibleRange kPlausibleRoughness{0.0, 200e-6, 5e-6,
                                             "asperity engagement heights are ~0.4-26 um (Rice & Gans, Tables 1-2)"};
constexpr PlausibleRange kPlausibleFriction{0.05, 1.5, 0.3, "web on roller: 0.13-0.55 (Rice & Gans, Table 3)"};
constexpr PlausibleRange kPlausibleViscosity{1e-5, 3e-5, 1.81e-5,
                                             "air: 1.7-2.0e-5 Pa*s from 0 to 100 C (Rice & Gans, Table 3: 1.81e-5)"};
constexpr PlausibleRange kPlausibleWebDensity{100.0, 3000.0, 1000.0,
                                              "papers ~500-1200 kg/m^3, PET films 1358 kg/m^3 (Rice & Gans, Table 1)"};
constexpr PlausibleRange kPlausibleLimit{0.1e-3, 0.1, 5e-3, "the field's limit is +-5 mm at mid-span (Ilomäki, with I-5; docs/reference/references.md)"};

// Plausible ranges: one row per kind of value, each with its reason. They
// catch unit slips, which are factors of 1e3 to 1e9, so they are wide.
//
// Moduli: the softest solid in a roll, wound paper across its layers, is of
// order 10 MPa (Jorkama & von Hertzen, Fig. 4) and loose layers a few times softer; the
// stiffest engineering solids (tungsten carbide, diamond) are near 1 TPa.
constexpr std::string_view kModulusWhy =
    "from a loosely wound paper layer (~1 MPa; wound paper ~10 MPa, Jorkama & von Hertzen) to diamond (~1.1 TPa)";
constexpr double kMinPlausibleModulus = 0.1e6, kMaxPlausibleModulus = 1.2e12;  // Pa
// Typical moduli, the aim of a suggestion: paperboard in its plane (E_theta,
// E_z, G_thetaz), across it (E_r; G_rtheta, G_rz), and isotropic E (steel and
// aluminium tubes, steel chucks): docs/reference/material-sources.md, the materials library.
constexpr double kTypicalInPlane = 5e9, kTypicalAcross = 30e6, kTypicalShearAcross = 100e6;
constexpr double kTypicalShearInPlane = 2e9, kTypicalIsotropic = 70e9;  // Pa
// Density: the lightest foams (~10 kg/m^3) to the densest metals (osmium 22 600).
constexpr PlausibleRange kPlausibleDensity{10.0, 25e3, 1000.0,
                                           "from foams (~10 kg/m^3) to the densest metals (osmium, 22 600 kg/m^3)"};
// Cores: 1 inch (25 mm) to 600 mm inside (ISO 11093 sizes; docs/reference/references.md),
// rolls up to ~4 m across; walls from under a millimetre; a test ring cut from
// a core is a few millimetres long, the widest machines ~10 m.
constexpr PlausibleRange kPlausibleDiameter{5e-3, 4.0, 0.1, "cores are 25-600 mm inside, rolls up to ~4 m across"};
constexpr PlausibleRange kPlausibleWall{0.3e-3, 1.0, 0.015, "core walls from under a millimetre (film cores) to ~100 mm"};
constexpr PlausibleRange kPlausibleCoreLength{1e-3, 20.0, 1.5,
                                              "from a test ring cut from a core (a few mm) to the widest machines (~10 m)"};
constexpr PlausibleRange kPlausibleRestPaper{50e-6, 2.0, 0.01, "from one sheet of paper (~0.1 mm) to a full roll (~1.5 m)"};

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

}  // namespace

const std::vector<KeySpec>& case_schema() {
    static const std::vector<KeySpec> schema = {
        plain_key("", "name", ValueKind::text),
        plain_key("", "description", ValueKind::text),
        plain_key("", "model", ValueKind::text),
        plain_key("", "core", ValueKind::table),
        plain_key("", "rest_paper", ValueKind::table),
        plain_key("", "supports", ValueKind::table),
        plain_key("", "analysis", ValueKind::table),
        plain_key("", "mesh", ValueKind::table),
        // Read by `coremodal study` and `coremodal calibrate` (scene/case_sweep.hpp,
        // docs/how-to/studies.md, docs/how-to/calibration.md); `coremodal run` ignores them.
        plain_key("", "study", ValueKind::table),
        plain_key("", "calibration", ValueKind::table),
        plain_key("", "rotation", ValueKind::table),
        plain_key("", "web", ValueKind::table),
        plain_key("", "damping", ValueKind::table),
        plain_key("", "excitation", ValueKind::table),
        plain_key("", "response", ValueKind::table),
        // Read by `coremodal traction` (docs/how-to/traction.md); other commands check it and ignore it.
        plain_key("", "traction", ValueKind::table),
        plain_key("", "limits", ValueKind::table),

        length_key("core", "inner_diameter", kMaxDiameter, kPlausibleDiameter),
        length_key("core", "outer_diameter", kMaxDiameter, kPlausibleDiameter),
        length_key("core", "wall", kMaxDiameter, kPlausibleWall),
        length_key("core", "length", kMaxLength, kPlausibleCoreLength),
        plain_key("core", "material", ValueKind::material),

        length_key("rest_paper", "thickness", kMaxDiameter, kPlausibleRestPaper),
        length_key("rest_paper", "outer_diameter", kMaxDiameter, kPlausibleDiameter),
        plain_key("rest_paper", "material", ValueKind::material),

        plain_key("material", "base", ValueKind::text),
        modulus_key("E", kTypicalIsotropic),
        poisson_key("nu"),
        modulus_key("E_r", kTypicalAcross),
        modulus_key("E_theta", kTypicalInPlane),
        modulus_key("E_z", kTypicalInPlane),
        modulus_key("G_rtheta", kTypicalShearAcross),
        modulus_key("G_rz", kTypicalShearAcross),
        modulus_key("G_thetaz", kTypicalShearInPlane),
        poisson_key("nu_rtheta"),
        poisson_key("nu_rz"),
        poisson_key("nu_thetaz"),
        {"material", "density", ValueKind::quantity, Dimension::density, 0.0, kMaxDensity, true, kPlausibleDensity},

        plain_key("supports", "type", ValueKind::text),
        plain_key("supports", "left", ValueKind::table),
        plain_key("supports", "right", ValueKind::table),

        length_key("clamp", "length", kMaxLength),
        {"clamp", "start", ValueKind::quantity, Dimension::length, 0.0, kMaxLength},
        {"clamp", "center", ValueKind::quantity, Dimension::length, 0.0, kMaxLength},

        // [supports.left] / [supports.right] of type = "chucks" (docs/theory/chucks.md).
        length_key("chuck", "inserted_length", kMaxLength),
        {"chuck", "clearance", ValueKind::quantity, Dimension::length, 0.0, kMaxDiameter},
        length_key("chuck", "body_diameter", kMaxDiameter),
        length_key("chuck", "shaft_diameter", kMaxDiameter),
        length_key("chuck", "shaft_length", kMaxLength),
        plain_key("chuck", "material", ValueKind::material),
        plain_key("chuck", "interface", ValueKind::text),
        plain_key("chuck", "expanded", ValueKind::boolean),
        plain_key("chuck", "contact", ValueKind::text),
        {"chuck", "normal_stiffness", ValueKind::quantity, Dimension::stiffness_per_area, 0.0, kInf, true},
        {"chuck", "tangential_stiffness", ValueKind::quantity, Dimension::stiffness_per_area, 0.0, kInf, true},
        {"chuck", "expansion_pressure", ValueKind::quantity, Dimension::pressure, 0.0, 1e9},
        plain_key("chuck", "expanding", ValueKind::tables),
        plain_key("chuck", "bearing", ValueKind::table),

        {"expanding", "center", ValueKind::quantity, Dimension::length, 0.0, kMaxLength},
        length_key("expanding", "width", kMaxLength),
        integer_key("expanding", "segments", 1, 64),
        {"expanding", "segment_angle", ValueKind::quantity, Dimension::angle, 0.0, 6.2832, true},

        plain_key("bearing", "type", ValueKind::text),
        {"bearing", "radial_stiffness", ValueKind::quantity, Dimension::stiffness, 0.0, kInf, true},
        {"bearing", "tilting_stiffness", ValueKind::quantity, Dimension::rotational_stiffness, 0.0, kInf, true},
        {"bearing", "frame_mass", ValueKind::quantity, Dimension::mass, 0.0, 1e6, true},
        {"bearing", "frame_stiffness", ValueKind::quantity, Dimension::stiffness, 0.0, kInf, true},

        integer_key("analysis", "modes", 1, kMaxModes),
        plain_key("analysis", "band", ValueKind::band),
        {"analysis", "tolerance", ValueKind::quantity, Dimension::dimensionless, 0.0, 0.1, true},
        integer_key("analysis", "max_iterations", 1, 1e7),

        plain_key("mesh", "level", ValueKind::text),
        integer_key("mesh", "through_wall", 1, kMaxElementsThrough),
        integer_key("mesh", "through_rest_paper", 1, kMaxElementsThrough),
        integer_key("mesh", "around", 8, kMaxElementsAround),
        integer_key("mesh", "along", 2, 100000),
        plain_key("mesh", "element", ValueKind::text),
        plain_key("mesh", "file", ValueKind::text),

        // [rotation]: the roll spins (docs/how-to/campbell.md).
        {"rotation", "speed", ValueKind::quantity, Dimension::frequency, 0.0, kMaxRotationHz},
        plain_key("rotation", "speeds", ValueKind::list),
        integer_key("rotation", "points", 2, kMaxRotationPoints),
        {"rotation", "web_speed", ValueKind::quantity, Dimension::speed, 0.0, kMaxWebSpeed},
        plain_key("rotation", "web_speeds", ValueKind::list),
        plain_key("rotation", "excitation_orders", ValueKind::list),
        plain_key("rotation", "operating_speeds", ValueKind::list),
        plain_key("rotation", "centrifugal_stiffening", ValueKind::boolean),

        // [web]: the paper web pulls on the roll along a line (docs/theory/web.md).
        {"web", "tension", ValueKind::quantity, Dimension::line_force, 0.0, 1e6, true, kPlausibleWebTension},
        {"web", "span", ValueKind::quantity, Dimension::length, 0.0, kMaxLength, true, kPlausibleWebSpan},
        {"web", "angle", ValueKind::quantity, Dimension::angle, -2 * M_PI, 2 * M_PI},
        {"web", "thickness", ValueKind::quantity, Dimension::length, 0.0, 0.1, true, kPlausibleWebThickness},
        {"web", "modulus", ValueKind::quantity, Dimension::pressure, 0.0, kMaxModulus, true, kPlausibleWebModulus},
        {"web", "shear_modulus", ValueKind::quantity, Dimension::pressure, 0.0, kMaxModulus, true, kPlausibleWebModulus},

        // [traction]: web-to-roller traction on one roller (Rice & Gans; docs/how-to/traction.md).
        length_key("traction", "roller_radius", kMaxDiameter, kPlausibleRollerRadius),
        {"traction", "wrap", ValueKind::quantity, Dimension::angle, 0.0, 2 * M_PI, true},
        {"traction", "tension", ValueKind::quantity, Dimension::line_force, 0.0, 1e6, true, kPlausibleWebTension},
        {"traction", "friction", ValueKind::quantity, Dimension::dimensionless, 0.0, 10.0, true, kPlausibleFriction},
        {"traction", "roller_roughness", ValueKind::quantity, Dimension::length, 0.0, 0.01, false, kPlausibleRoughness},
        {"traction", "web_roughness", ValueKind::quantity, Dimension::length, 0.0, 0.01, false, kPlausibleRoughness},
        plain_key("traction", "grooves", ValueKind::text),
        length_key("traction", "groove_depth", 0.1, kPlausibleGrooveSize),
        length_key("traction", "groove_width", 0.1, kPlausibleGrooveSize),
        length_key("traction", "groove_pitch", 0.1, kPlausibleGrooveSize),
        length_key("traction", "tool_radius", 0.1, kPlausibleGrooveSize),
        {"traction", "air_viscosity", ValueKind::quantity, Dimension::viscosity, 0.0, 1.0, true, kPlausibleViscosity},
        {"traction", "web_thickness", ValueKind::quantity, Dimension::length, 0.0, 0.1, true, kPlausibleWebThickness},
        {"traction", "web_density", ValueKind::quantity, Dimension::density, 0.0, kMaxDensity, true,
         kPlausibleWebDensity},
        {"traction", "web_modulus", ValueKind::quantity, Dimension::pressure, 0.0, kMaxModulus, true,
         kPlausibleWebModulus},
        {"traction", "web_poisson", ValueKind::quantity, Dimension::dimensionless, 0.0, 0.5, false},
        {"traction", "tension_difference", ValueKind::quantity, Dimension::line_force, 0.0, 1e6, false},
        {"traction", "web_speed", ValueKind::quantity, Dimension::speed, 0.0, kMaxWebSpeed},
        plain_key("traction", "web_speeds", ValueKind::list),
        integer_key("traction", "points", 2, kMaxResponsePoints),

        // [damping], [excitation], [response]: the forced response (docs/how-to/response.md).
        {"damping", "ratio", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
        {"damping", "log_decrement", ValueKind::quantity, Dimension::dimensionless, 0.0, 2 * M_PI, true,
         kPlausibleLogDecrement},
        plain_key("damping", "decay", ValueKind::table),
        {"decay", "amplitude_ratio", ValueKind::quantity, Dimension::dimensionless, 1.0, 1e6, true},
        {"decay", "cycles", ValueKind::quantity, Dimension::dimensionless, 0.0, 1e4, true},
        // Rayleigh's alpha (1/s) and beta (s) as plain SI numbers: no unit
        // names a rate apart from a frequency ("1/s" is 1 Hz here, a cycle
        // per second, which alpha is not).
        plain_key("damping", "rayleigh", ValueKind::table),
        {"rayleigh", "alpha", ValueKind::quantity, Dimension::dimensionless, 0.0, kInf},
        {"rayleigh", "beta", ValueKind::quantity, Dimension::dimensionless, 0.0, kInf},
        {"rayleigh", "zeta", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
        plain_key("rayleigh", "frequencies", ValueKind::list),
        {"damping", "bending", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
        {"damping", "torsion", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
        {"damping", "axial", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
        {"damping", "breathing", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
        {"damping", "ovalling", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
        plain_key("damping", "modes", ValueKind::tables),
        integer_key("modes", "mode", 1, kMaxModes),
        {"modes", "ratio", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleDampingRatio},
        // Structural damping: 0 < eta <= 1 for every part, 0 <= eta <= 1 per part (0: a lossless part).
        {"damping", "loss_factor", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true, kPlausibleLossFactor},
        plain_key("damping", "loss_factors", ValueKind::table),
        {"loss_factors", "core", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, false, kPlausibleLossFactor},
        {"loss_factors", "rest_paper", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, false, kPlausibleLossFactor},
        {"loss_factors", "chucks", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, false, kPlausibleLossFactor},
        {"excitation", "bow", ValueKind::quantity, Dimension::length, 0.0, 0.1, false, kPlausibleBow},
        plain_key("excitation", "bow_shape", ValueKind::text),
        {"excitation", "unbalance", ValueKind::quantity, Dimension::unbalance, 0.0, 100.0, false, kPlausibleUnbalance},
        {"excitation", "eccentricity", ValueKind::quantity, Dimension::length, 0.0, 0.1, false, kPlausibleEccentricity},
        {"excitation", "ovality", ValueKind::quantity, Dimension::length, 0.0, 0.1, false, kPlausibleOvality},
        plain_key("excitation", "gravity", ValueKind::boolean),
        plain_key("response", "speeds", ValueKind::list),
        plain_key("response", "web_speeds", ValueKind::list),
        integer_key("response", "points", 2, kMaxResponsePoints),
        length_key("response", "limit", 1.0, kPlausibleLimit),
        plain_key("response", "probes", ValueKind::list),

        // [limits]: one verdict over the rest-roll diameters (docs/how-to/limits.md).
        plain_key("limits", "diameters", ValueKind::list),
        integer_key("limits", "points", 2, kMaxLimitsPoints),
        {"limits", "web_speed", ValueKind::quantity, Dimension::speed, 0.0, kMaxWebSpeed, true},
        length_key("limits", "limit", 1.0, kPlausibleLimit),
        plain_key("limits", "band", ValueKind::boolean),

        // [study]: a sweep over case-file keys, with the modes tracked by MAC.
        plain_key("study", "parameters", ValueKind::tables),
        plain_key("study", "mesh", ValueKind::text),
        integer_key("study", "modes", 1, kMaxModes),
        {"study", "safe_factor", ValueKind::quantity, Dimension::dimensionless, 0.0, 1.0, true},
        {"study", "web_speed", ValueKind::quantity, Dimension::speed, 0.0, kMaxWebSpeed, true},

        // [calibration]: a sweep whose chuck factors are fitted (docs/how-to/calibration.md).
        plain_key("calibration", "parameters", ValueKind::tables),
        plain_key("calibration", "mesh", ValueKind::text),
        integer_key("calibration", "modes", 1, kMaxModes),
        integer_key("calibration", "holdout_every", 2, 1000),
        {"calibration", "max_error", ValueKind::quantity, Dimension::dimensionless, 0.0, 0.5, true},

        // One item of parameters = [...]: key (a dotted path, or a list of
        // paths set together) and either values or a range from/to/steps.
        plain_key("parameter", "key", ValueKind::text),
        plain_key("parameter", "values", ValueKind::list),
        plain_key("parameter", "from", ValueKind::quantity),
        plain_key("parameter", "to", ValueKind::quantity),
        integer_key("parameter", "steps", 2, kMaxSweepSteps),
        plain_key("parameter", "spacing", ValueKind::text),
    };
    return schema;
}

std::string_view default_material(std::string_view owner) {
    if (owner == "core") return kDefaultCoreMaterial;
    if (owner == "rest_paper") return kDefaultRestPaperMaterial;
    if (owner == "chuck") return kDefaultChuckMaterial;
    return "";
}

std::string child_table(std::string_view parent, std::string_view key, std::string_view support_type) {
    if (key == "material") return "material";
    if (parent == "supports" && (key == "left" || key == "right")) return support_type == "chucks" ? "chuck" : "clamp";
    return std::string(key);
}

const KeySpec* find_key(std::string_view table, std::string_view key) {
    for (const KeySpec& spec : case_schema())
        if (spec.table == table && spec.key == key) return &spec;
    return nullptr;
}

std::vector<std::string_view> keys_of(std::string_view table) {
    std::vector<std::string_view> out;
    for (const KeySpec& spec : case_schema())
        if (spec.table == table) out.push_back(spec.key);
    return out;
}

std::size_t edit_distance(std::string_view a, std::string_view b) {
    const auto low = [](char c) {
        return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    };
    // Optimal string alignment distance on three rolling rows.
    std::vector<std::size_t> before(b.size() + 1), previous(b.size() + 1), current(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t cost = low(a[i - 1]) == low(b[j - 1]) ? 0 : 1;
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, previous[j - 1] + cost});
            if (i > 1 && j > 1 && low(a[i - 1]) == low(b[j - 2]) && low(a[i - 2]) == low(b[j - 1]))
                current[j] = std::min(current[j], before[j - 2] + 1);
        }
        before.swap(previous);
        previous.swap(current);
    }
    return previous[b.size()];
}

std::string_view nearest(std::string_view word, const std::vector<std::string_view>& candidates) {
    // A typo changes a few characters; more than a third of the word is a
    // different word, and suggesting it would mislead.
    constexpr std::size_t kShortWord = 3;  // "nu", "E": one slip at most
    const std::size_t allowed =
        word.size() <= kShortWord ? 1 : std::max<std::size_t>(2, word.size() / 3);
    std::string_view best;
    std::size_t best_distance = allowed + 1;
    for (std::string_view c : candidates) {
        const std::size_t d = edit_distance(word, c);
        if (d < best_distance) {
            best = c;
            best_distance = d;
        }
    }
    return best;
}

std::string did_you_mean(std::string_view word, const std::vector<std::string_view>& candidates, char quote) {
    const std::string_view near = nearest(word, candidates);
    return near.empty() ? "" : "; did you mean " + (quote + std::string(near) + quote) + "?";
}

std::string did_you_mean_or_choices(std::string_view word, const std::vector<std::string_view>& candidates) {
    const std::string typo = did_you_mean(word, candidates);
    return typo.empty() ? "; expected one of " + join(candidates) : typo;
}

std::optional<std::string> out_of_range(const KeySpec& spec, double v, std::string_view plain_number) {
    if (spec.min_exclusive && !(v > spec.min))
        return "must be " + (spec.min == 0 ? std::string("positive")
                                           : "larger than " + format_quantity(spec.min, spec.dimension));
    if (!spec.min_exclusive && v < spec.min)
        return "must be " + (spec.min == 0 ? std::string("zero or positive")
                                           : "at least " + format_quantity(spec.min, spec.dimension));
    if (!(v > spec.max)) return std::nullopt;
    std::string why = "is too large: expected at most " + format_quantity(spec.max, spec.dimension);
    if (!plain_number.empty() && spec.dimension != Dimension::dimensionless)
        why += std::string("; plain numbers are in ") + si_unit(spec.dimension) +
               (spec.dimension == Dimension::length
                    ? ", for millimetres write \"" + std::string(plain_number) + " mm\""
                    : "");
    return why;
}

std::optional<std::string> integer_out_of_range(const KeySpec& spec, std::int64_t v) {
    // Compared as doubles: the bounds are far inside both ranges.
    if (static_cast<double>(v) >= spec.min && static_cast<double>(v) <= spec.max) return std::nullopt;
    return "is out of range; expected " + std::to_string(static_cast<long long>(spec.min)) + " to " +
           std::to_string(static_cast<long long>(spec.max));
}

}  // namespace coremodal
