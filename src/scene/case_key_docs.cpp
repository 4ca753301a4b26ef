// One row per key of the key table (scene/case_schema.cpp), in its order.
// Defaults are those of the reader (scene/case_file.cpp, scene/case_sweep.cpp,
// scene/chuck_contact.hpp, scene/scene.hpp) and of docs/case-files.md.
#include "scene/case_key_docs.hpp"

namespace coremodal {

const std::vector<KeyDoc>& case_key_docs() {
    static const std::vector<KeyDoc> docs = {
        {"", "name", "the file name without .toml", "case name, used in output file names and summaries; a name, not a path (no '/', not \"\", \".\" or \"..\")"},
        {"", "description", "\"\"", "free text, echoed in the summary"},
        {"", "model", "\"solid\"", "model level: 3D solid, axisymmetric-harmonic section, coupled harmonics (segmented chucks), auto, or Timoshenko beam network (run --model overrides it)", "solid harmonic coupled auto beam"},
        {"", "core", kRequired, "the paperboard core"},
        {"", "rest_paper", "none: a bare core", "paper still wound on the core, over its full length"},
        {"", "supports", "none: free-free", "how the core is held: free, rigid clamps or elastic chucks"},
        {"", "analysis", "the 20 lowest modes", "what to compute: the lowest modes or all modes in a band"},
        {"", "mesh", "level \"default\"", "mesh refinement, or a gmsh mesh file"},
        {"", "study", "none", "a sweep over this file's keys, for `coremodal study` (`run` ignores it)"},
        {"", "calibration", "none", "a sweep whose chuck factors are fitted, for `coremodal calibrate` (`run` ignores it)"},
        {"", "web", "none: no web", "the paper web pulls on the roll along one line of its surface (docs/web.md)"},
        {"", "rotation", "none: the roll stands still", "the roll, chucks and shafts spin: modes at a speed, or a Campbell sweep (`coremodal campbell`)"},
        {"", "damping", "none (needed by [response])", "relative damping of the modes, for the forced response (docs/response.md)"},
        {"", "excitation", "none (needed by [response])", "what excites the spinning roll: bow, unbalance, eccentricity, ovality with gravity"},
        {"", "response", "none: no forced response", "mid-span vibration against web speed and the safe speed from the amplitude limit (`coremodal response`)"},

        {"core", "inner_diameter", kRequired, "inner diameter Di of the core, smaller than the outer diameter"},
        {"core", "outer_diameter", "none: give outer_diameter or wall", "outer diameter Do; give exactly one of outer_diameter and wall"},
        {"core", "wall", "none: give wall or outer_diameter", "wall thickness; Do = Di + 2 wall"},
        {"core", "length", kRequired, "full core length Lc"},
        {"core", "material", "\"paperboard_core\"", "core material: a library name or an inline table (noted as an assumption when left out)"},

        {"rest_paper", "thickness", "none: give thickness or outer_diameter", "radial thickness of the paper; Dp = Do + 2 thickness"},
        {"rest_paper", "outer_diameter", "none: give outer_diameter or thickness", "outer diameter Dp of the paper, larger than the core's"},
        {"rest_paper", "material", "\"rest_paper\"", "paper cylinder material: a library name or an inline table"},

        {"material", "base", "none: every value given", "library material to start from; the other keys replace its values"},
        {"material", "E", "from base", "isotropic Young's modulus (G = E / (2 (1 + nu)))"},
        {"material", "nu", "from base", "isotropic Poisson ratio"},
        {"material", "E_r", "from base", "radial Young's modulus"},
        {"material", "E_theta", "from base", "circumferential Young's modulus"},
        {"material", "E_z", "from base", "axial Young's modulus"},
        {"material", "G_rtheta", "from base", "shear modulus in the r-theta plane"},
        {"material", "G_rz", "from base", "shear modulus in the r-z plane"},
        {"material", "G_thetaz", "from base", "shear modulus in the theta-z plane"},
        {"material", "nu_rtheta", "from base", "Poisson ratio nu_rtheta = -eps_theta/eps_r under sigma_r; compliance must stay positive definite"},
        {"material", "nu_rz", "from base", "Poisson ratio nu_rz = -eps_z/eps_r under sigma_r; compliance must stay positive definite"},
        {"material", "nu_thetaz", "from base", "Poisson ratio nu_thetaz = -eps_z/eps_theta under sigma_theta; compliance must stay positive definite"},
        {"material", "density", "from base", "mass density"},

        {"supports", "type", "\"free\"", "free-free (6 rigid-body modes), rigid clamps on the inner surface, or elastic chucks in a stand", "free clamped chucks"},
        {"supports", "left", "none: required when clamped or chucks", "clamp zone (type = \"clamped\") or chuck (type = \"chucks\") at the left end, z = 0"},
        {"supports", "right", "the mirror of left", "clamp zone or chuck at the right end, z = Lc"},

        {"clamp", "length", kRequired, "clamped length of the core's inner surface"},
        {"clamp", "start", "0", "distance from the core end to the zone's end-side edge"},
        {"clamp", "center", "none: give start or center", "distance from the core end to the zone centre; instead of start"},

        {"chuck", "inserted_length", kRequired, "chuck body length inside the core, at most half the core"},
        {"chuck", "clearance", "\"0.5 mm\"", "radial clearance: body diameter = bore - 2 clearance"},
        {"chuck", "body_diameter", "from clearance", "chuck body diameter, instead of clearance; smaller than the bore"},
        {"chuck", "shaft_diameter", "the body diameter", "shaft diameter from the core end to the bearing, at most the body diameter"},
        {"chuck", "shaft_length", "\"150 mm\"", "shaft length from the core end to the bearing"},
        {"chuck", "material", "\"steel\"", "chuck body and shaft material: a library name or an inline table"},
        {"chuck", "interface", "\"spring\"", "spring layer over the expanding elements, or shared displacements", "spring bonded"},
        {"chuck", "expanded", "true", "false: the chuck was not expanded (the bore rests on the body under gravity)"},
        {"chuck", "contact", "\"one-sided\" when not expanded, else \"uniform\"", "one-sided: compression-only contact across the clearance, closed where the roll's weight closes it (3D solid level); uniform: the spring layer all around", "uniform one-sided"},
        {"chuck", "normal_stiffness", "from the expansion pressure", "normal stiffness of the spring layer, instead of expansion_pressure"},
        {"chuck", "tangential_stiffness", "from the expansion pressure", "tangential stiffness of the spring layer, with normal_stiffness"},
        {"chuck", "expansion_pressure", "\"6 bar\"", "expansion pressure of the elements; gives the spring layer's stiffness (docs/chucks.md)"},
        {"chuck", "expanding", kRequired, "the expanding elements, [[supports.<end>.expanding]], at least one"},
        {"chuck", "bearing", "none: a rigid bearing", "the bearing at the shaft's end"},

        {"expanding", "center", kRequired, "axial centre of the element from the core end"},
        {"expanding", "width", kRequired, "axial width of the element"},
        {"expanding", "segments", "none: a full band", "N segments centred at 0, 360/N, ... degrees instead of a band; needs segment_angle"},
        {"expanding", "segment_angle", "none: required with segments", "angle each segment spans; segments x segment_angle <= 360 deg"},

        {"bearing", "type", "\"rigid\" (\"elastic\" when radial_stiffness is given)", "rigid or elastic bearing", "rigid elastic"},
        {"bearing", "radial_stiffness", "none: required when elastic", "radial stiffness of an elastic bearing"},
        {"bearing", "tilting_stiffness", "none: required when elastic", "tilting stiffness of an elastic bearing"},
        {"bearing", "frame_mass", "none: no frame", "mass of the stand's frame behind the bearing; needs frame_stiffness"},
        {"bearing", "frame_stiffness", "none: required with frame_mass", "stiffness of the frame to the ground"},

        {"analysis", "modes", "20", "the lowest modes wanted; rigid-body modes count; not with band"},
        {"analysis", "band", "none: the lowest modes", "all modes in [low, high], e.g. [\"0 Hz\", \"500 Hz\"]; instead of modes"},
        {"analysis", "tolerance", "1e-10", "eigensolver relative residual tolerance"},
        {"analysis", "max_iterations", "500", "eigensolver iteration limit"},

        {"mesh", "level", "\"default\"", "named refinement (docs/case-files.md, [mesh])", "coarse default fine very_fine"},
        {"mesh", "through_wall", "from the level", "elements through the core wall; overrides the level's"},
        {"mesh", "through_rest_paper", "from the level", "elements through the rest paper; overrides the level's"},
        {"mesh", "around", "from the level", "elements around the circumference, a multiple of 4; overrides the level's"},
        {"mesh", "along", "from the level", "elements along the core; overrides the level's"},
        {"mesh", "element", "\"hex20\"", "quadratic serendipity (hex20) or Lagrange (hex27) hexahedra", "hex20 hex27"},
        {"mesh", "file", "none: a generated mesh", "a gmsh .msh file of your own, relative to the case file's folder; excludes the other mesh keys except element"},

        {"web", "tension", "required", "the web's tension per unit width, e.g. \"300 N/m\""},
        {"web", "span", "required", "free span from the roll's surface to the first guide roller"},
        {"web", "angle", "required", "direction the web leaves the roll in, about the roll's axis (0 = +x, 90 deg = +y)"},
        {"web", "thickness", "required", "the web's thickness"},
        {"web", "modulus", "required", "the web's in-plane modulus along its length (MD)"},
        {"web", "shear_modulus", "0.387 sqrt(E_MD E_CD) with E_CD = E_MD / 2: 0.274 x modulus (Baum et al. 1981)", "the web's in-plane shear modulus"},
        {"rotation", "speed", "none: give one of speed, speeds, web_speed, web_speeds", "one rotation speed, e.g. \"1200 rpm\" (a plain number is in Hz)"},
        {"rotation", "speeds", "none: give one of speed, speeds, web_speed, web_speeds", "rotation speeds: a list, or [first, last] with points"},
        {"rotation", "points", "none: speeds is a list", "number of equally spaced speeds from the first to the last of speeds (or web_speeds)"},
        {"rotation", "web_speed", "none: give one of speed, speeds, web_speed, web_speeds", "one web speed v; f_rot = v / (pi Dp), Dp the roll's outer diameter"},
        {"rotation", "web_speeds", "none: give one of speed, speeds, web_speed, web_speeds", "web speeds: a list, or [first, last] with points; each f_rot = v / (pi Dp)"},
        {"rotation", "excitation_orders", "[1, 2]", "orders k of the excitation lines f = k f_rot (1: unbalance, 2: ovality, sag)"},
        {"rotation", "centrifugal_stiffening", "true", "the centrifugal prestress as geometric stiffness, where the level has a term for it (not at the beam level)"},

        {"damping", "ratio", "none: give one of ratio, log_decrement, decay, rayleigh", "relative damping zeta of every elastic mode not named by a family key or modes (cores and rest rolls 0.005-0.02)"},
        {"damping", "log_decrement", "none: give one of ratio, log_decrement, decay, rayleigh", "logarithmic decrement delta = ln(X0/X1) of a measured decay; zeta = delta / (2 pi) (I-1)"},
        {"damping", "decay", "none: give one of ratio, log_decrement, decay, rayleigh", "a measured decay { amplitude_ratio = X0/XN, cycles = N }; zeta = ln(X0/XN) / (2 pi N) (I-1)"},
        {"damping", "rayleigh", "none: give one of ratio, log_decrement, decay, rayleigh", "Rayleigh damping D = alpha M + beta K: { alpha = 0.5, beta = 1e-5 } (1/s, s) or { zeta = 0.01, frequencies = [\"20 Hz\", \"200 Hz\"] }; mode j gets alpha/(2 w_j) + beta w_j/2"},
        {"damping", "bending", "the base (ratio, ..., rayleigh)", "relative damping of every bending mode (mode label bending)"},
        {"damping", "torsion", "the base (ratio, ..., rayleigh)", "relative damping of every torsion mode (none in the lateral response: beam level, or n = 1 at the harmonic level)"},
        {"damping", "axial", "the base (ratio, ..., rayleigh)", "relative damping of every axial mode (none in the lateral response: beam level, or n = 1 at the harmonic level)"},
        {"damping", "breathing", "the base (ratio, ..., rayleigh)", "relative damping of every breathing mode (solid and harmonic levels)"},
        {"damping", "ovalling", "the base (ratio, ..., rayleigh)", "relative damping of every ovalling mode (solid and harmonic levels)"},
        {"damping", "modes", "none", "ratios of single modes: [{ mode = 1, ratio = 0.02 }], mode numbers as in modes.csv of the scene at rest; a degenerate pair shares one ratio"},
        {"rayleigh", "alpha", "0", "alpha of D = alpha M + beta K, in 1/s (a plain number)"},
        {"rayleigh", "beta", "0", "beta of D = alpha M + beta K, in s (a plain number)"},
        {"rayleigh", "zeta", "none: give alpha and beta, or zeta with frequencies", "the relative damping at both frequencies"},
        {"rayleigh", "frequencies", "none: give alpha and beta, or zeta with frequencies", "two frequencies at which the damping ratio is zeta, e.g. [\"20 Hz\", \"200 Hz\"]"},
        {"modes", "mode", kRequired, "the mode's number among the modes at rest (modes.csv), from 1"},
        {"modes", "ratio", kRequired, "its relative damping zeta (0 to 1)"},
        {"decay", "amplitude_ratio", kRequired, "X0/XN: the first amplitude over the amplitude N cycles later, larger than 1"},
        {"decay", "cycles", kRequired, "N: the cycles between the two amplitudes"},
        {"excitation", "bow", "0: straight", "straightness deviation of the core at mid-core (ISO 11093-5); the bow turns with the roll (order 1)"},
        {"excitation", "bow_shape", "\"half_sine\"", "shape of the bow along the core: a half sine over the core length, or the first bending mode at rest", "half_sine first_mode"},
        {"excitation", "unbalance", "0", "a point unbalance at mid-core (kg*m, e.g. \"2 kg*mm\"): force U Omega^2 turning with the roll (order 1)"},
        {"excitation", "eccentricity", "0", "the rest paper's mass centre off the axis, uniform along the roll (needs [rest_paper]): order 1"},
        {"excitation", "ovality", "0", "roundness deviation of the core, D_max - D_min; with gravity an order-2 load (2 x per revolution)"},
        {"excitation", "gravity", "true", "gravity acts vertically: the static sag, and with ovality the order-2 load"},
        {"response", "speeds", "none: give speeds or web_speeds", "rotation speeds: a list, or [first, last] with points (above 0)"},
        {"response", "web_speeds", "none: give speeds or web_speeds", "web speeds: a list, or [first, last] with points; each f_rot = v / (pi Dp)"},
        {"response", "points", "none: the speeds are a list", "number of equally spaced speeds from the first to the last"},
        {"response", "limit", "\"5 mm\"", "the amplitude limit at the first probe (semi-major axis of the orbit): the safe speed is where it is first reached"},
        {"response", "probes", "[\"mid-span\"]", "where the amplitude is reported: \"mid-span\" (the core's middle) or positions from the core's left end"},

        {"study", "parameters", kRequired, "what to vary, one table per parameter; several make a grid (first slowest)"},
        {"study", "mesh", "the case's [mesh], else \"coarse\"", "mesh level of every point", "coarse default fine very_fine"},
        {"study", "modes", "the case's [analysis] modes, else 12", "modes of every point"},
        {"study", "safe_factor", "0.7", "I-5 safe-speed factor"},
        {"study", "web_speed", "none", "the web speed line of Koenig's chart"},

        {"calibration", "parameters", kRequired, "what to vary, one table per parameter; several make a grid (first slowest)"},
        {"calibration", "mesh", "the case's [mesh], else \"coarse\"", "mesh level of every point", "coarse default fine very_fine"},
        {"calibration", "modes", "the case's [analysis] modes, else 6", "modes of every point"},
        {"calibration", "holdout_every", "4", "every Nth usable point is held out of the fit"},
        {"calibration", "max_error", "0.05", "stated error of I-7 with the fitted k"},

        {"parameter", "key", kRequired, "dotted key path into this file, e.g. \"core.length\", or a list of paths set together"},
        {"parameter", "values", "none: give values or from/to/steps", "the values, written as the key takes them (\"10 mm\", 6.5e9, \"steel\", true)"},
        {"parameter", "from", "none: give values or from/to/steps", "first value of a range, written as the key takes it"},
        {"parameter", "to", "none: give values or from/to/steps", "last value of a range (included)"},
        {"parameter", "steps", "none: give values or from/to/steps", "number of values in the range"},
        {"parameter", "spacing", "\"linear\"", "spacing of the range's values", "linear log"},
    };
    return docs;
}

const KeyDoc* find_key_doc(std::string_view table, std::string_view key) {
    for (const KeyDoc& doc : case_key_docs())
        if (doc.table == table && doc.key == key) return &doc;
    return nullptr;
}

}  // namespace coremodal
