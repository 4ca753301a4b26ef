#include "winder/winder_model.hpp"

#include "beam/beam_theory.hpp"
#include "common/error.hpp"
#include "common/format.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>

namespace coremodal {
namespace {

using Triplets = std::vector<Eigen::Triplet<double>>;

// Break points closer than this (m) are one node.
constexpr double kSameZ = 1e-9;
// Every stretch between break points (roll edges, bearings, mid-span) gets
// at least this many elements: a nip layer bends the drum over a decay
// length of the order of a roll's width, which one element cannot follow
// (the beam model's rule, beam/beam_model.cpp).
constexpr int kMinElementsPerGap = 2;
// Elements of a roll modelled as a beam (its bending over 1-2 m of width).
constexpr int kRollBeamElements = 4;
// Rigid-body DOFs of a rigid roll: ux0, uy0, theta_x, theta_y.
constexpr int kRigidDofs = 4;

double ring_area(double d_out, double d_in) { return M_PI / 4 * (d_out * d_out - d_in * d_in); }

// A paper roll's section: the core and the paper of diameter d around it.
BeamSection roll_section(const WinderScene& s, double d) {
    const WinderRolls& r = s.rolls;
    OrthotropicMaterial paper = winder_material(r.paper_material);
    paper.density = r.paper_density;
    BeamSection section = tube_beam_section(r.core_outer_diameter, r.core_inner_diameter, winder_material(r.core_material));
    if (d > r.core_outer_diameter) section += tube_beam_section(d, r.core_outer_diameter, paper);
    return section;
}

// z of roll j's ends: the row of rolls centred on the drums.
std::pair<double, double> roll_extent(const WinderScene& s, int j) {
    const WinderRolls& r = s.rolls;
    const double row = r.count * r.width + (r.count - 1) * r.gap;
    const double z0 = 0.5 * (s.drums.length - row) + j * (r.width + r.gap);
    return {z0, z0 + r.width};
}

std::vector<double> roll_edges(const WinderScene& s) {
    std::vector<double> edges;
    for (int j = 0; j < s.rolls.count; ++j) {
        const auto [z0, z1] = roll_extent(s, j);
        edges.push_back(z0), edges.push_back(z1);
    }
    return edges;
}

Matrix6 translation_spring(double kx, double ky) {
    Matrix6 k = Matrix6::Zero();
    k(beam_dof::ux, beam_dof::ux) = kx;
    k(beam_dof::uy, beam_dof::uy) = ky;
    return k;
}

// k n n^T on (ux, uy): a spring along the unit vector n only.
Matrix6 directed_spring(double k, const std::array<double, 2>& n) {
    Matrix6 m = Matrix6::Zero();
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) m(i, j) = k * n[i] * n[j];
    return m;
}

int add_tube(WinderModel& m, std::string name, BodyKind kind, const std::vector<double>& ends, const BeamSection& s) {
    const int beam = m.network.add_beam(name, ends, std::vector<BeamSection>(ends.size() - 1, s),
                                        [&](double z) { return m.network.add_node(z); });
    m.bodies.push_back({std::move(name), kind, beam, ends.front(), ends.back()});
    return beam;
}

int node_near(const BeamNetwork& net, int beam, double z) {
    for (int n : net.beams[beam].nodes)
        if (std::abs(net.node_z[n] - z) < kSameZ) return n;
    COREMODAL_ASSERT(!"no node at the requested z");
    return -1;
}

void add_drums(WinderModel& m, const WinderScene& s) {
    const WinderDrums& d = s.drums;
    const double L = d.length;
    std::vector<double> breaks = roll_edges(s);
    breaks.push_back(0.5 * L);
    const std::vector<double> ends = element_ends(0.0, L, breaks, d.elements);
    const BeamSection section = tube_beam_section(d.outer_diameter, d.outer_diameter - 2 * d.wall, winder_material(d.material));
    for (int side = 0; side < 2; ++side) {
        const int beam = add_tube(m, side == 0 ? "front drum" : "rear drum", BodyKind::drum, ends, section);
        const auto& nodes = m.network.beams[beam].nodes;
        const Matrix6 bearing = translation_spring(d.bearing_stiffness_horizontal, d.bearing_stiffness_vertical);
        m.network.springs.push_back({nodes.front(), -1, bearing});
        m.network.springs.push_back({nodes.back(), -1, bearing});
        m.drum_centre_node[side] = node_near(m.network, beam, 0.5 * L);
    }
}

void add_rider(WinderModel& m, const WinderScene& s) {
    const WinderRider& r = s.rider;
    const double z0 = 0.5 * (s.drums.length - r.length), z1 = z0 + r.length;
    const std::vector<double> ends = element_ends(z0, z1, roll_edges(s), r.elements);
    const BeamSection section = tube_beam_section(r.outer_diameter, r.outer_diameter - 2 * r.wall, winder_material(r.material));
    const int beam = add_tube(m, "rider", BodyKind::rider, ends, section);
    const auto& nodes = m.network.beams[beam].nodes;
    const Matrix6 support = translation_spring(r.support_stiffness, r.support_stiffness);
    m.network.springs.push_back({nodes.front(), -1, support});
    m.network.springs.push_back({nodes.back(), -1, support});
}

void add_rolls_and_nips(WinderModel& m, const WinderScene& s, double d) {
    const BeamSection section = roll_section(s, d);
    // One element holds a rigid roll's motion exactly; a roll beam bends over several.
    const int elements = s.rolls.model == RollModel::rigid ? 1 : kRollBeamElements;
    const double k_drum = m.state.drum_nip.stiffness_per_length, k_rider = m.state.rider_nip.stiffness_per_length;
    const auto front = nip_direction(m.state.geometry, DrumSide::front);
    const auto rear = nip_direction(m.state.geometry, DrumSide::rear);
    for (int j = 0; j < s.rolls.count; ++j) {
        const auto [z0, z1] = roll_extent(s, j);
        std::vector<double> ends;
        for (int e = 0; e <= elements; ++e) ends.push_back(e == elements ? z1 : z0 + (z1 - z0) * e / elements);
        const int roll = add_tube(m, "roll " + std::to_string(j + 1), BodyKind::roll, ends, section);
        m.network.couplings.push_back({m.bodies[0].beam, roll, z0, z1, directed_spring(k_drum, front)});
        m.network.couplings.push_back({m.bodies[1].beam, roll, z0, z1, directed_spring(k_drum, rear)});
        if (k_rider > 0) m.network.couplings.push_back({roll, m.bodies[2].beam, z0, z1, directed_spring(k_rider, {0.0, 1.0})});
    }
}

constexpr FamilySet kBending = 0b0011;  // bending_xz | bending_yz (beam_network.hpp)

// T: identity on every DOF outside a rigid roll; a rigid roll's node DOFs
// follow its centre's rigid-body DOFs, ux = ux0 + theta_y (z - zc),
// uy = uy0 - theta_x (z - zc), rx = theta_x, ry = theta_y (ry = dux/dz and
// rx = -duy/dz without shear, timoshenko_element.hpp).
void reduce(WinderModel& m, const WinderScene& s, const NetworkMatrices& full, const NetworkMatrices& structure) {
    std::map<int, int> rigid_roll_of_node;  // node -> body
    if (s.rolls.model == RollModel::rigid)
        for (size_t b = 0; b < m.bodies.size(); ++b)
            if (m.bodies[b].kind == BodyKind::roll)
                for (int n : m.network.beams[m.bodies[b].beam].nodes) rigid_roll_of_node[n] = static_cast<int>(b);
    std::map<int, int> body_of_node, first_rigid_column;
    for (size_t b = 0; b < m.bodies.size(); ++b)
        for (int n : m.network.beams[m.bodies[b].beam].nodes) body_of_node[n] = static_cast<int>(b);
    Triplets t;
    int column = 0;
    for (size_t row = 0; row < full.free_dofs.size(); ++row) {
        const int node = full.free_dofs[row] / beam_dof::per_node;
        if (rigid_roll_of_node.count(node)) continue;
        t.emplace_back(static_cast<int>(row), column++, 1.0);
        m.body_of.push_back(body_of_node.at(node));
    }
    for (size_t b = 0; b < m.bodies.size(); ++b)
        if (m.bodies[b].kind == BodyKind::roll && s.rolls.model == RollModel::rigid) {
            first_rigid_column[static_cast<int>(b)] = column;
            for (int k = 0; k < kRigidDofs; ++k) m.body_of.push_back(static_cast<int>(b));
            column += kRigidDofs;
        }
    for (size_t row = 0; row < full.free_dofs.size(); ++row) {
        const int node = full.free_dofs[row] / beam_dof::per_node, dof = full.free_dofs[row] % beam_dof::per_node;
        const auto it = rigid_roll_of_node.find(node);
        if (it == rigid_roll_of_node.end()) continue;
        const WinderBody& body = m.bodies[it->second];
        const int c = first_rigid_column.at(it->second);  // ux0, uy0, theta_x, theta_y
        const double arm = m.network.node_z[node] - 0.5 * (body.z_start + body.z_end);
        const int r = static_cast<int>(row);
        if (dof == beam_dof::ux) t.emplace_back(r, c, 1.0), t.emplace_back(r, c + 3, arm);
        if (dof == beam_dof::uy) t.emplace_back(r, c + 1, 1.0), t.emplace_back(r, c + 2, -arm);
        if (dof == beam_dof::rx) t.emplace_back(r, c + 2, 1.0);
        if (dof == beam_dof::ry) t.emplace_back(r, c + 3, 1.0);
    }
    m.T.resize(static_cast<Eigen::Index>(full.free_dofs.size()), column);
    m.T.setFromTriplets(t.begin(), t.end());
    m.network_dofs = full.free_dofs;
    // A rigid roll has no strain energy: its element's stiffness (zero for
    // rigid motion but for rounding) is taken out before the reduction.
    Eigen::SparseMatrix<double> rolls_own = structure.K;
    rolls_own.prune([&](Eigen::Index i, Eigen::Index j, double) {
        return rigid_roll_of_node.count(full.free_dofs[i] / beam_dof::per_node) &&
               rigid_roll_of_node.count(full.free_dofs[j] / beam_dof::per_node);
    });
    const Eigen::SparseMatrix<double> Tt = m.T.transpose();
    m.K = Tt * (full.K - rolls_own) * m.T;
    m.M = Tt * full.M * m.T;
    m.K_nips = Tt * (full.K - structure.K) * m.T;
    m.K.makeCompressed(), m.M.makeCompressed(), m.K_nips.makeCompressed();
}

}  // namespace

std::vector<double> element_ends(double a, double b, std::vector<double> breaks, int n_target) {
    breaks.push_back(a), breaks.push_back(b);
    std::sort(breaks.begin(), breaks.end());
    std::vector<double> stations;
    for (double z : breaks)
        if (z >= a - kSameZ && z <= b + kSameZ && (stations.empty() || z - stations.back() > kSameZ))
            stations.push_back(std::clamp(z, a, b));
    std::vector<double> ends = {stations.front()};
    for (size_t i = 0; i + 1 < stations.size(); ++i) {
        const double len = stations[i + 1] - stations[i];
        const int n = std::max(kMinElementsPerGap, static_cast<int>(std::ceil(n_target * len / (b - a) - 1e-9)));
        for (int e = 1; e <= n; ++e) ends.push_back(e == n ? stations[i + 1] : stations[i] + len * e / n);
    }
    return ends;
}

WinderGeometry winder_geometry(const WinderScene& scene, double d) {
    WinderGeometry g;
    g.roll_diameter = d;
    g.drum_spacing = scene.drums.outer_diameter + scene.drums.gap;
    const double centre_distance = 0.5 * (d + scene.drums.outer_diameter);
    COREMODAL_ASSERT(g.drum_spacing / 2 < centre_distance);  // the scene reader checks d > gap
    g.nip_angle = std::asin(g.drum_spacing / (d + scene.drums.outer_diameter));
    g.roll_height = std::sqrt(centre_distance * centre_distance - 0.25 * g.drum_spacing * g.drum_spacing);
    return g;
}

std::array<double, 2> nip_direction(const WinderGeometry& g, DrumSide drum) {
    const double sx = std::sin(g.nip_angle), cy = std::cos(g.nip_angle);
    return drum == DrumSide::front ? std::array<double, 2>{sx, cy} : std::array<double, 2>{-sx, cy};
}

WinderState winder_state(const WinderScene& s, double d) {
    WinderState st;
    st.geometry = winder_geometry(s, d);
    const WinderRolls& r = s.rolls;
    st.roll_mass_per_width = winder_material(r.core_material).density * ring_area(r.core_outer_diameter, r.core_inner_diameter) +
                             r.paper_density * ring_area(std::max(d, r.core_outer_diameter), r.core_outer_diameter);
    st.rider_line_load = s.rider.line_load;
    // Vertical equilibrium of a roll: both drum nips carry its weight and the
    // rider's load; web tension and drive torques are left out.
    st.drum_line_load = s.drums.line_load.value_or((kGravity * st.roll_mass_per_width + st.rider_line_load) /
                                                   (2 * std::cos(st.geometry.nip_angle)));
    try {
        st.drum_nip = jorkama_nip({st.drum_line_load, d, s.drums.outer_diameter, r.radial_modulus, r.poisson});
        st.rider_nip = jorkama_nip({st.rider_line_load, d, s.rider.outer_diameter, r.radial_modulus, r.poisson});
    } catch (const std::invalid_argument& e) {
        throw InputError(s.source_file + ": at roll diameter " + significant(d) + " m (drum line load " +
                         significant(st.drum_line_load) + " N/m, rider " + significant(st.rider_line_load) +
                         " N/m): " + e.what() + "; expected lower line loads or a stiffer [winder.rolls] radial_modulus");
    }
    return st;
}

const char* body_kind_name(BodyKind k) {
    switch (k) {
        case BodyKind::drum:
            return "drum";
        case BodyKind::roll:
            return "roll";
        default:
            return "rider";
    }
}

int WinderModel::reduced_dof(int node, int dof) const {
    const int network_dof = beam_dof::per_node * node + dof;
    const auto it = std::find(network_dofs.begin(), network_dofs.end(), network_dof);
    COREMODAL_ASSERT(it != network_dofs.end());
    const Eigen::Index row = it - network_dofs.begin();
    for (Eigen::Index c = 0; c < T.outerSize(); ++c)
        for (Eigen::SparseMatrix<double>::InnerIterator e(T, c); e; ++e)
            if (e.row() == row) return static_cast<int>(c);
    COREMODAL_ASSERT(!"network DOF without a reduced DOF");
    return -1;
}

WinderModel build_winder_model(const WinderScene& scene, double roll_diameter) {
    WinderModel m;
    m.state = winder_state(scene, roll_diameter);
    add_drums(m, scene);
    add_rider(m, scene);
    add_rolls_and_nips(m, scene, roll_diameter);
    const NetworkMatrices full = assemble_problems(m.network, {kBending}).front();
    BeamNetwork structure = m.network;
    structure.couplings.clear();
    const NetworkMatrices bodies_only = assemble_problems(structure, {kBending}).front();
    COREMODAL_ASSERT(bodies_only.free_dofs == full.free_dofs);
    reduce(m, scene, full, bodies_only);
    return m;
}

}  // namespace coremodal
