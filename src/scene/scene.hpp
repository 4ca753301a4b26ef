// A scene: what the user asked to simulate, resolved to SI units.
// Produced by parse_case_file (scene/case_file.hpp); read by every later stage.
#pragma once

#include "material/material.hpp"

#include <optional>
#include <string>
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

enum class SupportKind { free, clamped };

struct SupportSpec {
    SupportKind kind = SupportKind::free;
    std::vector<ClampSpec> clamps;  // empty for free; left then right for clamped
};

struct MeshSpec {
    std::string level = "default";  // coarse | default | fine | very_fine | custom
    int n_wall = 3;        // elements through the core wall
    int n_rest_paper = 2;  // elements through the rest paper
    int n_around = 32;     // elements around the circumference (multiple of 4)
    int n_along = 40;      // elements along the core length (over all segments)
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
    CoreSpec core;
    std::optional<RestPaperSpec> rest_paper;
    SupportSpec supports;
    MeshSpec mesh;
    AnalysisSpec analysis;
    // Values the program assumed because the file did not say (e.g. a library
    // material's transverse shear moduli): echoed in the summary.
    std::vector<std::string> assumptions;

    // The effects this scene simulates, e.g. {"core", "rest_paper", "rigid_clamps"}.
    std::vector<std::string> effects() const;
};

}  // namespace coremodal
