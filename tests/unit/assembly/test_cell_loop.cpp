// The cell loops with a dense Eigen sink: a small solid (hex20 cells, spring
// layers, bearings, frame masses) and a harmonic problem are assembled into
// dense matrices through the very loops a run uses (assemble_cells,
// assemble_couplings, assemble_harmonic_terms), and checked against
// independent truths: symmetry, rigid-body null spaces, the mass rho V, and
// the PETSc matrices a run assembles from the same loops.
#include "assembly/cell_loop.hpp"
#include "assembly/chuck_supports.hpp"
#include "assembly/harmonic_system.hpp"
#include "assembly/petsc_system.hpp"

#include "models/part_materials.hpp"
#include "verification/tube_scenes.hpp"

#include <catch2/catch.hpp>

#include <Eigen/Sparse>

#include <map>

using namespace coremodal;

namespace {

// A dense sink: one matrix per term, DOFs below 0 skipped (eliminated).
// For the small problems below (at most a few thousand DOFs).
struct DenseSink {
    int n = 0;
    std::map<Term, Eigen::MatrixXd> A;
    TermInsert insert() {
        return [this](Term t, const std::vector<int>& dofs, const Eigen::MatrixXd& e) {
            Eigen::MatrixXd& m = A.try_emplace(t, Eigen::MatrixXd::Zero(n, n)).first->second;
            for (size_t a = 0; a < dofs.size(); ++a)
                for (size_t b = 0; b < dofs.size(); ++b)
                    if (dofs[a] >= 0 && dofs[b] >= 0) m(dofs[a], dofs[b]) += e(a, b);
        };
    }
};

// A sparse sink for a scene too large for dense matrices (chucks).
struct SparseSink {
    int n = 0;
    std::map<Term, std::vector<Eigen::Triplet<double>>> entries;
    TermInsert insert() {
        return [this](Term t, const std::vector<int>& dofs, const Eigen::MatrixXd& e) {
            for (size_t a = 0; a < dofs.size(); ++a)
                for (size_t b = 0; b < dofs.size(); ++b)
                    if (dofs[a] >= 0 && dofs[b] >= 0) entries[t].emplace_back(dofs[a], dofs[b], e(a, b));
        };
    }
    Eigen::SparseMatrix<double> matrix(Term t) const {
        Eigen::SparseMatrix<double> A(n, n);
        A.setFromTriplets(entries.at(t).begin(), entries.at(t).end());
        return A;
    }
};

Eigen::SparseMatrix<double> sparse_of(Mat A) {
    PetscInt n;
    COREMODAL_PETSC(MatGetSize(A, &n, nullptr));
    std::vector<Eigen::Triplet<double>> t;
    for (PetscInt i = 0; i < n; ++i) {
        PetscInt count;
        const PetscInt* cols;
        const PetscScalar* vals;
        COREMODAL_PETSC(MatGetRow(A, i, &count, &cols, &vals));
        for (PetscInt k = 0; k < count; ++k) t.emplace_back(i, cols[k], vals[k]);
        COREMODAL_PETSC(MatRestoreRow(A, i, &count, &cols, &vals));
    }
    Eigen::SparseMatrix<double> out(n, n);
    out.setFromTriplets(t.begin(), t.end());
    return out;
}

Eigen::MatrixXd dense_of(Mat A) {
    PetscInt n;
    COREMODAL_PETSC(MatGetSize(A, &n, nullptr));
    Eigen::MatrixXd out = Eigen::MatrixXd::Zero(n, n);
    for (PetscInt i = 0; i < n; ++i) {
        PetscInt count;
        const PetscInt* cols;
        const PetscScalar* vals;
        COREMODAL_PETSC(MatGetRow(A, i, &count, &cols, &vals));
        for (PetscInt k = 0; k < count; ++k) out(i, cols[k]) = vals[k];
        COREMODAL_PETSC(MatRestoreRow(A, i, &count, &cols, &vals));
    }
    return out;
}

template <class Matrix>
double relative_difference(const Matrix& a, const Matrix& b) {
    return (a - b).norm() / b.norm();
}

// The rigid motions of a free 3D body, one column each: translations x, y, z
// and rotations about x, y, z.
Eigen::MatrixXd rigid_motions(const Mesh& mesh) {
    Eigen::MatrixXd R = Eigen::MatrixXd::Zero(3 * mesh.n_nodes(), 6);
    for (int i = 0; i < mesh.n_nodes(); ++i) {
        const Eigen::Vector3d x(mesh.nodes[i][0], mesh.nodes[i][1], mesh.nodes[i][2]);
        for (int d = 0; d < 3; ++d) R(3 * i + d, d) = 1;
        for (int d = 0; d < 3; ++d) {
            Eigen::Vector3d axis = Eigen::Vector3d::Zero();
            axis[d] = 1;
            R.block<3, 1>(3 * i, 3 + d) = axis.cross(x);
        }
    }
    return R;
}

}  // namespace

TEST_CASE("Cell loop, solid with chucks: an Eigen sink gets the same K and M as the run's PETSc matrices, with "
          "the physics' invariants", "[long][assembly][cell_loop]") {
    // A short, coarse 76x15 paper core on two chucks in elastic bearings with
    // frame masses: cells, spring layers, bearing springs and lumped masses.
    const Scene s = testing::on_elastic_bearings(
        testing::with_chucks(testing::paper_core(0.4, 8, 6), InterfaceKind::spring), 3e8, 4e6, 25.0, 6e7);
    const Mesh mesh = testing::generated_mesh(s);  // with the frame nodes
    const ChuckSupports supports = chuck_supports(s, mesh);
    const DofMap dofs = make_dof_map(mesh.n_nodes(), supports.eliminated, supports.ties);
    const std::vector<PartMaterial> materials = part_materials(s, mesh.part_names, "test");

    SparseSink sink{dofs.n_dofs, {}};
    double mass = assemble_cells(mesh, materials, dofs, [](int) { return true; }, sink.insert());
    mass += assemble_couplings(supports.couplings, dofs, [](const std::vector<int>&) { return true; }, sink.insert());
    REQUIRE(sink.entries.size() == 2);  // stiffness and mass only: this scene names no other effect
    const Eigen::SparseMatrix<double> K = sink.matrix(Term::stiffness), M = sink.matrix(Term::mass);

    SECTION("Both matrices are symmetric to round-off") {
        CHECK(relative_difference(Eigen::SparseMatrix<double>(K.transpose()), K) <= 1e-13);
        CHECK(relative_difference(Eigen::SparseMatrix<double>(M.transpose()), M) <= 1e-13);
    }
    SECTION("A rigid translation's kinetic energy is the model mass, rho V plus the frames") {
        for (int d = 0; d < 3; ++d) {
            Eigen::VectorXd t = Eigen::VectorXd::Zero(dofs.n_dofs);
            for (int i = 0; i < mesh.n_nodes(); ++i) t[dofs.dof(i, d)] = 1;
            CHECK(t.dot(M * t) == Approx(mass).epsilon(1e-12));
            // Springs to the ground (bearings to frames to the ground) resist it; the spring layers do not.
        }
        // The curved cells lose a^4/30 of the section's area (8 around: a = pi/8, 8e-4).
        CHECK(mass == Approx(s.mass_from_dimensions()).epsilon(1e-3));
    }
    SECTION("The run's PETSc matrices hold exactly what the sink got") {
        const OperatorSet ops = assemble_petsc(mesh, materials, dofs, supports.couplings, PETSC_COMM_SELF);
        CHECK(ops.terms() == std::vector<Term>{Term::stiffness, Term::mass});
        CHECK(relative_difference(sparse_of(ops.K()), K) < 1e-14);
        CHECK(relative_difference(sparse_of(ops.M()), M) < 1e-14);
        CHECK(ops.model_mass == Approx(mass).epsilon(1e-14));
    }
}

TEST_CASE("Cell loop, solid spinning: the gyroscopic term enters when asked, skew, and the PETSc matrix holds "
          "exactly it", "[long][assembly][cell_loop][rotation]") {
    // The scene above: every cell spins, the couplings (spring layers,
    // bearings, frames) add nothing to G.
    const Scene s = testing::on_elastic_bearings(
        testing::with_chucks(testing::paper_core(0.4, 8, 6), InterfaceKind::spring), 3e8, 4e6, 25.0, 6e7);
    const Mesh mesh = testing::generated_mesh(s);
    const ChuckSupports supports = chuck_supports(s, mesh);
    const DofMap dofs = make_dof_map(mesh.n_nodes(), supports.eliminated, supports.ties);
    const std::vector<PartMaterial> materials = part_materials(s, mesh.part_names, "test");
    SparseSink sink{dofs.n_dofs, {}};
    assemble_cells(mesh, materials, dofs, [](int) { return true; }, sink.insert(), {Term::gyroscopic});
    REQUIRE(sink.entries.count(Term::gyroscopic) == 1);
    const Eigen::SparseMatrix<double> G = sink.matrix(Term::gyroscopic), M = sink.matrix(Term::mass);
    CHECK(relative_difference(Eigen::SparseMatrix<double>(-Eigen::SparseMatrix<double>(G.transpose())), G) <= 1e-14);
    // A spinning body that swells slows down: breathing b against twist phi,
    // b^T G phi = -2 int rho r^2 dV = -2 b^T M b (element_gyroscopic), summed
    // over the cells (the bearing faces are eliminated: both fields vanish there).
    Eigen::VectorXd b = Eigen::VectorXd::Zero(dofs.n_dofs), phi = Eigen::VectorXd::Zero(dofs.n_dofs);
    for (int i = 0; i < mesh.n_nodes(); ++i) {
        if (dofs.dof(i, 0) < 0) continue;
        const auto& x = mesh.nodes[i];
        b[dofs.dof(i, 0)] = x[0], b[dofs.dof(i, 1)] = x[1];
        phi[dofs.dof(i, 0)] = -x[1], phi[dofs.dof(i, 1)] = x[0];
    }
    CHECK(b.dot(G * phi) == Approx(-2 * b.dot(M * b)).epsilon(1e-12));
    // MatSetValues reads row-major: a skew element matrix must arrive transposed (petsc_system.cpp).
    const OperatorSet ops = assemble_petsc(mesh, materials, dofs, supports.couplings, PETSC_COMM_SELF, {Term::gyroscopic});
    CHECK(ops.terms() == std::vector<Term>{Term::stiffness, Term::mass, Term::gyroscopic});
    CHECK(relative_difference(sparse_of(ops[Term::gyroscopic]), G) < 1e-14);
}

TEST_CASE("Cell loop, solid: a free body's dense K has the six rigid motions in its null space",
          "[assembly][cell_loop]") {
    const Scene s = testing::paper_core(0.1, 8, 2);  // a few hundred nodes: dense is fine
    const Mesh mesh = testing::generated_mesh(s);
    const DofMap dofs = make_dof_map(mesh.n_nodes(), {});
    DenseSink sink{dofs.n_dofs, {}};
    assemble_cells(mesh, part_materials(s, mesh.part_names, "test"), dofs, [](int) { return true; }, sink.insert());
    const Eigen::MatrixXd& K = sink.A.at(Term::stiffness);
    const Eigen::MatrixXd R = rigid_motions(mesh);
    // Cell stiffness entries are ~E h; K r must vanish to round-off of them.
    for (int k = 0; k < 6; ++k) {
        INFO("rigid motion " << k);
        CHECK((K * R.col(k)).norm() <= 1e-10 * K.norm() * R.col(k).norm());
    }
}

TEST_CASE("Cell loop, harmonic: a dense sink gets the run's K_n and M_n; free rigid motions are in K_n's null "
          "space", "[assembly][cell_loop][harmonic]") {
    const Scene s = testing::paper_core(0.5, 16, 12);  // free: no supports
    const SectionMesh section = make_section_mesh(make_tube_section(s), s.supports.clamps);
    const std::vector<PartMaterial> materials = part_materials(s, section.part_names, "test");
    for (int n : {0, 1, 2}) {
        INFO("wave number n = " << n);
        const HarmonicDofs dofs = harmonic_dofs(s, section, n);
        DenseSink sink{dofs.n_dofs, {}};
        const double mass = assemble_harmonic_terms(s, section, materials, dofs, n, sink.insert());
        const Eigen::MatrixXd& K = sink.A.at(Term::stiffness);
        const Eigen::MatrixXd& M = sink.A.at(Term::mass);
        CHECK((K - K.transpose()).norm() <= 1e-13 * K.norm());
        CHECK(mass == Approx(s.mass_from_dimensions()).epsilon(1e-12));  // exact in theta: no curved-cell loss

        const HarmonicSystem run = assemble_harmonic(s, section, materials, n, PETSC_COMM_SELF);
        CHECK(relative_difference(dense_of(run.operators.K()), K) < 1e-14);
        CHECK(relative_difference(dense_of(run.operators.M()), M) < 1e-14);

        // Rigid motions live in n = 0 (along and about z) and n = 1 (sideways).
        std::vector<RigidMotion> motions;
        if (n == 0) motions = {RigidMotion::z, RigidMotion::rz};
        if (n == 1) motions = {RigidMotion::x};
        for (RigidMotion m : motions) {
            const std::vector<double> field = harmonic_rigid_field(section, dofs, n, m);
            const Eigen::VectorXd r = Eigen::Map<const Eigen::VectorXd>(field.data(), dofs.n_dofs);
            CHECK((K * r).norm() <= 1e-10 * K.norm() * r.norm());
            // A translation's kinetic energy is the mass: n = 0, W = 1, weight
            // 2 pi; n = 1, U = V = 1, weight pi on each of the two components.
            if (m != RigidMotion::rz) CHECK(r.dot(M * r) == Approx(mass).epsilon(1e-12));
        }
    }
}

TEST_CASE("DOF numbering in slabs: the same matrices permuted, and two processes' blocks cut one layer of cells",
          "[assembly][cell_loop][mpi]") {
    const Scene s = testing::paper_core(0.3, 8, 6);  // along z, 0.3 m: the longest side
    const Mesh mesh = testing::generated_mesh(s);
    const DofMap plain = make_dof_map(mesh.n_nodes(), {});
    const DofMap slabs = make_dof_map(mesh.n_nodes(), {}, {}, slab_node_order(mesh));
    REQUIRE(slabs.n_dofs == plain.n_dofs);
    // Free nodes numbered in order of z: a permutation, monotone along the axis.
    std::vector<int> node_of_block(slabs.n_free_nodes, -1);
    for (int n = 0; n < mesh.n_nodes(); ++n) node_of_block.at(slabs.node_first_dof[n] / 3) = n;
    for (int b = 1; b < slabs.n_free_nodes; ++b)
        CHECK(mesh.nodes[node_of_block[b]][2] >= mesh.nodes[node_of_block[b - 1]][2]);

    SECTION("K and M are those of the mesh order, rows and columns permuted") {
        const auto materials = part_materials(s, mesh.part_names, "test");
        DenseSink a{plain.n_dofs, {}}, b{slabs.n_dofs, {}};
        assemble_cells(mesh, materials, plain, [](int) { return true; }, a.insert());
        assemble_cells(mesh, materials, slabs, [](int) { return true; }, b.insert());
        Eigen::VectorXi p(plain.n_dofs);  // plain dof -> slab dof
        for (int n = 0; n < mesh.n_nodes(); ++n)
            for (int c = 0; c < 3; ++c) p[plain.dof(n, c)] = slabs.dof(n, c);
        const Eigen::PermutationMatrix<Eigen::Dynamic> P(p);
        for (Term t : {Term::stiffness, Term::mass}) {
            const Eigen::MatrixXd permuted = P * a.A.at(t) * P.transpose();
            CHECK((permuted - b.A.at(t)).norm() <= 1e-14 * b.A.at(t).norm());
        }
    }
    SECTION("Two processes' blocks: the cells with nodes on both sides are one layer, not most of them") {
        const auto cut_cells = [&](const DofMap& dofs) {
            const int half = owned_free_nodes(dofs.n_free_nodes, 0, 2).second;
            int cut = 0;
            for (int c = 0; c < mesh.n_cells(); ++c) {
                int below_half = 0;
                for (int a = 0; a < mesh.nodes_per_cell(); ++a) below_half += dofs.node_first_dof[mesh.cell(c)[a]] / 3 < half;
                cut += below_half > 0 && below_half < mesh.nodes_per_cell();
            }
            return cut;
        };
        // hex20 nodes stand on 2 L + 1 planes of z for L layers of cells.
        std::vector<double> z;
        for (const auto& x : mesh.nodes) z.push_back(x[2]);
        std::sort(z.begin(), z.end());
        const auto same_plane = [](double x, double y) { return std::abs(x - y) < 1e-9; };
        const long planes = std::unique(z.begin(), z.end(), same_plane) - z.begin();
        const int per_layer = int(mesh.n_cells() / ((planes - 1) / 2));
        INFO("cells " << mesh.n_cells() << " in " << (planes - 1) / 2 << " layers; cut in mesh order " << cut_cells(plain)
                      << ", in slabs " << cut_cells(slabs));
        // The cut runs through a plane of nodes: the layers on its two sides.
        CHECK(cut_cells(slabs) <= 2 * per_layer);
        CHECK(cut_cells(slabs) < cut_cells(plain));
        CHECK(cut_cells(plain) > mesh.n_cells() / 2);  // why the slabs: gmsh numbers mid-side nodes last
    }
}
