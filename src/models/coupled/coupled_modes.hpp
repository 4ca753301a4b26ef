// The coupled problem truncated at N (the coupled-harmonic level's solve
// at one N, models/coupled/coupled_level): the independent sets of the
// harmonics n = 0 ... N (coupled_system) each solved, verified and counted,
// their modes mapped onto all blocks and merged in frequency order, with
// what the level reads off them (dominant harmonic, rigid-body products,
// amplitude at a local harmonic's zone edge, the shape on the revolved mesh).
#pragma once

#include "eigensolve/modal_solver.hpp"
#include "geometry/section_mesh.hpp"
#include "models/coupled/coupled_system.hpp"

#include <array>
#include <optional>
#include <vector>

namespace coremodal {

// The verified modes of the coupled problem truncated at N (values on rank 0).
struct CoupledModes {
    CoupledDofs dofs;
    double mass_kg = 0;
    long n_coupling_entries = 0;
    int n_components = 1;  // independent problems the pads leave (coupled_components)
    std::vector<double> eigenvalues, residuals;
    std::vector<std::vector<double>> vectors;           // M-normalised, on the coupled DOFs
    std::vector<std::vector<double>> block_energy;      // per mode, per block: x_b^T M_b x_b (sums to 1)
    std::vector<std::array<double, 4>> gamma;           // x^T M r for translation x, y, z and rotation about z
    Verification verification;

    // The wave number holding the largest share of mode k's kinetic energy.
    int dominant_n(size_t k) const;
};

CoupledModes solve_coupled(const Scene& scene, const SectionMesh& section, const std::vector<PartMaterial>& materials,
                           int n_max, const SolveRequest& request);
// The same with the attachments given (a one-sided contact's with its layer
// linearised about the static state: models/coupled/contact_static), and the
// harmonics above n_full kept near the pads only when `local` is given.
CoupledModes solve_coupled(const Scene& scene, const SectionMesh& section, const std::vector<PartMaterial>& materials,
                           int n_max, const SolveRequest& request, const Attachments& attached,
                           const std::optional<LocalHarmonics>& local = std::nullopt);

// The largest displacement of the first `n_wanted` modes on the edge of a
// local harmonic's zone (zone_edge_nodes of every block n > n_full),
// relative to the mode's largest anywhere. The restriction holds the nodes
// beyond that edge at zero: the energy it misses, and so the eigenvalue's
// error, is of the order of this amplitude squared (measured in
// docs/theory/coupled.md, "Local harmonics").
double zone_edge_amplitude(const CoupledModes& modes, const SectionMesh& section, const LocalHarmonics& local,
                           size_t n_wanted);

// Node-major (x, y, z) displacements of every revolved node (frame nodes
// too) for mode k: the sum over the blocks of revolved_field.
std::vector<double> coupled_revolved_shape(const RevolvedMesh& revolved, const CoupledModes& modes, size_t k,
                                           const std::vector<int>& frame_nodes);

}  // namespace coremodal
