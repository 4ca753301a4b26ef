#include "assembly/cell_loop.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <future>

namespace coremodal {

namespace {

// The element matrices of a batch of cells are computed on two threads (the
// machine's cores: half the assembly's wall time on a rest roll, issue 19),
// then inserted by the calling thread in cell order: the insertion callback
// (PETSc's MatSetValues) is not thread-safe, and the same order keeps every
// sum, hence every matrix entry, bitwise that of one thread.
constexpr int kCellsPerBatch = 256;

struct CellMatrices {
    bool taken = false;
    std::vector<int> dofs;
    Eigen::MatrixXd K, M, G;
};

void compute_cell(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs, int c,
                  bool spinning, CellMatrices& out) {
    const int npc = mesh.nodes_per_cell();
    CellCoords coords(npc, 3);
    out.dofs.resize(3 * npc);
    const int* nodes = mesh.cell(c);
    for (int a = 0; a < npc; ++a) {
        for (int d = 0; d < 3; ++d) {
            coords(a, d) = mesh.nodes[nodes[a]][d];
            out.dofs[3 * a + d] = dofs.dof(nodes[a], d);
        }
    }
    const PartMaterial& material = materials.at(mesh.cell_part[c]);
    try {
        element_matrices(mesh.cell_type, coords, material.C_cylindrical, material.density, out.K, out.M);
    } catch (const std::runtime_error& e) {
        throw InputError("mesh cell " + std::to_string(c) + " (part '" + mesh.part_names[mesh.cell_part[c]] +
                         "'): " + e.what());
    }
    if (spinning) out.G = element_gyroscopic(mesh.cell_type, coords, material.density);
}

}  // namespace

double assemble_cells(const Mesh& mesh, const std::vector<PartMaterial>& materials, const DofMap& dofs,
                      const std::function<bool(int)>& take, const TermInsert& insert,
                      const std::vector<Term>& extra_terms) {
    for (Term t : extra_terms) COREMODAL_ASSERT(t == Term::gyroscopic);  // the one cell term beyond K and M
    const bool spinning = !extra_terms.empty();
    std::vector<CellMatrices> batch(kCellsPerBatch);
    double mass = 0;
    for (int first = 0; first < mesh.n_cells(); first += kCellsPerBatch) {
        const int count = std::min(kCellsPerBatch, mesh.n_cells() - first);
        for (int i = 0; i < count; ++i) batch[i].taken = take(first + i);  // the caller's predicate, on its thread
        const auto compute = [&](int begin, int end) {
            for (int i = begin; i < end; ++i)
                if (batch[i].taken) compute_cell(mesh, materials, dofs, first + i, spinning, batch[i]);
        };
        std::future<void> second_half = std::async(std::launch::async, compute, count / 2, count);
        compute(0, count / 2);
        second_half.get();  // rethrows a cell's InputError
        for (int i = 0; i < count; ++i) {
            if (!batch[i].taken) continue;
            mass += batch[i].M.sum() / 3;  // each of the three component blocks sums to rho * V
            insert(Term::stiffness, batch[i].dofs, batch[i].K);
            insert(Term::mass, batch[i].dofs, batch[i].M);
            if (spinning) insert(Term::gyroscopic, batch[i].dofs, batch[i].G);
        }
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
