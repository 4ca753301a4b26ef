// The two-drum winder scene: a [winder] table in its own case file
// (`coremodal winder WINDER.toml`), read into SI values with every input
// error raised here as InputError "FILE:LINE:COL: [winder.drums] wall = ...:
// what is wrong; what is expected" (the same form as scene/case_file.hpp).
//
// Defaults come from Jorkama & von Hertzen's example where the paper gives a
// value (a 9.1 m winder, five 1.68 m rolls, 10 m drums of 0.85 m with a 50 mm
// wall, roll radial modulus 9.8 MPa, nu = 0.3, roll diameters 0.4-1.8 m;
// Jorkama & von Hertzen, Fig. 4, and the issue that asked for the winder). Every other
// default is an assumption, marked so beside it with its range; docs/how-to/winder.md
// lists them all and cases/11-two-drum-winder.toml shows them in use.
#pragma once

#include "material/material.hpp"

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace coremodal {

// The two drums (front and rear), alike: steel tubes on a bearing at each end.
struct WinderDrums {
    double outer_diameter = 0.85;  // m: the paper's d1 = 0.85 m (Jorkama & von Hertzen); range 0.3-2 m
    double wall = 0.05;            // m: the paper's 50 mm wall; range 10-150 mm
    double length = 10.0;          // m, bearing to bearing: the paper's 10 m drum; range 1-15 m
    // m between the two drums' surfaces: an assumption (the paper's value was not
    // available); range 10-500 mm. The rolls sit in the valley; a roll smaller
    // than the gap would fall through it.
    double gap = 0.1;
    std::string material = "steel";  // library name (scene/materials_library): E 210 GPa, 7850 kg/m^3
    // N/m of each bearing (and its housing and frame): an assumption, range
    // 1e7-1e11 N/m. Isotropic (equal) is the case of the drum-frequency
    // estimate (docs/how-to/winder.md); horizontal defaults to vertical.
    double bearing_stiffness_vertical = 1e9;
    double bearing_stiffness_horizontal = 1e9;
    // N/m of the roll-drum nips. Unset (default): from the roll's equilibrium,
    // P = (roll weight per width + rider line load) / (2 cos alpha) at every d.
    std::optional<double> line_load;
    int elements = 24;  // Timoshenko elements per drum (more are added at roll edges); range 4-400
};

enum class RollModel {
    rigid,  // each roll a rigid body: the default (docs/how-to/winder.md says why)
    beam,   // each roll a Timoshenko beam of core and paper (its own bending)
};

// The paper rolls, side by side on one line, centred on the drums.
struct WinderRolls {
    int count = 5;        // the paper's five rolls; range 1-20
    double width = 1.68;  // m: the paper's 1.68 m rolls; range 0.1-10 m
    double gap = 0.0;     // m between neighbouring rolls (slitting): assumed 0; range 0-0.5 m
    // The core: 150 x 13 mm (Do 176 mm), one of Ilomäki's named cores;
    // assumed, range Di 50-400 mm.
    double core_inner_diameter = 0.150;
    double core_outer_diameter = 0.176;
    std::string core_material = "paperboard_core";  // library: 920 kg/m^3 (Ilomäki), E_z 6.5 GPa
    // The paper's bending (E_z, G_thetaz; the "beam" roll model only): library
    // rest_paper, Ep = 5 GPa measured on rest rolls (Ilomäki).
    std::string paper_material = "rest_paper";
    // kg/m^3 of the wound paper: an assumption (fine papers' sheet densities are
    // 700-850 kg/m^3, docs/reference/material-sources.md); range 300-1500.
    double paper_density = 800.0;
    double radial_modulus = 9.8e6;  // Pa, E of the nip: the paper's 9.8 MPa; range 1-100 MPa
    double poisson = 0.3;           // nu of the nip: the paper's 0.3; range 0-0.49
    RollModel model = RollModel::rigid;
    double diameter_start = 0.4;  // m: the paper's smallest example diameter; >= core, > drum gap
    double diameter_end = 1.8;    // m: the paper's largest; range up to 3 m
};

// The rider roll: a steel tube on top of the rolls, on a spring at each end.
struct WinderRider {
    double outer_diameter = 0.5;  // m: assumed; range 0.1-1.5 m
    double wall = 0.03;           // m: assumed; range 5-150 mm
    double length = 9.1;          // m, spring to spring: the paper's 9.1 m winder; >= the row of rolls
    std::string material = "steel";
    // N/m of each end's support (loading arm, cylinder) in both directions:
    // assumed, range 1e5-1e11 N/m.
    double support_stiffness = 2e7;
    // N/m of the rider nip on each roll: assumed 2 kN/m, range 0-50 kN/m.
    // 0 opens the rider nips (no rider in the dynamics).
    double line_load = 2000.0;
    int elements = 16;  // Timoshenko elements (more at roll edges); range 2-400
};

// Modal damping ratios by modal strain energy: each mode's ratio is the
// energy-weighted mean of these (docs/how-to/winder.md, "Response").
struct WinderDamping {
    double drums = 0.01;  // drum bending and bearings: assumed, ζ of steel structures 0.005-0.02 (Ilomäki I-1...I-4)
    double nips = 0.05;   // nip springs (the paper's compression): assumed, range 0.005-0.3
    double rider = 0.01;  // rider bending and supports: assumed, as the drums
};

enum class DrumSide { front, rear };
enum class ResponseDirection { vertical, horizontal };

struct WinderSweep {
    int points = 57;              // diameters from start to end, evenly spaced (every 25 mm by default); 2-2000
    int harmonics = 4;            // roll rotation harmonics 1..N (the paper's 1st-4th); 1-12
    double max_frequency = 80.0;  // Hz: modes reported up to here; range 1-2000 Hz
    DrumSide response_drum = DrumSide::front;                      // X/F at this drum's centre
    ResponseDirection response_direction = ResponseDirection::vertical;  // force and displacement
};

struct WinderScene {
    std::string name, description, source_file;
    // m/s of the web (the rolls' surface): assumed 2000 m/min (fast two-drum
    // winders run 1500-3000 m/min); range 1-100 m/s.
    double web_speed = 2000.0 / 60.0;
    WinderDrums drums;
    WinderRolls rolls;
    WinderRider rider;
    WinderDamping damping;
    WinderSweep sweep;
    // The defaults in use that are physics, each with its origin:
    // "[winder.drums] gap = 0.1 m (assumed)", "... (paper)".
    std::vector<std::string> defaults;
};

// The winder case file's keys as a JSON Schema (draft-07), generated from the
// reader's key table: each key's table, type, unit pattern, the SI bounds of
// plain numbers and the string choices (`coremodal schema --winder`; editors
// as for the case schema, docs/reference/case-files.md "Editor support").
std::string winder_json_schema();

// Reads a winder case file. Throws InputError (file:line:col, the key, what
// is wrong, what is expected) on any problem.
WinderScene read_winder_file(const std::string& path);
WinderScene read_winder_text(std::string_view text, const std::string& path);

// The library material of a part, as a material (for beam sections).
OrthotropicMaterial winder_material(const std::string& library_name);

// "rigid" / "beam", "front" / "rear", "vertical" / "horizontal".
const char* roll_model_name(RollModel m);
const char* drum_side_name(DrumSide s);
const char* direction_name(ResponseDirection d);

}  // namespace coremodal
