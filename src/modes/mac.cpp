#include "modes/mac.hpp"

#include "common/error.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace coremodal {
namespace {

// Nodes whose normalised z differ by less than this are one ring (a generated
// mesh has exact rings; 1e-6 of the length is far below any element size).
constexpr double kRingTolerance = 1e-6;
// Angles closer than this (radians) are one position on a ring.
constexpr double kAngleTolerance = 1e-6;
// Nodes within this share of the largest radius are on the outer surface.
constexpr double kOuterRadiusShare = 1e-3;
// A user (tetrahedral) mesh has no rings: when fewer than half the surface
// nodes sit on rings that resolve harmonic 2 (5 distinct angles), the nodes
// are binned in z instead, into this many bins.
constexpr int kFallbackBins = 48;
constexpr int kAnglesForHarmonic2 = 5;

std::vector<int> outer_surface_nodes(const Mesh& mesh) {
    if (const auto it = mesh.node_groups.find("core_outer"); it != mesh.node_groups.end() && !it->second.empty())
        return it->second;
    const auto core = std::find(mesh.part_names.begin(), mesh.part_names.end(), "core");
    COREMODAL_ASSERT(core != mesh.part_names.end());
    const int core_part = static_cast<int>(core - mesh.part_names.begin());
    std::vector<char> in_core(mesh.n_nodes(), 0);
    for (int c = 0; c < mesh.n_cells(); ++c)
        if (mesh.cell_part[c] == core_part)
            for (int k = 0; k < mesh.nodes_per_cell(); ++k) in_core[mesh.cell(c)[k]] = 1;
    double r_max = 0;
    for (int n = 0; n < mesh.n_nodes(); ++n)
        if (in_core[n]) r_max = std::max(r_max, std::hypot(mesh.nodes[n][0], mesh.nodes[n][1]));
    std::vector<int> out;
    for (int n = 0; n < mesh.n_nodes(); ++n)
        if (in_core[n] && std::hypot(mesh.nodes[n][0], mesh.nodes[n][1]) >= (1 - kOuterRadiusShare) * r_max)
            out.push_back(n);
    return out;
}

int distinct_angles(std::vector<double> theta) {
    std::sort(theta.begin(), theta.end());
    int count = 0;
    for (size_t i = 0; i < theta.size(); ++i)
        if (i == 0 || theta[i] - theta[i - 1] > kAngleTolerance) ++count;
    if (count > 1 && theta.back() - theta.front() > 2 * M_PI - kAngleTolerance) --count;  // -pi and pi coincide
    return count;
}

using Ring = ModeSignatureSampler::Ring;

void finish_ring(Ring& ring, const Mesh& mesh) {
    for (int n : ring.nodes) ring.theta.push_back(std::atan2(mesh.nodes[n][1], mesh.nodes[n][0]));
    // A harmonic at the Nyquist limit of the ring would alias.
    ring.n_max = std::min(kSignatureHarmonics, (distinct_angles(ring.theta) - 1) / 2);
}

// Nodes sorted by normalised z, cut where z jumps by more than the tolerance.
std::vector<Ring> exact_rings(const std::vector<int>& nodes, const std::vector<double>& zeta, const Mesh& mesh) {
    std::vector<int> order(nodes.size());
    std::iota(order.begin(), order.end(), 0);
    std::sort(order.begin(), order.end(), [&](int a, int b) { return zeta[a] < zeta[b]; });
    std::vector<Ring> rings;
    for (int i : order) {
        if (rings.empty() || zeta[i] - rings.back().z > kRingTolerance) rings.push_back({zeta[i], {}, {}, 0});
        rings.back().nodes.push_back(nodes[i]);
    }
    for (Ring& r : rings) finish_ring(r, mesh);
    return rings;
}

std::vector<Ring> binned_rings(const std::vector<int>& nodes, const std::vector<double>& zeta, const Mesh& mesh) {
    std::vector<Ring> bins(kFallbackBins);
    for (size_t i = 0; i < nodes.size(); ++i) {
        const int b = std::min(kFallbackBins - 1, static_cast<int>(zeta[i] * kFallbackBins));
        bins[b].nodes.push_back(nodes[i]);
        bins[b].z += zeta[i];
    }
    std::erase_if(bins, [](const Ring& r) { return r.nodes.empty(); });
    for (Ring& r : bins) {
        r.z /= static_cast<double>(r.nodes.size());
        finish_ring(r, mesh);
    }
    return bins;
}

bool rings_resolve_ovalling(const std::vector<Ring>& rings, size_t n_nodes) {
    size_t resolved = 0;
    for (const Ring& r : rings)
        if (2 * r.n_max + 1 >= kAnglesForHarmonic2) resolved += r.nodes.size();
    return 2 * resolved >= n_nodes;
}

// Fourier coefficients (rows: a0, a1, b1, ...; columns: r, theta, z) of a ring.
Eigen::MatrixXd fit_ring(const Ring& ring, const std::vector<double>& shape) {
    const int n_basis = 1 + 2 * ring.n_max;
    const int n = static_cast<int>(ring.nodes.size());
    Eigen::MatrixXd A(n, n_basis), U(n, kSignatureComponents);
    for (int k = 0; k < n; ++k) {
        const double t = ring.theta[k], c = std::cos(t), s = std::sin(t);
        const size_t node = static_cast<size_t>(ring.nodes[k]);
        const double ux = shape[3 * node], uy = shape[3 * node + 1], uz = shape[3 * node + 2];
        U(k, 0) = c * ux + s * uy;
        U(k, 1) = -s * ux + c * uy;
        U(k, 2) = uz;
        A(k, 0) = 1;
        for (int h = 1; h <= ring.n_max; ++h) {
            A(k, 2 * h - 1) = std::cos(h * t);
            A(k, 2 * h) = std::sin(h * t);
        }
    }
    return A.colPivHouseholderQr().solve(U);
}

// Trapezoidal weight of station s on [0, 1].
double station_weight(int s) {
    const double h = 1.0 / (kSignatureStations - 1);
    return (s == 0 || s == kSignatureStations - 1) ? h / 2 : h;
}

}  // namespace

ModeSignatureSampler::ModeSignatureSampler(const Mesh& mesh) {
    const std::vector<int> nodes = outer_surface_nodes(mesh);
    COREMODAL_ASSERT(!nodes.empty());
    double z_min = 1e300, z_max = -1e300;
    for (int n : nodes) z_min = std::min(z_min, mesh.nodes[n][2]), z_max = std::max(z_max, mesh.nodes[n][2]);
    const double length = std::max(z_max - z_min, 1e-300);
    std::vector<double> zeta;
    for (int n : nodes) zeta.push_back((mesh.nodes[n][2] - z_min) / length);
    rings_ = exact_rings(nodes, zeta, mesh);
    if (!rings_resolve_ovalling(rings_, nodes.size())) rings_ = binned_rings(nodes, zeta, mesh);
}

Signature ModeSignatureSampler::operator()(const std::vector<double>& shape) const {
    std::vector<Eigen::MatrixXd> fits;
    fits.reserve(rings_.size());
    for (const Ring& r : rings_) fits.push_back(fit_ring(r, shape));

    Signature out(kSignatureSize, 0.0);
    for (int h = 0; h <= kSignatureHarmonics; ++h) {
        // The rings that resolve harmonic h, in z order.
        std::vector<int> usable;
        for (size_t i = 0; i < rings_.size(); ++i)
            if (rings_[i].n_max >= h) usable.push_back(static_cast<int>(i));
        if (usable.empty()) continue;
        const std::vector<int> rows = h == 0 ? std::vector<int>{0} : std::vector<int>{2 * h - 1, 2 * h};
        const double harmonic_scale = std::sqrt(h == 0 ? 2 * M_PI : M_PI);
        size_t j = 0;  // first usable ring at or above the station
        for (int s = 0; s < kSignatureStations; ++s) {
            const double z = static_cast<double>(s) / (kSignatureStations - 1);
            while (j < usable.size() && rings_[usable[j]].z < z) ++j;
            const int above = usable[std::min(j, usable.size() - 1)];
            const int below = usable[j == 0 ? 0 : j - 1];
            const double z0 = rings_[below].z, z1 = rings_[above].z;
            const double t = (above == below || z1 <= z0) ? 0.0 : std::clamp((z - z0) / (z1 - z0), 0.0, 1.0);
            const double scale = harmonic_scale * std::sqrt(station_weight(s));
            for (int c = 0; c < kSignatureComponents; ++c)
                for (int row : rows)
                    out[signature_index(s, c, row)] =
                        scale * ((1 - t) * fits[below](row, c) + t * fits[above](row, c));
        }
    }
    return out;
}

double mac(const Signature& a, const Signature& b) {
    COREMODAL_ASSERT(a.size() == b.size());
    double ab = 0, aa = 0, bb = 0;
    for (size_t i = 0; i < a.size(); ++i) ab += a[i] * b[i], aa += a[i] * a[i], bb += b[i] * b[i];
    if (aa <= 0 || bb <= 0) return 0;
    return ab * ab / (aa * bb);
}

namespace {

// Orthonormal basis of the span of the vectors (zero or dependent vectors drop out).
Eigen::MatrixXd orthonormal_basis(const std::vector<Signature>& vectors) {
    // Directions below this share of the largest are numerically dependent.
    constexpr double kRankTolerance = 1e-8;
    if (vectors.empty()) return {};
    const Eigen::Index n = static_cast<Eigen::Index>(vectors.front().size());
    Eigen::MatrixXd V(n, static_cast<Eigen::Index>(vectors.size()));
    for (size_t j = 0; j < vectors.size(); ++j) {
        COREMODAL_ASSERT(static_cast<Eigen::Index>(vectors[j].size()) == n);
        V.col(static_cast<Eigen::Index>(j)) = Eigen::Map<const Eigen::VectorXd>(vectors[j].data(), n);
    }
    Eigen::JacobiSVD<Eigen::MatrixXd> svd(V, Eigen::ComputeThinU);
    const Eigen::VectorXd& sigma = svd.singularValues();
    Eigen::Index rank = 0;
    while (rank < sigma.size() && sigma(rank) > kRankTolerance * sigma(0) && sigma(rank) > 0) ++rank;
    return svd.matrixU().leftCols(rank);
}

}  // namespace

double subspace_mac(const std::vector<Signature>& a, const std::vector<Signature>& b) {
    if (a.size() == 1 && b.size() == 1) return mac(a.front(), b.front());
    const Eigen::MatrixXd Qa = orthonormal_basis(a), Qb = orthonormal_basis(b);
    if (Qa.cols() == 0 || Qb.cols() == 0) return 0;
    COREMODAL_ASSERT(Qa.rows() == Qb.rows());
    const double overlap = (Qa.transpose() * Qb).squaredNorm();
    return overlap / static_cast<double>(std::max(Qa.cols(), Qb.cols()));
}

}  // namespace coremodal
