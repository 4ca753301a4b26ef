// Steps of `coremodal run` that the solid and harmonic model levels share
// (app/run_case.cpp, app/run_harmonic.cpp).
#pragma once

#include "app/run_case.hpp"
#include "assembly/cell_loop.hpp"
#include "common/petsc_handle.hpp"
#include "common/stopwatch.hpp"
#include "eigensolve/modal_solver.hpp"
#include "mesh/mesh.hpp"

#include <iostream>
#include <string>
#include <vector>

namespace coremodal {

// Progress lines on standard output, when on.
struct Printer {
    bool on;
    void operator()(const std::string& line) const {
        if (on) std::cout << "  " << line << std::endl;
    }
};

// An empty report of a run of `scene` on this many MPI ranks; it keeps the
// case reader's warnings (printed when the file was read) for the summary.
inline RunReport new_report(Scene scene) {
    RunReport report;
    report.mpi_ranks = mpi_size();
    report.warnings = scene.warnings;
    report.scene = std::move(scene);
    return report;
}

// The material of each named part ("core", "rest_paper", "chuck_<name>");
// InputError naming `source` for a part the case file gives no material.
std::vector<PartMaterial> part_materials(const Scene& scene, const std::vector<std::string>& part_names,
                                         const std::string& source);

// What the case's [analysis] asks of the eigensolver: the lowest modes or a
// band; the shift's scale from the closed-form estimates of the first elastic
// mode of every family (beam/eigenvalue_scale.hpp).
SolveRequest solve_request(const Scene& scene);
// A progress line: which family's estimate set the shift, and its frequency.
std::string shift_scale_text(const Scene& scene);

// Rigid-body motions of a free body in three dimensions.
constexpr int kFreeBodyRigidModes = 6;

// A free scene (generated model, band from 0 if any) must show exactly its
// six rigid-body modes as its lowest; SolveError otherwise: the body is too
// thin for double precision to tell them from its elastic modes.
void check_rigid_modes(const RunReport& report);

// Steps 7 and 8 of a run whose modes are named: beam comparison, chuck
// factor, rigid-clamp variant, console tables, the results folder (the
// modes' shapes live on `mesh`).
void finish_run(RunReport& report, const Mesh& mesh, const RunOptions& options, const Stopwatch& total,
                Stopwatch& stage);

}  // namespace coremodal
