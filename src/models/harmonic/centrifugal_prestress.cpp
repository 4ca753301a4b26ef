#include "models/harmonic/centrifugal_prestress.hpp"

#include "assembly/harmonic_system.hpp"
#include "common/error.hpp"

#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// A relative residual above this is a failed solve, never a prestress.
constexpr double kMaxStaticResidual = 1e-8;
// K r below this fraction of ||K|| ||r|| (infinity norms) is a rigid motion.
constexpr double kRigidTolerance = 1e-10;

SparseMatrix stiffness_at_rest(const Scene& scene, const SectionMesh& mesh, const std::vector<PartMaterial>& materials,
                               const HarmonicDofs& dofs) {
    std::vector<Eigen::Triplet<double>> entries;
    assemble_harmonic_terms(scene, mesh, materials, dofs, 0,
                            [&](Term t, const std::vector<int>& d, const Eigen::MatrixXd& A) {
                                if (t != Term::stiffness) return;
                                for (size_t a = 0; a < d.size(); ++a)
                                    for (size_t b = 0; b < d.size(); ++b)
                                        if (d[a] >= 0 && d[b] >= 0) entries.emplace_back(d[a], d[b], A(a, b));
                            });
    SparseMatrix K(dofs.n_dofs, dofs.n_dofs);
    K.setFromTriplets(entries.begin(), entries.end());
    return K;
}

double max_abs(const Eigen::VectorXd& v) { return v.size() ? v.cwiseAbs().maxCoeff() : 0.0; }

double infinity_norm(const SparseMatrix& K) {
    Eigen::VectorXd rows = Eigen::VectorXd::Zero(K.rows());
    for (int k = 0; k < K.outerSize(); ++k)
        for (SparseMatrix::InnerIterator it(K, k); it; ++it) rows[it.row()] += std::abs(it.value());
    return max_abs(rows);
}

// The DOF to hold for each rigid motion (along z, about z) that K leaves
// free: where the motion is largest.
std::vector<int> dofs_to_hold(const SparseMatrix& K, const SectionMesh& mesh, const HarmonicDofs& dofs) {
    std::vector<int> held;
    const double norm = infinity_norm(K);
    for (RigidMotion motion : {RigidMotion::z, RigidMotion::rz}) {
        const std::vector<double> field = harmonic_rigid_field(mesh, dofs, 0, motion);
        const Eigen::Map<const Eigen::VectorXd> r(field.data(), static_cast<Eigen::Index>(field.size()));
        if (max_abs(r) == 0 || max_abs(K * r) > kRigidTolerance * norm * max_abs(r)) continue;
        Eigen::Index at;
        r.cwiseAbs().maxCoeff(&at);
        held.push_back(static_cast<int>(at));
    }
    return held;
}

// K with the rows and columns of `held` replaced by a unit diagonal scaled like K.
SparseMatrix with_held(SparseMatrix K, const std::vector<int>& held) {
    if (held.empty()) return K;
    const double diagonal = K.diagonal().cwiseAbs().maxCoeff();
    const auto is_held = [&](Eigen::Index i) { return std::find(held.begin(), held.end(), i) != held.end(); };
    K.prune([&](Eigen::Index i, Eigen::Index j, double) { return !is_held(i) && !is_held(j); });
    for (int d : held) K.coeffRef(d, d) = diagonal;
    return K;
}

}  // namespace

CentrifugalPrestress centrifugal_prestress(const Scene& scene, const SectionMesh& mesh,
                                           const std::vector<PartMaterial>& materials) {
    const HarmonicDofs dofs = harmonic_dofs(scene, mesh, 0);
    const SparseMatrix K = stiffness_at_rest(scene, mesh, materials, dofs);
    const std::vector<double> load = assemble_harmonic_centrifugal_load(mesh, materials, dofs);
    Eigen::VectorXd f = Eigen::Map<const Eigen::VectorXd>(load.data(), static_cast<Eigen::Index>(load.size()));
    const std::vector<int> held = dofs_to_hold(K, mesh, dofs);
    for (int d : held) f[d] = 0;

    Eigen::SimplicialLDLT<SparseMatrix> factor(with_held(K, held));
    if (factor.info() != Eigen::Success)
        throw SolveError("the centrifugal prestress: the axisymmetric stiffness could not be factored (a part that "
                         "nothing holds?)");
    const Eigen::VectorXd u = factor.solve(f);
    CentrifugalPrestress out;
    out.held_rigid_motions = static_cast<int>(held.size());
    out.relative_residual = (K * u - f).norm() / f.norm();
    if (!(out.relative_residual <= kMaxStaticResidual))
        throw SolveError("the centrifugal prestress: the static solve's relative residual is " +
                         std::to_string(out.relative_residual) + " (a part that nothing holds?)");
    out.displacement.assign(u.data(), u.data() + u.size());
    out.stress = harmonic_section_stress(mesh, materials, dofs, out.displacement);
    return out;
}

}  // namespace coremodal
