#include "models/harmonic/spinning_harmonic.hpp"

#include "common/error.hpp"
#include "modes/mode_shapes.hpp"

namespace coremodal {
namespace {

// A 2 x 2 block matrix (null blocks are zero) as one AIJ matrix; `rows`
// receives where each block row sits in it (PETSc interleaves the blocks
// rank by rank in parallel).
PetscMatrix block_matrix(MPI_Comm comm, Mat a00, Mat a01, Mat a10, Mat a11, bool symmetric,
                         PetscIndexSet* rows = nullptr) {
    PetscMatrix nest, out;
    Mat blocks[4] = {a00, a01, a10, a11};
    COREMODAL_PETSC(MatCreateNest(comm, 2, nullptr, 2, nullptr, blocks, nest.out()));
    COREMODAL_PETSC(MatConvert(nest, MATAIJ, MAT_INITIAL_MATRIX, out.out()));
    if (symmetric) COREMODAL_PETSC(MatSetOption(out, MAT_SYMMETRIC, PETSC_TRUE));
    if (rows) {
        IS is[2];
        COREMODAL_PETSC(MatNestGetISs(nest, is, nullptr));
        for (int k = 0; k < 2; ++k) COREMODAL_PETSC(ISDuplicate(is[k], rows[k].out()));
    }
    return out;
}

std::vector<double> sub_values(Vec x, IS rows) {
    Vec part;
    COREMODAL_PETSC(VecGetSubVector(x, rows, &part));
    std::vector<double> values = gather_to_root(part);
    COREMODAL_PETSC(VecRestoreSubVector(x, rows, &part));
    return values;
}

}  // namespace

namespace {

// The n = 0 DOFs split into meridional (U, W, frames) and tangential (V) ones (header).
void split_meridional(SpinningHarmonic& h) {
    std::vector<char> kind(h.dofs.n_dofs, 0);  // 1 meridional, 2 tangential, 3 both
    for (size_t k = 0; k < h.dofs.of_component.size(); ++k)
        if (const int d = h.dofs.of_component[k]; d >= 0) kind[d] |= (k % 3 == 1) ? 2 : 1;
    for (int d : h.dofs.frame)
        if (d >= 0) kind[d] |= 1;
    std::vector<PetscInt> rows[2];
    for (int d = 0; d < h.dofs.n_dofs; ++d) {
        if (kind[d] != 1 && kind[d] != 2) return;
        rows[kind[d] - 1].push_back(d);
    }
    if (rows[0].empty() || rows[1].empty()) return;
    COREMODAL_PETSC(ISCreateGeneral(PETSC_COMM_SELF, rows[0].size(), rows[0].data(), PETSC_COPY_VALUES,
                                    h.meridional_rows.out()));
    COREMODAL_PETSC(ISCreateGeneral(PETSC_COMM_SELF, rows[1].size(), rows[1].data(), PETSC_COPY_VALUES,
                                    h.tangential_rows.out()));
}

}  // namespace

SpinningHarmonic assemble_spinning_harmonic(const Scene& scene, const SectionMesh& mesh,
                                            const std::vector<PartMaterial>& materials, int n,
                                            const CentrifugalPrestress* prestress) {
    HarmonicSystem rest = assemble_harmonic(scene, mesh, materials, n);
    SpinningHarmonic out;
    out.n = n;
    out.dofs = rest.dofs;
    out.operators.model_mass = rest.operators.model_mass;
    const MPI_Comm comm = PetscObjectComm((PetscObject)rest.operators.K());
    PetscMatrix gamma = assemble_harmonic_spin_coupling(mesh, materials, rest.dofs, n, comm);
    COREMODAL_PETSC(MatScale(gamma, 2.0));  // G = 2 x the cross term's matrix (header)
    PetscMatrix centrifugal;
    if (prestress) centrifugal = assemble_harmonic_centrifugal(mesh, materials, rest.dofs, n, prestress->stress, comm);
    if (n == 0) {
        if (mpi_size(comm) == 1) split_meridional(out);
        out.operators.matrices[Term::stiffness] = std::move(rest.operators.matrices[Term::stiffness]);
        out.operators.matrices[Term::mass] = std::move(rest.operators.matrices[Term::mass]);
        out.operators.matrices[Term::gyroscopic] = std::move(gamma);
        if (prestress) out.operators.matrices[Term::centrifugal] = std::move(centrifugal);
        return out;
    }
    PetscMatrix minus_gamma;
    COREMODAL_PETSC(MatDuplicate(gamma, MAT_COPY_VALUES, minus_gamma.out()));
    COREMODAL_PETSC(MatScale(minus_gamma, -1.0));
    const Mat K = rest.operators.K(), M = rest.operators.M();
    PetscIndexSet rows[2];
    out.operators.matrices[Term::stiffness] = block_matrix(comm, K, nullptr, nullptr, K, true, rows);
    out.operators.matrices[Term::mass] = block_matrix(comm, M, nullptr, nullptr, M, true);
    out.operators.matrices[Term::gyroscopic] = block_matrix(comm, nullptr, gamma, minus_gamma, nullptr, false);
    if (prestress)
        out.operators.matrices[Term::centrifugal] = block_matrix(comm, centrifugal, nullptr, nullptr, centrifugal, true);
    out.cos_rows = std::move(rows[0]);
    out.sin_rows = std::move(rows[1]);
    return out;
}

namespace {

// Another owner of A (the damped set shares the undamped set's terms).
PetscMatrix shared(Mat A) {
    COREMODAL_PETSC(PetscObjectReference((PetscObject)A));
    return PetscMatrix(A);
}

}  // namespace

OperatorSet damped_harmonic_terms(const SpinningHarmonic& h, const SectionMesh& mesh,
                                  const std::vector<PartMaterial>& materials, const OperatorDamping& damping) {
    OperatorSet out;
    out.model_mass = h.operators.model_mass;
    for (const auto& [term, A] : h.operators.matrices) out.matrices[term] = shared(A);
    if (damping.has_viscous()) {
        PetscMatrix D;
        COREMODAL_PETSC(MatDuplicate(h.operators.M(), MAT_COPY_VALUES, D.out()));
        COREMODAL_PETSC(MatScale(D, damping.viscous.alpha));
        COREMODAL_PETSC(MatAXPY(D, damping.viscous.beta, h.operators.K(), DIFFERENT_NONZERO_PATTERN));
        out.matrices[Term::damping] = std::move(D);
    }
    const std::vector<double> weights = damping.imaginary_stiffness_weights(mesh.part_names);
    if (weights.empty()) return out;
    const MPI_Comm comm = PetscObjectComm((PetscObject)h.operators.K());
    PetscMatrix H = assemble_harmonic_weighted_stiffness(mesh, materials, h.dofs, h.n, weights, comm);
    out.matrices[Term::imaginary_stiffness] =
        h.n == 0 ? std::move(H) : block_matrix(comm, H, nullptr, nullptr, H, true);
    return out;
}

FamilyValues family_values(const SpinningHarmonic& h, Vec x) {
    if (h.n == 0) return {gather_to_root(x), {}};
    return {sub_values(x, h.cos_rows), sub_values(x, h.sin_rows)};
}

}  // namespace coremodal
