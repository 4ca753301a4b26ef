// One wave number n of a spinning body of revolution (effects/rotation.hpp,
// docs/theory/rotation-harmonic.md): the operator set M q'' + Omega G q' + K q = 0 the
// gyroscopic solver takes (eigensolve/gyroscopic_solver.hpp).
//
// n = 0: its one family, G = 2 Gamma_0 (skew: spinning material moving
// radially is pushed around, and back).
// n >= 1: the spin couples the cos and sin families (the two members of a
// pair at rest), so both are unknowns, q = (a, b):
//     K2 = [[K, 0], [0, K]],  M2 = [[M, 0], [0, M]],  G2 = 2 [[0, Gamma], [-Gamma, 0]]
// (element/harmonic_element.hpp, harmonic_quad8_spin_coupling). With a
// centrifugal prestress the set also has K_Omega (Term::centrifugal, per unit
// Omega^2): K_Omega on each family, [[K_Omega, 0], [0, K_Omega]] for n >= 1
// (harmonic_quad8_centrifugal). A mode
// q = (a, b) e^{i omega t} travels with the spin (forward) when
// Im(a . conj b) > 0: a forward wave cos(n theta - omega t) is a = cos, b = sin.
// At rest the problem is the harmonic level's, each pair found twice.
#pragma once

#include "assembly/harmonic_system.hpp"
#include "assembly/operator_set.hpp"
#include "effects/damping.hpp"
#include "geometry/section_mesh.hpp"
#include "material/material.hpp"
#include "models/harmonic/centrifugal_prestress.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace coremodal {

struct SpinningHarmonic {
    int n = 0;
    HarmonicDofs dofs;      // of one family (the harmonic level's)
    OperatorSet operators;  // n = 0: on dofs; n >= 1: on (a, b), 2 x dofs.n_dofs
    PetscIndexSet cos_rows, sin_rows;  // n >= 1: where a and b sit in a vector of the set
    // n = 0 on one process: the meridional DOFs (U, W and the frames' axial
    // DOFs) and the tangential ones (V). K, M and K_Omega do not couple them
    // and G couples only them (L_0 turns u_r into u_theta): the count's
    // Hermitian Q is then a real symmetric matrix of the set's size
    // (gyroscopic_inertia.hpp). Null where a DOF is both (a tie) or in parallel.
    PetscIndexSet meridional_rows, tangential_rows;

    int n_families() const { return n == 0 ? 1 : 2; }
};

// `prestress` null: no centrifugal term (gyroscopic only).
SpinningHarmonic assemble_spinning_harmonic(const Scene& scene, const SectionMesh& mesh,
                                            const std::vector<PartMaterial>& materials, int n,
                                            const CentrifugalPrestress* prestress = nullptr);

// [damping] as terms of a wave number's set (effects/damping.hpp), for the
// projected solver's damped branch (eigensolve/projected_damped.hpp): h's
// terms, shared, with the viscous D = alpha M + beta K (Term::damping; absent
// when alpha = beta = 0) and the imaginary stiffness H = sum_p w_p K_p over the
// parts' section cells (Term::imaginary_stiffness, springs carry none; on
// each family for n >= 1; absent when no part has a weight).
OperatorSet damped_harmonic_terms(const SpinningHarmonic& h, const SectionMesh& mesh,
                                  const std::vector<PartMaterial>& materials, const OperatorDamping& damping);

// The values of a vector of the set on rank 0 (empty elsewhere), split into
// the cos and sin families (sin empty for n = 0).
struct FamilyValues {
    std::vector<double> cos_values, sin_values;
};
FamilyValues family_values(const SpinningHarmonic& h, Vec x);

}  // namespace coremodal
