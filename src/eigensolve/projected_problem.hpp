// The small problem of ProjectedGyroscopic in its basis (ProjectedGyroscopic::Basis):
// the terms projected once, the candidates at a speed from the Hermitian
// linearization, their residuals on the full problem, their orthogonality,
// and the inertia counts with their gap certificates (header
// projected_gyroscopic.hpp, docs/theory/rotation-harmonic.md). Private to
// projected_gyroscopic.cpp, the one file that includes it; apart so that
// the solver's steps (build, modes at a speed, the rigid line) read on
// their own.
#pragma once

#include "eigensolve/projected_gyroscopic.hpp"

#include "common/error.hpp"
#include "common/log_event.hpp"
#include "eigensolve/gyroscopic_inertia.hpp"
#include "eigensolve/petsc_algebra.hpp"
#include "eigensolve/projection_basis.hpp"
#include "eigensolve/tolerances.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>

namespace coremodal {
namespace {

// Counting at fewer speeds (header, docs/theory/rotation-harmonic.md). The bound gamma is
// guessed from the projected term (its largest |eigenvalue| in the basis, a
// lower bound of the full term's), times kBoundMargin, and doubled up to
// kBoundTries times until the inertia count proves it (the margin keeps
// gamma M -+ i G away from singular, where the LDL^T's signs would be
// round-off). A certificate's gap delta is this fraction of the
// distance, in omega^2, from the count's point to the nearest candidate
// (the candidates are approximations; the two counts decide), and one is
// made only where the bound predicts it covers kMinCertifiedSteps more
// speeds of the sweep's step: it costs two counts where a speed costs one.
constexpr double kBoundMargin = 1.25;
constexpr int kBoundTries = 4;
constexpr double kGapFraction = 0.5;
constexpr double kMinCertifiedSteps = 3;

using Dense = Eigen::MatrixXd;
using Complex = std::complex<double>;

struct ProjectedCandidate {
    double omega = 0;
    Eigen::VectorXcd y;  // in the basis, |y| = 1: x = V y, x^H M x = 1
    // One family's basis (mirrored families): +1 a forward mode x = (f, -i f) / sqrt 2,
    // -1 a backward one x = (f, i f) / sqrt 2, f = V y; 0 in the whole set's basis.
    int sign = 0;
};

// The eigenvalues omega^2 of the candidates, ascending as they are: what
// eigensolve/band_edge.hpp's report and count rule reads.
std::vector<double> squared_omegas(const std::vector<ProjectedCandidate>& c) {
    std::vector<double> lambdas;
    for (const ProjectedCandidate& x : c) lambdas.push_back(x.omega * x.omega);
    return lambdas;
}

// K(Omega) + omega_0^2 M, the count's premise (gyroscopic_solver.hpp).
GyroscopicInertia::Combination stiffness_at(double spin, double rigid_omega) {
    return {1.0, spin * spin, rigid_omega * rigid_omega, 0.0};
}

}  // namespace

struct ProjectedGyroscopic::Basis {
    SolveRequest request;
    double rigid_omega = 0;
    bool centrifugal = false;
    // Mirrored families (gyroscopic_inertia.hpp, 1): the basis is one
    // family's, and G below is the projected coupling Gab (symmetric).
    bool family = false;
    std::vector<PetscInt> first_rows, second_rows;  // where the families sit in a vector of the set
    Dense V;                     // N x m, M-orthonormal
    Dense K0, K_omega, G;        // projected: K + K_sigma, K_Omega, G (or Gab)
    Eigen::MatrixXd R;           // of W = [V, K0 V, (K_Omega V), M V, G V] = Q_W R
    double norm_K0 = 0, norm_G = 0, norm_M = 0;
    PetscMatrix k0_union, k_omega_union, k_work;  // for ||K(Omega)||_1 with a centrifugal term
    Mat K_template = nullptr;    // for vectors of the set's layout
    std::unique_ptr<GyroscopicInertia> inertia;
    double rigid_line_clear_up_to = -1;  // rad/s: neg Q(omega_0) = 0 proven for spins up to it
    // Counting at fewer speeds (header): the proven bounds (gamma < 0: none),
    // the certificates made so far and the last speed counted.
    double gamma = -1, kappa = 0;
    struct Certificate {
        double spin, omega, delta;
        long count;
    };
    mutable std::vector<Certificate> certificates;
    mutable double last_spin = -1;
    mutable CountStatistics stats;
    double stiffness_clear_up_to = -1;   // rad/s: K(Omega) + omega_0^2 M >= 0 proven for spins up to it

    Eigen::Index m() const { return V.cols(); }

    // 3. Every term projected once, and the R factor of the residual's columns
    // (the operators: K + K_sigma, K_Omega or null, M, G, as the basis was built from).
    void project(Mat k0_op, Mat k_omega_op, Mat m_op, Mat g_op, PetscInt n_dofs) {
        std::vector<Dense> columns{V, apply_columns(k0_op, V)};
        K0 = V.transpose() * columns.back();
        K_omega = Dense::Zero(m(), m());
        if (centrifugal) {
            columns.push_back(apply_columns(k_omega_op, V));
            K_omega = V.transpose() * columns.back();
        }
        columns.push_back(apply_columns(m_op, V));
        columns.push_back(apply_columns(g_op, V));
        G = V.transpose() * columns.back();
        G = family ? Dense(0.5 * (G + G.transpose())) : Dense(0.5 * (G - G.transpose()));
        Dense W(n_dofs, m() * columns.size());
        for (size_t k = 0; k < columns.size(); ++k) W.middleCols(k * m(), m()) = columns[k];
        columns.clear();
        // R is W's upper trapezoidal factor: as many rows as W has columns, or as
        // it has rows when a small problem has fewer DOFs than W has columns
        // (||W c|| = ||R c|| either way).
        const LogEvent qr_event("CmProjQR");
        R = Eigen::HouseholderQR<Dense>(W).matrixQR().topRows(std::min(W.rows(), W.cols())).triangularView<Eigen::Upper>();
    }

    // 4. The norms of the residual's scale.
    void residual_norms(Mat k0_op, Mat k_omega_op, Mat m_op, Mat g_op) {
        norm_K0 = norm_1(k0_op);
        norm_G = norm_1(g_op);
        norm_M = norm_1(m_op);
        if (centrifugal) {
            COREMODAL_PETSC(MatDuplicate(k0_op, MAT_COPY_VALUES, k0_union.out()));
            COREMODAL_PETSC(MatAXPY(k0_union, 1.0, k_omega_op, DIFFERENT_NONZERO_PATTERN));
            COREMODAL_PETSC(MatDuplicate(k0_union, MAT_DO_NOT_COPY_VALUES, k_omega_union.out()));
            COREMODAL_PETSC(MatZeroEntries(k0_union));  // the union's pattern, then k0_op's values on it
            COREMODAL_PETSC(MatAXPY(k0_union, 1.0, k0_op, SUBSET_NONZERO_PATTERN));
            COREMODAL_PETSC(MatZeroEntries(k_omega_union));
            COREMODAL_PETSC(MatAXPY(k_omega_union, 1.0, k_omega_op, SUBSET_NONZERO_PATTERN));
            COREMODAL_PETSC(MatDuplicate(k0_union, MAT_DO_NOT_COPY_VALUES, k_work.out()));
        }
    }

    double norm_K(double spin) const {
        if (!centrifugal || spin == 0) return norm_K0;
        COREMODAL_PETSC(MatCopy(k0_union, k_work, SAME_NONZERO_PATTERN));
        COREMODAL_PETSC(MatAXPY(k_work, spin * spin, k_omega_union, SAME_NONZERO_PATTERN));
        return norm_1(k_work);
    }

    // ||Q(omega) x|| / ((||K(Omega)|| + omega Omega ||G|| + omega^2 ||M||) ||x||) for x = V y (header),
    // `norm_K_at_spin` = norm_K(spin). In one family's basis Q x = 0 is
    // (K(Omega) - omega^2 M + sign omega Omega Gab) f = 0 with ||Q x|| = ||that||
    // and ||x|| = ||f|| (U of gyroscopic_inertia.hpp is unitary), and the
    // 1-norms of K, M and G are those of S, M_S and Gab (block diagonal; G's
    // columns each hold one block of Gab).
    double relative_residual(double spin, double omega, const ProjectedCandidate& x, double norm_K_at_spin) const {
        const Eigen::VectorXcd& y = x.y;
        const Eigen::Index n = m(), blocks = R.cols() / n;
        Eigen::VectorXcd c = Eigen::VectorXcd::Zero(R.cols()), cx = Eigen::VectorXcd::Zero(R.cols());
        Eigen::Index b = 1;
        c.segment(b++ * n, n) = y;
        if (centrifugal) c.segment(b++ * n, n) = spin * spin * y;
        c.segment(b++ * n, n) = -omega * omega * y;
        c.segment(b++ * n, n) = (family ? Complex(x.sign * omega * spin, 0) : Complex(0, omega * spin)) * y;
        COREMODAL_ASSERT(b == blocks);
        cx.head(n) = y;
        const auto upper = R.triangularView<Eigen::Upper>();
        const auto norm = [&](const Eigen::VectorXcd& v) {
            return std::hypot((upper * v.real()).norm(), (upper * v.imag()).norm());
        };
        return norm(c) / ((norm_K_at_spin + omega * spin * norm_G + omega * omega * norm_M) * norm(cx));
    }

    // The modes of the small problem, ascending: the rigid ones at 0 Hz,
    // then every eigenvalue omega >= the rigid line of the Hermitian
    // linearization H = [[i Omega G, Lambda^1/2], [Lambda^1/2, 0]]
    // (docs/theory/rotation-harmonic.md). H's eigenvalues below the line come in pairs
    // +-omega (a rigid direction's zero twice at rest; a free body's tilt at
    // 0 and its precession at +-omega once it spins); each pair is one mode
    // of the quadratic problem, as the full solver reports it, and a rigid
    // direction of K(Omega) is exactly one (Q(0) x = K(Omega) x = 0), so the
    // first ones stand for them.
    std::vector<ProjectedCandidate> candidates(double spin) const {
        return family ? family_candidates(spin) : set_candidates(spin);
    }

    // K(Omega) in the basis, symmetrised, and its eigen-decomposition: the
    // linearizations below are written in its eigenvectors.
    Eigen::SelfAdjointEigenSolver<Dense> stiffness_eigen(double spin) const {
        const Dense K = K0 + spin * spin * K_omega;
        return Eigen::SelfAdjointEigenSolver<Dense>(0.5 * (K + K.transpose()));
    }

    std::vector<ProjectedCandidate> set_candidates(double spin) const {
        const Eigen::SelfAdjointEigenSolver<Dense> ks = stiffness_eigen(spin);
        const Dense& U = ks.eigenvectors();
        const Eigen::VectorXd& lambda = ks.eigenvalues();
        const Eigen::Index n = m();
        Eigen::MatrixXcd H = Eigen::MatrixXcd::Zero(2 * n, 2 * n);
        H.topLeftCorner(n, n) = Complex(0, spin) * (U.transpose() * G * U).cast<Complex>();
        for (Eigen::Index k = 0; k < n; ++k) H(k, n + k) = H(n + k, k) = std::sqrt(std::max(lambda[k], 0.0));
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> hs(H);
        const Eigen::VectorXd& omegas = hs.eigenvalues();
        const long below_line = (omegas.array().abs() < rigid_omega).count();
        const long rigid_directions = (lambda.array() < rigid_omega * rigid_omega).count();
        std::vector<ProjectedCandidate> out;
        for (Eigen::Index k = 0; k < std::min((below_line + 1) / 2, rigid_directions); ++k)
            out.push_back({0.0, U.col(k).cast<Complex>()});
        for (Eigen::Index j = 0; j < 2 * n; ++j) {
            if (omegas[j] < rigid_omega) continue;
            const Eigen::VectorXcd eta = hs.eigenvectors().col(j).head(n);  // z = (omega eta, Lambda^1/2 eta)
            out.push_back({omegas[j], (U.cast<Complex>() * eta).normalized()});
        }
        return out;
    }

    // One family's basis (mirrored families, gyroscopic_inertia.hpp): Q is
    // unitarily diag(A + B, A - B), A = K(Omega) - omega^2 M_S, B = omega Omega
    // Gab, and A - B at omega is A + B at -omega, so the modes are the real
    // eigenvalues omega of the real symmetric quadratic problem
    //     (K(Omega) + omega Omega Gab - omega^2 M_S) f = 0,
    // omega > 0 a forward mode (x = (f, -i f) / sqrt 2: Im(a . conj b) > 0,
    // spinning_harmonic.hpp) at omega, omega < 0 a backward one
    // (x = (f, i f) / sqrt 2) at |omega|. Its exact linearization, as the
    // beam level's planes alike (docs/theory/rotation-harmonic.md), is real symmetric of
    // twice the family basis' size: H = [[Omega Gab^, Lambda^1/2],
    // [Lambda^1/2, 0]] in the eigenvectors of K(Omega)^; a quarter of the
    // whole set's Hermitian H's size in complex arithmetic, some thirty
    // times less work. Each eigenvalue is one mode (the whole set's H has
    // it twice, +-omega). Below the rigid line: a rigid direction f of
    // K(Omega)^ stands for two rigid modes of the set, (f, -+i f) / sqrt 2,
    // as many as H has eigenvalues there, at most.
    std::vector<ProjectedCandidate> family_candidates(double spin) const {
        const Eigen::SelfAdjointEigenSolver<Dense> ks = stiffness_eigen(spin);
        const Dense& U = ks.eigenvectors();
        const Eigen::VectorXd& lambda = ks.eigenvalues();
        const Eigen::Index n = m();
        Dense H = Dense::Zero(2 * n, 2 * n);
        H.topLeftCorner(n, n) = spin * (U.transpose() * G * U);
        for (Eigen::Index k = 0; k < n; ++k) H(k, n + k) = H(n + k, k) = std::sqrt(std::max(lambda[k], 0.0));
        const Eigen::SelfAdjointEigenSolver<Dense> hs(H);
        const Eigen::VectorXd& omegas = hs.eigenvalues();
        const long below_line = (omegas.array().abs() < rigid_omega).count();
        const long rigid_directions = (lambda.array() < rigid_omega * rigid_omega).count();
        std::vector<ProjectedCandidate> out;
        for (Eigen::Index k = 0; k < std::min(below_line, 2 * rigid_directions); ++k)
            out.push_back({0.0, U.col(k / 2).cast<Complex>(), k % 2 == 0 ? +1 : -1});
        for (Eigen::Index j = 0; j < 2 * n; ++j) {
            if (std::abs(omegas[j]) < rigid_omega) continue;
            const Eigen::VectorXd eta = hs.eigenvectors().col(j).head(n);  // z = (omega eta, Lambda^1/2 eta)
            out.push_back({std::abs(omegas[j]), (U * eta).normalized().cast<Complex>(), omegas[j] > 0 ? +1 : -1});
        }
        return out;
    }

    // x_j^H ((omega_i + omega_j) M - i Omega G) x_i normalised, over elastic
    // modes of distinct frequency (gyroscopic_solver.hpp), in the basis. In
    // one family's basis, for two modes of one sign s, it is
    // (omega_i + omega_j) f_j^H f_i - s Omega f_j^H Gab f_i; of opposite signs zero.
    double orthogonality_error(double spin, const std::vector<ProjectedCandidate>& c, int n_report) const {
        const Eigen::MatrixXcd iG = Complex(0, spin) * G.cast<Complex>();
        const Eigen::MatrixXcd sG = spin * G.cast<Complex>();
        const auto product = [&](int j, int i) {
            if (!family) return Complex(c[j].y.dot((c[i].omega + c[j].omega) * c[i].y - iG * c[i].y));
            if (c[i].sign != c[j].sign) return Complex(0, 0);
            return Complex(c[j].y.dot((c[i].omega + c[j].omega) * c[i].y - double(c[i].sign) * (sG * c[i].y)));
        };
        double worst = 0;
        for (int i = 0; i < n_report; ++i)
            for (int j = 0; j < i; ++j) {
                const double wi = c[i].omega, wj = c[j].omega;
                if (wj < rigid_omega || (wi * wi - wj * wj) <= kClusterTolerance * wi * wi) continue;
                worst = std::max(worst, std::abs(product(j, i)) / std::sqrt(std::abs(product(i, i) * product(j, j))));
            }
        return worst;
    }

    // neg Q at the count's point and the modes found between the rigid line
    // and it: at the band edge `check` (one count), or at an earlier
    // certificate's point where Weyl's bound covers this speed (no count),
    // or at the band edge with a new certificate (two counts; three where
    // they differ). Only where the rigid line is proven clear (nothing to
    // subtract) and the bounds are proven; header and docs/theory/rotation-harmonic.md.
    struct Count {
        double point;
        long negative, found;
    };
    Count count_modes(double spin, const std::vector<ProjectedCandidate>& c, int n_report, double check,
                      double norm_K_at_spin) const {
        ++stats.speeds;
        const long found_reported = std::count_if(c.begin(), c.begin() + n_report,
                                                  [&](const ProjectedCandidate& x) { return x.omega >= rigid_omega; });
        const bool certifiable = gamma >= 0 && spin <= rigid_line_clear_up_to;
        const double step = last_spin >= 0 ? std::abs(spin - last_spin) : 0;
        last_spin = spin;
        if (!certifiable) {
            ++stats.counted;
            return {check, inertia->negative_count(spin, check), found_reported};
        }
        // The candidates below `point`, every one beyond the reported ones verified; or none.
        const auto found_below = [&](double point) -> std::optional<long> {
            long found = 0;
            for (size_t i = 0; i < c.size() && c[i].omega < point; ++i) {
                if (int(i) >= n_report && relative_residual(spin, c[i].omega, c[i], norm_K_at_spin) > kMaxProjectedResidual)
                    return std::nullopt;
                if (c[i].omega >= rigid_omega) ++found;
            }
            return found;
        };
        for (auto k = certificates.rbegin(); k != certificates.rend(); ++k) {
            if (k->omega <= c[n_report - 1].omega) continue;  // above the reported modes only
            const double moved =
                std::abs(spin * spin - k->spin * k->spin) * kappa + k->omega * std::abs(spin - k->spin) * gamma;
            if (moved >= k->delta) continue;
            if (const std::optional<long> found = found_below(k->omega)) {
                ++stats.certified;
                return {k->omega, k->count, *found};
            }
        }
        if (step > 0 && n_report < int(c.size())) {
            const double p2 = check * check, lo = c[n_report - 1].omega * c[n_report - 1].omega,
                         hi = c[n_report].omega * c[n_report].omega;
            const double delta = kGapFraction * std::min(p2 - lo, hi - p2);
            const double reach = kMinCertifiedSteps * step;
            const double moved = ((spin + reach) * (spin + reach) - spin * spin) * kappa + check * reach * gamma;
            if (delta > 0 && moved < delta) {
                ++stats.certificates;
                const long below = inertia->negative_count({1.0, spin * spin, -p2 + delta, check * spin});  // Q + delta M
                const long above = inertia->negative_count({1.0, spin * spin, -p2 - delta, check * spin});  // Q - delta M
                if (below == above) {
                    certificates.push_back({spin, check, delta, below});
                    return {check, below, found_reported};
                }
                ++stats.certificate_failed;
            }
        }
        ++stats.counted;
        return {check, inertia->negative_count(spin, check), found_reported};
    }

    // gamma and kappa of the header, proven by inertia counts (gamma < 0: not proven).
    void prove_bounds() {
        const auto largest = [](const Eigen::VectorXd& eigenvalues) { return eigenvalues.cwiseAbs().maxCoeff(); };
        const auto proven = [](double guess, const auto& holds) {
            for (int k = 0; k < kBoundTries; ++k, guess *= 2)
                if (holds(guess)) return guess;
            return -1.0;
        };
        // With a centrifugal term the bound kappa (kappa M -+ K_Omega >= 0)
        // enters too, and it is the worst vector's |x^H K_Omega x| / x^H M x:
        // the prestress's geometric stiffness on the mesh's shortest waves
        // makes it 10^3 to 10^4 on cases 07 and 08 (2.8e3 to 3.7e4, found by
        // doubling), where a sweep's step would need it below ~10; proving it
        // cost counts and no certificate ever followed (docs/theory/rotation-harmonic.md). So
        // certificates are made for sets without the term only (kappa = 0).
        if (centrifugal) return;
        const double k = 0;
        const Eigen::MatrixXcd iG = family ? G.cast<Complex>() : Eigen::MatrixXcd(Complex(0, 1) * G.cast<Complex>());
        const double g0 = kBoundMargin * std::max(largest(Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd>(iG).eigenvalues()), 1e-300);
        // gamma M - i G and gamma M + i G have one spectrum (complex conjugates, G real): one count.
        const double g = proven(g0, [&](double x) { return inertia->negative_count({0.0, 0.0, x, -1.0}) == 0; });
        if (g < 0) return;
        gamma = g;
        kappa = k;
        stats.gamma = g;
    }

    GyroscopicMode full_mode(const ProjectedCandidate& c, double relative_residual) const {
        GyroscopicMode mode;
        mode.omega = c.omega;
        mode.relative_residual = relative_residual;
        const Eigen::VectorXcd x = V * c.y;
        const auto fill = [&](PetscVector& part, const Eigen::VectorXd& values) {
            COREMODAL_PETSC(MatCreateVecs(K_template, part.out(), nullptr));
            PetscScalar* a;
            COREMODAL_PETSC(VecGetArray(part, &a));
            Eigen::Map<Eigen::VectorXd>(a, values.size()) = values;
            COREMODAL_PETSC(VecRestoreArray(part, &a));
        };
        const auto fill_families = [&](PetscVector& part, const Eigen::VectorXd& first, const Eigen::VectorXd& second) {
            COREMODAL_PETSC(MatCreateVecs(K_template, part.out(), nullptr));
            PetscScalar* a;
            COREMODAL_PETSC(VecGetArray(part, &a));
            for (size_t k = 0; k < first_rows.size(); ++k) a[first_rows[k]] = first[k];
            for (size_t k = 0; k < second_rows.size(); ++k) a[second_rows[k]] = second[k];
            COREMODAL_PETSC(VecRestoreArray(part, &a));
        };
        if (!family) {
            fill(mode.real, x.real());
            fill(mode.imag, x.imag());
            return mode;
        }
        // (f, -i s f) / sqrt 2 with f = p + i q: real parts (p, s q), imaginary (q, -s p), over sqrt 2.
        const double s = c.sign, r = 1 / std::sqrt(2.0);
        fill_families(mode.real, r * x.real(), s * r * x.imag());
        fill_families(mode.imag, r * x.imag(), -s * r * x.real());
        return mode;
    }
};

}  // namespace coremodal
