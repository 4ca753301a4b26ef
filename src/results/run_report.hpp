// Everything a run reports, gathered once and written by several writers
// (console table, summary.json, modes.csv, modes.h5).
#pragma once

#include "beam/speeds.hpp"

#include "modes/mode_set.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

struct ModelInfo {
    ModelChoice level = ModelChoice::solid;  // the level that ran (never automatic)
    std::string element;
    long n_dofs = 0;
    long n_nodes = 0;
    long n_elements = 0;
    long n_eliminated_nodes = 0;
    double mass_kg = 0;           // sum of rho V over the cells
    double expected_mass_kg = 0;  // from the scene's dimensions (generated meshes)
    std::string mesh_source;      // "generated" or the user's .msh path
    // Harmonic level: per wave number n its DOFs, modes and inertia count; "" otherwise.
    std::string harmonics;
};

struct BeamComparison {
    double span_m = 0;
    std::string ends;  // "clamped-clamped" or "free-free"
    double euler_bernoulli_hz = 0;
    double timoshenko_hz = 0;
    double fe_first_bending_hz = 0;  // 0 if no bending mode was found (then written as null)
    int fe_mode_index = 0;           // 1-based; 0: none found
    double fe_over_timoshenko = 0;
    double fe_over_euler_bernoulli = 0;
    std::string fe_missing;  // why no bending mode was found, e.g. "no modes between 0 and 1 Hz"; "" when found
    bool fe_found() const { return fe_mode_index > 0; }
};

// Ilomäki's chuck factor k = f1 / f2 (Ilomäki I-6): f1 the first
// bending frequency of the scene, f2 the free-free first bending frequency
// of the same core (and rest paper) cut to the free span L = Lc - Li_left -
// Li_right (= Lc - 2 Li for equal ends).
struct ChuckFactor {
    double li_left_m = 0, li_right_m = 0;
    double li_m = 0;  // the mean of the two ends (equal ends: Li)
    double free_span_m = 0;
    double f1_hz = 0;
    double f2_fe_hz = 0;    // FE, free-free, same mesh density
    double f2_beam_hz = 0;  // Timoshenko beam, free-free
    double chuck_factor = 0;       // f1 / f2_fe
    double chuck_factor_beam = 0;  // f1 / f2_beam
};

// One row of the rigid-vs-elastic comparison (app/rigid_comparison.hpp).
struct ModeShift {
    std::string type;
    int n = 0, m = 0;
    int elastic_index = 0, rigid_index = 0;  // 0: no partner
    double elastic_hz = 0, rigid_hz = 0;
    double shift_percent() const { return elastic_index && rigid_index ? 100 * (elastic_hz / rigid_hz - 1) : 0; }
};

struct Timing {
    // factor_and_solve includes verification and the inertia count.
    double mesh = 0, assemble = 0, factor_and_solve = 0, classify = 0, chuck_factor = 0, total = 0;
};

struct RunReport {
    Scene scene;
    ModelInfo model;
    ModeSet modes;
    BeamComparison beam;
    std::optional<ChuckFactor> chuck;  // scenes with elastic chucks
    std::vector<ModeShift> rigid_comparison;  // run --compare-rigid: elastic vs rigid-clamp modes
    Timing timing_s;
    double peak_memory_mb = 0;  // sum over MPI ranks of the peak resident set
    int mpi_ranks = 1;
    std::vector<std::string> warnings;  // things the user should know (e.g. an unheld part)
};

// The safe and critical speeds of the report's roll from its FE first
// bending frequency (beam/speeds.hpp): what summary.json and report.md give.
inline RollSpeeds report_speeds(const RunReport& r) {
    const std::string missing = r.beam.fe_found()           ? ""
                                : r.beam.fe_missing.empty() ? "no bending mode was found"
                                                            : r.beam.fe_missing;
    return roll_speeds(r.scene, r.beam.fe_first_bending_hz, missing);
}

}  // namespace coremodal
