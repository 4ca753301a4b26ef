#include "models/response/solid_loads.hpp"

#include "models/response/sparse_sink.hpp"
#include "assembly/cell_loop.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "effects/excitation.hpp"
#include "element/element.hpp"
#include "models/part_materials.hpp"
#include "models/solid/solid_level.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <functional>
#include <map>

namespace coremodal {
namespace {

using cd = std::complex<double>;

bool in_part(const SolidResponseModel& m, int cell, const std::string& part) {
    return m.mesh.part_names[m.mesh.cell_part[cell]] == part;
}

bool in_roll(const SolidResponseModel& m, int cell) { return in_part(m, cell, "core") || in_part(m, cell, "rest_paper"); }

Eigen::SparseMatrix<double> cells_matrix(const SolidResponseModel& m, const std::function<bool(int)>& take, Term term) {
    SparseSink sink(m.dofs.n_dofs);
    assemble_cells(m.mesh, m.materials, m.dofs, take, sink.insert());
    return sink.matrix(term);
}

// A load turning forward from its pattern in the x-z plane and the same a
// quarter turn later, in the y-z plane: Re((p_x - i p_y) e^{i omega t}).
Eigen::VectorXcd turning(const Eigen::VectorXd& in_x, const Eigen::VectorXd& in_y) {
    return in_x.cast<cd>() - cd(0, 1) * in_y.cast<cd>();
}

// The unit translation along x (axis 0) or y (1) of every node, frames included.
Eigen::VectorXd translation(const SolidResponseModel& m, int axis) {
    Eigen::VectorXd r = Eigen::VectorXd::Zero(m.dofs.n_dofs);
    for (int node = 0; node < static_cast<int>(m.mesh.nodes.size()); ++node)
        if (const int d = m.dofs.dof(node, axis); d >= 0) r(d) = 1;
    return r;
}

// K_roll u_bow element by element with the bowed axis at every node, held
// ones included (harmonic_loads.cpp says why): in the plane of `axis`,
// u_axis = w(z), u_z = -x_axis w'(z) (plane sections turned with the axis).
Eigen::VectorXd half_sine_bow_load(const SolidResponseModel& m, double bow_m, double length, int axis) {
    const int npc = m.mesh.nodes_per_cell();
    CellCoords coords(npc, 3);
    Eigen::MatrixXd K, M;
    Eigen::VectorXd u(3 * npc), f = Eigen::VectorXd::Zero(m.dofs.n_dofs);
    for (int c = 0; c < m.mesh.n_cells(); ++c) {
        if (!in_roll(m, c)) continue;
        const int* nodes = m.mesh.cell(c);
        u.setZero();
        for (int a = 0; a < npc; ++a) {
            for (int d = 0; d < 3; ++d) coords(a, d) = m.mesh.nodes[nodes[a]][d];
            u(3 * a + axis) = half_sine_bow(bow_m, coords(a, 2), length);
            u(3 * a + 2) = -coords(a, axis) * half_sine_bow_slope(bow_m, coords(a, 2), length);
        }
        const PartMaterial& mat = m.materials.at(m.mesh.cell_part[c]);
        element_matrices(m.mesh.cell_type, coords, mat.C_cylindrical, mat.density, K, M);
        const Eigen::VectorXd fe = K * u;
        for (int a = 0; a < npc; ++a)
            for (int d = 0; d < 3; ++d)
                if (const int dof = m.dofs.dof(nodes[a], d); dof >= 0) f(dof) += fe(3 * a + d);
    }
    return f;
}

// The first bending pair as the bow in each plane: the combination of its
// two members with no motion across that plane at mid-core, scaled to b
// along it there.
Eigen::VectorXcd first_mode_bow_load(const SolidResponseModel& m, double bow_m, double length,
                                     const Eigen::MatrixXd& pair) {
    COREMODAL_ASSERT(pair.cols() == 2 && pair.rows() == m.dofs.n_dofs);
    const ProbeWeights mid = solid_section_probe(m, 0.5 * length);
    const Eigen::VectorXd wx = mid.x.real(), wy = mid.y.real();
    const auto in_plane = [&](const Eigen::VectorXd& along, const Eigen::VectorXd& across) {
        const Eigen::VectorXd shape = across.dot(pair.col(1)) * pair.col(0) - across.dot(pair.col(0)) * pair.col(1);
        return Eigen::VectorXd(bow_m / along.dot(shape) * shape);
    };
    return turning(m.K_roll * in_plane(wx, wy), m.K_roll * in_plane(wy, wx));
}

std::vector<int> core_nodes(const SolidResponseModel& m) {
    std::vector<char> in(m.mesh.nodes.size(), 0);
    for (int c = 0; c < m.mesh.n_cells(); ++c)
        if (in_part(m, c, "core"))
            for (int a = 0; a < m.mesh.nodes_per_cell(); ++a) in[m.mesh.cell(c)[a]] = 1;
    std::vector<int> out;
    for (size_t n = 0; n < in.size(); ++n)
        if (in[n]) out.push_back(static_cast<int>(n));
    return out;
}

}  // namespace

PartStiffness solid_part_stiffness(const SolidResponseModel& m) {
    return {m.K.rows(), m.mesh.part_names,
            [&m](const std::string& part) { return cells_matrix(m, [&](int c) { return in_part(m, c, part); }, Term::stiffness); },
            "each part's cells (core, rest paper, chucks)"};
}

SolidResponseModel assemble_solid_response_model(const Scene& scene) {
    SolidResponseModel m;
    m.mesh = make_solid_mesh(scene);
    m.chucks = chuck_supports(scene, m.mesh);
    LevelModes summary;  // the model summary and warnings the run at rest reports; not repeated here
    m.dofs = solid_dofs(scene, m.mesh, m.chucks, summary);
    m.materials = part_materials(scene, m.mesh.part_names, "generated mesh");
    SparseSink whole(m.dofs.n_dofs);
    const auto every = [](int) { return true; };
    assemble_cells(m.mesh, m.materials, m.dofs, every, whole.insert(), {Term::gyroscopic});
    assemble_couplings(m.chucks.couplings, m.dofs, [](const std::vector<int>&) { return true; }, whole.insert());
    m.K = whole.matrix(Term::stiffness);
    m.M = whole.matrix(Term::mass);
    m.G = whole.matrix(Term::gyroscopic);  // every cell spins; the couplings do not
    m.K_roll = cells_matrix(m, [&](int c) { return in_roll(m, c); }, Term::stiffness);
    m.K_core = cells_matrix(m, [&](int c) { return in_part(m, c, "core"); }, Term::stiffness);
    m.M_rest_paper = cells_matrix(m, [&](int c) { return in_part(m, c, "rest_paper"); }, Term::mass);
    return m;
}

ProbeWeights solid_section_probe(const SolidResponseModel& m, double z) {
    constexpr double kSameLayer = 1e-9;  // m: nodes of one layer share their z exactly (extruded mesh)
    std::map<double, std::vector<int>> layers;  // z -> the core's nodes there
    for (int n : core_nodes(m)) layers[m.mesh.nodes[n][2]].push_back(n);
    auto above = layers.lower_bound(z - kSameLayer);
    if (above == layers.end() || (above == layers.begin() && above->first > z + kSameLayer))
        throw InputError("[response] probe at z = " + significant(z, 4) + " m is not on the core");
    auto below = above->first <= z + kSameLayer ? above : std::prev(above);
    const double t = above == below ? 0.0 : (z - below->first) / (above->first - below->first);
    ProbeWeights w{Eigen::VectorXcd::Zero(m.dofs.n_dofs), Eigen::VectorXcd::Zero(m.dofs.n_dofs)};
    for (const auto& [layer, share] : {std::pair{below, 1 - t}, std::pair{above, t}}) {
        if (share == 0) continue;
        for (int n : layer->second)
            for (int axis = 0; axis < 2; ++axis)
                if (const int d = m.dofs.dof(n, axis); d >= 0)
                    (axis == 0 ? w.x : w.y)(d) += share / static_cast<double>(layer->second.size());
    }
    return w;
}

LevelLoads build_solid_loads(const Scene& scene, const ExcitationSpec& x, const SolidResponseModel& m,
                             const ModalResponse& response, const Eigen::MatrixXd& first_pair) {
    LevelLoads out;
    const Eigen::VectorXcd zero = Eigen::VectorXcd::Zero(m.dofs.n_dofs);
    const double L = scene.core.length;
    const Eigen::VectorXd r_x = translation(m, 0), r_y = translation(m, 1);
    if (x.unbalance_kg_m > 0) {  // U Omega^2 on the core's cross-section at mid-core
        const ProbeWeights mid = solid_section_probe(m, 0.5 * L);
        add_order_load(out.orders, 1, zero, x.unbalance_kg_m * turning(mid.x.real(), mid.y.real()), Unbalance::kName);
    }
    if (x.eccentricity_m > 0)  // the rest paper's mass, e Omega^2 sideways
        add_order_load(out.orders, 1, zero, x.eccentricity_m * turning(m.M_rest_paper * r_x, m.M_rest_paper * r_y),
                       Eccentricity::kName);
    if (x.bow_m > 0)
        add_order_load(out.orders, 1,
                       x.bow_shape == BowShape::half_sine
                           ? turning(half_sine_bow_load(m, x.bow_m, L, 0), half_sine_bow_load(m, x.bow_m, L, 1))
                           : first_mode_bow_load(m, x.bow_m, L, first_pair),
                       zero, Bow::kName);
    if (x.gravity) out.sag = response.static_response(kGravity * (m.M * r_x));
    if (x.ovality_m > 0 && x.gravity) {
        out.ovality_split = ovality_stiffness_split(x.ovality_m, scene.core.outer_diameter, scene.core.inner_diameter);
        const Eigen::VectorXd sag_y = response.static_response(kGravity * (m.M * r_y));
        add_ovality_load(out, turning(m.K_core * out.sag, m.K_core * sag_y),
                         "turning at twice the speed, to first order in eps (the wall's own ovalling is not loaded)");
    }
    sort_orders(out);
    return out;
}

}  // namespace coremodal
