// The forced response at the harmonic level (docs/response.md, "At the
// harmonic level"): the roll's sideways motion is wave number n = 1 of the
// r-z section alone, its two planes one complex plane (plane_response.hpp);
// the modes at rest of n = 1 up to the cutoff come from SLEPc (verified,
// complete by inertia), the static part of the others from a sparse factor
// of K, and the check is the direct sparse solve of the whole n = 1 problem.
#include "analyses/response/harmonic_loads.hpp"
#include "analyses/response/plane_response.hpp"
#include "analyses/response/response_levels.hpp"
#include "analyses/response/response_sweep.hpp"
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

class HarmonicResponseModel : public ResponseModel {
public:
    HarmonicResponseModel(const PlaneResponse& plane, const HarmonicLoads& loads, std::vector<Eigen::VectorXd> probes,
                          std::vector<ModeLabel> labels, int n_used)
        : plane_(plane), loads_(loads), probes_(std::move(probes)), labels_(std::move(labels)), n_used_(n_used) {
        for (const OrderLoad& l : loads_.orders) orders_.push_back(l.order);
    }

    const std::vector<int>& orders() const override { return orders_; }
    size_t n_probes() const override { return probes_.size(); }
    bool has_complete_basis() const override { return false; }

    // The cos family's amplitudes a per order (the sin family's are -i a).
    // "complete" is every mode solved (with the static part of the rest).
    std::vector<Eigen::VectorXcd> solve(double speed_hz, ResponseMethod method) const override {
        const double spin = 2 * M_PI * speed_hz;
        std::vector<Eigen::VectorXcd> out;
        for (const OrderLoad& load : loads_.orders) {
            const Eigen::VectorXcd p = load.at(spin);
            const double omega = load.order * spin;
            if (method == ResponseMethod::direct) out.push_back(plane_.direct(p, spin, omega));
            else out.push_back(plane_.superpose(p, spin, omega, method == ResponseMethod::complete ? plane_.n_modes() : n_used_, true));
        }
        return out;
    }

    ProbeAmplitude at_probe(const std::vector<Eigen::VectorXcd>& x, size_t probe) const override {
        ProbeAmplitude a;
        for (const Eigen::VectorXcd& cos_family : x) {
            const cd ux = probes_[probe].cast<cd>().dot(cos_family);
            a.per_order_m.push_back(orbit_semi_major(ux, cd(0, -1) * ux));  // a forward circle
            a.total_m += a.per_order_m.back();
        }
        return a;
    }

    AnsweringMode answering_mode(size_t order_index, double speed_hz) const override {
        const OrderLoad& load = loads_.orders[order_index];
        const double spin = 2 * M_PI * speed_hz;
        const Eigen::VectorXcd eta = plane_.modal_coordinates(load.at(spin), spin, load.order * spin, n_used_);
        int best = 0;
        double best_share = -1;
        for (int j = 0; j < n_used_; ++j) {
            const double share = std::abs(eta(j)) * std::abs(probes_.front().dot(plane_.modes().col(j)));
            if (share > best_share) best_share = share, best = j;
        }
        return {labels_[static_cast<size_t>(best)], plane_.mode_frequency_hz(best)};
    }

private:
    const PlaneResponse& plane_;
    const HarmonicLoads& loads_;
    std::vector<Eigen::VectorXd> probes_;
    std::vector<ModeLabel> labels_;
    int n_used_;
    std::vector<int> orders_;
};

double first_bending_hz(const LevelModes& rest) {
    for (const Mode& m : rest.modes)
        if (m.label.type == "bending") return m.frequency_hz;
    return 0;
}

// The lowest basis mode labelled bending (the bow's shape "first_mode").
Eigen::VectorXd first_bending_mode(const ModalBasis& basis, const std::vector<ModeLabel>& labels) {
    for (size_t j = 0; j < labels.size(); ++j)
        if (labels[j].type == "bending") return basis.Phi.col(static_cast<Eigen::Index>(j));
    throw SolveError("the roll has no bending mode among the modes at rest of n = 1 kept for the response");
}

// The highest order the excitation loads (effects/excitation.hpp): 2 with an
// oval core under gravity, else 1.
int highest_order(const ExcitationSpec& x) { return x.ovality_m > 0 && x.gravity ? 2 : 1; }

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
    PlaneResponse response(plane.K, plane.M, plane.G, basis, lambda_scale);
    const LateralDampingPlan damping = plan_plane_damping(setup.damping, rest, basis, labels, lambda_scale);
    response.set_damping(damping.rayleigh, damping.zeta);
    out.n_dofs = response.n_dofs();
    const Eigen::VectorXd first_mode =
        setup.excitation.bow_shape == BowShape::first_mode ? first_bending_mode(basis, labels) : Eigen::VectorXd();
    const HarmonicLoads loads = build_harmonic_loads(scene, setup.excitation, plane, response, first_mode);
    COREMODAL_ASSERT(!loads.orders.empty());  // the reader refuses an [excitation] that excites nothing
    for (const std::string& a : damping.assumptions) out.assumptions.push_back(a);
    for (const std::string& a : loads.assumptions) out.assumptions.push_back(a);
    for (const OrderLoad& l : loads.orders) out.orders.push_back(l.order), out.order_sources.push_back(l.sources);
    std::vector<Eigen::VectorXd> probes;
    for (const ResponseRange::Probe& p : range.probes) probes.push_back(section_probe(plane, p.z_m));
    if (loads.sag.size() > 0) out.sag_m = std::abs(probes.front().dot(loads.sag));
    out.ovality_split = loads.ovality_split;
    // 3-5. The sweep, the peaks, the speed at the limit, the checks.
    out.checks.n_modes_all = response.n_modes();
    const int n_used = std::max(std::min(kMinModesKept, response.n_modes()), response.modes_below(2 * M_PI * out.checks.cutoff_hz));
    out.checks.n_modes_used = n_used;
    out.mode_damping.assign(damping.modes.begin(), damping.modes.begin() + n_used);
    const HarmonicResponseModel model(response, loads, probes, labels, n_used);
    sweep_response(model, range, f1, out.roll_outer_diameter, out);
    out.assumptions.push_back(kept_modes_assumption(out.checks, "modes at rest of wave number n = 1 solved") +
                              " (K^-1 p less the kept modes' part)");
    out.solve_seconds = clock.lap();
    return out;
}

}  // namespace coremodal
