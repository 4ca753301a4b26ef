#include "beam/network_modes.hpp"

#include "common/error.hpp"
#include "eigensolve/tolerances.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <random>
#include <string>

namespace coremodal {
namespace {

using SparseMatrix = Eigen::SparseMatrix<double>;

// sigma = -kShiftFraction * lambda_scale: far enough below zero that rigid
// modes factor safely, near enough that the lowest elastic modes dominate.
constexpr double kShiftFraction = 0.1;
// Up to this many DOFs, or when the Krylov space would hold half of them,
// the dense solver is the faster one.
constexpr int kDenseLimit = 16;
// Lanczos: vectors added per step (2: exact pairs within one problem, such as
// two identical overhangs), and when the Ritz pairs are first checked: this
// many columns per wanted mode plus kExtraVectors (as a rule enough for a
// residual of 1e-10; each check is a dense eigensolve), then every time the
// space grew by a quarter.
constexpr int kBlockSize = 2;
constexpr int kColumnsPerMode = 3;
constexpr int kExtraVectors = 8;
// Random start vectors, fixed so that runs repeat bit for bit.
constexpr unsigned kStartSeed = 20261122;

// One independent eigenproblem; a mirrored one also stands for the y-z
// plane (uy = ux, rx = -ry).
struct Problem {
    NetworkMatrices system;
    bool mirrored = false;
    // Analysed once on the pattern K and M share; factored anew for each
    // shift (one use at a time: a count, or a Krylov run).
    std::unique_ptr<BandedLDLT> factor;

    Problem(NetworkMatrices m, bool mirror) : system(std::move(m)), mirrored(mirror), factor(new BandedLDLT) {
        COREMODAL_ASSERT(system.K.isCompressed() && system.M.isCompressed() &&
                         system.K.nonZeros() == system.M.nonZeros());
        factor->analyzePattern(system.K);
    }
    int multiplicity() const { return mirrored ? 2 : 1; }
    int size() const { return static_cast<int>(system.K.rows()); }

    // K - lambda M: the value arrays combined (one pattern).
    SparseMatrix shifted(double lambda) const {
        SparseMatrix A = system.K;
        Eigen::Map<Eigen::VectorXd>(A.valuePtr(), A.nonZeros()) -=
            lambda * Eigen::Map<const Eigen::VectorXd>(system.M.valuePtr(), system.M.nonZeros());
        return A;
    }
    const BandedLDLT& factored(double lambda) const {
        factor->factorize(shifted(lambda));
        return *factor;
    }
};

std::vector<Problem> make_problems(const BeamNetwork& net, bool& mirrored) {
    std::vector<FamilySet> sets = independent_family_sets(net);
    const auto xz = std::find(sets.begin(), sets.end(), family_bit(MotionFamily::bending_xz));
    const auto yz = std::find(sets.begin(), sets.end(), family_bit(MotionFamily::bending_yz));
    mirrored = xz != sets.end() && yz != sets.end() && bending_planes_alike(net);
    if (mirrored) sets.erase(yz);
    std::vector<NetworkMatrices> systems = assemble_problems(net, sets);
    std::vector<Problem> problems;
    for (size_t i = 0; i < sets.size(); ++i)
        if (systems[i].K.rows() > 0)
            problems.emplace_back(std::move(systems[i]), mirrored && sets[i] == family_bit(MotionFamily::bending_xz));
    std::stable_sort(problems.begin(), problems.end(), [](const Problem& a, const Problem& b) { return a.size() > b.size(); });
    return problems;
}

// Sylvester: the negative pivots of K - lambda M = the eigenvalues below lambda;
// nothing when a pivot is zero (the count would be ambiguous).
std::optional<long> negative_pivots(const BandedLDLT& factor) {
    if (factor.info() != Eigen::Success) return std::nullopt;
    const Eigen::VectorXd d = factor.vectorD();  // a copy: vectorD() returns by value
    if (!d.allFinite() || (d.array() == 0).any()) return std::nullopt;
    return static_cast<long>((d.array() < 0).count());
}

// ---- one problem -----------------------------------------------------------

struct ProblemModes {
    Eigen::VectorXd lambda;  // ascending
    Eigen::MatrixXd X;       // M-normalised columns
};

double matrix_norm(const SparseMatrix& A) {  // max column sum = max row sum (symmetric)
    double norm = 0;
    for (int col = 0; col < A.outerSize(); ++col) {
        double sum = 0;
        for (SparseMatrix::InnerIterator it(A, col); it; ++it) sum += std::abs(it.value());
        norm = std::max(norm, sum);
    }
    return norm;
}

// The dense solver works on the inverted pencil M x = mu (K - sigma M) x,
// mu = 1 / (lambda - sigma): solving (K, M) directly would give the lowest
// eigenvalues only to within rounding of the highest (eps lambda_max, which
// stiff steel chucks beside a paperboard core push to 1e-6 of the lowest);
// inverted, the lowest modes are the largest mu and keep their relative accuracy.
ProblemModes dense_modes(const Problem& p, int nev, double sigma) {
    // Equilibrated first (unit diagonal of A): steel next to paperboard
    // spreads the diagonal over many decades, which the Cholesky reduction
    // would otherwise pay for in accuracy.
    const SparseMatrix A_sparse = p.shifted(sigma);
    const Eigen::VectorXd scale = A_sparse.diagonal().cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd M = scale.asDiagonal() * Eigen::MatrixXd(p.system.M) * scale.asDiagonal();
    const Eigen::MatrixXd A = scale.asDiagonal() * Eigen::MatrixXd(A_sparse) * scale.asDiagonal();
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(M, A);
    if (solver.info() != Eigen::Success)
        throw SolveError("beam model: the dense eigensolver failed on a " + std::to_string(p.size()) +
                         "-DOF problem (is every free DOF given mass?)");
    // Largest mu first; the vectors come A-normalised, x^T M x = mu x^T A x = mu.
    const Eigen::VectorXd mu = solver.eigenvalues().tail(nev).reverse();
    const Eigen::MatrixXd X = scale.asDiagonal() * solver.eigenvectors().rightCols(nev).rowwise().reverse() *
                              mu.cwiseSqrt().cwiseInverse().asDiagonal();
    return {(sigma + mu.array().inverse()).matrix(), X};
}

// Block Lanczos with full reorthogonalisation on the shift-and-invert
// operator T = (K - sigma M)^-1 M, which is self-adjoint in the M inner
// product: V is an M-orthonormal basis of the block Krylov space, and the
// Gram-Schmidt coefficients of T V are the projected operator
// H = V^T M T V, so Rayleigh-Ritz needs no product with K. A Ritz pair
// (theta, y) of T is the pair (sigma + 1/theta, y) of (K, M).
class ShiftInvertLanczos {
public:
    ShiftInvertLanczos(const Problem& p, const BandedLDLT& factor, int capacity)
        : M_(p.system.M), factor_(factor), n_(p.size()), w_(n_), Mw_(n_), h_(n_) {
        reserve(capacity);
        for (int j = 0; j < kBlockSize && k_ < n_; ++j) add_column(random_vector(), kNotAnImage);
    }

    int size() const { return k_; }
    // Columns whose image under T is in H; the Ritz pairs live on these.
    int processed() const { return processed_; }

    // Images of the oldest block not yet processed, orthogonalised into the basis.
    void extend() {
        const int b = std::min(kBlockSize, k_ - processed_);
        const Eigen::MatrixXd W = factor_.solve(MV_.middleCols(processed_, b));
        for (int j = 0; j < b && k_ < n_; ++j) add_column(W.col(j), processed_ + j);
        processed_ += b;
    }

    // The nev largest Ritz values theta of T on the processed columns, their
    // vectors, and the norm of the part of T y outside the processed span
    // relative to theta (zero when the space is invariant).
    struct Ritz {
        Eigen::VectorXd theta;
        Eigen::MatrixXd X;
        double worst_estimate;
    };
    Ritz ritz(int nev) const {
        const int m = processed_;
        const Eigen::MatrixXd Hm = H_.topLeftCorner(m, m);
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(0.5 * (Hm + Hm.transpose()));
        const Eigen::MatrixXd S = solver.eigenvectors().rightCols(nev).rowwise().reverse();
        const Eigen::VectorXd theta = solver.eigenvalues().tail(nev).reverse();
        const Eigen::MatrixXd outside = H_.block(m, 0, k_ - m, m) * S;
        const double worst = (outside.colwise().norm().transpose().array() / theta.array().abs()).maxCoeff();
        return {theta, V_.leftCols(m) * S, k_ > m ? worst : 0.0};
    }

private:
    // Below this share of its length before orthogonalisation a column
    // carries no new direction; a second Gram-Schmidt pass is needed when
    // the first one removes more than 1 - kReorthogonalise of it (DGKS).
    static constexpr double kBreakdown = 1e-8;
    static constexpr double kReorthogonalise = 0.7071;

    void reserve(int columns) {
        const Eigen::Index capacity = std::min<Eigen::Index>(n_, columns);
        if (capacity <= V_.cols()) return;
        V_.conservativeResize(n_, capacity);
        MV_.conservativeResize(n_, capacity);
        H_.conservativeResizeLike(Eigen::MatrixXd::Zero(capacity, capacity));
    }

    Eigen::VectorXd random_vector() {
        return Eigen::VectorXd::NullaryExpr(n_, [this](Eigen::Index) { return normal_(random_); });
    }

    // Orthogonalises w into the basis. When w is T times column `image_of`,
    // that column of H takes its components, the new column's included.
    static constexpr int kNotAnImage = -1;
    void add_column(const Eigen::Ref<const Eigen::VectorXd>& w_in, int image_of) {
        if (k_ + 1 > V_.cols()) reserve(std::max<int>(k_ + 1, 2 * static_cast<int>(V_.cols())));
        w_ = w_in;
        h_.head(k_).setZero();
        double before = w_.norm();
        for (int pass = 0; pass < 2; ++pass) {
            const Eigen::VectorXd c = MV_.leftCols(k_).transpose() * w_;
            w_.noalias() -= V_.leftCols(k_) * c;
            h_.head(k_) += c;
            const double after = w_.norm();
            if (after > kReorthogonalise * before) break;
            before = after;
        }
        if (image_of != kNotAnImage) H_.col(image_of).head(k_) = h_.head(k_);
        if (w_.norm() <= kBreakdown * w_in.norm()) {  // invariant subspace: go on with a fresh direction
            add_column(random_vector(), kNotAnImage);
            return;
        }
        Mw_.noalias() = M_ * w_;
        const double length = std::sqrt(w_.dot(Mw_));
        if (image_of != kNotAnImage) H_(k_, image_of) = length;
        V_.col(k_) = w_ / length;
        MV_.col(k_) = Mw_ / length;
        ++k_;
    }

    const SparseMatrix& M_;
    const BandedLDLT& factor_;
    int n_;
    Eigen::MatrixXd V_, MV_, H_;
    Eigen::VectorXd w_, Mw_, h_;  // workspace
    int k_ = 0, processed_ = 0;
    std::mt19937 random_{kStartSeed};
    std::normal_distribution<double> normal_;
};

// The nev lowest modes by shift-and-invert block Lanczos (sigma < 0 keeps the
// factor positive definite with rigid-body modes): the Krylov space grows
// until the wanted Ritz pairs have relative residuals below the tolerance,
// at the latest when it spans every DOF and Rayleigh-Ritz is exact. Blocks of
// two vectors find both members of an exactly degenerate pair; anything the
// space still misses, the inertia count catches.
ProblemModes krylov_modes(const Problem& p, int nev, const NetworkSolveRequest& r) {
    const int n = p.size();
    const double sigma = -kShiftFraction * r.lambda_scale;
    const BandedLDLT& factor = p.factored(sigma);
    if (factor.info() != Eigen::Success)
        throw SolveError("beam model: K - sigma M is singular at sigma = " + std::to_string(sigma) +
                         " (a part of the network without mass or stiffness?)");
    const double norm_K = matrix_norm(p.system.K);
    int check_at = std::min(n, kColumnsPerMode * nev + kExtraVectors);
    ShiftInvertLanczos lanczos(p, factor, check_at + 2 * kBlockSize);
    for (;;) {
        while (lanczos.processed() < check_at && lanczos.processed() < lanczos.size()) lanczos.extend();
        const ShiftInvertLanczos::Ritz ritz = lanczos.ritz(std::min(nev, lanczos.processed()));
        const bool exhausted = lanczos.processed() >= n;
        if (ritz.worst_estimate <= r.tolerance || exhausted) {
            ProblemModes modes{(sigma + ritz.theta.array().inverse()).matrix(), ritz.X};
            // The estimate is for T; the tolerance is for (K, M): check it.
            const Eigen::MatrixXd R = p.system.K * modes.X - (p.system.M * modes.X) * modes.lambda.asDiagonal();
            const double worst = (R.colwise().norm().array() / (norm_K * modes.X.colwise().norm().array())).maxCoeff();
            if (worst <= r.tolerance || exhausted) return modes;
        }
        check_at = std::min(n, lanczos.processed() + std::max(kBlockSize, lanczos.processed() / 4));
    }
}

ProblemModes lowest_modes(const Problem& p, int nev, const NetworkSolveRequest& r) {
    if (nev <= 0) return {Eigen::VectorXd(0), Eigen::MatrixXd(p.size(), 0)};
    const bool dense = r.force_dense || p.size() <= kDenseLimit ||
                       2 * (kColumnsPerMode * nev + kExtraVectors) >= p.size();
    return dense ? dense_modes(p, nev, -kShiftFraction * r.lambda_scale) : krylov_modes(p, nev, r);
}

// How many of a problem's eigenvalues lie below lambda; all of them when the
// factor cannot tell (the dense solver then finds every mode).
int modes_below(const Problem& p, double lambda) {
    const std::optional<long> count = negative_pivots(p.factored(lambda));
    return count ? static_cast<int>(*count) : p.size();
}

// ---- the whole network -------------------------------------------------------

double cluster_gap(double lambda, const NetworkSolveRequest& r) {
    return kClusterTolerance * std::max(std::abs(lambda), r.lambda_scale);
}

// Every problem's modes below one bound, and how many eigenvalues the
// inertia puts below it (the proof that none was missed).
struct Solution {
    std::vector<ProblemModes> found;
    double bound = std::numeric_limits<double>::infinity();
    long eigenvalues_below = 0;  // with multiplicity; all of them when the bound is infinite
};

// The bound: the top of a band; else a bound of the n-th lowest eigenvalue of
// the whole network, supplied by the largest problem that holds enough modes
// on its own. Every problem is then solved for its modes below the bound.
Solution solve_problems(const std::vector<Problem>& problems, const NetworkSolveRequest& r) {
    Solution s;
    s.found.resize(problems.size());
    if (r.lambda_max) {
        s.bound = *r.lambda_max;
    } else {
        for (size_t i = 0; i < problems.size() && !std::isfinite(s.bound); ++i) {
            const int need = (r.n_modes + problems[i].multiplicity() - 1) / problems[i].multiplicity();
            if (need > problems[i].size()) continue;
            s.found[i] = lowest_modes(problems[i], need, r);
            s.bound = s.found[i].lambda(need - 1) + cluster_gap(s.found[i].lambda(need - 1), r);
        }
    }
    for (size_t i = 0; i < problems.size(); ++i) {
        const int below = std::isfinite(s.bound) ? modes_below(problems[i], s.bound) : problems[i].size();
        s.eigenvalues_below += long(problems[i].multiplicity()) * below;
        const int nev = std::min(below, problems[i].size());
        if (s.found[i].lambda.size() < nev) s.found[i] = lowest_modes(problems[i], nev, r);
    }
    return s;
}

struct FoundMode {
    double lambda;
    int problem, column;
    bool mirror;
};

std::vector<FoundMode> merge(const std::vector<Problem>& problems, const Solution& s) {
    std::vector<FoundMode> all;
    for (size_t i = 0; i < problems.size(); ++i)
        for (int c = 0; c < s.found[i].lambda.size(); ++c)
            for (int copy = 0; copy < problems[i].multiplicity(); ++copy)
                all.push_back({s.found[i].lambda(c), int(i), c, copy == 1});
    std::stable_sort(all.begin(), all.end(), [](const FoundMode& a, const FoundMode& b) { return a.lambda < b.lambda; });
    return all;
}

// The reported modes: the band, or the lowest n_modes and the rest of the last cluster.
std::vector<FoundMode> select(const std::vector<FoundMode>& all, const NetworkSolveRequest& r) {
    std::vector<FoundMode> out;
    for (const FoundMode& m : all) {
        if (r.lambda_max) {
            if (m.lambda >= r.lambda_min.value_or(-std::numeric_limits<double>::infinity()) && m.lambda <= *r.lambda_max)
                out.push_back(m);
        } else if (int(out.size()) < r.n_modes || m.lambda - out.back().lambda <= cluster_gap(out.back().lambda, r)) {
            out.push_back(m);
        }
    }
    return out;
}

// Sylvester: as many modes found below the bound as the inertia counts.
Verification verify(const std::vector<Problem>& problems, const Solution& s, const std::vector<FoundMode>& all,
                    const NetworkSolveRequest& r) {
    Verification v;
    v.check_shift = std::isfinite(s.bound) ? s.bound
                    : all.empty()          ? 0.0
                                           : all.back().lambda + cluster_gap(all.back().lambda, r);
    v.negative_pivots_at_shift = s.eigenvalues_below;
    v.modes_below_shift = std::count_if(all.begin(), all.end(), [&](const FoundMode& m) { return m.lambda < v.check_shift; });
    v.complete = v.negative_pivots_at_shift == v.modes_below_shift;
    for (size_t i = 0; i < problems.size(); ++i) {
        const Eigen::Index n = s.found[i].lambda.size();
        if (n == 0) continue;
        const Eigen::MatrixXd& X = s.found[i].X;
        const Eigen::MatrixXd gram = X.transpose() * (problems[i].system.M * X) - Eigen::MatrixXd::Identity(n, n);
        v.max_orthonormality_error = std::max(v.max_orthonormality_error, gram.cwiseAbs().maxCoeff());
    }
    return v;
}

// A problem vector as a network vector; the mirror image lies in the y-z
// plane: uy = ux, rx = -ry.
Eigen::VectorXd network_vector(const Problem& p, const Eigen::VectorXd& x, bool mirror, Eigen::Index n_network) {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(n_network);
    for (int i = 0; i < p.size(); ++i) {
        const int d = p.system.free_dofs[i];
        if (!mirror) {
            v(d) = x(i);
            continue;
        }
        const bool translation = d % beam_dof::per_node == beam_dof::ux;
        v(d - d % beam_dof::per_node + (translation ? beam_dof::uy : beam_dof::rx)) = translation ? x(i) : -x(i);
    }
    return v;
}

}  // namespace

std::optional<long> count_eigenvalues_below(const SparseMatrix& K, const SparseMatrix& M, double lambda) {
    return negative_pivots(BandedLDLT(K - lambda * M));
}

NetworkModes solve_network_modes(const BeamNetwork& net, const NetworkSolveRequest& r) {
    COREMODAL_ASSERT(r.lambda_scale > 0 && r.n_modes > 0);
    NetworkModes out;
    const std::vector<Problem> problems = make_problems(net, out.mirrored_planes);
    out.n_problems = static_cast<int>(problems.size());
    for (const Problem& p : problems) out.n_free_dofs += long(p.multiplicity()) * p.size();

    Solution solution = solve_problems(problems, r);
    std::vector<FoundMode> all = merge(problems, solution);
    out.verification = verify(problems, solution, all, r);
    if (!out.verification.complete && !r.force_dense) {  // the one retry: every problem densely
        NetworkSolveRequest dense = r;
        dense.force_dense = true;
        out.dense_retry = true;
        solution = solve_problems(problems, dense);
        all = merge(problems, solution);
        out.verification = verify(problems, solution, all, r);
    }

    const Eigen::Index n_network = static_cast<Eigen::Index>(net.held.size());
    std::vector<double> norm_K;
    for (const Problem& p : problems) norm_K.push_back(matrix_norm(p.system.K));
    for (const FoundMode& m : select(all, r)) {
        const Problem& p = problems[m.problem];
        const Eigen::VectorXd x = solution.found[m.problem].X.col(m.column);
        const Eigen::VectorXd Mx = p.system.M * x;
        out.eigenvalues.push_back(m.lambda);
        out.shapes.push_back(network_vector(p, x, m.mirror, n_network));
        out.mass_shapes.push_back(network_vector(p, Mx, m.mirror, n_network));
        out.relative_residuals.push_back((p.system.K * x - m.lambda * Mx).norm() / (norm_K[m.problem] * x.norm()));
    }
    if (!out.relative_residuals.empty())
        out.verification.max_relative_residual =
            *std::max_element(out.relative_residuals.begin(), out.relative_residuals.end());
    return out;
}

}  // namespace coremodal
