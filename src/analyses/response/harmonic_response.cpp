// The forced response at the harmonic level (docs/response.md, "At the
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

// The modes at rest of n = 1 up to cutoff_hz (at least kMinModesKept),
// M-orthonormal: the harmonic level's SLEPc solve of that problem alone.
ModalBasis plane_basis(const Scene& scene, const HarmonicPlane& plane, double cutoff_hz) {
    HarmonicSystem system = assemble_harmonic(scene, plane.section, plane.materials, 1);
    SolveRequest request = solve_request(scene);
    request.lambda_min.reset(), request.lambda_max.reset();  // the lowest modes, whatever band the case asks for
    const double lambda_cut = std::pow(2 * M_PI * cutoff_hz, 2);
    request.n_modes = std::max<int>(kMinModesKept, static_cast<int>(count_eigenvalues_below(system.operators, lambda_cut)));
    const SolvedModes solved = solve_for_case(scene, system.operators, request, [](const std::string&) {},
                                              "the problem of wave number n = 1 (the forced response): ");
    ModalBasis basis;
    basis.Phi.resize(plane.dofs.n_dofs, static_cast<Eigen::Index>(solved.vectors.size()));
    basis.lambda = Eigen::Map<const Eigen::VectorXd>(solved.eigenvalues.data(), basis.Phi.cols());
    for (size_t j = 0; j < solved.vectors.size(); ++j) {
        const std::vector<double> values = gather_to_root(solved.vectors[j]);
        basis.Phi.col(static_cast<Eigen::Index>(j)) = Eigen::Map<const Eigen::VectorXd>(values.data(), basis.Phi.rows());
    }
    return basis;
}

// Each basis mode named on the revolved section with the solid's classifier,
// as the harmonic level names its modes.
std::vector<ModeLabel> basis_labels(const Scene& scene, const HarmonicPlane& plane, const ModalBasis& basis,
                                    double lambda_scale) {
    RevolvedMesh revolved = revolve_section(plane.section, std::min(scene.mesh.n_around, kMaxDisplayAround));
    add_frame_nodes(scene, revolved.mesh);
    const std::vector<int> frame_nodes = frame_nodes_of(scene, revolved.mesh);
    const ModeClassifier classifier(revolved.mesh, roll_nodes(revolved.mesh));
    std::vector<ModeLabel> out;
    for (Eigen::Index j = 0; j < basis.Phi.cols(); ++j) {
        const std::vector<double> mode(basis.Phi.col(j).data(), basis.Phi.col(j).data() + basis.Phi.rows());
        out.push_back(classifier.classify(revolved_field(revolved, plane.dofs, 1, mode, {}, frame_nodes),
                                          basis.lambda(j), lambda_scale));
    }
    return out;
}

// [damping] on the basis: each n = 1 mode is the pair at rest of its
// eigenvalue (the harmonic level reports both members, numbered as in modes.csv).
LateralDampingPlan plan_plane_damping(const DampingSpec& spec, const LevelModes& rest, const ModalBasis& basis,
                                      const std::vector<ModeLabel>& labels, double lambda_scale) {
    std::vector<NumberedRestMode> numbered;
    for (const Mode& m : rest.modes) numbered.push_back({m.label, m.frequency_hz, m.label.n == 1});
    std::vector<BasisMode> modes;
    for (Eigen::Index j = 0; j < basis.lambda.size(); ++j) {
        const double lambda = basis.lambda(j), tolerance = kClusterTolerance * std::max(std::abs(lambda), lambda_scale);
        BasisMode b{lambda, labels[static_cast<size_t>(j)], {}};
        for (const Mode& m : rest.modes)
            if (m.label.n == 1 && std::abs(m.eigenvalue - lambda) <= tolerance) b.rest_modes.push_back(m.index);
        modes.push_back(std::move(b));
    }
    return plan_modal_damping(spec, numbered, modes, "wave number n = 1 only");
}

// The lowest basis mode labelled bending (the bow's shape "first_mode").
Eigen::VectorXd first_bending_mode(const ModalBasis& basis, const std::vector<ModeLabel>& labels) {
    for (size_t j = 0; j < labels.size(); ++j)
        if (labels[j].type == "bending") return basis.Phi.col(static_cast<Eigen::Index>(j));
    throw SolveError("the roll has no bending mode among the modes at rest of n = 1 kept for the response");
}

}  // namespace

ResponseResult run_harmonic_response(const Scene& scene_given, const ResponseSetup& setup) {
    Stopwatch clock;
    Scene scene = scene_given;
    scene.model = "harmonic";  // "auto" resolved
    if (mpi_size() > 1)
        throw InputError(scene.source_file + ": the forced response at the harmonic level runs in one process; run it "
                                             "without mpirun");
    ResponseResult out = response_result_for(scene, setup, "harmonic");
    out.solver = "modal superposition in the modes at rest of wave number n = 1 (gyroscopic coupling projected) with "
                 "the static part of the others, checked by a direct sparse solve";
    const ResponseRange& range = setup.response;
    // 1. At rest: the harmonic level's run (f1, the modes as modes.csv numbers them).
    HarmonicLevel level;
    const LevelModes rest = level.solve(scene, Printer{false});
    const double f1 = first_bending_hz(rest);
    out.speeds_at_rest = roll_speeds(scene, f1, f1 > 0 ? "" : "no bending mode");
    // 2. Wave number n = 1: its matrices, its modes up to the cutoff, their damping and the loads.
    const double lambda_scale = solve_request(scene).lambda_scale;
    const HarmonicPlane plane = assemble_harmonic_plane(scene);
    out.checks.cutoff_hz = kTruncationFactor * highest_order(setup.excitation) * range.speeds_hz.back();
    const ModalBasis basis = plane_basis(scene, plane, out.checks.cutoff_hz);
    const std::vector<ModeLabel> labels = basis_labels(scene, plane, basis, lambda_scale);
    ModalResponse response(plane.K, plane.M, plane.G, kOnePlane, basis, lambda_scale);
    const LateralDampingPlan damping = plan_plane_damping(setup.damping, rest, basis, labels, lambda_scale);
    response.set_damping(damping.rayleigh, damping.zeta);
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
                          range, f1, out);
    out.solve_seconds = clock.lap();
    return out;
}

}  // namespace coremodal
