#include "models/response/response_loads.hpp"

#include "beam/beam_theory.hpp"
#include "beam/timoshenko_element.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "effects/excitation.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace coremodal {
namespace {

using cd = std::complex<double>;

int dof(int node, int d) { return beam_dof::per_node * node + d; }

// A load p on the x-z plane (ux, ry) turning forward with the roll: the y-z
// plane carries it a quarter turn later, uy = -i p_ux and rx = +i p_ry
// (the y-z plane's rotation is -rx; effects/excitation.hpp).
Eigen::VectorXcd turning(const Eigen::VectorXd& p) {
    Eigen::VectorXcd f = Eigen::VectorXcd::Zero(p.size());
    for (Eigen::Index node = 0; node * beam_dof::per_node < p.size(); ++node) {
        const int n = static_cast<int>(node);
        f(dof(n, beam_dof::ux)) = p(dof(n, beam_dof::ux));
        f(dof(n, beam_dof::ry)) = p(dof(n, beam_dof::ry));
        f(dof(n, beam_dof::uy)) = cd(0, -1) * p(dof(n, beam_dof::ux));
        f(dof(n, beam_dof::rx)) = cd(0, 1) * p(dof(n, beam_dof::ry));
    }
    return f;
}

// sum over the core's elements of K_e u_e, with each element's own section;
// with extra_EI > 0, only the part of K_e that bending stiffness extra_EI
// (N m^2) adds: K_e is linear in EI, and the element needs every stiffness
// positive, so that part is K_e(EI + extra_EI) - K_e(EI).
Eigen::VectorXd core_stiffness_load(const BeamNetwork& net, const Eigen::VectorXd& u, double extra_EI = 0) {
    const BeamNetwork::Beam& core = net.beams.front();
    Eigen::VectorXd out = Eigen::VectorXd::Zero(u.size());
    for (size_t e = 0; e < core.sections.size(); ++e) {
        const int nodes[kElementNodes] = {core.nodes[2 * e], core.nodes[2 * e + 1], core.nodes[2 * e + 2]};
        TimoshenkoElement element{net.node_z[nodes[2]] - net.node_z[nodes[0]], core.sections[e]};
        BeamElementMatrix K = element_matrices(element).K;
        if (extra_EI > 0) {
            element.section.EI += extra_EI;
            K = element_matrices(element).K - K;
        }
        Eigen::Matrix<double, kElementDofs, 1> ue;
        for (int i = 0; i < kElementDofs; ++i) ue(i) = u(dof(nodes[i / beam_dof::per_node], i % beam_dof::per_node));
        const Eigen::Matrix<double, kElementDofs, 1> fe = K * ue;
        for (int i = 0; i < kElementDofs; ++i) out(dof(nodes[i / beam_dof::per_node], i % beam_dof::per_node)) += fe(i);
    }
    return out;
}

// The bow along the core (ux and its slope ry), per network DOF.
Eigen::VectorXd bow_shape(const Scene& scene, const ExcitationSpec& x, const BeamNetwork& net,
                          const Eigen::VectorXd& first_bending) {
    Eigen::VectorXd u = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(net.held.size()));
    const double L = scene.core.length;
    if (x.bow_shape == BowShape::half_sine) {
        for (int node : net.beams.front().nodes) {
            u(dof(node, beam_dof::ux)) = half_sine_bow(x.bow_m, net.node_z[node], L);
            u(dof(node, beam_dof::ry)) = half_sine_bow_slope(x.bow_m, net.node_z[node], L);
        }
        return u;
    }
    // The first bending mode at rest: its plane's (w, phi), x-z (ux, ry) or y-z (uy, -rx).
    COREMODAL_ASSERT(first_bending.size() == u.size());
    const CorePoint mid = core_point(net, 0.5 * L);
    double wx = 0, wy = 0;
    for (int a = 0; a < 3; ++a) {
        wx += mid.shape[a] * first_bending(dof(mid.nodes[a], beam_dof::ux));
        wy += mid.shape[a] * first_bending(dof(mid.nodes[a], beam_dof::uy));
    }
    const bool in_x = std::abs(wx) >= std::abs(wy);
    const double scale = x.bow_m / (in_x ? wx : wy);
    for (int node : net.beams.front().nodes) {
        u(dof(node, beam_dof::ux)) = scale * first_bending(dof(node, in_x ? beam_dof::ux : beam_dof::uy));
        u(dof(node, beam_dof::ry)) = scale * (in_x ? 1.0 : -1.0) * first_bending(dof(node, in_x ? beam_dof::ry : beam_dof::rx));
    }
    return u;
}

// The static sag under gravity, per network DOF: K u = g M e, e = 1 on every ux.
Eigen::VectorXd gravity_sag(const LateralResponse& lateral) {
    const NetworkMatrices& m = lateral.matrices();
    Eigen::VectorXd e = Eigen::VectorXd::Zero(m.K.rows());
    for (size_t r = 0; r < m.free_dofs.size(); ++r)
        if (m.free_dofs[r] % beam_dof::per_node == beam_dof::ux) e(static_cast<Eigen::Index>(r)) = 1.0;
    const Eigen::VectorXd weight = kGravity * (m.M * e);
    return lateral.to_network(lateral.static_response(weight).cast<cd>()).real();
}

}  // namespace

void add_order_load(std::vector<OrderLoad>& orders, int order, const Eigen::VectorXcd& constant,
                    const Eigen::VectorXcd& per_spin2, const std::string& source) {
    auto it = std::find_if(orders.begin(), orders.end(), [&](const OrderLoad& o) { return o.order == order; });
    if (it == orders.end()) {
        orders.push_back({order, Eigen::VectorXcd::Zero(constant.size()), Eigen::VectorXcd::Zero(constant.size()), {}});
        it = std::prev(orders.end());
    }
    it->constant += constant;
    it->per_spin_squared += per_spin2;
    it->sources.push_back(source);
}

CorePoint core_point(const BeamNetwork& net, double z) {
    const BeamNetwork::Beam& core = net.beams.front();
    const size_t n_elements = core.sections.size();
    size_t e = 0;
    while (e + 1 < n_elements && net.node_z[core.nodes[2 * e + 2]] < z) ++e;
    CorePoint p;
    for (int a = 0; a < 3; ++a) p.nodes[a] = core.nodes[2 * e + a];
    const double z0 = net.node_z[p.nodes[0]], z2 = net.node_z[p.nodes[2]];
    const Eigen::RowVector3d N = element_shape(std::clamp((z - z0) / (z2 - z0), 0.0, 1.0));
    for (int a = 0; a < 3; ++a) p.shape[a] = N(a);
    return p;
}

ResponseLoads build_response_loads(const Scene& scene, const ExcitationSpec& x, const BeamNetwork& net,
                                   const LateralResponse& lateral, const Eigen::VectorXd& first_bending) {
    ResponseLoads out;
    const Eigen::Index n = static_cast<Eigen::Index>(net.held.size());
    const Eigen::VectorXcd zero = Eigen::VectorXcd::Zero(n);
    const double L = scene.core.length;
    if (x.unbalance_kg_m > 0) {  // U Omega^2 at mid-core, consistent with the element's shape functions
        Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
        const CorePoint mid = core_point(net, 0.5 * L);
        for (int a = 0; a < 3; ++a) p(dof(mid.nodes[a], beam_dof::ux)) += mid.shape[a] * x.unbalance_kg_m;
        add_order_load(out.orders, 1, zero, turning(p), Unbalance::kName);
    }
    if (x.eccentricity_m > 0) {  // rho_p A_p e Omega^2 per length: int N_a dz = (1, 4, 1) h / 6
        const double Do = scene.core.outer_diameter, Dp = scene.rest_paper->outer_diameter;
        const double per_length = scene.rest_paper->material.density * M_PI / 4 * (Dp * Dp - Do * Do) * x.eccentricity_m;
        Eigen::VectorXd p = Eigen::VectorXd::Zero(n);
        const BeamNetwork::Beam& core = net.beams.front();
        for (size_t e = 0; e < core.sections.size(); ++e) {
            const double h = net.node_z[core.nodes[2 * e + 2]] - net.node_z[core.nodes[2 * e]];
            const double w[3] = {h / 6, 4 * h / 6, h / 6};
            for (int a = 0; a < 3; ++a) p(dof(core.nodes[2 * e + a], beam_dof::ux)) += w[a] * per_length;
        }
        add_order_load(out.orders, 1, zero, turning(p), Eccentricity::kName);
    }
    if (x.bow_m > 0)
        add_order_load(out.orders, 1, turning(core_stiffness_load(net, bow_shape(scene, x, net, first_bending))), zero,
            Bow::kName);
    if (x.gravity) out.sag = gravity_sag(lateral);
    if (x.ovality_m > 0 && x.gravity) {
        out.ovality_split = ovality_stiffness_split(x.ovality_m, scene.core.outer_diameter, scene.core.inner_diameter);
        // The core's E_c I_c alone: the part the ovality splits.
        const double EIc = tube_beam_section(scene.core.outer_diameter, scene.core.inner_diameter, scene.core.material).EI;
        add_order_load(out.orders, 2, turning(out.ovality_split * core_stiffness_load(net, out.sag, EIc)), zero,
            OvalityGravity::kName);
        out.assumptions.push_back(
            "ovality: the core's wall is oval through its thickness (r = R + delta cos 2 theta, delta = ovality / 4), "
            "the rest paper round; eps = " + significant(out.ovality_split, 3) +
            " splits the core's E_c I_c; the order-2 load is eps K_EIc u_sag to first order in eps (effects/excitation.hpp)");
    }
    std::sort(out.orders.begin(), out.orders.end(), [](const OrderLoad& a, const OrderLoad& b) { return a.order < b.order; });
    return out;
}

}  // namespace coremodal
