#include "models/solid/predicted_start.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>

namespace coremodal {
namespace {

// The revolved mesh as a table: the node of section node s at plane t
// (planes at theta = 2 pi t / n_planes; one node at t = 0 on the axis).
struct Planes {
    int n_planes = 0;
    std::vector<int> section_nodes;         // the distinct section nodes, ascending
    std::map<int, int> row;                 // section node -> its row in `at`
    std::vector<std::array<double, 2>> rz;  // per row
    std::vector<std::vector<int>> at;       // per row: node per plane (-1: none)
};

Planes planes_of(const RevolvedMesh& revolved) {
    Planes p;
    double smallest = 2 * M_PI;
    for (double theta : revolved.theta)
        if (theta > 1e-12) smallest = std::min(smallest, theta);
    p.n_planes = std::max(1, int(std::lround(2 * M_PI / smallest)));
    for (std::size_t i = 0; i < revolved.section_node.size(); ++i) {
        const int s = revolved.section_node[i];
        auto [it, added] = p.row.emplace(s, int(p.at.size()));
        if (added) {
            p.at.emplace_back(p.n_planes, -1);
            const auto& x = revolved.mesh.nodes[i];
            p.rz.push_back({std::hypot(x[0], x[1]), x[2]});
        }
        const int t = int(std::lround(revolved.theta[i] * p.n_planes / (2 * M_PI))) % p.n_planes;
        p.at[it->second][t] = int(i);
    }
    return p;
}

// The row of the section node nearest (r, z): a uniform grid of buckets
// over the section, searched ring by ring outwards.
class NearestSectionNode {
public:
    explicit NearestSectionNode(const std::vector<std::array<double, 2>>& rz) : rz_(rz) {
        for (const auto& p : rz) {
            lo_ = {std::min(lo_[0], p[0]), std::min(lo_[1], p[1])};
            hi_ = {std::max(hi_[0], p[0]), std::max(hi_[1], p[1])};
        }
        const double area = std::max((hi_[0] - lo_[0]) * (hi_[1] - lo_[1]), 1e-30);
        h_ = std::max(std::sqrt(area / double(std::max<std::size_t>(rz.size(), 1))), 1e-12);
        nx_ = int((hi_[0] - lo_[0]) / h_) + 1;
        ny_ = int((hi_[1] - lo_[1]) / h_) + 1;
        bucket_.resize(std::size_t(nx_) * ny_);
        for (std::size_t i = 0; i < rz.size(); ++i)
            bucket_[index(cell(rz[i][0], 0), cell(rz[i][1], 1))].push_back(int(i));
    }

    int operator()(double r, double z) const {
        const int cx = cell(r, 0), cy = cell(z, 1);
        int best = -1;
        double best_d2 = std::numeric_limits<double>::max();
        for (int ring = 0; ring <= std::max(nx_, ny_); ++ring) {
            for (int ix = cx - ring; ix <= cx + ring; ++ix)
                for (int iy = cy - ring; iy <= cy + ring; ++iy) {
                    if (std::max(std::abs(ix - cx), std::abs(iy - cy)) != ring) continue;
                    if (ix < 0 || iy < 0 || ix >= nx_ || iy >= ny_) continue;
                    for (int i : bucket_[index(ix, iy)]) {
                        const double d2 = std::pow(rz_[i][0] - r, 2) + std::pow(rz_[i][1] - z, 2);
                        if (d2 < best_d2) best_d2 = d2, best = i;
                    }
                }
            // Every point beyond this ring is at least ring * h away.
            if (best >= 0 && std::sqrt(best_d2) <= ring * h_) break;
        }
        return best;
    }

private:
    int cell(double v, int axis) const {
        const int n = axis == 0 ? nx_ : ny_;
        return std::clamp(int((v - lo_[axis]) / h_), 0, n - 1);
    }
    std::size_t index(int ix, int iy) const { return std::size_t(ix) * ny_ + iy; }

    const std::vector<std::array<double, 2>>& rz_;
    std::array<double, 2> lo_{std::numeric_limits<double>::max(), std::numeric_limits<double>::max()};
    std::array<double, 2> hi_{std::numeric_limits<double>::lowest(), std::numeric_limits<double>::lowest()};
    double h_ = 1;
    int nx_ = 1, ny_ = 1;
    std::vector<std::vector<int>> bucket_;
};

// (u_r, u_theta, u_z) of a Cartesian displacement at angle theta.
std::array<double, 3> cylindrical(const double* u, double theta) {
    const double c = std::cos(theta), s = std::sin(theta);
    return {c * u[0] + s * u[1], -s * u[0] + c * u[1], u[2]};
}

}  // namespace

std::vector<PetscVector> harmonic_modes_on_solid(const RevolvedMesh& revolved, const std::vector<Mode>& modes,
                                                 const Mesh& solid, const DofMap& dofs, Mat K) {
    if (mpi_size(PetscObjectComm((PetscObject)K)) > 1 || modes.empty()) return {};
    const std::size_t shape_size = 3 * revolved.mesh.nodes.size();
    for (const Mode& m : modes)
        if (m.shape.size() != shape_size) return {};
    const Planes planes = planes_of(revolved);
    const NearestSectionNode nearest(planes.rz);
    std::vector<PetscVector> out(modes.size());
    std::vector<PetscScalar*> x(modes.size());
    for (std::size_t k = 0; k < modes.size(); ++k) {
        COREMODAL_PETSC(MatCreateVecs(K, out[k].out(), nullptr));
        COREMODAL_PETSC(VecSet(out[k], 0.0));
        COREMODAL_PETSC(VecGetArray(out[k], &x[k]));
    }
    const double step = 2 * M_PI / planes.n_planes;
    for (int node = 0; node < solid.n_nodes(); ++node) {
        if (dofs.node_first_dof[node] < 0) continue;
        const auto& p = solid.nodes[node];
        const double r = std::hypot(p[0], p[1]);
        double theta = std::atan2(p[1], p[0]);
        if (theta < 0) theta += 2 * M_PI;
        const std::vector<int>& at = planes.at[nearest(r, p[2])];
        // The present planes on either side: a section corner node turns into
        // every plane, a mid-side node into every other one, an axis node
        // into one (its displacement then taken as it is).
        const int n = planes.n_planes;
        int t0 = int(theta / step) % n, t1 = (t0 + 1) % n, back = 0, ahead = 0;
        while (at[t0] < 0 && back < n) t0 = (t0 + n - 1) % n, ++back;
        while (at[t1] < 0 && ahead < n) t1 = (t1 + 1) % n, ++ahead;
        if (at[t0] < 0) continue;
        if (t0 == t1 || at[t1] < 0) {
            for (std::size_t k = 0; k < modes.size(); ++k)
                for (int i = 0; i < 3; ++i) x[k][dofs.dof(node, i)] = modes[k].shape[3 * std::size_t(at[t0]) + i];
            continue;
        }
        const double gap = ((t1 - t0 + n) % n) * step, past = std::fmod(theta - t0 * step + 2 * M_PI, 2 * M_PI);
        const double w = std::clamp(past / gap, 0.0, 1.0);
        const int a = at[t0], b = at[t1];
        const double c = std::cos(theta), s = std::sin(theta);
        for (std::size_t k = 0; k < modes.size(); ++k) {
            const std::array<double, 3> ua = cylindrical(&modes[k].shape[3 * std::size_t(a)], t0 * step);
            const std::array<double, 3> ub = cylindrical(&modes[k].shape[3 * std::size_t(b)], t1 * step);
            std::array<double, 3> u;
            for (int i = 0; i < 3; ++i) u[i] = (1 - w) * ua[i] + w * ub[i];
            const double cart[3] = {c * u[0] - s * u[1], s * u[0] + c * u[1], u[2]};
            for (int i = 0; i < 3; ++i) x[k][dofs.dof(node, i)] = cart[i];
        }
    }
    for (std::size_t k = 0; k < modes.size(); ++k) COREMODAL_PETSC(VecRestoreArray(out[k], &x[k]));
    return out;
}

}  // namespace coremodal
