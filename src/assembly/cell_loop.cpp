#include "assembly/cell_loop.hpp"

#include "common/error.hpp"

namespace coremodal {

double assemble_cells(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                      const std::function<bool(int)>& take, const TermInsert& insert,
                      const std::vector<Term>& extra_terms) {
    for (Term t : extra_terms) COREMODAL_ASSERT(t == Term::gyroscopic);  // the one cell term beyond K and M
    const bool spinning = !extra_terms.empty();
    const int npc = mesh.nodes_per_cell();
    CellCoords coords(npc, 3);
    Eigen::MatrixXd K, M;
    std::vector<int> cell_dofs(3 * npc);
    double mass = 0;
    for (int c = 0; c < mesh.n_cells(); ++c) {
        if (!take(c)) continue;
        const int* nodes = mesh.cell(c);
        for (int a = 0; a < npc; ++a) {
            for (int d = 0; d < 3; ++d) {
                coords(a, d) = mesh.nodes[nodes[a]][d];
                cell_dofs[3 * a + d] = dofs.dof(nodes[a], d);
            }
        }
        const PartMaterial& material = materials.at(mesh.cell_part[c]);
        try {
            element_matrices(mesh.cell_type, coords, material.C_cylindrical, material.density, K, M);
        } catch (const std::runtime_error& e) {
            throw InputError("mesh cell " + std::to_string(c) + " (part '" +
                             mesh.part_names[mesh.cell_part[c]] + "'): " + e.what());
        }
        mass += M.sum() / 3;  // each of the three component blocks sums to rho * V
        insert(Term::stiffness, cell_dofs, K);
        insert(Term::mass, cell_dofs, M);
        if (spinning) insert(Term::gyroscopic, cell_dofs, element_gyroscopic(mesh.cell_type, coords, material.density));
    }
    return mass;
}

const Eigen::MatrixXd& CouplingElement::matrix(Term term) const {
    static const Eigen::MatrixXd none;
    for (const TermMatrix& t : terms)
        if (t.term == term) return t.matrix;
    return none;
}

double assemble_couplings(const std::vector<CouplingElement>& couplings, const DofMap& dofs,
                          const std::function<bool(const std::vector<int>&)>& take, const TermInsert& insert,
                          const std::vector<Term>& pad_to) {
    double mass = 0;
    std::vector<int> element_dofs;
    for (const CouplingElement& e : couplings) {
        if (!take(e.nodes)) continue;
        element_dofs.clear();
        for (int n : e.nodes)
            for (int c = 0; c < 3; ++c) element_dofs.push_back(dofs.dof(n, c));
        for (const TermMatrix& t : e.terms) {
            insert(t.term, element_dofs, t.matrix);
            if (t.term == Term::mass) mass += t.matrix.sum() / 3;  // lumped: each component block sums to m
        }
        for (Term t : pad_to)
            if (e.matrix(t).size() == 0) {
                const int n = static_cast<int>(element_dofs.size());
                insert(t, element_dofs, Eigen::MatrixXd::Zero(n, n));
            }
    }
    return mass;
}

Eigen::MatrixXd spring_between(const Eigen::MatrixXd& k) {
    Eigen::MatrixXd K(2 * k.rows(), 2 * k.cols());
    K << k, -k, -k, k;
    return K;
}

}  // namespace coremodal
