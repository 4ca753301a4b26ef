#include "beam/beam_network.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace coremodal {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Entries between two families below this share of their diagonals are
// rounding (e.g. the integral of sin(theta) over a pad centred on theta = 0),
// not a coupling; mirror images agree to the same share.
constexpr double kRoundingShare = 1e-12;

// Where every network DOF goes: which problem and which row (-1: held, or in
// no wanted problem). Rows are numbered node by node along z, so that each
// K and M is banded (beams and springs only join nodes near each other in z)
// and factors without a fill-reducing ordering.
struct Placement {
    std::vector<int> problem, row;
    std::vector<std::vector<int>> dofs;  // network DOF of each row, per problem
};

Placement place_dofs(const BeamNetwork& net, const std::vector<FamilySet>& sets) {
    std::vector<int> nodes(net.node_z.size());
    std::iota(nodes.begin(), nodes.end(), 0);
    std::stable_sort(nodes.begin(), nodes.end(), [&](int a, int b) { return net.node_z[a] < net.node_z[b]; });
    Placement p{std::vector<int>(net.held.size(), -1), std::vector<int>(net.held.size(), -1),
                std::vector<std::vector<int>>(sets.size())};
    for (int node : nodes)
        for (int d = beam_dof::per_node * node; d < beam_dof::per_node * (node + 1); ++d) {
            if (net.held[d]) continue;
            for (size_t s = 0; s < sets.size(); ++s)
                if (sets[s] & family_bit(motion_family(d))) {
                    p.problem[d] = static_cast<int>(s);
                    p.row[d] = static_cast<int>(p.dofs[s].size());
                    p.dofs[s].push_back(d);
                }
        }
    return p;
}

// The six DOFs of each node in `nodes`, in order.
template <size_t N>
std::array<int, 6 * N> dofs_of(const std::array<int, N>& nodes) {
    std::array<int, 6 * N> out{};
    for (size_t a = 0; a < N; ++a)
        for (int d = 0; d < beam_dof::per_node; ++d) out[6 * a + d] = beam_dof::per_node * nodes[a] + d;
    return out;
}

// Adds local matrices into the triplets of the problems their DOFs belong
// to (entries joining two problems are zero: the problems are independent).
struct Assembler {
    const Placement& place;
    std::vector<Triplets> K, M;

    explicit Assembler(const Placement& p) : place(p), K(p.dofs.size()), M(p.dofs.size()) {}

    // K and M entries at once; where only one of them has an entry the other
    // gets an explicit zero: K and M share one pattern, so K - lambda M is a
    // sum of value arrays and every shift factors on one symbolic analysis.
    template <typename MatrixK, typename MatrixM, size_t N>
    void add(const MatrixK& k, const MatrixM& m, const std::array<int, N>& dofs) {
        for (size_t i = 0; i < N; ++i) {
            const int problem = place.problem[dofs[i]];
            if (problem < 0) continue;
            for (size_t j = 0; j < N; ++j)
                if (place.problem[dofs[j]] == problem && (k(i, j) != 0.0 || m(i, j) != 0.0)) {
                    K[problem].emplace_back(place.row[dofs[i]], place.row[dofs[j]], k(i, j));
                    M[problem].emplace_back(place.row[dofs[i]], place.row[dofs[j]], m(i, j));
                }
        }
    }
    template <typename Matrix, size_t N>
    void add_stiffness(const Matrix& k, const std::array<int, N>& dofs) {
        add(k, Matrix::Zero(), dofs);
    }
};

TimoshenkoElement element_of(const BeamNetwork& net, const BeamNetwork::Beam& beam, size_t e) {
    return {net.node_z[beam.nodes[2 * e + 2]] - net.node_z[beam.nodes[2 * e]], beam.sections[e]};
}

std::array<int, kElementNodes> element_nodes(const BeamNetwork::Beam& beam, size_t e) {
    return {beam.nodes[2 * e], beam.nodes[2 * e + 1], beam.nodes[2 * e + 2]};
}

// The element of `beam` holding z (the first one, at a shared end).
size_t element_containing(const BeamNetwork& net, const BeamNetwork::Beam& beam, double z) {
    for (size_t e = 0; e < beam.sections.size(); ++e)
        if (z >= net.node_z[beam.nodes[2 * e]] && z <= net.node_z[beam.nodes[2 * e + 2]]) return e;
    COREMODAL_ASSERT(!"coupling range outside its beam");
    return 0;
}

void check_beam(const BeamNetwork& net, const BeamNetwork::Beam& beam) {
    COREMODAL_ASSERT(!beam.sections.empty() && beam.nodes.size() == 2 * beam.sections.size() + 1);
    for (size_t e = 0; e < beam.sections.size(); ++e) {
        const double z0 = net.node_z[beam.nodes[2 * e]], z1 = net.node_z[beam.nodes[2 * e + 2]];
        COREMODAL_ASSERT(z1 > z0);
        COREMODAL_ASSERT(std::abs(net.node_z[beam.nodes[2 * e + 1]] - 0.5 * (z0 + z1)) <= 1e-9 * (z1 - z0));
    }
}

void add_beam(Assembler& out, const BeamNetwork& net, const BeamNetwork::Beam& beam) {
    check_beam(net, beam);
    for (size_t e = 0; e < beam.sections.size(); ++e) {
        const ElementMatrices m = element_matrices(element_of(net, beam, e));
        const auto dofs = dofs_of<kElementNodes>(element_nodes(beam, e));
        out.add(m.K, m.M, dofs);
    }
}

// One piece of a coupling: the weights int N_i N_j dz of its nodes (signed
// by the beam they belong to) times the 6x6 per length, into K.
template <int n_nodes>
void add_coupling_piece(Assembler& out, const Eigen::Matrix<double, n_nodes, n_nodes>& weights, const Matrix6& k,
                        const std::array<int, n_nodes>& nodes) {
    Eigen::Matrix<double, 6 * n_nodes, 6 * n_nodes> local;
    for (int i = 0; i < n_nodes; ++i)
        for (int j = 0; j < n_nodes; ++j) local.template block<6, 6>(6 * i, 6 * j) = weights(i, j) * k;
    out.add_stiffness(local, dofs_of<n_nodes>(nodes));
}

// Integrates d^T k d over the coupling range, d = N_b q_b - N_a q_a (or
// -N_a q_a to the ground), piece by piece between the nodes of both beams
// (each piece inside one element of each), with 3-point Gauss: exact for the
// quadratic shape functions. Every motion is interpolated alike (N = N_node
// I_6), so each pair of nodes adds the 6x6 block (sign N_i)(sign N_j) k.
void add_coupling(Assembler& out, const BeamNetwork& net, const BeamNetwork::Coupling& c) {
    const std::array<double, 3> g = {0.5 - 0.5 * std::sqrt(0.6), 0.5, 0.5 + 0.5 * std::sqrt(0.6)};
    const std::array<double, 3> w = {5.0 / 18, 8.0 / 18, 5.0 / 18};
    const BeamNetwork::Beam& a = net.beams.at(c.beam_a);
    const BeamNetwork::Beam* b = c.beam_b >= 0 ? &net.beams.at(c.beam_b) : nullptr;  // null: the ground
    std::vector<double> cuts = {c.z_start, c.z_end};
    for (const auto* beam : {&a, b})
        if (beam)
            for (int n : beam->nodes)
                if (net.node_z[n] > c.z_start && net.node_z[n] < c.z_end) cuts.push_back(net.node_z[n]);
    std::sort(cuts.begin(), cuts.end());
    constexpr int n3 = kElementNodes, n6 = 2 * kElementNodes;
    for (size_t p = 0; p + 1 < cuts.size(); ++p) {
        const double z0 = cuts[p], h = cuts[p + 1] - z0;
        if (h <= 1e-12 * (c.z_end - c.z_start)) continue;
        const size_t ea = element_containing(net, a, z0 + h / 2);
        const TimoshenkoElement el_a = element_of(net, a, ea);
        const double za = net.node_z[a.nodes[2 * ea]];
        const auto na = element_nodes(a, ea);
        if (!b) {
            Eigen::Matrix<double, n3, n3> weights = Eigen::Matrix<double, n3, n3>::Zero();
            for (size_t q = 0; q < g.size(); ++q) {
                const Eigen::Matrix<double, 1, n3> N = element_shape((z0 + g[q] * h - za) / el_a.length);
                weights += w[q] * h * N.transpose() * N;
            }
            add_coupling_piece<n3>(out, weights, c.stiffness_per_length, na);
            continue;
        }
        const size_t eb = element_containing(net, *b, z0 + h / 2);
        const TimoshenkoElement el_b = element_of(net, *b, eb);
        const double zb = net.node_z[b->nodes[2 * eb]];
        Eigen::Matrix<double, n6, n6> weights = Eigen::Matrix<double, n6, n6>::Zero();
        for (size_t q = 0; q < g.size(); ++q) {
            const double z = z0 + g[q] * h;
            Eigen::Matrix<double, 1, n6> N;
            N << -element_shape((z - za) / el_a.length), element_shape((z - zb) / el_b.length);
            weights += w[q] * h * N.transpose() * N;
        }
        const auto nb = element_nodes(*b, eb);
        add_coupling_piece<n6>(out, weights, c.stiffness_per_length, {na[0], na[1], na[2], nb[0], nb[1], nb[2]});
    }
}

void add_spring(Assembler& out, const BeamNetwork::Spring& s) {
    if (s.node_b < 0) {
        out.add_stiffness(s.stiffness, dofs_of<1>({s.node_a}));
        return;
    }
    Eigen::Matrix<double, 12, 12> local;
    local << s.stiffness, -s.stiffness, -s.stiffness, s.stiffness;
    out.add_stiffness(local, dofs_of<2>({s.node_a, s.node_b}));
}

void add_point_mass(Assembler& out, const BeamNetwork::PointMass& m) {
    Matrix6 local = Matrix6::Zero();
    for (int d : {beam_dof::ux, beam_dof::uy, beam_dof::uz}) local(d, d) = m.mass;
    out.add(Matrix6::Zero(), local, dofs_of<1>({m.node}));
}

// Every 6x6 stiffness the network holds besides its beams (and a coupling's
// per-length one stands for its integral: same pattern).
std::vector<const Matrix6*> spring_matrices(const BeamNetwork& net) {
    std::vector<const Matrix6*> out;
    for (const auto& c : net.couplings) out.push_back(&c.stiffness_per_length);
    for (const auto& s : net.springs) out.push_back(&s.stiffness);
    return out;
}

bool negligible(double value, const Matrix6& k, int i, int j) {
    return std::abs(value) <= kRoundingShare * std::sqrt(std::abs(k(i, i) * k(j, j)));
}

}  // namespace

MotionFamily motion_family(int network_dof) {
    switch (network_dof % beam_dof::per_node) {
        case beam_dof::ux:
        case beam_dof::ry:
            return MotionFamily::bending_xz;
        case beam_dof::uy:
        case beam_dof::rx:
            return MotionFamily::bending_yz;
        case beam_dof::uz:
            return MotionFamily::axial;
        default:
            return MotionFamily::torsion;
    }
}

int BeamNetwork::add_node(double z) {
    node_z.push_back(z);
    held.resize(held.size() + beam_dof::per_node, false);
    return n_nodes() - 1;
}

void BeamNetwork::hold_all(int node) {
    for (int d = 0; d < beam_dof::per_node; ++d) hold(node, d);
}

int BeamNetwork::n_elements() const {
    int n = 0;
    for (const Beam& b : beams) n += static_cast<int>(b.sections.size());
    return n;
}

double BeamNetwork::mass() const {
    double m = 0;
    for (const Beam& b : beams)
        for (size_t e = 0; e < b.sections.size(); ++e)
            m += b.sections[e].rho_A * (node_z[b.nodes[2 * e + 2]] - node_z[b.nodes[2 * e]]);
    for (const PointMass& p : masses) m += p.mass;
    return m;
}

FamilySet family_bit(MotionFamily f) { return 1u << static_cast<unsigned>(f); }

std::vector<FamilySet> independent_family_sets(const BeamNetwork& net) {
    std::array<int, kMotionFamilies> root = {0, 1, 2, 3};
    const auto find = [&root](int f) {
        while (root[f] != f) f = root[f];
        return f;
    };
    for (const Matrix6* k : spring_matrices(net))
        for (int i = 0; i < beam_dof::per_node; ++i)
            for (int j = 0; j < beam_dof::per_node; ++j) {
                const int a = find(static_cast<int>(motion_family(i))), b = find(static_cast<int>(motion_family(j)));
                if (a != b && !negligible((*k)(i, j), *k, i, j)) root[std::max(a, b)] = std::min(a, b);
            }
    std::vector<FamilySet> sets;
    for (int f = 0; f < kMotionFamilies; ++f) {
        if (find(f) != f) continue;
        FamilySet set = 0;
        for (int g = 0; g < kMotionFamilies; ++g)
            if (find(g) == f) set |= family_bit(static_cast<MotionFamily>(g));
        sets.push_back(set);
    }
    return sets;
}

bool bending_planes_alike(const BeamNetwork& net) {
    using namespace beam_dof;
    // (w, phi) of the x-z plane is (ux, ry), of the y-z plane (uy, -rx).
    for (const Matrix6* k : spring_matrices(net)) {
        const Matrix6& m = *k;
        const auto same = [&](double a, double b, int i, int j) { return negligible(a - b, m, i, j); };
        if (!same(m(ux, ux), m(uy, uy), ux, ux) || !same(m(ry, ry), m(rx, rx), ry, ry) ||
            !same(m(ux, ry), -m(uy, rx), ux, ry))
            return false;
    }
    for (int node = 0; node < net.n_nodes(); ++node) {
        const auto held = [&](int d) { return net.held[per_node * node + d]; };
        if (held(ux) != held(uy) || held(ry) != held(rx)) return false;
    }
    return true;
}

std::vector<NetworkMatrices> assemble_problems(const BeamNetwork& net, const std::vector<FamilySet>& sets) {
    COREMODAL_ASSERT(net.held.size() == size_t(beam_dof::per_node) * net.node_z.size());
    const Placement place = place_dofs(net, sets);
    Assembler out(place);
    for (const auto& beam : net.beams) add_beam(out, net, beam);
    for (const auto& c : net.couplings) add_coupling(out, net, c);
    for (const auto& s : net.springs) add_spring(out, s);
    for (const auto& m : net.masses) add_point_mass(out, m);
    std::vector<NetworkMatrices> problems(sets.size());
    for (size_t p = 0; p < sets.size(); ++p) {
        const auto n = static_cast<Eigen::Index>(place.dofs[p].size());
        problems[p].free_dofs = place.dofs[p];
        problems[p].K.resize(n, n);
        problems[p].M.resize(n, n);
        problems[p].K.setFromTriplets(out.K[p].begin(), out.K[p].end());
        problems[p].M.setFromTriplets(out.M[p].begin(), out.M[p].end());
    }
    return problems;
}

NetworkMatrices assemble_network(const BeamNetwork& net) { return assemble_problems(net, {kAllFamilies}).front(); }

}  // namespace coremodal
