// A scene: what the user asked to simulate, resolved to SI units.
// Produced by parse_case_file (scene/case_file.hpp); read by every later stage.
#pragma once

#include "material/material.hpp"
#include "scene/model_choice.hpp"

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace coremodal {

struct CoreSpec {
    double inner_diameter = 0;  // m
    double outer_diameter = 0;  // m
    double length = 0;          // m
    OrthotropicMaterial material;
};

struct RestPaperSpec {
    double outer_diameter = 0;  // m (thickness given in the file is resolved to this)
    OrthotropicMaterial material;
};

// A rigid clamp on the core's inner surface over [z_start, z_end], measured
// in metres from the left core end (z = 0). All DOFs of the nodes of the core
// inner surface in that range are eliminated.
struct ClampSpec {
    std::string name;  // "left" or "right"
    double z_start = 0, z_end = 0;
};

// One expanding element of a chuck: a full circumferential band, or
// `segments` equal pads each spanning `segment_angle`, spaced evenly around
// (the first centred at theta = 0, the +x axis).
struct ExpandingElement {
    double center = 0;  // m, from this chuck's core end, towards the core middle
    double width = 0;   // m, along the axis
    int segments = 0;   // 0 = full band
    double segment_angle = 0;  // rad, span of one segment (segments > 0)
};

// How the core is held over the expanding elements (Ilomäki I-6,
// docs/theory/chucks.md): bonded = shared displacements; spring = a distributed
// spring layer with normal and tangential stiffness per unit area.
enum class InterfaceKind { bonded, spring };

// How the spring layer touches the bore: uniform = all around the expanding
// elements, in tension and compression alike (an expanded chuck); one_sided =
// a not-expanded chuck: the bore rests on the chuck body across the radial
// clearance under gravity, contact in compression only, closed over the arc
// the static solve finds (docs/theory/chucks.md, "A chuck that was not expanded").
enum class ContactKind { uniform, one_sided };

struct ChuckInterface {
    InterfaceKind kind = InterfaceKind::spring;
    bool expanded = true;               // false: the chuck was not expanded (soft contact)
    ContactKind contact = ContactKind::uniform;  // one_sided by default when not expanded
    double normal_stiffness = 0;        // Pa/m (pressure per unit relative displacement; one_sided: at zero pressure)
    double tangential_stiffness = 0;    // Pa/m
    std::optional<double> expansion_pressure;  // Pa, when the stiffnesses were derived from it
};

// The stand's bearing at the shaft end. Rigid: the shaft end face is held
// (all displacements zero). Elastic: springs to the frame (or the ground).
struct BearingSpec {
    bool rigid = true;
    double radial_stiffness = 0;   // N/m
    double tilting_stiffness = 0;  // N m/rad
    std::optional<double> frame_mass;       // kg, a lumped frame mass behind the bearing
    std::optional<double> frame_stiffness;  // N/m, frame to ground (needed with a frame mass)
};

// An elastic chuck at one core end: a solid steel body inside the core, a
// shaft outside it to the bearing, and expanding elements on the body.
// Axial positions are measured from this chuck's own core end, inwards.
struct ChuckSpec {
    std::string name;              // "left" or "right"
    double inserted_length = 0;    // m, body length inside the core
    double body_diameter = 0;      // m, = core inner diameter - 2 x radial clearance
    double shaft_diameter = 0;     // m
    double shaft_length = 0;       // m, core end to the bearing
    OrthotropicMaterial material;  // steel unless given
    std::vector<ExpandingElement> expanding;
    ChuckInterface interface;
    BearingSpec bearing;

    // Li: core end to the middle of the furthest expanding element (Ilomäki).
    // Where the chuck acts along the core: effects/chuck_placement.hpp.
    double li() const;
};

// [web]: the paper web leaving the roll along one line of its outer surface
// towards the first guide roller (effects/web.hpp, docs/theory/web.md).
struct WebSpec {
    double tension = 0;        // N/m, per unit width
    double span = 0;           // m, roll surface to the guide roller
    double angle = 0;          // rad, the direction the web leaves in (0 = +x, about +z)
    double thickness = 0;      // m
    double modulus = 0;        // Pa, in-plane modulus along the web (MD)
    double shear_modulus = 0;  // Pa, in-plane shear modulus
    std::string shear_source;  // where shear_modulus comes from: "[web] shear_modulus" or the default's rule
};

enum class SupportKind { free, clamped, chucks };

struct SupportSpec {
    SupportKind kind = SupportKind::free;
    std::vector<ClampSpec> clamps;  // empty for free; left then right for clamped
    std::vector<ChuckSpec> chucks;  // left then right for chucks
};

struct MeshSpec {
    std::string level = "default";  // coarse | default | fine | very_fine | custom
    int n_wall = 3;        // elements through the core wall
    int n_rest_paper = 2;  // elements through the rest paper
    int n_around = 32;     // elements around the circumference (multiple of 4)
    int n_along = 40;      // elements along the core length (over all segments)
    // Elements per axial segment (from z = 0), when set: exact counts instead
    // of n_along distributed by length. The converge ladder uses it to refine
    // every segment by the same integer factor. Not a case-file key.
    std::vector<int> along_per_segment;
    std::string element = "hex20";    // hex20 | hex27
    std::optional<std::string> file;  // user .msh (absolute or resolved against the case file)
};

struct AnalysisSpec {
    int n_modes = 20;                 // lowest modes wanted (rigid-body modes count)
    std::optional<double> f_min_hz;   // band request instead of n_modes, if both set
    std::optional<double> f_max_hz;
    double tolerance = 1e-10;         // SLEPc convergence tolerance
    int max_iterations = 500;
};

struct Scene {
    std::string name;         // case name (file stem unless given)
    std::string source_file;  // path of the case file, as given
    std::string description;  // free text from the case file, "" when not given
    // Model level: solid (3D FE), harmonic (axisymmetric, one 2D problem per n), coupled
    // (harmonics coupled by segmented chucks, a chuck not expanded or the web), automatic
    // ("auto": the cheapest that fits, models/choose.cpp) or beam (Timoshenko network).
    ModelChoice model = ModelChoice::solid;
    CoreSpec core;
    std::optional<RestPaperSpec> rest_paper;
    SupportSpec supports;
    std::optional<WebSpec> web;
    MeshSpec mesh;
    AnalysisSpec analysis;
    // Values the program assumed because the file did not say (e.g. a library
    // material's transverse shear moduli): echoed in the summary.
    std::vector<std::string> assumptions;
    // Values that parse but look like slips (a modulus of 6.5 Pa, a core
    // 10 um long): each a sentence that starts with file:line:col and names
    // the key. The command that read the file prints them once on stderr;
    // the summary keeps them. They do not stop a run.
    std::vector<std::string> warnings;

    // rho V of the core and rest paper from their dimensions, kg.
    double roll_mass() const;
    // rho V of every part (roll, chuck bodies and shafts) and the frame masses, kg.
    double mass_from_dimensions() const;

    // The effects this scene simulates, e.g. {"core", "rest_paper", "rigid_clamps"}:
    // the names of the effects the model levels apply (effect_names in
    // effects/support_effects.hpp, where this is defined).
    std::vector<std::string> effects() const;
};

}  // namespace coremodal
