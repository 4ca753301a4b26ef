#include "beam/rotating_modes.hpp"

#include "common/error.hpp"
#include "effects/rotation.hpp"
#include "eigensolve/rigid_modes.hpp"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>

namespace coremodal {
namespace {

using cd = std::complex<double>;

bool has_bending(FamilySet set) {
    return set & (family_bit(MotionFamily::bending_xz) | family_bit(MotionFamily::bending_yz));
}

// The independent family sets with every set that bends merged into one: G
// couples x-z with y-z bending.
std::vector<FamilySet> rotating_sets(const BeamNetwork& net) {
    std::vector<FamilySet> out;
    FamilySet bending = 0;
    for (FamilySet s : independent_family_sets(net)) {
        if (has_bending(s))
            bending |= s;
        else
            out.push_back(s);
    }
    if (bending) out.insert(out.begin(), bending);
    return out;
}

double max_column_sum(const Eigen::SparseMatrix<double>& A) {
    double norm = 0;
    for (Eigen::Index k = 0; k < A.outerSize(); ++k) {
        double sum = 0;
        for (Eigen::SparseMatrix<double>::InnerIterator it(A, k); it; ++it) sum += std::abs(it.value());
        norm = std::max(norm, sum);
    }
    return norm;
}

// Per network DOF, zero where the problem has no row.
Eigen::VectorXcd to_network(const std::vector<int>& free_dofs, const Eigen::VectorXcd& rows, size_t n_network) {
    Eigen::VectorXcd out = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(n_network));
    for (size_t r = 0; r < free_dofs.size(); ++r) out(free_dofs[r]) = rows(static_cast<Eigen::Index>(r));
    return out;
}

double circularity(const Eigen::VectorXcd& x) {
    double turn = 0, size = 0;
    for (Eigen::Index d = 0; d + beam_dof::per_node <= x.size(); d += beam_dof::per_node) {
        const cd ux = x(d + beam_dof::ux), uy = x(d + beam_dof::uy);
        turn += 2 * std::imag(ux * std::conj(uy));
        size += std::norm(ux) + std::norm(uy);
    }
    return size > 0 ? turn / size : 0.0;
}

// Quadratic Lagrange shape functions on [0, 1] and the 3-point Gauss rule
// (as in timoshenko_element.cpp: the rotary mass's integration).
constexpr std::array<double, 3> kGaussX = {0.5 - 0.38729833462074170, 0.5, 0.5 + 0.38729833462074170};
constexpr std::array<double, 3> kGaussW = {5.0 / 18, 8.0 / 18, 5.0 / 18};

}  // namespace

BeamElementMatrix element_gyroscopic(const TimoshenkoElement& e) {
    COREMODAL_ASSERT(e.length > 0 && e.section.rho_J > 0);
    const Eigen::Matrix2d g = Gyroscopic::per_length(e.section.rho_J);
    BeamElementMatrix G = BeamElementMatrix::Zero();
    const int r[2] = {beam_dof::rx, beam_dof::ry};
    for (size_t q = 0; q < kGaussX.size(); ++q) {
        const Eigen::RowVector3d N = element_shape(kGaussX[q]);
        for (int a = 0; a < kElementNodes; ++a)
            for (int b = 0; b < kElementNodes; ++b)
                for (int i = 0; i < 2; ++i)
                    for (int j = 0; j < 2; ++j)
                        G(beam_dof::per_node * a + r[i], beam_dof::per_node * b + r[j]) +=
                            kGaussW[q] * e.length * N(a) * N(b) * g(i, j);
    }
    return G;
}

std::vector<Eigen::SparseMatrix<double>> assemble_gyroscopic(const BeamNetwork& net,
                                                             const std::vector<NetworkMatrices>& problems) {
    std::vector<int> problem(net.held.size(), -1), row(net.held.size(), -1);
    for (size_t p = 0; p < problems.size(); ++p)
        for (size_t r = 0; r < problems[p].free_dofs.size(); ++r) {
            problem[problems[p].free_dofs[r]] = static_cast<int>(p);
            row[problems[p].free_dofs[r]] = static_cast<int>(r);
        }
    std::vector<std::vector<Eigen::Triplet<double>>> triplets(problems.size());
    for (const BeamNetwork::Beam& beam : net.beams)
        for (size_t e = 0; e < beam.sections.size(); ++e) {
            const int n0 = beam.nodes[2 * e], n2 = beam.nodes[2 * e + 2];
            const BeamElementMatrix G = element_gyroscopic({net.node_z[n2] - net.node_z[n0], beam.sections[e]});
            const int nodes[kElementNodes] = {n0, beam.nodes[2 * e + 1], n2};
            for (int i = 0; i < kElementDofs; ++i)
                for (int j = 0; j < kElementDofs; ++j) {
                    if (G(i, j) == 0.0) continue;
                    const int di = beam_dof::per_node * nodes[i / beam_dof::per_node] + i % beam_dof::per_node;
                    const int dj = beam_dof::per_node * nodes[j / beam_dof::per_node] + j % beam_dof::per_node;
                    if (problem[di] < 0 || problem[di] != problem[dj]) continue;  // held, or another problem
                    triplets[problem[di]].emplace_back(row[di], row[dj], G(i, j));
                }
        }
    std::vector<Eigen::SparseMatrix<double>> out(problems.size());
    for (size_t p = 0; p < problems.size(); ++p) {
        const auto n = static_cast<Eigen::Index>(problems[p].free_dofs.size());
        out[p].resize(n, n);
        out[p].setFromTriplets(triplets[p].begin(), triplets[p].end());
    }
    return out;
}

const char* whirl_name(Whirl w) {
    switch (w) {
        case Whirl::forward: return "FW";
        case Whirl::backward: return "BW";
        case Whirl::none: return "";
    }
    return "";
}

double complex_mac(const Eigen::VectorXcd& x, const Eigen::VectorXcd& y) {
    const double xx = x.squaredNorm(), yy = y.squaredNorm();
    if (xx == 0 || yy == 0) return 0;
    return std::norm(x.dot(y)) / (xx * yy);
}

RotatingNetwork::RotatingNetwork(const BeamNetwork& network, double lambda_scale)
    : network_(&network), lambda_scale_(lambda_scale) {
    const std::vector<FamilySet> sets = rotating_sets(network);
    std::vector<NetworkMatrices> systems = assemble_problems(network, sets);
    std::vector<Eigen::SparseMatrix<double>> gyro = assemble_gyroscopic(network, systems);
    for (size_t s = 0; s < sets.size(); ++s) {
        Problem p;
        p.m = std::move(systems[s]);
        p.G = std::move(gyro[s]);
        p.spins = p.G.nonZeros() > 0 && p.G.cwiseAbs().sum() > 0;
        if (p.m.K.rows() == 0) continue;
        // M x = mu (K - sigma M) x with the negative shift of the solver at
        // rest (positive definite even with rigid modes): mu = 1 / (lambda -
        // sigma) is largest for the lowest modes, which the dense solve then
        // gets to round-off relative to themselves, not to the highest mode.
        const double sigma = -0.5 * lambda_scale;
        const Eigen::MatrixXd K(p.m.K), M(p.m.M);
        Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(M, K - sigma * M);
        if (solver.info() != Eigen::Success)
            throw SolveError("the rotating beam network's K - sigma M is not positive definite (a free DOF without "
                             "mass or stiffness)");
        const Eigen::Index n = K.rows();
        p.lambda.resize(n);
        p.Phi.resize(n, n);
        for (Eigen::Index j = 0; j < n; ++j) {  // ascending lambda: descending mu
            const Eigen::Index from = n - 1 - j;
            p.lambda(j) = sigma + 1.0 / solver.eigenvalues()(from);
            const Eigen::VectorXd x = solver.eigenvectors().col(from);
            p.Phi.col(j) = x / std::sqrt(x.dot(M * x));
        }
        if (p.spins) p.Ghat = p.Phi.transpose() * (p.G * p.Phi);
        p.norm_K = max_column_sum(p.m.K), p.norm_M = max_column_sum(p.m.M), p.norm_G = max_column_sum(p.G);
        n_free_dofs_ += static_cast<long>(p.m.K.rows());
        problems_.push_back(std::move(p));
    }
}

RotatingMode RotatingNetwork::finish(const Problem& p, const Eigen::VectorXcd& eta_in, double omega,
                                     double omega_spin) const {
    RotatingMode mode;
    mode.frequency_hz = omega / (2 * M_PI);
    const Eigen::VectorXcd eta = eta_in / eta_in.norm();  // x^H M x = eta^H eta = 1
    const Eigen::VectorXcd x = p.Phi.cast<cd>() * eta;
    const Eigen::SparseMatrix<cd> K = p.m.K.cast<cd>(), M = p.m.M.cast<cd>(), G = p.G.cast<cd>();
    const Eigen::VectorXcd r = K * x + cd(0, omega * omega_spin) * (G * x) - omega * omega * (M * x);
    mode.relative_residual =
        r.norm() / ((p.norm_K + omega * omega_spin * p.norm_G + omega * omega * p.norm_M) * x.norm());
    const size_t n_network = network_->held.size();
    mode.shape = to_network(p.m.free_dofs, x, n_network);
    mode.circularity = circularity(mode.shape);
    // The label of the largest real snapshot Re(x e^{i a}): 2a = -arg(sum x_d^2).
    const cd phase = std::polar(1.0, -0.5 * std::arg(x.cwiseProduct(x).sum()));
    const Eigen::VectorXd snapshot = (x * phase).real();
    const Eigen::VectorXd mass_snapshot = p.m.M * snapshot;
    Eigen::VectorXd shape = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n_network));
    Eigen::VectorXd mass_shape = shape;
    for (size_t row = 0; row < p.m.free_dofs.size(); ++row) {
        shape(p.m.free_dofs[row]) = snapshot(static_cast<Eigen::Index>(row));
        mass_shape(p.m.free_dofs[row]) = mass_snapshot(static_cast<Eigen::Index>(row));
    }
    mode.label = label_beam_mode(*network_, shape, mass_shape, omega * omega, lambda_scale_);
    const bool lateral = mode.label.type == "bending" || mode.label.type == "mixed";
    if (lateral && std::abs(mode.circularity) > kPlanarCircularity)
        mode.whirl = mode.circularity > 0 ? Whirl::forward : Whirl::backward;
    return mode;
}

void RotatingNetwork::add_candidates(const Problem& p, double omega_spin, std::vector<Candidate>& out) const {
    const double rigid = kRigidEigenvalueFraction * lambda_scale_;
    const Eigen::Index n = p.lambda.size();
    for (Eigen::Index j = 0; j < n; ++j)  // rigid: K phi = 0 solves the quadratic problem at omega = 0
        if (std::abs(p.lambda(j)) < rigid) out.push_back({&p, 0.0, Eigen::VectorXcd::Unit(n, j)});
    if (!p.spins || omega_spin == 0) {
        for (Eigen::Index j = 0; j < n; ++j)
            if (std::abs(p.lambda(j)) >= rigid)
                out.push_back({&p, std::sqrt(std::max(p.lambda(j), 0.0)), Eigen::VectorXcd::Unit(n, j)});
        return;
    }
    const Eigen::VectorXd root = p.lambda.cwiseMax(0.0).cwiseSqrt();
    Eigen::MatrixXcd H = Eigen::MatrixXcd::Zero(2 * n, 2 * n);
    H.topLeftCorner(n, n) = cd(0, omega_spin) * p.Ghat.cast<cd>();
    H.topRightCorner(n, n).diagonal() = root.cast<cd>();
    H.bottomLeftCorner(n, n).diagonal() = root.cast<cd>();
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXcd> solver(H);
    if (solver.info() != Eigen::Success) throw SolveError("the rotating beam network's eigensolver did not converge");
    const double omega_rigid = std::sqrt(rigid);
    for (Eigen::Index k = 0; k < 2 * n; ++k) {
        const double omega = solver.eigenvalues()(k);
        if (omega < omega_rigid) continue;
        // z = (omega eta, Lambda^1/2 eta): eta is the first half, up to the factor omega.
        out.push_back({&p, omega, solver.eigenvectors().col(k).head(n)});
    }
}

std::vector<RotatingMode> RotatingNetwork::modes_at(double speed_hz, int max_modes) const {
    COREMODAL_ASSERT(speed_hz >= 0 && max_modes >= 0);
    const double omega_spin = 2 * M_PI * speed_hz;
    std::vector<Candidate> candidates;
    for (const Problem& p : problems_) add_candidates(p, omega_spin, candidates);
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return a.omega < b.omega; });
    if (candidates.size() > static_cast<size_t>(max_modes)) candidates.resize(max_modes);
    std::vector<RotatingMode> out;
    for (const Candidate& c : candidates) out.push_back(finish(*c.problem, c.eta, c.omega, omega_spin));
    return out;
}

}  // namespace coremodal
