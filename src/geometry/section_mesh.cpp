#include "geometry/section_mesh.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace coremodal {
namespace {

// Same tolerance as the solid's model builder: a micrometre separates every real boundary.
constexpr double kTolerance = 1e-6;

// Element edges [x0, x1, ...] refined with midpoints: the quadratic node lines.
std::vector<double> with_midpoints(const std::vector<double>& edges) {
    std::vector<double> out;
    for (size_t i = 0; i + 1 < edges.size(); ++i) {
        out.push_back(edges[i]);
        out.push_back((edges[i] + edges[i + 1]) / 2);
    }
    out.push_back(edges.back());
    return out;
}

void append_uniform(std::vector<double>& edges, double x0, double x1, int n) {
    if (edges.empty()) edges.push_back(x0);
    for (int k = 1; k <= n; ++k) edges.push_back(x0 + (x1 - x0) * k / n);
}

void append_segment(std::vector<double>& edges, const AxialSegment& seg) {
    if (edges.empty() || std::abs(edges.back() - seg.z_start) > kTolerance) edges.push_back(seg.z_start);
    for (double f : segment_layer_fractions(seg)) edges.push_back(seg.z_start + f * (seg.z_end - seg.z_start));
}

// A structured block of quad8 cells on the node lines R x Z (midpoints
// included); nodes are made when a cell first needs them.
class Block {
public:
    Block(SectionMesh& mesh, std::vector<double> r_lines, std::vector<double> z_lines)
        : mesh_(mesh), R_(std::move(r_lines)), Z_(std::move(z_lines)) {}

    int cells_r() const { return static_cast<int>(R_.size()) / 2; }
    int cells_z() const { return static_cast<int>(Z_.size()) / 2; }
    double r_line(int i) const { return R_[i]; }
    double z_line(int j) const { return Z_[j]; }

    int node(int i, int j) {
        auto [it, fresh] = index_.try_emplace({i, j}, mesh_.n_nodes());
        if (fresh) mesh_.nodes.push_back({R_[i], Z_[j]});
        return it->second;
    }
    void add_cell(int ci, int cj, int part) {
        const int i = 2 * ci, j = 2 * cj;
        mesh_.cells.push_back({node(i, j), node(i + 2, j), node(i + 2, j + 2), node(i, j + 2), node(i + 1, j),
                               node(i + 2, j + 1), node(i + 1, j + 2), node(i, j + 1)});
        mesh_.cell_part.push_back(part);
    }
    // The edge along z on node line i over cell row cj, and along r on node line j over cell column ci.
    SectionEdge edge_along_z(int i, int cj) { return {node(i, 2 * cj), node(i, 2 * cj + 2), node(i, 2 * cj + 1)}; }
    SectionEdge edge_along_r(int ci, int j) { return {node(2 * ci, j), node(2 * ci + 2, j), node(2 * ci + 1, j)}; }

private:
    SectionMesh& mesh_;
    std::vector<double> R_, Z_;
    std::map<std::pair<int, int>, int> index_;
};

int part_index(SectionMesh& mesh, const std::string& name) {
    const auto it = std::find(mesh.part_names.begin(), mesh.part_names.end(), name);
    if (it != mesh.part_names.end()) return static_cast<int>(it - mesh.part_names.begin());
    mesh.part_names.push_back(name);
    return static_cast<int>(mesh.part_names.size()) - 1;
}

bool within(double z0, double z1, double a, double b) { return z0 >= a - kTolerance && z1 <= b + kTolerance; }

void mesh_tube(const TubeSection& s, const std::vector<ClampSpec>& clamps, SectionMesh& mesh) {
    std::vector<double> r_edges, z_edges;
    std::vector<int> layer_of_cell;
    for (size_t l = 0; l < s.layers.size(); ++l) {
        append_uniform(r_edges, s.layers[l].r_inner, s.layers[l].r_outer, s.layers[l].n_elements);
        layer_of_cell.insert(layer_of_cell.end(), s.layers[l].n_elements, static_cast<int>(l));
    }
    for (const AxialSegment& seg : s.segments) append_segment(z_edges, seg);
    Block tube(mesh, with_midpoints(r_edges), with_midpoints(z_edges));
    std::vector<int> parts;
    for (const RadialLayer& layer : s.layers) parts.push_back(part_index(mesh, layer.part));
    for (int cj = 0; cj < tube.cells_z(); ++cj)
        for (int ci = 0; ci < tube.cells_r(); ++ci) tube.add_cell(ci, cj, parts[layer_of_cell[ci]]);
    const int core_outer_line = 2 * s.layers.front().n_elements;
    for (int j = 0; j <= 2 * tube.cells_z(); ++j) mesh.node_groups["core_outer"].push_back(tube.node(core_outer_line, j));
    for (int cj = 0; cj < tube.cells_z(); ++cj) {
        const SectionEdge e = tube.edge_along_z(0, cj);
        const double z0 = tube.z_line(2 * cj), z1 = tube.z_line(2 * cj + 2);
        mesh.edge_groups["core_inner"].push_back(e);
        mesh.edge_groups["roll_outer"].push_back(tube.edge_along_z(2 * tube.cells_r(), cj));
        for (const auto& [chuck, zone] : s.interfaces)
            if (within(z0, z1, zone.first, zone.second)) mesh.edge_groups["interface_" + chuck + "_core"].push_back(e);
        for (const ClampSpec& c : clamps)
            if (within(z0, z1, c.z_start, c.z_end)) mesh.node_groups["clamp_" + c.name].insert(
                mesh.node_groups["clamp_" + c.name].end(), e.begin(), e.end());
    }
}

// A chuck: its body beside the core (cells over the full radius) and its
// shaft beyond the core end (cells inside the shaft radius), one block.
void mesh_chuck(const TubeSection& s, const ChuckBody& c, SectionMesh& mesh) {
    std::vector<double> r_edges;
    const double a = kOGridCoreShare * c.shaft_radius;
    append_uniform(r_edges, 0, a, 1);
    append_uniform(r_edges, a, c.shaft_radius, chuck_ring_elements(a, c.shaft_radius, s.n_around));
    const bool has_outer = c.body_radius > c.shaft_radius + kTolerance;
    if (has_outer)
        append_uniform(r_edges, c.shaft_radius, c.body_radius, chuck_ring_elements(c.shaft_radius, c.body_radius, s.n_around));
    const int n_shaft_r = static_cast<int>(std::find_if(r_edges.begin(), r_edges.end(), [&](double r) {
                                               return r > c.shaft_radius - kTolerance;
                                           }) - r_edges.begin());

    std::vector<double> z_edges;
    const AxialSegment shaft{0, c.shaft_length, c.n_shaft};
    const auto append_shaft = [&](double z_from, double sign) {
        std::vector<double> f = segment_layer_fractions(shaft);
        f.insert(f.begin(), 0.0);
        std::vector<double> zs;
        for (double x : f) zs.push_back(z_from + sign * x * c.shaft_length);
        if (sign < 0) std::reverse(zs.begin(), zs.end());
        for (double z : zs)
            if (z_edges.empty() || z > z_edges.back() + kTolerance) z_edges.push_back(z);
    };
    if (c.shaft_below) append_shaft(c.z_body_start, -1);
    for (const AxialSegment& seg : s.segments)
        if (within(seg.z_start, seg.z_end, c.z_body_start, c.z_body_end)) append_segment(z_edges, seg);
    if (!c.shaft_below) append_shaft(c.z_body_end, +1);

    Block block(mesh, with_midpoints(r_edges), with_midpoints(z_edges));
    const int part = part_index(mesh, "chuck_" + c.name);
    for (int cj = 0; cj < block.cells_z(); ++cj) {
        const double z0 = block.z_line(2 * cj), z1 = block.z_line(2 * cj + 2);
        const bool in_body = within(z0, z1, c.z_body_start, c.z_body_end);
        for (int ci = 0; ci < block.cells_r(); ++ci)
            if (in_body || ci < n_shaft_r) block.add_cell(ci, cj, part);
        if (!in_body) continue;
        for (const auto& [chuck, zone] : s.interfaces)
            if (chuck == c.name && within(z0, z1, zone.first, zone.second))
                mesh.edge_groups["interface_" + chuck + "_chuck"].push_back(block.edge_along_z(2 * block.cells_r(), cj));
    }
    const int j_bearing = c.shaft_below ? 0 : 2 * block.cells_z();
    for (int ci = 0; ci < n_shaft_r; ++ci) mesh.edge_groups["bearing_" + c.name].push_back(block.edge_along_r(ci, j_bearing));
    for (int j = 0; j <= 2 * block.cells_z(); ++j) mesh.node_groups["axis"].push_back(block.node(0, j));
}

}  // namespace

SectionMesh make_section_mesh(const TubeSection& section, const std::vector<ClampSpec>& clamps) {
    SectionMesh mesh;
    mesh_tube(section, clamps, mesh);
    for (const ChuckBody& c : section.chucks) {
        COREMODAL_ASSERT(c.shaft_radius <= c.body_radius + kTolerance);  // the case reader refuses wider shafts
        mesh_chuck(section, c, mesh);
    }
    for (auto& [name, nodes] : mesh.node_groups) {
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
    }
    // Facing interface edges must meet at the same z (the chuck's axial lines are the core's).
    for (const ChuckBody& c : section.chucks) {
        const auto core = mesh.edge_groups.find("interface_" + c.name + "_core");
        const auto chuck = mesh.edge_groups.find("interface_" + c.name + "_chuck");
        if (core == mesh.edge_groups.end() && chuck == mesh.edge_groups.end()) continue;
        COREMODAL_ASSERT(core != mesh.edge_groups.end() && chuck != mesh.edge_groups.end() &&
                         core->second.size() == chuck->second.size());
        for (size_t k = 0; k < core->second.size(); ++k)
            for (int p = 0; p < 3; ++p)
                COREMODAL_ASSERT(std::abs(mesh.nodes[core->second[k][p]][1] - mesh.nodes[chuck->second[k][p]][1]) < kTolerance);
    }
    return mesh;
}

RevolvedMesh revolve_section(const SectionMesh& section, int n_around) {
    RevolvedMesh out;
    Mesh& mesh = out.mesh;
    mesh.cell_type = CellType::hex20;
    mesh.part_names = section.part_names;
    const int n_angles = 2 * n_around;  // corner planes and the planes half-way between them
    std::vector<int> node_at(static_cast<size_t>(section.n_nodes()) * n_angles, -1);
    const auto node = [&](int s, int t) {
        t %= n_angles;
        const double r = section.nodes[s][0];
        if (r < kTolerance) t = 0;  // one node on the axis
        int& id = node_at[static_cast<size_t>(s) * n_angles + t];
        if (id < 0) {
            id = mesh.n_nodes();
            const double theta = M_PI * t / n_around;
            mesh.nodes.push_back({r * std::cos(theta), r * std::sin(theta), section.nodes[s][1]});
            out.section_node.push_back(s);
            out.theta.push_back(theta);
        }
        return id;
    };
    // Hex20 in gmsh order with the bottom face at the later angle, so that
    // (xi, eta, zeta) = (r, z, -theta) is right-handed.
    for (int c = 0; c < section.n_cells(); ++c) {
        const auto& q = section.cells[c];
        for (int k = 0; k < n_around; ++k) {
            const int b = 2 * k + 2, m = 2 * k + 1, t = 2 * k;
            const std::array<int, 20> hex = {
                node(q[0], b), node(q[1], b), node(q[2], b), node(q[3], b),   // bottom corners
                node(q[0], t), node(q[1], t), node(q[2], t), node(q[3], t),   // top corners
                node(q[4], b), node(q[7], b), node(q[0], m), node(q[5], b),   // edges 0-1, 0-3, 0-4, 1-2
                node(q[1], m), node(q[6], b), node(q[2], m), node(q[3], m),   // 1-5, 2-3, 2-6, 3-7
                node(q[4], t), node(q[7], t), node(q[5], t), node(q[6], t)};  // 4-5, 4-7, 5-6, 6-7
            mesh.cells.insert(mesh.cells.end(), hex.begin(), hex.end());
            mesh.cell_part.push_back(section.cell_part[c]);
        }
    }
    for (const auto& [name, nodes] : section.node_groups) {
        if (name == "axis") continue;
        std::vector<int>& group = mesh.node_groups[name];
        for (int s : nodes)
            for (int t = 0; t < n_angles; ++t)
                if (const int id = node_at[static_cast<size_t>(s) * n_angles + t]; id >= 0) group.push_back(id);
        std::sort(group.begin(), group.end());
        group.erase(std::unique(group.begin(), group.end()), group.end());
    }
    return out;
}

}  // namespace coremodal
