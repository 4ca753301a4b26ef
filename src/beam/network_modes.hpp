// The lowest modes of an assembled beam network, K x = lambda M x (Eigen only).
//
// 1. Split: the DOFs fall into four motion families (x-z bending: ux, ry;
//    y-z bending: uy, rx; axial: uz; torsion: rz). Beams never couple them;
//    only an asymmetric spring layer can. Families that no spring couples
//    are assembled and solved as separate, smaller problems.
// 2. Mirror: when the y-z problem equals the x-z one (every axisymmetric
//    scene), it is solved once and each mode is reported twice, as the exact
//    degenerate bending pair.
// 3. Solve each problem: a dense generalized solver when small, else a block
//    Krylov space of (K - sigma M)^-1 M with a negative shift (positive
//    definite even with rigid-body modes) and Rayleigh-Ritz, grown until the
//    wanted Ritz pairs converge.
// 4. Count: the first problem solved bounds the n-th eigenvalue of the whole;
//    the inertia of K - lambda M (Sylvester, sparse LDL^T) then says how many
//    modes every problem has below that bound, so none is missed, and proves
//    the final set complete (the same check as the solid model's). Should the
//    count disagree, every problem is solved again densely (complete by
//    construction).
#pragma once

#include "beam/beam_network.hpp"
#include "eigensolve/mode_request.hpp"
#include "modes/mode_set.hpp"  // Verification

#include <Eigen/Dense>

#include <optional>
#include <vector>

namespace coremodal {

// The case's request (eigensolve/mode_request.hpp) and the choice of solver.
struct NetworkSolveRequest : ModeRequest {
    bool force_dense = false;  // tests: the dense solver whatever the size
};

struct NetworkModes {
    std::vector<double> eigenvalues;  // ascending, rad^2/s^2
    // Per network DOF (6 per node, beam_dof order), M-normalised, zero where held.
    std::vector<Eigen::VectorXd> shapes;
    std::vector<Eigen::VectorXd> mass_shapes;  // M times each shape, per network DOF
    std::vector<double> relative_residuals;    // ||K x - lambda M x|| / (||K|| ||x||) in its problem
    Verification verification;
    long n_free_dofs = 0;
    int n_problems = 0;            // independent problems solved
    bool mirrored_planes = false;  // y-z bending taken from x-z
    bool dense_retry = false;      // the inertia count disagreed once: solved again densely
};

// Throws SolveError when a problem cannot be factored (a free DOF without mass
// or stiffness: a bug in the network, not in the input).
NetworkModes solve_network_modes(const BeamNetwork& network, const NetworkSolveRequest& request);

// Eigenvalues of K x = lambda M x below lambda (Sylvester), or nothing when
// the LDL^T factor meets a zero pivot.
std::optional<long> count_eigenvalues_below(const Eigen::SparseMatrix<double>& K,
                                            const Eigen::SparseMatrix<double>& M, double lambda);

}  // namespace coremodal
