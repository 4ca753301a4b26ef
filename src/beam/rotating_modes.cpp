#include "beam/rotating_modes.hpp"

#include "common/error.hpp"
#include "effects/rotation.hpp"
#include "eigensolve/tolerances.hpp"

#include <Eigen/Eigenvalues>
#include <Eigen/SparseLU>

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

namespace {

// G of the x-z plane problem in u = ux + i uy (phi = ry - i rx): the rows ry
// of the spinning beams' element matrices, int rho_J N_a N_b (symmetric).
Eigen::SparseMatrix<double> plane_gyroscopic(const BeamNetwork& net, const NetworkMatrices& plane) {
    std::vector<int> row(net.held.size(), -1);
    for (size_t r = 0; r < plane.free_dofs.size(); ++r) row[plane.free_dofs[r]] = static_cast<int>(r);
    std::vector<Eigen::Triplet<double>> triplets;
    for (const BeamNetwork::Beam& beam : net.beams)
        for (size_t e = 0; e < beam.sections.size(); ++e) {
            const int n0 = beam.nodes[2 * e], n2 = beam.nodes[2 * e + 2];
            const BeamElementMatrix G = element_gyroscopic({net.node_z[n2] - net.node_z[n0], beam.sections[e]});
            const int nodes[kElementNodes] = {n0, beam.nodes[2 * e + 1], n2};
            for (int a = 0; a < kElementNodes; ++a)
                for (int b = 0; b < kElementNodes; ++b) {
                    const int ra = row[beam_dof::per_node * nodes[a] + beam_dof::ry];
                    const int rb = row[beam_dof::per_node * nodes[b] + beam_dof::ry];
                    if (ra < 0 || rb < 0) continue;
                    triplets.emplace_back(ra, rb, G(beam_dof::per_node * a + beam_dof::rx, beam_dof::per_node * b + beam_dof::ry));
                }
        }
    const auto n = static_cast<Eigen::Index>(plane.free_dofs.size());
    Eigen::SparseMatrix<double> out(n, n);
    out.setFromTriplets(triplets.begin(), triplets.end());
    return out;
}

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

FamilySet lateral_family_set(const BeamNetwork& network) {
    const std::vector<FamilySet> sets = rotating_sets(network);
    return !sets.empty() && has_bending(sets.front()) ? sets.front() : 0;
}

DenseModes dense_modes_at_rest(const NetworkMatrices& problem, double lambda_scale) {
    // M x = mu (K - sigma M) x with the negative shift of the solver at
    // rest (positive definite even with rigid modes): mu = 1 / (lambda -
    // sigma) is largest for the lowest modes, which the dense solve then
    // gets to round-off relative to themselves, not to the highest mode.
    const double sigma = -0.5 * lambda_scale;
    const Eigen::MatrixXd K(problem.K), M(problem.M);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(M, K - sigma * M);
    if (solver.info() != Eigen::Success)
        throw SolveError("the rotating beam network's K - sigma M is not positive definite (a free DOF without "
                         "mass or stiffness)");
    const Eigen::Index n = K.rows();
    DenseModes out;
    out.lambda.resize(n);
    out.Phi.resize(n, n);
    for (Eigen::Index j = 0; j < n; ++j) {  // ascending lambda: descending mu
        const Eigen::Index from = n - 1 - j;
        out.lambda(j) = sigma + 1.0 / solver.eigenvalues()(from);
        const Eigen::VectorXd x = solver.eigenvectors().col(from);
        out.Phi.col(j) = x / std::sqrt(x.dot(M * x));
    }
    return out;
}

RotatingNetwork::RotatingNetwork(const BeamNetwork& network, double lambda_scale)
    : network_(&network), lambda_scale_(lambda_scale) {
    const FamilySet xz = family_bit(MotionFamily::bending_xz), yz = family_bit(MotionFamily::bending_yz);
    std::vector<FamilySet> sets = independent_family_sets(network);
    const bool planes = bending_planes_alike(network) && std::count(sets.begin(), sets.end(), xz) == 1 &&
                        std::count(sets.begin(), sets.end(), yz) == 1;
    if (planes)
        sets.erase(std::find(sets.begin(), sets.end(), yz));
    else
        sets = rotating_sets(network);
    std::vector<NetworkMatrices> systems = assemble_problems(network, sets);
    std::vector<Eigen::SparseMatrix<double>> gyro = assemble_gyroscopic(network, systems);
    for (size_t s = 0; s < sets.size(); ++s)
        if (planes && sets[s] == xz) gyro[s] = plane_gyroscopic(network, systems[s]);
    for (size_t s = 0; s < sets.size(); ++s) {
        Problem p;
        p.plane = planes && sets[s] == xz;
        p.m = std::move(systems[s]);
        p.G = std::move(gyro[s]);
        p.spins = p.G.nonZeros() > 0 && p.G.cwiseAbs().sum() > 0;
        if (p.m.K.rows() == 0) continue;
        DenseModes rest = dense_modes_at_rest(p.m, lambda_scale);
        p.lambda = std::move(rest.lambda);
        p.Phi = std::move(rest.Phi);
        if (p.spins) p.Ghat = p.Phi.transpose() * (p.G * p.Phi);
        p.norm_K = max_column_sum(p.m.K), p.norm_M = max_column_sum(p.m.M), p.norm_G = max_column_sum(p.G);
        n_free_dofs_ += static_cast<long>(p.m.K.rows()) * (p.plane ? 2 : 1);
        problems_.push_back(std::move(p));
    }
}

Eigen::VectorXcd RotatingNetwork::network_shape(const Problem& p, const Eigen::VectorXcd& x, Kind kind,
                                                double omega) const {
    if (kind == Kind::rows) return to_network(p.m.free_dofs, x, network_->held.size());
    // From the x-z plane (ux, ry): uy = -+i ux and rx = +-i ry for a forward
    // (omega > 0) / backward whirl, so that ux + i uy turns as e^{+-i|omega| t}.
    Eigen::VectorXcd out = Eigen::VectorXcd::Zero(static_cast<Eigen::Index>(network_->held.size()));
    const cd turn = kind == Kind::whirl ? cd(0, omega > 0 ? 1.0 : -1.0) : cd(0, 0);
    for (size_t r = 0; r < p.m.free_dofs.size(); ++r) {
        const int d = p.m.free_dofs[r], node = d / beam_dof::per_node, local = d % beam_dof::per_node;
        const cd v = x(static_cast<Eigen::Index>(r));
        const int base = beam_dof::per_node * node;
        const bool translation = local == beam_dof::ux;
        if (kind == Kind::planar_x) {
            out(d) = v;
        } else if (kind == Kind::planar_y) {  // (uy, -rx) is the y-z plane's (w, phi)
            out(base + (translation ? beam_dof::uy : beam_dof::rx)) = translation ? v : -v;
        } else {
            out(d) = v;
            out(base + (translation ? beam_dof::uy : beam_dof::rx)) = translation ? -turn * v : turn * v;
        }
    }
    return out;
}

RotatingMode RotatingNetwork::finish(const Candidate& c, double omega_spin) const {
    const Problem& p = *c.problem;
    const double omega = c.omega;  // signed for a plane's whirl
    RotatingMode mode;
    mode.frequency_hz = std::abs(omega) / (2 * M_PI);
    const Eigen::VectorXcd eta = c.eta / c.eta.norm();  // x^H M x = eta^H eta = 1
    const Eigen::VectorXcd x = p.Phi.cast<cd>() * eta;
    const Eigen::SparseMatrix<cd> K = p.m.K.cast<cd>(), M = p.m.M.cast<cd>(), G = p.G.cast<cd>();
    const cd gyro = p.plane ? cd(omega * omega_spin, 0) : cd(0, omega * omega_spin);
    const Eigen::VectorXcd r = K * x + gyro * (G * x) - omega * omega * (M * x);
    mode.relative_residual =
        r.norm() / ((p.norm_K + std::abs(omega) * omega_spin * p.norm_G + omega * omega * p.norm_M) * x.norm());
    const size_t n_network = network_->held.size();
    mode.shape = network_shape(p, x, c.kind, omega);
    if (c.kind != Kind::rows) mode.shape /= std::sqrt(mode.shape.squaredNorm() / x.squaredNorm());  // M-normalised
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

void RotatingNetwork::add_plane_candidates(const Problem& p, double omega_spin, std::vector<Candidate>& out) const {
    const double rigid = kRigidEigenvalueFraction * lambda_scale_;
    const Eigen::Index n = p.lambda.size();
    for (Eigen::Index j = 0; j < n; ++j) {  // at rest, or rigid: each plane mode once in x-z, once in y-z
        const bool rigid_mode = std::abs(p.lambda(j)) < rigid;
        if (!rigid_mode && omega_spin > 0) continue;
        const double omega = rigid_mode ? 0.0 : std::sqrt(std::max(p.lambda(j), 0.0));
        out.push_back({&p, omega, Eigen::VectorXcd::Unit(n, j), Kind::planar_x});
        out.push_back({&p, omega, Eigen::VectorXcd::Unit(n, j), Kind::planar_y});
    }
    if (omega_spin == 0) return;
    const Eigen::VectorXd root = p.lambda.cwiseMax(0.0).cwiseSqrt();
    Eigen::MatrixXd H = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    H.topLeftCorner(n, n) = omega_spin * p.Ghat;
    H.topRightCorner(n, n).diagonal() = root;
    H.bottomLeftCorner(n, n).diagonal() = root;
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(H);
    if (solver.info() != Eigen::Success) throw SolveError("the rotating beam network's eigensolver did not converge");
    const double omega_rigid = std::sqrt(rigid);
    for (Eigen::Index k = 0; k < 2 * n; ++k) {
        const double omega = solver.eigenvalues()(k);
        if (std::abs(omega) < omega_rigid) continue;
        out.push_back({&p, omega, solver.eigenvectors().col(k).head(n).cast<cd>(), Kind::whirl});
    }
}

void RotatingNetwork::add_candidates(const Problem& p, double omega_spin, std::vector<Candidate>& out) const {
    if (p.plane) {
        add_plane_candidates(p, omega_spin, out);
        return;
    }
    const double rigid = kRigidEigenvalueFraction * lambda_scale_;
    const Eigen::Index n = p.lambda.size();
    for (Eigen::Index j = 0; j < n; ++j)  // rigid: K phi = 0 solves the quadratic problem at omega = 0
        if (std::abs(p.lambda(j)) < rigid) out.push_back({&p, 0.0, Eigen::VectorXcd::Unit(n, j), Kind::rows});
    if (!p.spins || omega_spin == 0) {
        for (Eigen::Index j = 0; j < n; ++j)
            if (std::abs(p.lambda(j)) >= rigid)
                out.push_back({&p, std::sqrt(std::max(p.lambda(j), 0.0)), Eigen::VectorXcd::Unit(n, j), Kind::rows});
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
        out.push_back({&p, omega, solver.eigenvectors().col(k).head(n), Kind::rows});
    }
}

std::vector<RotatingMode> RotatingNetwork::modes_at(double speed_hz, int max_modes) const {
    COREMODAL_ASSERT(speed_hz >= 0 && max_modes >= 0);
    const double omega_spin = 2 * M_PI * speed_hz;
    std::vector<Candidate> candidates;
    for (const Problem& p : problems_) add_candidates(p, omega_spin, candidates);
    std::stable_sort(candidates.begin(), candidates.end(),
                     [](const Candidate& a, const Candidate& b) { return std::abs(a.omega) < std::abs(b.omega); });
    if (candidates.size() > static_cast<size_t>(max_modes)) candidates.resize(max_modes);
    std::vector<RotatingMode> out;
    for (const Candidate& c : candidates) out.push_back(finish(c, omega_spin));
    return out;
}

std::optional<std::vector<PlaneCrossing>> plane_critical_speeds(const BeamNetwork& network, double lambda_scale,
                                                                const std::vector<int>& orders, double max_speed_hz) {
    const FamilySet xz = family_bit(MotionFamily::bending_xz), yz = family_bit(MotionFamily::bending_yz);
    const std::vector<FamilySet> sets = independent_family_sets(network);
    if (!bending_planes_alike(network) || std::count(sets.begin(), sets.end(), xz) != 1 ||
        std::count(sets.begin(), sets.end(), yz) != 1)
        return std::nullopt;
    const NetworkMatrices plane = std::move(assemble_problems(network, {xz}).front());
    const Eigen::SparseMatrix<double> G = plane_gyroscopic(network, plane);
    const Eigen::MatrixXd K(plane.K);
    const double max_spin = 2 * M_PI * max_speed_hz;
    std::vector<PlaneCrossing> out;
    for (int order : orders)
        for (const Whirl whirl : {Whirl::forward, Whirl::backward}) {
            // (order^2 M -+ order G) a = mu K a, mu = 1 / Omega^2: the lowest
            // speeds are the largest mu.
            const double sign = whirl == Whirl::forward ? -1.0 : 1.0;
            const Eigen::SparseMatrix<double> As = double(order * order) * plane.M + sign * order * G;
            const Eigen::MatrixXd A(As);
            const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(A, K, Eigen::EigenvaluesOnly);
            if (solver.info() != Eigen::Success) return std::nullopt;  // K not positive definite
            for (Eigen::Index k = solver.eigenvalues().size(); k-- > 0;) {
                const double mu = solver.eigenvalues()(k);
                if (!(mu > 0) || 1 / std::sqrt(mu) > max_spin) break;
                const double spin = 1 / std::sqrt(mu);
                // The shape (for its label): two steps of inverse iteration on the
                // nearly singular K - s A (s a hair off Omega^2), from the load A 1.
                Eigen::SparseLU<Eigen::SparseMatrix<double>> lu(Eigen::SparseMatrix<double>(plane.K - spin * spin * (1 + 1e-9) * As));
                Eigen::VectorXd a = Eigen::VectorXd::Ones(plane.K.rows());
                for (int step = 0; step < 2 && lu.info() == Eigen::Success; ++step) {
                    a = lu.solve(Eigen::VectorXd(As * a));
                    a /= a.norm();
                }
                Eigen::VectorXd shape = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(network.held.size()));
                Eigen::VectorXd mass_shape = shape;
                const Eigen::VectorXd Ma = plane.M * a;
                for (size_t r = 0; r < plane.free_dofs.size(); ++r) {
                    shape(plane.free_dofs[r]) = a(static_cast<Eigen::Index>(r));
                    mass_shape(plane.free_dofs[r]) = Ma(static_cast<Eigen::Index>(r));
                }
                const double omega = order * spin;
                out.push_back({order, whirl, spin / (2 * M_PI),
                               label_beam_mode(network, shape, mass_shape, omega * omega, lambda_scale)});
            }
        }
    std::sort(out.begin(), out.end(), [](const PlaneCrossing& a, const PlaneCrossing& b) { return a.speed_hz < b.speed_hz; });
    return out;
}

}  // namespace coremodal
