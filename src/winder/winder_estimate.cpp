#include "winder/winder_estimate.hpp"

#include "common/error.hpp"

#include <Eigen/Dense>

#include <cmath>

namespace coremodal {
namespace {

// The reduced DOFs of one body on one network DOF kind (beam_dof::...).
std::vector<int> body_dofs(const WinderModel& m, int body, int kind) {
    std::vector<int> out;
    for (Eigen::Index c = 0; c < m.T.outerSize(); ++c) {
        if (m.body_of[c] != body) continue;
        Eigen::SparseMatrix<double>::InnerIterator e(m.T, c);
        if (e && m.network_dofs[e.row()] % beam_dof::per_node == kind) out.push_back(static_cast<int>(c));
    }
    return out;
}

Eigen::MatrixXd sub_matrix(const Eigen::MatrixXd& A, const std::vector<int>& rows) {
    const int n = static_cast<int>(rows.size());
    Eigen::MatrixXd S(n, n);
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) S(i, j) = A(rows[i], rows[j]);
    return S;
}

// The front drum alone on its bearings (its own stiffness, no nips), in the
// vertical plane: the lowest mode, M-normalised, on (uy, rx) of its nodes.
struct DrumMode {
    double lambda = 0;
    std::vector<int> uy, rx;  // reduced DOFs, node by node
    Eigen::VectorXd w, r;     // the mode's values on them
};

DrumMode front_drum_mode(const WinderModel& m) {
    DrumMode d;
    d.uy = body_dofs(m, 0, beam_dof::uy);
    d.rx = body_dofs(m, 0, beam_dof::rx);
    std::vector<int> all = d.uy;
    all.insert(all.end(), d.rx.begin(), d.rx.end());
    const Eigen::MatrixXd K = sub_matrix(Eigen::MatrixXd(m.K - m.K_nips), all), M = sub_matrix(Eigen::MatrixXd(m.M), all);
    Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(K, M);
    COREMODAL_ASSERT(solver.info() == Eigen::Success);
    d.lambda = solver.eigenvalues()[0];
    const Eigen::VectorXd x = solver.eigenvectors().col(0);  // M-normalised
    const auto n = static_cast<Eigen::Index>(d.uy.size());
    d.w = x.head(n), d.r = x.tail(x.size() - n);
    return d;
}

// The drum mode set along a direction (nx, ny) on drum `body`: the x-z plane
// takes (ux, ry) = n_x (uy, -rx) of the vertical mode (isotropic drum).
void place(const WinderModel& m, const DrumMode& d, int body, std::array<double, 2> n, Eigen::VectorXd& v) {
    const auto ux = body_dofs(m, body, beam_dof::ux), ry = body_dofs(m, body, beam_dof::ry);
    const auto uy = body_dofs(m, body, beam_dof::uy), rx = body_dofs(m, body, beam_dof::rx);
    COREMODAL_ASSERT(ux.size() == d.uy.size() && uy.size() == d.uy.size() && rx.size() == d.rx.size());
    for (size_t i = 0; i < ux.size(); ++i) v[ux[i]] = n[0] * d.w[i], v[uy[i]] = n[1] * d.w[i];
    for (size_t i = 0; i < rx.size(); ++i) v[ry[i]] = -n[0] * d.r[i], v[rx[i]] = n[1] * d.r[i];
}

// The model mode with the largest share of `v`'s motion, (v^T M x)^2 / (v^T M v).
std::pair<double, double> best_mode(const WinderModel& m, const WinderModes& modes, const Eigen::VectorXd& v) {
    const Eigen::VectorXd Mv = m.M * v;
    const double vMv = v.dot(Mv);
    double best = -1, hz = 0;
    for (int i = 0; i < modes.n_reported; ++i) {
        const double p = std::pow(Mv.dot(modes.shapes.col(i)), 2) / vMv;
        if (p > best) best = p, hz = modes.modes[i].frequency_hz;
    }
    return {hz, std::max(best, 0.0)};
}

}  // namespace

TwoModeRoots two_mode_roots(double lambda_d, double K_n, double roll) {
    if (!(K_n > 0)) return {lambda_d, roll};
    const double b = lambda_d + K_n + roll;
    const double root = std::sqrt(std::max(b * b - 4 * lambda_d * roll, 0.0));
    const double low = 0.5 * (b - root), high = 0.5 * (b + root);
    // Drum share of a root's mode: 1 / (1 + (lambda_d + K_n - lambda)^2 / (K_n Omega^2)).
    const auto drum_share = [&](double l) {
        return roll > 0 ? 1.0 / (1.0 + std::pow(lambda_d + K_n - l, 2) / (K_n * roll)) : (l == high ? 1.0 : 0.0);
    };
    return drum_share(high) >= drum_share(low) ? TwoModeRoots{high, low} : TwoModeRoots{low, high};
}

DrumFrequencyEstimate estimate_drum_frequency(const WinderModel& m, const WinderModes& modes) {
    DrumFrequencyEstimate e;
    const DrumMode drum = front_drum_mode(m);
    e.drum_alone_hz = eigenvalue_hz(drum.lambda);
    const auto bearings = m.network.springs.front().stiffness;
    e.isotropic = bearings(beam_dof::ux, beam_dof::ux) == bearings(beam_dof::uy, beam_dof::uy);
    const auto front = nip_direction(m.state.geometry, DrumSide::front);
    const auto rear = nip_direction(m.state.geometry, DrumSide::rear);
    Eigen::VectorXd v_front = Eigen::VectorXd::Zero(m.n_dofs());
    place(m, drum, 0, front, v_front);
    e.nip_modal_stiffness = v_front.dot(m.K_nips * v_front);  // rolls held: k * integral of phi^2
    const double k = m.state.drum_nip.stiffness_per_length, alpha = m.state.geometry.nip_angle;
    for (int f = 0; f < kDrumFamilies; ++f) {
        const bool symmetric = f == static_cast<int>(DrumFamily::symmetric);
        const double p = symmetric ? std::cos(alpha) : std::sin(alpha);
        const double roll = 2 * k * p * p / m.state.roll_mass_per_width;
        const TwoModeRoots roots = two_mode_roots(drum.lambda, e.nip_modal_stiffness, roll);
        DrumFrequencyEstimate::Family& out = e.family[f];
        out.roll_bounce_hz = eigenvalue_hz(roll), out.drum_hz = eigenvalue_hz(roots.drum),
        out.roll_hz = eigenvalue_hz(roots.roll);
        out.heavy_roll_hz = eigenvalue_hz(drum.lambda + e.nip_modal_stiffness);
        Eigen::VectorXd v = v_front;
        place(m, drum, 1, symmetric ? rear : std::array<double, 2>{-rear[0], -rear[1]}, v);
        std::tie(out.model_hz, out.model_participation) = best_mode(m, modes, v);
    }
    return e;
}

}  // namespace coremodal
