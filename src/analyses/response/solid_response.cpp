// The forced response at the solid level (docs/response.md, "At the solid
// level"): the solid run's mesh with both planes (G skew, as the beam
// network's), the modes at rest of the whole solid up to the cutoff from
// SLEPc (verified, complete by inertia), the static part of the others from
// a sparse factor of K, and the check by the direct sparse solve of the
// whole 3D problem. For bodies of revolution only (the gyroscopic term is
// the stationary frame's, docs/rotation.md), and for coarse meshes in
// practice: a sparse LU of the 3D problem per checked speed.
#include "analyses/response/modal_response_model.hpp"
#include "analyses/response/response_levels.hpp"
#include "analyses/response/solid_loads.hpp"
#include "assembly/petsc_system.hpp"
#include "common/error.hpp"
#include "common/stopwatch.hpp"
#include "eigensolve/tolerances.hpp"
#include "models/choose.hpp"
#include "models/solid/solid_level.hpp"
#include "models/solve_steps.hpp"
#include "modes/classify.hpp"
#include "modes/mode_shapes.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// At least the first bending pair is kept, however low the speeds (the
// beam level's two: a pair is two modes of the solid).
constexpr int kMinModesKept = 2;

// The solid's modes at rest up to cutoff_hz (at least kMinModesKept),
// M-orthonormal: the solid run's SLEPc solve (without the gyroscopic term).
ModalBasis solid_basis(const Scene& scene, const SolidResponseModel& m, double cutoff_hz) {
    const OperatorSet operators = assemble_petsc(m.mesh, m.materials, m.dofs, m.chucks.couplings);
    SolveRequest request = solve_request(scene);
    request.lambda_min.reset(), request.lambda_max.reset();  // the lowest modes, whatever band the case asks for
    const double lambda_cut = std::pow(2 * M_PI * cutoff_hz, 2);
    request.n_modes = std::max<int>(kMinModesKept, static_cast<int>(count_eigenvalues_below(operators, lambda_cut)));
    const SolvedModes solved = solve_for_case(scene, operators, request, [](const std::string&) {},
                                              "the solid's modes at rest (the forced response): ");
    ModalBasis basis;
    basis.Phi.resize(m.dofs.n_dofs, static_cast<Eigen::Index>(solved.vectors.size()));
    basis.lambda = Eigen::Map<const Eigen::VectorXd>(solved.eigenvalues.data(), basis.Phi.cols());
    for (size_t j = 0; j < solved.vectors.size(); ++j) {
        const std::vector<double> values = gather_to_root(solved.vectors[j]);
        basis.Phi.col(static_cast<Eigen::Index>(j)) = Eigen::Map<const Eigen::VectorXd>(values.data(), basis.Phi.rows());
    }
    return basis;
}

// Each basis mode named on the mesh with the solid run's classifier.
std::vector<ModeLabel> solid_labels(const SolidResponseModel& m, const ModalBasis& basis, double lambda_scale) {
    const ModeClassifier classifier(m.mesh, roll_nodes(m.mesh));
    std::vector<ModeLabel> out;
    std::vector<double> field(3 * m.mesh.nodes.size());
    for (Eigen::Index j = 0; j < basis.Phi.cols(); ++j) {
        for (size_t node = 0; node < m.mesh.nodes.size(); ++node)
            for (int c = 0; c < 3; ++c) {
                const int d = m.dofs.dof(static_cast<int>(node), c);
                field[3 * node + c] = d >= 0 ? basis.Phi(d, j) : 0.0;
            }
        out.push_back(classifier.classify(field, basis.lambda(j), lambda_scale));
    }
    return out;
}

// [damping] on the basis: every mode of the solid below the cutoff is in it;
// each is the mode (or a pair's member) at rest of its eigenvalue.
LateralDampingPlan plan_solid_damping(const DampingSpec& spec, const LevelModes& rest, const ModalBasis& basis,
                                      const std::vector<ModeLabel>& labels, double lambda_scale) {
    std::vector<NumberedRestMode> numbered;
    for (const Mode& m : rest.modes) numbered.push_back({m.label, m.frequency_hz, true});
    std::vector<BasisMode> modes;
    for (Eigen::Index j = 0; j < basis.lambda.size(); ++j) {
        const double lambda = basis.lambda(j), tolerance = kClusterTolerance * std::max(std::abs(lambda), lambda_scale);
        BasisMode b{lambda, labels[static_cast<size_t>(j)], {}};
        for (const Mode& m : rest.modes)
            if (std::abs(m.eigenvalue - lambda) <= tolerance) b.rest_modes.push_back(m.index);
        modes.push_back(std::move(b));
    }
    return plan_modal_damping(spec, numbered, modes, "every mode of the solid below the cutoff");
}

// The two members of the lowest bending pair (the bow's shape "first_mode").
Eigen::MatrixXd first_bending_pair(const ModalBasis& basis, const std::vector<ModeLabel>& labels) {
    for (size_t j = 0; j + 1 < labels.size(); ++j)
        if (labels[j].type == "bending") {
            Eigen::MatrixXd pair(basis.Phi.rows(), 2);
            pair << basis.Phi.col(static_cast<Eigen::Index>(j)), basis.Phi.col(static_cast<Eigen::Index>(j + 1));
            return pair;
        }
    throw SolveError("the roll has no bending pair among the solid's modes at rest kept for the response");
}

}  // namespace

ResponseResult run_solid_response(const Scene& scene_given, const ResponseSetup& setup) {
    Stopwatch clock;
    Scene scene = scene_given;
    scene.model = "solid";
    require_response_level(scene);
    if (mpi_size() > 1)
        throw InputError(scene.source_file + ": the forced response at the solid level runs in one process; run it "
                                             "without mpirun");
    ResponseResult out = response_result_for(scene, setup, "solid");
    out.solver = "modal superposition in the solid's modes at rest (gyroscopic coupling projected) with the static "
                 "part of the others, checked by a direct sparse solve";
    const ResponseRange& range = setup.response;
    // 1. At rest: the solid level's run (f1, the modes as modes.csv numbers them).
    SolidLevel level;
    const LevelModes rest = level.solve(scene, Printer{false});
    const double f1 = first_bending_hz(rest);
    out.speeds_at_rest = roll_speeds(scene, f1, f1 > 0 ? "" : "no bending mode");
    // 2. The solid with its gyroscopic term, its modes up to the cutoff, their damping and the loads.
    const double lambda_scale = solve_request(scene).lambda_scale;
    const SolidResponseModel model = assemble_solid_response_model(scene);
    out.checks.cutoff_hz = kTruncationFactor * highest_order(setup.excitation) * range.speeds_hz.back();
    const ModalBasis basis = solid_basis(scene, model, out.checks.cutoff_hz);
    const std::vector<ModeLabel> labels = solid_labels(model, basis, lambda_scale);
    ModalResponse response(model.K, model.M, model.G, kTwoPlanes, basis, lambda_scale);
    const LateralDampingPlan damping = plan_solid_damping(setup.damping, rest, basis, labels, lambda_scale);
    response.set_damping(damping.rayleigh, damping.zeta);
    const Eigen::MatrixXd first_pair =
        setup.excitation.bow_shape == BowShape::first_mode ? first_bending_pair(basis, labels) : Eigen::MatrixXd();
    const LevelLoads loads = build_solid_loads(scene, setup.excitation, model, response, first_pair);
    std::vector<ProbeWeights> probes;
    for (const ResponseRange::Probe& p : range.probes) probes.push_back(solid_section_probe(model, p.z_m));
    // 3-5. The sweep, the peaks, the speed at the limit, the checks.
    finish_modal_response({response, damping, loads, probes, labels, kMinModesKept, "modes of the solid at rest solved"},
                          range, f1, out);
    out.solve_seconds = clock.lap();
    return out;
}

}  // namespace coremodal
