// What every hard case (issue 5) asserts, and where its scene comes from: a
// case file in cases/hard/, the same file a user can run.
#pragma once

#include "assembly/dof_map.hpp"
#include "eigensolve/modal_solver.hpp"
#include "mesh/mesh.hpp"
#include "modes/classify.hpp"
#include "modes/mode_set.hpp"
#include "modes/mode_shapes.hpp"
#include "scene/case_file.hpp"

#include <catch2/catch.hpp>

#include <string>
#include <vector>

namespace coremodal::testing {

// The scene of cases/hard/<file>.
inline Scene hard_case(const std::string& file) {
    return parse_case_file(std::string(COREMODAL_SOURCE_DIR) + "/cases/hard/" + file);
}

// The solver's proof of its answer: no mode missed (the inertia count of the
// shifted factor equals the modes found below the shift), every pair
// converged (relative residual) and the set M-orthonormal, both to 1e-8.
inline void check_verified(const Verification& v) {
    CHECK(v.complete);
    CHECK(v.negative_pivots_at_shift == v.modes_below_shift);
    CHECK(v.max_relative_residual <= 1e-8);
    CHECK(v.max_orthonormality_error <= 1e-8);
}

// The labels run_scene would give the solved modes on this mesh.
inline std::vector<ModeLabel> labels_of(const SolvedModes& solved, const Mesh& mesh, const DofMap& dofs,
                                        double lambda_scale) {
    const ModeClassifier classifier(mesh, roll_nodes(mesh));
    std::vector<ModeLabel> labels;
    for (size_t i = 0; i < solved.eigenvalues.size(); ++i)
        labels.push_back(classifier.classify(gather_node_displacements(solved.vectors[i], mesh, dofs),
                                             solved.eigenvalues[i], lambda_scale));
    return labels;
}

// Two label lists name the same modes: type, wave number n and axial m.
inline void check_same_labels(const std::vector<ModeLabel>& a, const std::vector<ModeLabel>& b) {
    REQUIRE(a.size() == b.size());
    for (size_t i = 0; i < a.size(); ++i) {
        INFO("mode " << i + 1 << ": " << a[i].type << " n=" << a[i].n << " m=" << a[i].m << " against " << b[i].type
                     << " n=" << b[i].n << " m=" << b[i].m);
        CHECK(a[i].type == b[i].type);
        CHECK(a[i].n == b[i].n);
        CHECK(a[i].m == b[i].m);
    }
}

// The same problem renumbered and turned about the axis: only round-off
// differs, so the eigenvalues agree to 1e-8 and the modes keep their names.
// Solved: anything with .eigenvalues and .labels.
template <class Solved>
void check_invariant(const Solved& reference, const Solved& renumbered, const Solved& turned) {
    REQUIRE(renumbered.eigenvalues.size() == reference.eigenvalues.size());
    REQUIRE(turned.eigenvalues.size() == reference.eigenvalues.size());
    for (size_t i = 0; i < reference.eigenvalues.size(); ++i) {
        CHECK(renumbered.eigenvalues[i] == Approx(reference.eigenvalues[i]).epsilon(1e-8));
        CHECK(turned.eigenvalues[i] == Approx(reference.eigenvalues[i]).epsilon(1e-8));
    }
    check_same_labels(renumbered.labels, reference.labels);
    check_same_labels(turned.labels, reference.labels);
}

}  // namespace coremodal::testing
