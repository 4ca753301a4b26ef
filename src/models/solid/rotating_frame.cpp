#include "models/solid/rotating_frame.hpp"

#include "common/error.hpp"
#include "models/choose.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <set>

namespace coremodal {
namespace {

// A support spring is the same from every angle when it commutes with the
// rotation generator J node by node, to this share of its size (round-off
// of the springs' face integration).
constexpr double kIsotropicSupport = 1e-10;
// Surface nodes lie on the largest radius to this share of it.
constexpr double kSurfaceRadius = 1e-6;

// (I (x) B) for the 3x3 block B over n nodes, node-major.
Eigen::MatrixXd nodewise(const Eigen::Matrix3d& B, Eigen::Index n_nodes) {
    Eigen::MatrixXd T = Eigen::MatrixXd::Zero(3 * n_nodes, 3 * n_nodes);
    for (Eigen::Index a = 0; a < n_nodes; ++a) T.block<3, 3>(3 * a, 3 * a) = B;
    return T;
}

Eigen::Matrix3d generator_J() {
    Eigen::Matrix3d J;
    J << 0, -1, 0, 1, 0, 0, 0, 0, 0;  // J u = e_z x u
    return J;
}

// The block-diagonal matrix with B on every free node's 3x3 block.
PetscMatrix blockwise(Mat like, const Eigen::Matrix3d& B) {
    PetscInt n = 0, lo = 0, hi = 0;
    COREMODAL_PETSC(MatGetSize(like, &n, nullptr));
    COREMODAL_PETSC(MatGetOwnershipRange(like, &lo, &hi));
    PetscMatrix T;
    COREMODAL_PETSC(MatCreateAIJ(PetscObjectComm(reinterpret_cast<PetscObject>(like)), hi - lo, hi - lo, n, n, 3,
                                 nullptr, 0, nullptr, T.out()));
    for (PetscInt row = lo; row < hi; ++row) {
        const PetscInt first = row - row % 3;
        for (int c = 0; c < 3; ++c)
            if (B(row % 3, c) != 0) COREMODAL_PETSC(MatSetValue(T, row, first + c, B(row % 3, c), INSERT_VALUES));
    }
    COREMODAL_PETSC(MatAssemblyBegin(T, MAT_FINAL_ASSEMBLY));
    COREMODAL_PETSC(MatAssemblyEnd(T, MAT_FINAL_ASSEMBLY));
    return T;
}

PetscMatrix mass_times(Mat M, const Eigen::Matrix3d& B) {
    const PetscMatrix T = blockwise(M, B);
    PetscMatrix out;
    COREMODAL_PETSC(MatMatMult(M, T, MAT_INITIAL_MATRIX, PETSC_DEFAULT, out.out()));
    return out;
}

}  // namespace

std::optional<std::string> why_not_corotating(const Scene& scene) {
    if (const auto why = one_sided_contact_reason(scene))
        return *why + ": gravity and a contact closed on one side stay put while the roll turns, so neither frame "
                      "sees constant coefficients (a time-periodic problem)";
    return std::nullopt;
}

std::optional<std::string> anisotropic_support(const ChuckSupports& supports) {
    const std::set<int> grounded(supports.grounded.begin(), supports.grounded.end());
    for (const CouplingElement& e : supports.couplings) {
        const bool to_stand = std::any_of(e.nodes.begin(), e.nodes.end(), [&](int n) { return grounded.count(n) > 0; });
        const Eigen::MatrixXd& k = e.matrix(Term::stiffness);
        if (!to_stand || k.size() == 0) continue;
        const Eigen::MatrixXd T = nodewise(generator_J(), static_cast<Eigen::Index>(e.nodes.size()));
        if ((k * T - T * k).norm() > kIsotropicSupport * k.norm())
            return std::string("a support to the stand (a bearing or frame spring, or the web's span) differs in x and y");
    }
    return std::nullopt;
}

void add_rotating_frame_terms(OperatorSet& operators, const DofMap& dofs) {
    COREMODAL_ASSERT(dofs.n_dofs == 3 * dofs.n_free_nodes);  // whole nodes: 3 DOFs each, node-major
    PetscMatrix G = mass_times(operators.M(), generator_J());
    COREMODAL_PETSC(MatScale(G, 2.0));
    operators.matrices[Term::gyroscopic] = std::move(G);
    PetscMatrix M_P = mass_times(operators.M(), Eigen::Vector3d(1, 1, 0).asDiagonal().toDenseMatrix());
    if (operators.has(Term::centrifugal)) {
        COREMODAL_PETSC(MatAXPY(operators[Term::centrifugal], -1.0, M_P, DIFFERENT_NONZERO_PATTERN));
    } else {
        COREMODAL_PETSC(MatScale(M_P, -1.0));
        operators.matrices[Term::centrifugal] = std::move(M_P);
    }
    COREMODAL_PETSC(MatSetOption(operators[Term::centrifugal], MAT_SYMMETRIC, PETSC_TRUE));
}

std::vector<int> roll_surface_nodes(const Mesh& mesh, const std::vector<int>& roll_nodes) {
    const auto radius = [&](int n) { return std::hypot(mesh.nodes[n][0], mesh.nodes[n][1]); };
    double r_max = 0;
    for (int n : roll_nodes) r_max = std::max(r_max, radius(n));
    std::vector<int> out;
    for (int n : roll_nodes)
        if (radius(n) >= r_max * (1 - kSurfaceRadius)) out.push_back(n);
    return out;
}

WaveContent dominant_harmonic(const std::vector<double>& re, const std::vector<double>& im, const Mesh& mesh,
                              const std::vector<int>& surface, int max_k) {
    using C = std::complex<double>;
    std::vector<std::array<C, 3>> a(2 * max_k + 1, {C{}, C{}, C{}});
    for (int n : surface) {
        const double theta = std::atan2(mesh.nodes[n][1], mesh.nodes[n][0]);
        const double c = std::cos(theta), s = std::sin(theta);
        const C ux(re[3 * n], im[3 * n]), uy(re[3 * n + 1], im[3 * n + 1]), uz(re[3 * n + 2], im[3 * n + 2]);
        const std::array<C, 3> u = {c * ux + s * uy, -s * ux + c * uy, uz};  // (u_r, u_theta, u_z)
        for (int k = -max_k; k <= max_k; ++k) {
            const C phase = std::polar(1.0, -k * theta);
            for (int d = 0; d < 3; ++d) a[k + max_k][d] += u[d] * phase;
        }
    }
    WaveContent out;
    double total = 0, best = -1;
    for (int k = -max_k; k <= max_k; ++k) {
        const auto& ak = a[k + max_k];
        const double e = std::norm(ak[0]) + std::norm(ak[1]) + std::norm(ak[2]);
        total += e;
        if (e > best) best = e, out.k = k;
    }
    out.share = total > 0 ? best / total : 1.0;
    return out;
}

}  // namespace coremodal
