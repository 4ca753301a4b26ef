// Everything a run reports, gathered once and written by several writers
// (console table, summary.json, modes.csv, modes.h5).
#pragma once

#include "modes/mode_set.hpp"
#include "scene/scene.hpp"

#include <string>
#include <vector>

namespace coremodal {

struct ModelInfo {
    std::string level = "solid3d";
    std::string element;
    long n_dofs = 0;
    long n_nodes = 0;
    long n_elements = 0;
    long n_eliminated_nodes = 0;
    double mass_kg = 0;           // sum of rho V over the cells
    double expected_mass_kg = 0;  // from the scene's dimensions (generated meshes)
    std::string mesh_source;      // "generated" or the user's .msh path
};

struct BeamComparison {
    double span_m = 0;
    std::string ends;  // "clamped-clamped" or "free-free"
    double euler_bernoulli_hz = 0;
    double timoshenko_hz = 0;
    double fe_first_bending_hz = 0;  // 0 if no bending mode was found
    int fe_mode_index = 0;
    double fe_over_timoshenko = 0;
    double fe_over_euler_bernoulli = 0;
};

struct Timing {
    // factor_and_solve includes verification and the inertia count.
    double mesh = 0, assemble = 0, factor_and_solve = 0, classify = 0, total = 0;
};

struct RunReport {
    Scene scene;
    ModelInfo model;
    ModeSet modes;
    BeamComparison beam;
    Timing timing_s;
    double peak_memory_mb = 0;  // sum over MPI ranks of the peak resident set
    int mpi_ranks = 1;
    std::vector<std::string> warnings;  // things the user should know (e.g. an unheld part)
};

}  // namespace coremodal
