// The forced response at the harmonic level (docs/theory/response.md, "At the
// harmonic level"): the roll's sideways motion is wave number n = 1 of the
// r-z section alone, its two planes one complex plane (modal_response.hpp);
// the modes at rest of n = 1 up to the cutoff come from SLEPc (verified,
// complete by inertia), the static part of the others from a sparse factor
// of K, and the check is the direct sparse solve of the whole n = 1 problem.
#include "analyses/response/harmonic_loads.hpp"
#include "analyses/response/modal_response_model.hpp"
#include "analyses/response/response_levels.hpp"
#include "assembly/chuck_supports.hpp"
#include "common/error.hpp"
#include "common/stopwatch.hpp"
#include "effects/rotation.hpp"
#include "eigensolve/tolerances.hpp"
#include "models/harmonic/harmonic_level.hpp"
#include "models/harmonic/harmonic_shapes.hpp"
#include "models/solve_steps.hpp"
#include "modes/classify.hpp"
#include "modes/mode_shapes.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace coremodal {
namespace {

using cd = std::complex<double>;

// At least this many modes of n = 1 are kept, however low the speeds: the
// beam level's two (there the first pair's two planes; here the first two
// bending modes, whose pairs are one plane each).
constexpr int kMinModesKept = 2;

// Each basis mode named on the revolved section with the solid's classifier,
// as the harmonic level names its modes.
std::vector<ModeLabel> basis_labels(const Scene& scene, const HarmonicPlane& plane, const ModalBasis& basis,
                                    double lambda_scale) {
    RevolvedMesh revolved = revolve_section(plane.section, std::min(scene.mesh.n_around, kMaxDisplayAround));
    add_frame_nodes(scene, revolved.mesh);
    const std::vector<int> frame_nodes = frame_nodes_of(scene, revolved.mesh);
    const ModeClassifier classifier(revolved.mesh, roll_nodes(revolved.mesh), body_held(scene));
    std::vector<ModeLabel> out;
    for (Eigen::Index j = 0; j < basis.Phi.cols(); ++j) {
        const std::vector<double> mode(basis.Phi.col(j).data(), basis.Phi.col(j).data() + basis.Phi.rows());
        out.push_back(classifier.classify(revolved_field(revolved, plane.dofs, 1, mode, {}, frame_nodes),
                                          basis.lambda(j), lambda_scale));
    }
    return out;
}

// The lowest basis mode labelled bending (the bow's shape "first_mode").
Eigen::VectorXd first_bending_mode(const ModalBasis& basis, const std::vector<ModeLabel>& labels) {
    for (size_t j = 0; j < labels.size(); ++j)
        if (labels[j].type == "bending") return basis.Phi.col(static_cast<Eigen::Index>(j));
    throw SolveError("the roll has no bending mode among the modes at rest of n = 1 kept for the response");
}

// The order-1 and order-2 crossings, forward and backward, up to the range's
// top speed (ModalResponse::synchronous_crossings).
std::vector<ResponseCrossing> crossings_of(const ModalResponse& response, const std::vector<ModeLabel>& labels,
                                           double top_speed_hz, double dp) {
    std::vector<ResponseCrossing> out;
    for (int order : {1, 2})
        for (int direction : {1, -1})
            for (const ModalResponse::SynchronousCrossing& c :
                 response.synchronous_crossings(order, direction, 2 * M_PI * top_speed_hz)) {
                Eigen::Index dominant = 0;
                c.modal.cwiseAbs().maxCoeff(&dominant);
                const double speed_hz = c.omega_spin / (2 * M_PI);
                out.push_back({order, direction == 1, speed_hz, web_speed(speed_hz, dp),
                               labels[static_cast<size_t>(dominant)]});
            }
    std::sort(out.begin(), out.end(),
              [](const ResponseCrossing& a, const ResponseCrossing& b) { return a.speed_hz < b.speed_hz; });
    return out;
}

}  // namespace

const ResponseLevel kHarmonicResponse{
    .level = ModelChoice::harmonic,
    .note = "forced response at the harmonic level: modal superposition in the modes at rest of wave number n = 1 "
            "(the cos and sin families are the two bending planes) with the gyroscopic coupling of the spinning "
            "bodies of revolution projected, and the static part of the modes above the cutoff; checked against "
            "the direct sparse solve of the full n = 1 problem"};

ResponseResult run_harmonic_response(const Scene& scene_given, const ResponseSetup& setup, ResponseChecking checking) {
    Stopwatch clock;
    Scene scene = scene_given;
    scene.model = "harmonic";  // "auto" resolved
    // 1. At rest: the harmonic level's run (f1, the modes as modes.csv numbers them).
    LevelModes rest;
    ResponseResult out = start_mesh_level_response(
        scene, setup, kHarmonicResponse,
        "modal superposition in the modes at rest of wave number n = 1 (gyroscopic coupling projected) with the "
        "static part of the others, checked by a direct sparse solve",
        rest);
    // 2. Wave number n = 1: its matrices, its modes up to the cutoff, their damping and the loads.
    const ResponseRange& range = setup.response;
    const double lambda_scale = solve_request(scene).lambda_scale;
    const HarmonicPlane plane = assemble_harmonic_plane(scene);
    out.checks.cutoff_hz = kTruncationFactor * highest_order(setup.excitation) * range.speeds_hz.back();
    const ModalBasis basis =
        modal_basis_below(scene, assemble_harmonic(scene, plane.section, plane.materials, 1).operators,
                          out.checks.cutoff_hz, kMinModesKept, "the problem of wave number n = 1 (the forced response): ");
    const std::vector<ModeLabel> labels = basis_labels(scene, plane, basis, lambda_scale);
    ModalResponse response(plane.K, plane.M, plane.G, kOnePlane, basis, lambda_scale);
    // Each n = 1 mode is the pair at rest of its eigenvalue (both members numbered in modes.csv).
    const LateralDampingPlan damping = plan_basis_damping(setup.damping, rest, basis, labels, lambda_scale,
                                                          [](const ModeLabel& l) { return l.n == 1; },
                                                          "wave number n = 1 only");
    response.set_damping(damping.rayleigh, damping.zeta);
    add_structural_damping(
        response, setup.damping, [&](const StructuralDamping& s) { return harmonic_hysteretic(plane, s); },
        "each part's cells of wave number n = 1 (core, rest paper, chucks)", out.assumptions);
    const Eigen::VectorXd first_mode =
        setup.excitation.bow_shape == BowShape::first_mode ? first_bending_mode(basis, labels) : Eigen::VectorXd();
    const LevelLoads loads = build_harmonic_loads(scene, setup.excitation, plane, response, first_mode);
    std::vector<ProbeWeights> probes;
    for (const ResponseRange::Probe& p : range.probes) {  // u_y = -i u_x: the sin family is -i a
        const Eigen::VectorXcd w = section_probe(plane, p.z_m).cast<cd>();
        probes.push_back({w, cd(0, -1) * w});
    }
    // 3-5. The sweep, the peaks, the speed at the limit, the checks.
    finish_modal_response({response, damping, loads, probes, labels, kMinModesKept, "modes at rest of wave number n = 1 solved"},
                          range, out.speeds_at_rest.f1_hz, out, checking);
    out.crossings = crossings_of(response, labels, range.speeds_hz.back(), out.roll_outer_diameter);
    out.solve_seconds = clock.lap();
    return out;
}

}  // namespace coremodal
