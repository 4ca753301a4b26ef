// The forced response at the harmonic level (docs/theory/response.md, "At the
// harmonic level"): the roll's sideways motion is wave number n = 1 of the
// r-z section alone, its two planes one complex plane (modal_response.hpp);
// the modes at rest of n = 1 up to the cutoff come from SLEPc (verified,
// complete by inertia), the static part of the others from a sparse factor
// of K, and the check is the direct sparse solve of the whole n = 1 problem.
#include "models/response/harmonic_loads.hpp"
#include "models/response/modal_response_model.hpp"
#include "models/response/response_levels.hpp"
#include "models/response/level_response.hpp"
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

// The lowest basis mode labelled bending, Hz (0: none): the whole run's f1
// (its bending modes are wave number n = 1's).
double first_bending_hz(const ModalBasis& basis, const std::vector<ModeLabel>& labels) {
    for (size_t j = 0; j < labels.size(); ++j)
        if (labels[j].type == "bending") return eigenvalue_hz(basis.lambda(static_cast<Eigen::Index>(j)));
    return 0;
}

// The setups one n = 1 model serves (run_harmonic_responses): the same
// basis (speeds, highest order) and damping of the parts.
void require_one_model(const std::vector<ResponseSetup>& setups) {
    const ResponseSetup& first = setups.front();
    for (const ResponseSetup& s : setups)
        COREMODAL_ASSERT(s.response.speeds_hz == first.response.speeds_hz &&
                         highest_order(s.excitation) == highest_order(first.excitation) &&
                         same_part_damping(s.damping, first.damping));
}

// The probes on the section: u_y = -i u_x (the sin family is -i a).
std::vector<ProbeWeights> section_probes(const HarmonicPlane& plane, const ResponseRange& range) {
    std::vector<ProbeWeights> out;
    for (const ResponseRange::Probe& p : range.probes) {
        const Eigen::VectorXcd w = section_probe(plane, p.z_m).cast<cd>();
        out.push_back({w, cd(0, -1) * w});
    }
    return out;
}

// The shared n = 1 model of run_harmonic_responses.
struct PlaneModel {
    const HarmonicPlane& plane;
    const ModalBasis& basis;
    const std::vector<ModeLabel>& labels;
    double lambda_scale;
    ModalResponse& response;
    const std::vector<ProbeWeights>& probes;
};

// One setup's damping and loads on the shared model; 3-5. its sweep, peaks,
// speed at the limit and checks.
void respond(const Scene& scene, const ResponseSetup& setup, const LevelModes& rest, const PlaneModel& m,
             ResponseChecking checking, ResponseResult& out) {
    // Each n = 1 mode is the pair at rest of its eigenvalue (both members numbered in modes.csv).
    const LateralDampingPlan damping = plan_basis_damping(setup.damping, rest, m.basis, m.labels, m.lambda_scale,
                                                          [](const ModeLabel& l) { return l.n == 1; },
                                                          "wave number n = 1 only");
    m.response.set_damping(damping.rayleigh, damping.zeta);
    const Eigen::VectorXd first_mode =
        setup.excitation.bow_shape == BowShape::first_mode ? first_bending_mode(m.basis, m.labels) : Eigen::VectorXd();
    const LevelLoads loads = build_harmonic_loads(scene, setup.excitation, m.plane, m.response, first_mode);
    finish_modal_response(
        {m.response, damping, loads, m.probes, m.labels, kMinModesKept, "modes at rest of wave number n = 1 solved"},
        setup.response, out.speeds_at_rest.f1_hz, out, checking);
}

}  // namespace

const ResponseLevel kHarmonicResponse{
    .level = ModelChoice::harmonic,
    .note = "forced response at the harmonic level: modal superposition in the modes at rest of wave number n = 1 "
            "(the cos and sin families are the two bending planes) with the gyroscopic coupling of the spinning "
            "bodies of revolution projected, and the static part of the modes above the cutoff; checked against "
            "the direct sparse solve of the full n = 1 problem"};

namespace {

std::vector<ResponseResult> run_harmonic_responses(const Scene& scene_given, const std::vector<ResponseSetup>& setups,
                                                   ResponseChecking checking, RestModes rest_modes) {
    COREMODAL_ASSERT(!setups.empty());
    require_one_model(setups);
    Stopwatch clock;
    Scene scene = scene_given;
    scene.model = ModelChoice::harmonic;  // "auto" resolved
    const ResponseSetup& first = setups.front();
    // 1. At rest: the harmonic level's run (f1, the modes as modes.csv numbers
    // them), or only n = 1's own basis below (RestModes::lateral; mode numbers
    // in [damping] need the whole run's numbering).
    const bool every_wave_number =
        rest_modes == RestModes::every_wave_number ||
        std::any_of(setups.begin(), setups.end(), [](const ResponseSetup& s) { return !s.damping.modes.empty(); });
    const std::string solver =
        "modal superposition in the modes at rest of wave number n = 1 (gyroscopic coupling projected) with the "
        "static part of the others, checked by a direct sparse solve";
    LevelModes rest;
    std::vector<ResponseResult> outs;
    for (const ResponseSetup& s : setups)
        outs.push_back(every_wave_number && outs.empty()
                           ? start_mesh_level_response(scene, s, kHarmonicResponse, solver, rest)
                           : start_mesh_level_response(scene, s, kHarmonicResponse, solver));
    // 2. Wave number n = 1: its matrices, its modes up to the cutoff and their
    // labels, and the factor of K, once for every setup.
    const double lambda_scale = solve_request(scene).lambda_scale;
    const HarmonicPlane plane = assemble_harmonic_plane(scene);
    const double cutoff_hz = kTruncationFactor * highest_order(first.excitation) * first.response.speeds_hz.back();
    const ModalBasis basis =
        modal_basis_below(scene, assemble_harmonic(scene, plane.section, plane.materials, 1).operators, cutoff_hz,
                          kMinModesKept, "the problem of wave number n = 1 (the forced response): ");
    const std::vector<ModeLabel> labels = basis_labels(scene, plane, basis, lambda_scale);
    const double f1 = first_bending_hz(basis, labels);
    const RollSpeeds at_rest = every_wave_number ? outs.front().speeds_at_rest
                                                 : roll_speeds(scene, f1, f1 > 0 ? "" : "no bending mode");
    ModalResponse response(plane.K, plane.M, plane.G, kOnePlane, basis, lambda_scale);
    std::vector<std::string> part_damping;
    add_part_damping(response, first.damping, harmonic_part_stiffness(plane), part_damping);
    const std::vector<ProbeWeights> probes = section_probes(plane, first.response);
    const std::vector<ResponseCrossing> crossings =
        crossings_of(response, labels, first.response.speeds_hz.back(), outs.front().roll_outer_diameter);
    const PlaneModel model{plane, basis, labels, lambda_scale, response, probes};
    for (size_t k = 0; k < setups.size(); ++k) {
        ResponseResult& out = outs[k];
        out.speeds_at_rest = at_rest;
        out.checks.cutoff_hz = cutoff_hz;
        out.assumptions.insert(out.assumptions.end(), part_damping.begin(), part_damping.end());
        respond(scene, setups[k], rest, model, checking, out);
        out.crossings = crossings;
    }
    const double seconds = clock.lap();
    for (ResponseResult& out : outs) out.solve_seconds = seconds / static_cast<double>(outs.size());
    return outs;
}

// The harmonic level's forced response (ModelLevel::response): several
// setups from one n = 1 basis, its labels and K's factor (run_harmonic_responses);
// the scene outlives it (the driver's call).
class HarmonicResponse : public LevelResponse {
public:
    explicit HarmonicResponse(const Scene& scene) : scene_(scene) {}
    ResponseResult respond(const ResponseSetup& setup, ResponseChecking checking, RestModes rest) override {
        return run_harmonic_responses(scene_, {setup}, checking, rest).front();
    }
    std::vector<ResponseResult> respond_all(const std::vector<ResponseSetup>& setups, ResponseChecking checking,
                                            RestModes rest) override {
        return run_harmonic_responses(scene_, setups, checking, rest);
    }

private:
    const Scene& scene_;
};

}  // namespace

std::unique_ptr<LevelResponse> HarmonicLevel::response(const Scene& scene, const BeamModelOptions&) {
    return std::make_unique<HarmonicResponse>(scene);
}

}  // namespace coremodal
