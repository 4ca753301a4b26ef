#include "modes/classify.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <complex>
#include <numeric>

namespace coremodal {
namespace {

// Stations along z. Fine enough to resolve ~10 axial half-waves, coarse
// enough that each holds a ring of nodes (a generated mesh has node layers at
// every half element; bins that catch no node are skipped).
constexpr int kStations = 64;
// Ignore stations whose amplitude is below this share of the largest when
// counting sign changes: near a node the projected amplitude is noise.
constexpr int kComponents = 3;  // r, theta, z
constexpr int kHarmonics = kMaxWaveNumber + 1;

// Fourier coefficients a_n (cos), b_n (sin) per station, component, harmonic.
struct StationFit {
    std::array<std::array<std::complex<double>, kHarmonics>, kComponents> c{};
};

// Mean square amplitude per component and harmonic, summed over the stations.
using Energy = std::array<std::array<double, kHarmonics>, kComponents>;

// One station's least-squares fit of the shape's cylindrical components by
// 1, cos t, sin t, ... up to n_max; adds its energy and its |u|^2 to `total`.
StationFit fit_station(const std::vector<int>& nodes, const std::vector<double>& theta, int n_max,
                       const std::vector<double>& shape, Energy& energy, double& total) {
    StationFit fit;
    const int n_basis = 1 + 2 * n_max;
    Eigen::MatrixXd A(nodes.size(), n_basis);
    Eigen::MatrixXd U(nodes.size(), kComponents);
    for (size_t k = 0; k < nodes.size(); ++k) {
        const int node = nodes[k];
        const double t = theta[node], c = std::cos(t), sn = std::sin(t);
        const double ux = shape[3 * node], uy = shape[3 * node + 1], uz = shape[3 * node + 2];
        U(k, 0) = c * ux + sn * uy;
        U(k, 1) = -sn * ux + c * uy;
        U(k, 2) = uz;
        total += ux * ux + uy * uy + uz * uz;
        A(k, 0) = 1;
        for (int h = 1; h <= n_max; ++h) {
            A(k, 2 * h - 1) = std::cos(h * t);
            A(k, 2 * h) = std::sin(h * t);
        }
    }
    const Eigen::MatrixXd coef = A.colPivHouseholderQr().solve(U);
    const double count = double(nodes.size());
    for (int comp = 0; comp < kComponents; ++comp) {
        fit.c[comp][0] = coef(0, comp);
        energy[comp][0] += count * coef(0, comp) * coef(0, comp);
        for (int h = 1; h <= n_max; ++h) {
            const double a = coef(2 * h - 1, comp), b = coef(2 * h, comp);
            fit.c[comp][h] = {a, b};
            energy[comp][h] += count * 0.5 * (a * a + b * b);  // mean of (a cos + b sin)^2
        }
    }
    return fit;
}

// The dominant harmonic's amplitude along z, in its principal phase.
std::vector<double> axial_profile(const std::vector<StationFit>& fits, int comp, int n) {
    std::vector<double> profile;
    if (n == 0) {
        for (const auto& f : fits) profile.push_back(f.c[comp][0].real());
        return profile;
    }
    double sxx = 0, syy = 0, sxy = 0;
    for (const auto& f : fits) {
        const auto v = f.c[comp][n];
        sxx += v.real() * v.real(), syy += v.imag() * v.imag(), sxy += v.real() * v.imag();
    }
    const double phi = 0.5 * std::atan2(2 * sxy, sxx - syy);
    for (const auto& f : fits) {
        const auto v = f.c[comp][n];
        profile.push_back(v.real() * std::cos(phi) + v.imag() * std::sin(phi));
    }
    return profile;
}


}  // namespace


int ModeClassifier::distinct_angles(const std::vector<int>& nodes) const {
    // Angles closer than this (radians) are one ring position: mesh nodes on a
    // ring are at least 2 pi / (2 * 512) apart even on the finest meshes.
    constexpr double kAngleTolerance = 1e-6;
    std::vector<double> t;
    for (int n : nodes) t.push_back(theta_[n]);
    std::sort(t.begin(), t.end());
    int count = 0;
    for (size_t i = 0; i < t.size(); ++i)
        if (i == 0 || t[i] - t[i - 1] > kAngleTolerance) ++count;
    if (count > 1 && t.back() - t.front() > 2 * M_PI - kAngleTolerance) --count;  // -pi and pi coincide
    return count;
}

ModeClassifier::ModeClassifier(const Mesh& mesh, const std::vector<int>& nodes, BodyHeld held) : held_(held) {
    std::vector<int> looked_at = nodes;
    if (looked_at.empty()) {
        looked_at.resize(mesh.n_nodes());
        std::iota(looked_at.begin(), looked_at.end(), 0);
    }
    std::array<double, 3> centroid{};
    for (int n : looked_at)
        for (int k = 0; k < 3; ++k) centroid[k] += mesh.nodes[n][k] / double(looked_at.size());
    nodes_ = looked_at;
    for (int n : looked_at)
        offset_.push_back({mesh.nodes[n][0] - centroid[0], mesh.nodes[n][1] - centroid[1], mesh.nodes[n][2] - centroid[2]});
    double z_min = 1e300, z_max = -1e300;
    for (int n : looked_at) {
        z_min = std::min(z_min, mesh.nodes[n][2]);
        z_max = std::max(z_max, mesh.nodes[n][2]);
    }
    const double width = std::max(z_max - z_min, 1e-12) / kStations;
    stations_.assign(kStations, {});
    theta_.resize(mesh.n_nodes());
    for (int n : looked_at) {
        const auto& x = mesh.nodes[n];
        theta_[n] = std::atan2(x[1], x[0]);
        stations_[std::min(kStations - 1, int((x[2] - z_min) / width))].push_back(n);
    }
    std::erase_if(stations_, [](const auto& s) { return s.empty(); });
}

double ModeClassifier::deformation_share(const std::vector<double>& shape) const {
    // Normal equations of u_i = t + w x r_i: per node the 3 x 6 block [I, -[r_i]x].
    Eigen::Matrix<double, 6, 6> AtA = Eigen::Matrix<double, 6, 6>::Zero();
    Eigen::Matrix<double, 6, 1> Atu = Eigen::Matrix<double, 6, 1>::Zero();
    double total = 0;
    for (size_t k = 0; k < nodes_.size(); ++k) {
        const auto& r = offset_[k];
        Eigen::Matrix<double, 3, 6> A;
        A << 1, 0, 0, 0, r[2], -r[1],  //
            0, 1, 0, -r[2], 0, r[0],   //
            0, 0, 1, r[1], -r[0], 0;
        const Eigen::Vector3d u(shape[3 * nodes_[k]], shape[3 * nodes_[k] + 1], shape[3 * nodes_[k] + 2]);
        AtA += A.transpose() * A;
        Atu += A.transpose() * u;
        total += u.squaredNorm();
    }
    if (total <= 0) return 1;
    // Rotation about the axis of a body of revolution is one freedom of
    // six; a pseudo-inverse copes with nodes all on one line (a beam).
    const Eigen::Matrix<double, 6, 1> p = AtA.completeOrthogonalDecomposition().solve(Atu);
    // Least squares: the residual's square is |u|^2 minus the fit's projection.
    return std::clamp((total - p.dot(Atu)) / total, 0.0, 1.0);
}

ModeLabel ModeClassifier::classify(const std::vector<double>& shape, double lambda, double lambda_scale) const {
    ModeLabel label;
    Energy energy{};
    double total = 0;
    std::vector<StationFit> fits(stations_.size());
    for (size_t s = 0; s < stations_.size(); ++s) {
        // Basis: 1, cos t, sin t, ..., limited to what the station's distinct
        // angles can resolve (a harmonic at the Nyquist limit would alias).
        const int n_max = std::min<int>(kMaxWaveNumber, (distinct_angles(stations_[s]) - 1) / 2);
        fits[s] = fit_station(stations_[s], theta_, n_max, shape, energy, total);
    }
    if (total <= 0) return label;

    // Dominant family: harmonic n summed over components.
    int best_n = 0;
    double best_family = -1;
    for (int h = 0; h < kHarmonics; ++h) {
        const double e = energy[0][h] + energy[1][h] + energy[2][h];
        if (e > best_family) best_family = e, best_n = h;
    }
    int best_comp = 0;
    for (int comp = 1; comp < kComponents; ++comp)
        if (energy[comp][best_n] > energy[best_comp][best_n]) best_comp = comp;

    label.n = best_n;
    // For n = 0 the three components are three different families.
    label.dominant_share = (best_n == 0 ? energy[best_comp][0] : best_family) / total;

    // Principal phase of the dominant harmonic along z, then sign changes.
    label.m = sign_changes(axial_profile(fits, best_comp, best_n));

    if (std::abs(lambda) < kRigidEigenvalueFraction * lambda_scale) {
        label = {"rigid", 0, 0, 1.0};  // any mix of rigid motions: n and m mean nothing
    } else if (deformation_share(shape) < kRigidMotionDeformationShare) {
        // The roll moving as a whole at a frequency of its own: n and m say
        // how (translation m = 0, rocking m = 1, axial or torsional n = 0).
        label.type = held_ == BodyHeld::held ? "support" : "rigid";
    } else if (label.dominant_share < kMinDominantShare) {
        label.type = "mixed";
    } else if (best_n == 1) {
        label.type = "bending";
    } else if (best_n >= 2) {
        label.type = "ovalling";
    } else {
        static const char* kZeroFamilies[kComponents] = {"breathing", "torsion", "axial"};
        label.type = kZeroFamilies[best_comp];
    }
    return label;
}

std::vector<int> roll_nodes(const Mesh& mesh) {
    std::vector<char> take(mesh.n_nodes(), 0);
    for (int c = 0; c < mesh.n_cells(); ++c) {
        const std::string& part = mesh.part_names[mesh.cell_part[c]];
        if (part != "core" && part != "rest_paper") continue;
        for (int a = 0; a < mesh.nodes_per_cell(); ++a) take[mesh.cell(c)[a]] = 1;
    }
    std::vector<int> nodes;
    for (int n = 0; n < mesh.n_nodes(); ++n)
        if (take[n]) nodes.push_back(n);
    return nodes;
}

}  // namespace coremodal
