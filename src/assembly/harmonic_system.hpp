// K and M of one circumferential wave number n of the axisymmetric-harmonic
// model (element/harmonic_element.hpp): section cells, rigid clamps and rigid
// bearings eliminated, bonded chuck interfaces tied, spring layers and
// bearing springs as ring springs, the frame mass as one extra DOF in the
// harmonics it moves in (n = 0 along the axis, n = 1 sideways). Nodes on the
// axis obey the conditions that keep the field single-valued there:
//   n = 0: U = V = 0;  n = 1: W = 0 and V = U;  n >= 2: U = V = W = 0.
#pragma once

#include "assembly/cell_loop.hpp"
#include "assembly/operator_set.hpp"
#include "element/harmonic_element.hpp"
#include "geometry/section_mesh.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace coremodal {

struct HarmonicDofs {
    // Global DOF of (node, component) at 3 * node + c, or -1 where the
    // component is held at zero. Tied components share a DOF.
    std::vector<int> of_component;
    // Per scene chuck: the DOF of its frame mass in this harmonic, or -1.
    std::vector<int> frame;
    int n_dofs = 0;
};

struct HarmonicSystem {
    int n = 0;  // circumferential wave number
    HarmonicDofs dofs;
    OperatorSet operators;  // model_mass: the revolved cells plus frame masses, kg
};

// The DOFs of wave number n: clamps and rigid bearings held, bonded
// interfaces tied, the axis conditions, one frame DOF per frame mass in n <= 1;
// `also_held` nodes held too (the coupled level's local harmonics).
HarmonicDofs harmonic_dofs(const Scene& scene, const SectionMesh& mesh, int n, const std::vector<int>& also_held = {});

// The section cells' stiffness and mass alone (no supports) for the cells
// `take(cell)` selects, handed to `insert`. Returns their mass (kg).
double assemble_harmonic_cells(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const HarmonicDofs& dofs, int n, const std::function<bool(int)>& take,
                               const TermInsert& insert);

// sum over the section cells of weight[part] K_cell (no supports), weight
// indexed as mesh.part_names: an imaginary stiffness H = sum_p w_p K_p
// (Term::imaginary_stiffness, effects/damping.hpp) at the harmonic level. Symmetric.
PetscMatrix assemble_harmonic_weighted_stiffness(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                                                 const HarmonicDofs& dofs, int n, const std::vector<double>& weight,
                                                 MPI_Comm comm = PETSC_COMM_WORLD);

// Gamma_n of every section cell (assemble_harmonic_spin_coupling's terms)
// handed to `insert` as Term::gyroscopic.
void assemble_harmonic_spin_terms(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                                  const HarmonicDofs& dofs, int n, const TermInsert& insert);

// Every term of wave number n (section cells, spring layers, bearing springs,
// frame masses) handed to `insert`, the same loop for a run (PETSc COO) and a
// unit test (dense Eigen). Returns the mass (kg) of what it inserted.
double assemble_harmonic_terms(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const HarmonicDofs& dofs, int n, const TermInsert& insert);

// The scene must be axisymmetric (models/choose.hpp, require_axisymmetric: no segmented
// expanding elements).
HarmonicSystem assemble_harmonic(const Scene& scene, const SectionMesh& mesh,
                                 const std::vector<PartMaterial>& materials, int n,
                                 MPI_Comm comm = PETSC_COMM_WORLD);

// Gamma_n of wave number n (element/harmonic_element.hpp,
// harmonic_quad8_spin_coupling) over every section cell: the core, rest
// paper, chuck bodies and shafts all spin; springs and frame masses (the
// stand) do not. Symmetric for n >= 1, skew for n = 0; on the DOFs of one
// family (the spinning level, models/harmonic/spinning_harmonic, builds G).
PetscMatrix assemble_harmonic_spin_coupling(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                                            const HarmonicDofs& dofs, int n, MPI_Comm comm = PETSC_COMM_WORLD);

// The centrifugal body force rho r e_r per unit Omega^2 on the n = 0 DOFs
// (every section cell spins), as a vector of dofs.n_dofs values.
std::vector<double> assemble_harmonic_centrifugal_load(const SectionMesh& mesh,
                                                       const std::vector<PartMaterial>& materials,
                                                       const HarmonicDofs& dofs);

// The n = 0 stress (element/harmonic_element.hpp, harmonic_quad8_stress) of
// a solution x on the n = 0 DOFs, per section cell.
std::vector<SectionStress> harmonic_section_stress(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                                                   const HarmonicDofs& dofs, const std::vector<double>& x);

// K_Omega of wave number n (element/harmonic_element.hpp,
// harmonic_quad8_centrifugal) over every section cell, from the prestress
// `stress` (one SectionStress per cell, per unit Omega^2): symmetric, on the
// DOFs of one family; the springs and frames do not spin and add nothing.
PetscMatrix assemble_harmonic_centrifugal(const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                                          const HarmonicDofs& dofs, int n, const std::vector<SectionStress>& stress,
                                          MPI_Comm comm = PETSC_COMM_WORLD);

// Rigid-body fields of harmonic n on the DOFs: translation along x (n = 1:
// U = V = 1), along z (n = 0: W = 1) and rotation about z (n = 0: V = r);
// all zero in the harmonics they do not live in. For effective masses.
enum class RigidMotion { x, z, rz };
std::vector<double> harmonic_rigid_field(const SectionMesh& mesh, const HarmonicDofs& dofs, int n, RigidMotion motion);

}  // namespace coremodal
