// K and M of the coupled-harmonic model (docs/theory/coupled.md, "Coupled
// harmonics"): the axisymmetric bodies expanded in wave numbers n = 0 ... N,
// one family for n = 0 and both (cos, sin) for n >= 1, on the harmonic
// level's r–z section; an attachment that acts over arcs of the bore (a
// segmented expanding element's spring layer) couples the harmonics.
//
// The split: k chi(theta) = k - k (1 - chi(theta)). The first term is the
// full band, which is axisymmetric: every block (n, family) is the harmonic
// level's K_n, M_n of the scene with its segments widened to full bands
// (assembly/harmonic_system, assemble_harmonic_terms, unchanged; the sin
// family's block equals the cos family's). The second, the band minus the
// pads, is the coupling: on each interface edge over a segmented element,
// for every pair of blocks (a, b) and component c,
//     k_c (int_pads t_c(a) t_c(b) dtheta - int_0^2pi t_c(a) t_c(b) dtheta) int N_i N_j r ds
// (models/coupled/pad_integrals), on core minus chuck. It is nonzero only
// for m = |n +- j N_s| (pads evenly spaced), and never between a cos and a
// sin family (pads centred at theta = 0 are mirror symmetric about it).
// The paper web's line adds, on each edge of the roll's outer surface,
//     int N_i N_j dz  B_a(theta)^T K_line B_b(theta)
// for every pair of blocks (B = harmonic_to_cartesian at the line's angle).
#pragma once

#include "assembly/harmonic_system.hpp"
#include "effects/support_effects.hpp"
#include "models/coupled/contact_layer.hpp"
#include "models/coupled/pad_integrals.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace coremodal {

// The scene with every segmented expanding element widened to a full band:
// the same section mesh (the interfaces span the same z), axisymmetric.
Scene with_full_bands(const Scene& scene);

// A segmented expanding element's spring layer: where it acts and how stiff.
struct PadLayer {
    std::string chuck;      // "left" or "right": the mesh groups "interface_<chuck>_core/_chuck"
    ZRange zone;            // m, z of the element
    std::vector<Arc> arcs;  // the pads
    int segments = 0;       // N_s
    SpringLayer layer;      // k_n, k_t per unit bore area
};

// Every segmented element of the scene's chucks. A chuck whose segmented
// element is bonded throws InputError (the coupled level models spring
// layers only; models/choose says which level can). A chuck not expanded
// has none: its elements are retracted and the bore rests on its body
// (the one-sided contact, Attachments::contact).
std::vector<PadLayer> pad_layers(const Scene& scene);

// The paper web's line on the roll's outer surface (effects/web.hpp): at the
// polar angle theta of its tangent point, springs per unit length of roll in
// global x, y, z. A line at one angle couples every n to every m, and the
// cos with the sin families unless theta lies on their symmetry lines.
struct WebLine {
    double theta = 0;
    Eigen::Matrix3d stiffness = Eigen::Matrix3d::Zero();  // N/m^2
};

// The Cartesian displacement (x, y, z) at angle theta of one node's (U, V, W)
// in block h: (u_r, u_theta, u_z) = (t_r U, t_theta V, t_z W) turned by theta.
Eigen::Matrix3d harmonic_to_cartesian(HarmonicFamily h, double theta);

// B_a^T K_line B_b: the web's line between blocks a and b, per unit length
// and per pair of node values.
Eigen::Matrix3d web_between(const WebLine& web, HarmonicFamily a, HarmonicFamily b);

// Below this share of the line's stiffness an entry is round-off of one that
// vanishes exactly (sin n theta at theta on a symmetry line).
inline constexpr double kVanishingShare = 1e-12;

// What couples the harmonics: the segmented elements' pads, the web's line
// and a chuck not expanded's one-sided contact. The contact's layer depends
// on the static state under gravity (models/coupled/contact_static), which
// `attachments(scene)` does not solve: it only sets `one_sided`, and the
// level fills `contact` before assembling.
struct Attachments {
    std::vector<PadLayer> pads;
    std::optional<WebLine> web;
    bool one_sided = false;                // some chuck is not expanded
    std::optional<ContactLayer> contact;   // its layer linearised about the static state
    bool any() const { return !pads.empty() || web.has_value() || one_sided; }
    // Whether they couple blocks a and b (some term of theirs nonzero between them).
    bool couple(HarmonicFamily a, HarmonicFamily b) const;
    // Whether they couple component ca (0: U, 1: V, 2: W) of block a with component cb of block b.
    bool couple(HarmonicFamily a, int ca, HarmonicFamily b, int cb) const;
    // N grows in steps of this: the smallest N_s of the pads (they couple n to
    // n +- j N_s), or 1 for a web or a contact without pads (they couple every n).
    int step() const;
};
Attachments attachments(const Scene& scene);

// One block of the coupled unknowns: a wave number and family, its DOFs
// (harmonic_dofs of the full-band scene) and where they start.
struct CoupledBlock {
    HarmonicFamily harmonic;
    HarmonicDofs dofs;
    int offset = 0;
};

struct CoupledDofs {
    int n_max = 0;  // N
    std::vector<CoupledBlock> blocks;  // (0, cos), (1, cos), (1, sin), ..., (N, cos), (N, sin)
    int n_dofs = 0;
    // The block of (n, family), or -1.
    int block_of(int n, Family family) const;
};

// Where the harmonics above `n_full` are kept: near the pads. A pad layer's
// load on the bore is self-equilibrated in every n >= 2, so the harmonics it
// stirs die out along z within about a diameter (Saint-Venant; faster the
// higher n: a harmonic n of a solid of revolution decays like e^{-n z / r}).
// Block n > n_full keeps the nodes within reach(n) of a pad layer along z
// and holds the rest: a Ritz restriction, so every eigenvalue stays an upper
// bound and growing n_full or the reach keeps the spaces nested. Whether
// the reach sufficed is checked on each solution (zone_edge_amplitude).
struct LocalHarmonics {
    int n_full = 1;            // n = 0, 1 (the beam's modes) are whole
    std::vector<ZRange> pads;  // z of every pad layer and one-sided contact
    double reach_2 = 0;        // m, the reach of n = 2; n keeps 2/n of it
    double reach(int n) const { return reach_2 * 2.0 / n; }
};
// Local harmonics for pads and one-sided contacts (the web's line runs the
// roll's length: none), reaching kLocalReach diameters of the section's
// largest radius at n = 2.
inline constexpr double kLocalReach = 4;
std::optional<LocalHarmonics> local_harmonics(const Attachments& attached, const SectionMesh& mesh);

// The nodes block n holds beyond the reach, and the kept nodes of the cells
// the reach cuts (where the restriction's error would show).
std::vector<int> far_nodes(const SectionMesh& mesh, const LocalHarmonics& local, int n);
std::vector<int> zone_edge_nodes(const SectionMesh& mesh, const LocalHarmonics& local, int n);

CoupledDofs coupled_dofs(const Scene& scene, const SectionMesh& mesh, int n_max,
                         const std::optional<LocalHarmonics>& local = std::nullopt);

// The blocks split into the independent problems the attachments leave: the
// connected components of Attachments::couple, component by component. The
// block n = 0 is two nodes of that graph: its (U, W) (radial and axial, even
// under a mirror through theta = 0) and its V (torsion, odd), which K_0 and
// M_0 never couple (an orthotropic C couples no cos row with a sin row);
// every block n >= 1 is one node. Three pads: {0 (U, W), 3c, 6c, ...},
// {0 (V), 3s, 6s, ...}, {1, 2, 4, 5, ...} cos and the same sin; the last two are
// degenerate partners, a turned copy of each other. A one-sided contact's
// arc, symmetric about the vertical: {0 (U, W), 2c, 4c, ..., 1s, 3s, ...}
// and {0 (V), 1c, 3c, ..., 2s, 4s, ...} (models/coupled/contact_static.hpp).
// Each component's blocks are renumbered from offset 0; `offset_in` keeps
// where each block sits in `all`, and `dof_in`, for the part of block n = 0
// that holds only some of its components (the others held at zero in
// `dofs`), where each of its DOFs sits in `all` (empty for a whole block).
//
// A set of sin families whose every coupling equals that of the set of the
// same wave numbers' cos families up to a sign per wave number is that set's
// partner: K_sin = S K_cos S and M_sin = S M_cos S with S = diag(s_n), s_n =
// +-1 (three pads: s_n = +1 for n = 1 mod 3, -1 for n = 2 mod 3; the blocks'
// own K_n, M_n are the same for both families). A congruence by a signature
// matrix: the same eigenvalues, the same inertia at every shift, and
// eigenvectors S x. The partner is not solved; `partner_of` names its
// primary and `block_sign` holds s per block.
struct CoupledComponent {
    CoupledDofs dofs;
    std::vector<int> offset_in;  // per block of dofs: its offset in `all`
    std::vector<std::vector<int>> dof_in;  // per block of dofs: its DOFs in `all`, or empty (offset_in + i)
    int partner_of = -1;             // index of the component this one mirrors, or -1
    std::vector<double> block_sign;  // s per block (partners only)
};
std::vector<CoupledComponent> coupled_components(const CoupledDofs& all, const Attachments& attached);

// Receives one matrix of one term on rows x cols of the coupled DOFs (-1:
// held). The block terms come with rows == cols; a coupling between blocks
// a != b comes once as (a, b) and once as (b, a).
using CoupledInsert = std::function<void(Term, const std::vector<int>& rows, const std::vector<int>& cols,
                                         const Eigen::MatrixXd&)>;

// Every term of the coupled problem, the same loop for a run (PETSc COO) and
// a unit test (dense Eigen). Returns the model's mass (kg, once, not per block).
double assemble_coupled_terms(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                              const CoupledDofs& dofs, const CoupledInsert& insert);
// The same with the attachments given (a one-sided contact's needs its layer).
double assemble_coupled_terms(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                              const CoupledDofs& dofs, const Attachments& attached, const CoupledInsert& insert);

struct CoupledSystem {
    CoupledDofs dofs;
    OperatorSet operators;  // K, M (symmetric); model_mass
    long n_coupling_entries = 0;  // nonzero entries between different blocks (K)
};

// K and M on `dofs` (all blocks, or one component's).
CoupledSystem assemble_coupled(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const CoupledDofs& dofs, MPI_Comm comm = PETSC_COMM_WORLD);
CoupledSystem assemble_coupled(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const CoupledDofs& dofs, const Attachments& attached, MPI_Comm comm = PETSC_COMM_WORLD);

}  // namespace coremodal
