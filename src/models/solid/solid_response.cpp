// The forced response at the solid level (docs/theory/response.md, "At the solid
// level"): the solid run's mesh with both planes (G skew, as the beam
// network's), the modes at rest of the whole solid up to the cutoff from
// SLEPc (verified, complete by inertia), the static part of the others from
// a sparse factor of K, and the check by the direct sparse solve of the
// whole 3D problem. For bodies of revolution only (the gyroscopic term is
// the stationary frame's, docs/theory/rotation-solid.md), and for coarse meshes in
// practice: a sparse LU of the 3D problem per checked speed.
#include "models/response/modal_response_model.hpp"
#include "models/response/response_levels.hpp"
#include "models/response/level_response.hpp"
#include "models/response/solid_loads.hpp"
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

// Each basis mode named on the mesh with the solid run's classifier.
std::vector<ModeLabel> solid_labels(const SolidResponseModel& m, const ModalBasis& basis, double lambda_scale,
                                    BodyHeld held) {
    const ModeClassifier classifier(m.mesh, roll_nodes(m.mesh), held);
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

const ResponseLevel kSolidResponse{
    .level = ModelChoice::solid,
    .note = "forced response at the solid level: modal superposition in the solid's modes at rest with the "
            "gyroscopic coupling of the spinning cells projected, and the static part of the modes above the "
            "cutoff; checked against the direct sparse solve of the whole solid"};

namespace {

ResponseResult run_solid_response(const Scene& scene_given, const ResponseSetup& setup, ResponseChecking checking) {
    Stopwatch clock;
    Scene scene = scene_given;
    scene.model = ModelChoice::solid;
    require_response_level(scene);
    // 1. At rest: the solid level's run (f1, the modes as modes.csv numbers them).
    LevelModes rest;
    ResponseResult out = start_mesh_level_response(
        scene, setup, kSolidResponse,
        "modal superposition in the solid's modes at rest (gyroscopic coupling projected) with the static part of "
        "the others, checked by a direct sparse solve",
        rest);
    // 2. The solid with its gyroscopic term, its modes up to the cutoff, their damping and the loads.
    const ResponseRange& range = setup.response;
    const double lambda_scale = solve_request(scene).lambda_scale;
    const SolidResponseModel model = assemble_solid_response_model(scene);
    out.checks.cutoff_hz = kTruncationFactor * highest_order(setup.excitation) * range.speeds_hz.back();
    const ModalBasis basis =
        modal_basis_below(scene, assemble_petsc(model.mesh, model.materials, model.dofs, model.chucks.couplings),
                          out.checks.cutoff_hz, kMinModesKept, "the solid's modes at rest (the forced response): ");
    const std::vector<ModeLabel> labels = solid_labels(model, basis, lambda_scale, body_held(scene));
    ModalResponse response(model.K, model.M, model.G, kTwoPlanes, basis, lambda_scale);
    // Every mode of the solid below the cutoff is in the response.
    const LateralDampingPlan damping = plan_basis_damping(setup.damping, rest, basis, labels, lambda_scale,
                                                          [](const ModeLabel&) { return true; },
                                                          "every mode of the solid below the cutoff");
    response.set_damping(damping.rayleigh, damping.zeta);
    add_part_damping(response, setup.damping, solid_part_stiffness(model), out.assumptions);
    const Eigen::MatrixXd first_pair =
        setup.excitation.bow_shape == BowShape::first_mode ? first_bending_pair(basis, labels) : Eigen::MatrixXd();
    const LevelLoads loads = build_solid_loads(scene, setup.excitation, model, response, first_pair);
    std::vector<ProbeWeights> probes;
    for (const ResponseRange::Probe& p : range.probes) probes.push_back(solid_section_probe(model, p.z_m));
    // 3-5. The sweep, the peaks, the speed at the limit, the checks.
    finish_modal_response({response, damping, loads, probes, labels, kMinModesKept, "modes of the solid at rest solved"},
                          range, out.speeds_at_rest.f1_hz, out, checking);
    out.solve_seconds = clock.lap();
    return out;
}


// The solid's forced response (ModelLevel::response); the scene outlives it
// (the driver's call).
class SolidResponse : public LevelResponse {
public:
    explicit SolidResponse(const Scene& scene) : scene_(scene) {}
    // The solid level's run at rest is the lateral problem's already (RestModes).
    ResponseResult respond(const ResponseSetup& setup, ResponseChecking checking, RestModes) override {
        return run_solid_response(scene_, setup, checking);
    }

private:
    const Scene& scene_;
};

}  // namespace

std::unique_ptr<LevelResponse> SolidLevel::response(const Scene& scene, const BeamModelOptions&) {
    return std::make_unique<SolidResponse>(scene);
}

}  // namespace coremodal
