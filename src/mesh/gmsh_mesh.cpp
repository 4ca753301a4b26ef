#include "mesh/gmsh_mesh.hpp"

#include "common/error.hpp"

#include <gmsh.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <numeric>

namespace coremodal {
namespace {

// gmsh element type numbers (gmsh reference manual, "MSH file format").
constexpr int kGmshTet10 = 11;
constexpr int kGmshHex27 = 12;
constexpr int kGmshHex20 = 17;
constexpr int kGmshQuad8 = 16;
constexpr int kGmshQuad9 = 10;

CellType cell_type_of(int gmsh_type, const std::string& source) {
    switch (gmsh_type) {
    case kGmshHex20: return CellType::hex20;
    case kGmshHex27: return CellType::hex27;
    case kGmshTet10: return CellType::tet10;
    }
    std::string name;
    int dim, order, n_nodes, n_primary;
    std::vector<double> local;
    gmsh::model::mesh::getElementProperties(gmsh_type, name, dim, order, n_nodes, local, n_primary);
    throw InputError(source + ": mesh has cells of type '" + name + "' (order " + std::to_string(order) +
                     "); coremodal needs quadratic volume cells: 20- or 27-node hexahedra or 10-node "
                     "tetrahedra (in gmsh: Mesh.ElementOrder = 2)");
}

std::string physical_name(int dim, int tag) {
    std::string name;
    gmsh::model::getPhysicalName(dim, tag, name);
    return name.empty() ? std::to_string(tag) : name;
}

std::string join(const std::vector<std::string>& items) {
    std::string out;
    for (const auto& s : items) out += (out.empty() ? "" : ", ") + ("'" + s + "'");
    return out.empty() ? "none" : out;
}

// Quadratic quadrilateral faces of a surface group, if it has only those.
void read_quad_faces(int dim, int group, const std::vector<int>& index_of, Mesh& mesh) {
    std::vector<int> entities;
    gmsh::model::getEntitiesForPhysicalGroup(dim, group, entities);
    FaceSet set;
    for (int entity : entities) {
        std::vector<int> types;
        std::vector<std::vector<std::size_t>> element_tags, node_tags;
        gmsh::model::mesh::getElements(types, element_tags, node_tags, 2, entity);
        for (size_t t = 0; t < types.size(); ++t) {
            if (types[t] != kGmshQuad8 && types[t] != kGmshQuad9) return;
            set.nodes_per_face = types[t] == kGmshQuad8 ? 8 : 9;
            for (std::size_t tag : node_tags[t]) {
                if (tag >= index_of.size() || index_of[tag] < 0) return;  // not a node of any cell
                set.faces.push_back(index_of[tag]);
            }
        }
    }
    if (!set.faces.empty()) mesh.face_groups[physical_name(dim, group)] = std::move(set);
}

}  // namespace

GmshSession::GmshSession() {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    gmsh::option::setNumber("General.Verbosity", 1);
}

GmshSession::~GmshSession() { gmsh::finalize(); }

namespace {

// The nodes (our numbering, sorted) and quadrilateral faces of every
// physical surface; index_of maps gmsh node tags to our nodes (-1: unused).
void read_surface_groups(const std::vector<int>& index_of, Mesh& mesh) {
    const std::size_t max_tag = index_of.empty() ? 0 : index_of.size() - 1;
    gmsh::vectorpair surface_groups;
    gmsh::model::getPhysicalGroups(surface_groups, 2);
    for (auto [dim, group] : surface_groups) {
        std::vector<std::size_t> tags;
        std::vector<double> xyz;
        gmsh::model::mesh::getNodesForPhysicalGroup(dim, group, tags, xyz);
        std::vector<int> nodes;
        for (std::size_t t : tags)
            if (t <= max_tag && index_of[t] >= 0) nodes.push_back(index_of[t]);
        std::sort(nodes.begin(), nodes.end());
        nodes.erase(std::unique(nodes.begin(), nodes.end()), nodes.end());
        mesh.node_groups[physical_name(dim, group)] = std::move(nodes);
        read_quad_faces(dim, group, index_of, mesh);
    }
}

}  // namespace

Mesh read_current_gmsh_mesh(const std::string& source) {
    Mesh mesh;
    gmsh::vectorpair volume_groups;
    gmsh::model::getPhysicalGroups(volume_groups, 3);
    if (volume_groups.empty())
        throw InputError(source + ": mesh has no physical volume; name the core's volume 'core' "
                                  "(and the rest paper's 'rest_paper') as physical groups");

    std::vector<std::size_t> cell_node_tags;  // gmsh node tags, cell by cell
    int cell_gmsh_type = -1;
    for (auto [dim, group] : volume_groups) {
        const int part = static_cast<int>(mesh.part_names.size());
        mesh.part_names.push_back(physical_name(dim, group));
        std::vector<int> entities;
        gmsh::model::getEntitiesForPhysicalGroup(dim, group, entities);
        for (int entity : entities) {
            std::vector<int> types;
            std::vector<std::vector<std::size_t>> element_tags, node_tags;
            gmsh::model::mesh::getElements(types, element_tags, node_tags, 3, entity);
            for (size_t t = 0; t < types.size(); ++t) {
                if (cell_gmsh_type >= 0 && types[t] != cell_gmsh_type)
                    throw InputError(source + ": mesh mixes volume cell types; coremodal needs one type "
                                              "(hex20, hex27 or tet10) throughout");
                mesh.cell_type = cell_type_of(types[t], source);
                cell_gmsh_type = types[t];
                cell_node_tags.insert(cell_node_tags.end(), node_tags[t].begin(), node_tags[t].end());
                mesh.cell_part.insert(mesh.cell_part.end(), element_tags[t].size(), part);
            }
        }
    }
    if (mesh.cell_part.empty())
        throw InputError(source + ": the physical volumes hold no volume cells; mesh in 3D (gmsh -3)");

    // Number only the nodes used by cells, in order of their gmsh tags.
    std::vector<std::size_t> node_tags;
    std::vector<double> coords, params;
    gmsh::model::mesh::getNodes(node_tags, coords, params, -1, -1, true, false);
    const std::size_t max_tag = node_tags.empty() ? 0 : *std::max_element(node_tags.begin(), node_tags.end());
    std::vector<int> index_of(max_tag + 1, -1);
    for (std::size_t t : cell_node_tags) index_of.at(t) = 0;
    std::vector<std::size_t> position(max_tag + 1);
    for (size_t k = 0; k < node_tags.size(); ++k) position[node_tags[k]] = k;
    for (std::size_t tag = 1; tag <= max_tag; ++tag) {
        if (index_of[tag] < 0) continue;
        index_of[tag] = mesh.n_nodes();
        const double* x = &coords[3 * position[tag]];
        mesh.nodes.push_back({x[0], x[1], x[2]});
    }
    mesh.cells.reserve(cell_node_tags.size());
    for (std::size_t t : cell_node_tags) mesh.cells.push_back(index_of[t]);

    read_surface_groups(index_of, mesh);
    return mesh;
}

Mesh read_msh_file(const std::string& path) {
    if (!std::filesystem::exists(path)) throw InputError(path + ": mesh file does not exist");
    if (!std::ifstream(path)) throw InputError(path + ": mesh file cannot be read (permissions?)");
    gmsh::clear();
    try {
        gmsh::open(path);
    } catch (const std::exception& e) {
        throw InputError(path + ": gmsh cannot read this mesh file: " + e.what());
    } catch (const std::string& e) {  // gmsh's C++ API throws its last error message as a string
        throw InputError(path + ": gmsh cannot read this mesh file: " + e);
    }
    // gmsh opens an empty file (or one of only comments) without complaint.
    gmsh::vectorpair entities;
    gmsh::model::getEntities(entities);
    if (entities.empty()) throw InputError(path + ": gmsh found no mesh in this file; expected a gmsh .msh mesh");
    return read_current_gmsh_mesh(path);
}

void require_groups(const Mesh& mesh, const std::vector<std::string>& parts,
                    const std::vector<std::string>& node_groups, const std::string& source,
                    const std::string& needed_by) {
    for (const auto& part : parts)
        if (std::find(mesh.part_names.begin(), mesh.part_names.end(), part) == mesh.part_names.end())
            throw InputError(source + ": mesh has no physical volume '" + part + "' (needed by " +
                             needed_by + "); physical volumes found: " + join(mesh.part_names));
    std::vector<std::string> present;
    for (const auto& [name, nodes] : mesh.node_groups) present.push_back(name);
    for (const auto& group : node_groups)
        if (!mesh.node_groups.count(group))
            throw InputError(source + ": mesh has no physical surface '" + group + "' (needed by " +
                             needed_by + "); physical surfaces found: " + join(present));
}

}  // namespace coremodal
