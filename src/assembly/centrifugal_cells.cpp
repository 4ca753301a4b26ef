#include "assembly/centrifugal_cells.hpp"

#include "common/error.hpp"
#include "element/centrifugal_element.hpp"

namespace coremodal {
namespace {

// A cell's node coordinates and global dofs.
struct CellView {
    CellCoords coords;
    std::vector<int> dofs;
};

CellView view(const Mesh& mesh, const DofMap& dofs, int c) {
    const int npc = mesh.nodes_per_cell();
    CellView v{CellCoords(npc, 3), std::vector<int>(3 * npc)};
    const int* nodes = mesh.cell(c);
    for (int a = 0; a < npc; ++a)
        for (int d = 0; d < 3; ++d) {
            v.coords(a, d) = mesh.nodes[nodes[a]][d];
            v.dofs[3 * a + d] = dofs.dof(nodes[a], d);
        }
    return v;
}

// The element kernels throw std::runtime_error on a bad cell; name it as assemble_cells does.
template <typename F>
auto named_cell(const Mesh& mesh, int c, F&& kernel) {
    try {
        return kernel();
    } catch (const std::runtime_error& e) {
        throw InputError("mesh cell " + std::to_string(c) + " (part '" + mesh.part_names[mesh.cell_part[c]] +
                         "'): " + e.what());
    }
}

}  // namespace

void assemble_centrifugal_load(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                               const std::function<bool(int)>& take, const VectorInsert& insert) {
    for (int c = 0; c < mesh.n_cells(); ++c) {
        if (!take(c)) continue;
        const CellView v = view(mesh, dofs, c);
        const double rho = materials.at(mesh.cell_part[c]).density;
        insert(v.dofs, named_cell(mesh, c, [&] { return element_centrifugal_load(mesh.cell_type, v.coords, rho); }));
    }
}

void assemble_centrifugal_cells(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                                const std::function<bool(int)>& take, const NodeField& u1, CentrifugalPart part,
                                const TermInsert& insert) {
    const int npc = mesh.nodes_per_cell();
    Eigen::VectorXd u(3 * npc);
    for (int c = 0; c < mesh.n_cells(); ++c) {
        if (!take(c)) continue;
        const CellView v = view(mesh, dofs, c);
        for (int a = 0; a < npc; ++a) u.segment<3>(3 * a) = u1(mesh.cell(c)[a]);
        const PartMaterial& m = materials.at(mesh.cell_part[c]);
        const Eigen::MatrixXd k = named_cell(mesh, c, [&]() -> Eigen::MatrixXd {
            const auto stresses = element_stresses(mesh.cell_type, v.coords, m.C_cylindrical, u);
            Eigen::MatrixXd k_sigma = element_stress_stiffness(mesh.cell_type, v.coords, stresses);
            if (part == CentrifugalPart::stress_stiffness_only) return k_sigma;
            return k_sigma - element_spin_softening(mesh.cell_type, v.coords, m.density);
        });
        insert(Term::centrifugal, v.dofs, k);
    }
}

}  // namespace coremodal
