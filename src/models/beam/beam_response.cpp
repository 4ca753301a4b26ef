// The forced response at the beam level (docs/theory/response.md): the lateral
// problem of the Timoshenko network (both bending planes) with every mode
// at rest, so that the truncated sum is checked against the complete basis
// and the complete basis against the direct dense solve.
#include "models/response/lateral_response.hpp"
#include "models/response/modal_response_model.hpp"  // highest_order
#include "models/response/response_levels.hpp"
#include "models/response/level_response.hpp"
#include "models/beam/beam_level.hpp"
#include "models/response/response_loads.hpp"
#include "models/response/response_sweep.hpp"
#include "beam/beam_theory.hpp"
#include "beam/rotating_modes.hpp"
#include "beam/timoshenko_element.hpp"
#include "effects/damping.hpp"
#include "modes/verification_check.hpp"
#include "common/error.hpp"
#include "common/stopwatch.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace coremodal {
namespace {

using cd = std::complex<double>;

// The response of the network at one speed by one method, and its orbits.
class BeamResponseModel : public ResponseModel {
public:
    BeamResponseModel(const BeamModelResult& rest, const LateralResponse& lateral, const ResponseLoads& loads,
                      std::vector<CorePoint> probes, int n_used)
        : rest_(rest), lateral_(lateral), loads_(loads), probes_(std::move(probes)), n_used_(n_used) {
        for (const OrderLoad& l : loads_.orders) {
            orders_.push_back(l.order);
            // The static part of the modes left out, K^-1 (c + Omega^2 p):
            // K^-1 c and K^-1 p once for the sweep's every speed (two sparse
            // solves per order and speed otherwise: a tenth of the verdict).
            std::optional<Eigen::VectorXcd> c = lateral_.static_solve(lateral_.to_rows(l.constant));
            std::optional<Eigen::VectorXcd> p = lateral_.static_solve(lateral_.to_rows(l.per_spin_squared));
            if (c && p) static_parts_.push_back({std::move(*c), std::move(*p)});
        }
    }

    const std::vector<int>& orders() const override { return orders_; }
    size_t n_probes() const override { return probes_.size(); }

    std::vector<Eigen::VectorXcd> solve(double speed_hz, ResponseMethod method) const override {
        const double spin = 2 * M_PI * speed_hz;
        std::vector<Eigen::VectorXcd> out;
        for (size_t k = 0; k < loads_.orders.size(); ++k) {
            const OrderLoad& load = loads_.orders[k];
            const Eigen::VectorXcd f = lateral_.to_rows(load.at(spin));
            const double omega = load.order * spin;
            if (method == ResponseMethod::direct) out.push_back(lateral_.direct(f, spin, omega));
            else if (method == ResponseMethod::complete) out.push_back(lateral_.superpose(f, spin, omega, lateral_.n_modes()));
            else if (static_parts_.empty()) out.push_back(lateral_.superpose(f, spin, omega, n_used_, true));
            else {
                const Eigen::VectorXcd K_inverse_f = static_parts_[k].first + spin * spin * static_parts_[k].second;
                out.push_back(lateral_.superpose(f, spin, omega, n_used_, true, &K_inverse_f));
            }
        }
        return out;
    }

    ProbeAmplitude at_probe(const std::vector<Eigen::VectorXcd>& x, size_t probe) const override {
        ProbeAmplitude a;
        for (const Eigen::VectorXcd& rows : x) {
            const Eigen::VectorXcd net = lateral_.to_network(rows);
            cd ux = 0, uy = 0;
            for (int k = 0; k < 3; ++k) {
                ux += probes_[probe].shape[k] * net(beam_dof::per_node * probes_[probe].nodes[k] + beam_dof::ux);
                uy += probes_[probe].shape[k] * net(beam_dof::per_node * probes_[probe].nodes[k] + beam_dof::uy);
            }
            a.per_order_m.push_back(orbit_semi_major(ux, uy));
            a.total_m += a.per_order_m.back();
        }
        return a;
    }

    bool has_complete_basis() const override { return lateral_.complete(); }

    AnsweringMode answering_mode(size_t order_index, double speed_hz) const override {
        const int j = answering_index(loads_.orders[order_index], speed_hz);
        const double frequency_hz = lateral_.mode_frequency_hz(j);
        const double lambda = std::pow(2 * M_PI * frequency_hz, 2);
        return {label_beam_mode(rest_.network, lateral_.mode_shape(j), lateral_.mode_mass_shape(j), lambda,
                                rest_.lambda_scale),
                frequency_hz};
    }

private:
    std::vector<std::pair<Eigen::VectorXcd, Eigen::VectorXcd>> static_parts_;  // per order: K^-1 c, K^-1 p
    // The kept mode with the largest share of the first probe's motion.
    int answering_index(const OrderLoad& load, double speed_hz) const {
        const double spin = 2 * M_PI * speed_hz;
        const Eigen::VectorXcd eta =
            lateral_.modal_coordinates(lateral_.to_rows(load.at(spin)), spin, load.order * spin, n_used_);
        const CorePoint& probe = probes_.front();
        int best = 0;
        double best_share = -1;
        for (int j = 0; j < n_used_; ++j) {
            const Eigen::VectorXd phi = lateral_.mode_shape(j);
            double at_probe = 0;
            for (int k = 0; k < 3; ++k)
                at_probe += probe.shape[k] * std::hypot(phi(beam_dof::per_node * probe.nodes[k] + beam_dof::ux),
                                                        phi(beam_dof::per_node * probe.nodes[k] + beam_dof::uy));
            const double share = std::abs(eta(j)) * std::abs(at_probe);
            if (share > best_share) best_share = share, best = j;
        }
        return best;
    }

    const BeamModelResult& rest_;
    const LateralResponse& lateral_;
    const ResponseLoads& loads_;
    std::vector<CorePoint> probes_;
    int n_used_;
    std::vector<int> orders_;
};

// Each part's stiffness on the lateral rows: the core's elements split into
// their layers (the core's wall and the rest paper, beam_theory.hpp: K_e is
// linear in the section's stiffnesses, so K_e(core) + K_e(rest paper) is the
// element's K_e), the chucks' elements whole; springs are no part. The
// scene, the network and the response outlive it.
PartStiffness beam_part_stiffness(const Scene& scene, const BeamNetwork& net, const LateralResponse& lateral) {
    // The element stiffness of one part's section, summed on the rows over the beams that carry it.
    const auto part_stiffness = [&scene, &net, &lateral](const std::string& part) {
        const std::vector<int>& free = lateral.matrices().free_dofs;
        std::vector<int> row_of(net.held.size(), -1);
        for (size_t r = 0; r < free.size(); ++r) row_of[static_cast<size_t>(free[r])] = static_cast<int>(r);
        const auto n = static_cast<Eigen::Index>(free.size());
        std::vector<Eigen::Triplet<double>> triplets;
        for (const BeamNetwork::Beam& beam : net.beams) {
            std::optional<BeamSection> layer;  // none: the part is not in this beam
            if (beam.name == "core" && part == "core")
                layer = tube_beam_section(scene.core.outer_diameter, scene.core.inner_diameter, scene.core.material);
            if (beam.name == "core" && part == "rest_paper" && scene.rest_paper)
                layer = tube_beam_section(scene.rest_paper->outer_diameter, scene.core.outer_diameter,
                                          scene.rest_paper->material);
            const bool chuck = beam.name.starts_with("chuck") && part == "chucks";
            if (!layer && !chuck) continue;
            for (size_t e = 0; e < beam.sections.size(); ++e) {
                const int nodes[kElementNodes] = {beam.nodes[2 * e], beam.nodes[2 * e + 1], beam.nodes[2 * e + 2]};
                const TimoshenkoElement element{net.node_z[nodes[2]] - net.node_z[nodes[0]],
                                                chuck ? beam.sections[e] : *layer};
                const BeamElementMatrix K = element_matrices(element).K;
                for (int i = 0; i < kElementDofs; ++i)
                    for (int j = 0; j < kElementDofs; ++j) {
                        const int ri = row_of[beam_dof::per_node * nodes[i / beam_dof::per_node] + i % beam_dof::per_node];
                        const int rj = row_of[beam_dof::per_node * nodes[j / beam_dof::per_node] + j % beam_dof::per_node];
                        if (ri >= 0 && rj >= 0 && K(i, j) != 0) triplets.emplace_back(ri, rj, K(i, j));
                    }
            }
        }
        Eigen::SparseMatrix<double> K(n, n);
        K.setFromTriplets(triplets.begin(), triplets.end());
        return K;
    };
    return {lateral.matrices().K.rows(), {"core", "rest_paper", "chucks"}, part_stiffness,
            "the core's and rest paper's layers of each core element and the chucks' elements"};
}

double first_bending_hz(const BeamModelResult& rest) {
    for (const BeamMode& m : rest.modes)
        if (m.label.type == "bending") return m.frequency_hz;
    return 0;
}

Eigen::VectorXd first_bending_shape(const BeamModelResult& rest) {
    for (const BeamMode& m : rest.modes)
        if (m.label.type == "bending") return m.shape;
    throw SolveError("the roll has no bending mode among the modes at rest; expected [analysis] modes to include one");
}

// The lateral problem's modes: every one (a run that checks its sum against
// the complete basis and the direct solve), or those up to the cutoff of the
// highest order the excitation can load, when the caller checks elsewhere or
// lightly against the sparse direct solve (lateral_response.hpp); the
// complete basis where the truncated one cannot be had.
LateralResponse lateral_basis(const BeamModelResult& rest, const ResponseSetup& setup, ResponseChecking checking,
                              double tolerance) {
    if (checking != ResponseChecking::full) {
        const double cutoff_hz =
            kTruncationFactor * highest_order(setup.excitation) * setup.response.speeds_hz.back();
        if (std::optional<LateralResponse> truncated =
                LateralResponse::truncated(rest.network, rest.lambda_scale, 2 * M_PI * cutoff_hz, tolerance))
            return std::move(*truncated);
    }
    return LateralResponse(rest.network, rest.lambda_scale);
}

}  // namespace

const ResponseLevel kBeamResponse{
    .level = ModelChoice::beam,
    .note = "forced response at the beam level: modal superposition in the modes at rest with the gyroscopic coupling of "
            "the spinning beams projected, checked against the direct solve of the full network"};

namespace {

ResponseResult run_beam_response(const Scene& scene, const ResponseSetup& setup, const BeamModelOptions& options,
                                 ResponseChecking checking) {
    Stopwatch clock;
    ResponseResult out = response_result_for(scene, setup, kBeamResponse);
    out.solver = "modal superposition in the modes at rest (gyroscopic coupling projected), checked by a direct dense solve";
    const ResponseRange& range = setup.response;
    // 1. At rest.
    const BeamModelResult rest = solve_beam_model(scene, options);
    // A response in modes that are not verified is no response (modes/verification_check.hpp).
    require_verified("the modes at rest of " + scene.name + " (beam level)",
                     verification_failures({}, rest.verification, scene.analysis.tolerance), false);
    const double f1 = first_bending_hz(rest);
    out.speeds_at_rest = roll_speeds(scene, f1, f1 > 0 ? "" : "no bending mode");
    // 2. The lateral problem, its modes, their damping and the loads.
    LateralResponse lateral = lateral_basis(rest, setup, checking, scene.analysis.tolerance);
    const LateralDampingPlan damping = plan_damping(setup.damping, rest, lateral);
    lateral.set_damping(damping.rayleigh, damping.zeta);
    out.n_dofs = lateral.matrices().K.rows();
    const Eigen::VectorXd first_shape =
        setup.excitation.bow_shape == BowShape::first_mode ? first_bending_shape(rest) : Eigen::VectorXd();
    const ResponseLoads loads = build_response_loads(scene, setup.excitation, rest.network, lateral, first_shape);
    COREMODAL_ASSERT(!loads.orders.empty());  // the reader refuses an [excitation] that excites nothing
    for (const std::string& a : damping.assumptions) out.assumptions.push_back(a);
    add_part_damping(lateral, setup.damping, beam_part_stiffness(scene, rest.network, lateral), out.assumptions);
    for (const std::string& a : loads.assumptions) out.assumptions.push_back(a);
    for (const OrderLoad& l : loads.orders) out.orders.push_back(l.order), out.order_sources.push_back(l.sources);
    std::vector<CorePoint> probes;
    for (const ResponseRange::Probe& p : range.probes) probes.push_back(core_point(rest.network, p.z_m));
    if (loads.sag.size() > 0)
        for (int k = 0; k < 3; ++k) out.sag_m += probes[0].shape[k] * loads.sag(beam_dof::per_node * probes[0].nodes[k]);
    out.sag_m = std::abs(out.sag_m);
    out.ovality_split = loads.ovality_split;
    // 3-5. The sweep with the modes up to kTruncationFactor times the highest
    // load frequency, the peaks, the speed at the limit, the checks.
    const double top_hz = out.orders.back() * range.speeds_hz.back();
    out.checks.n_modes_all = lateral.n_all_modes();
    out.checks.cutoff_hz = kTruncationFactor * top_hz;
    const int n_used = std::max(std::min(2, lateral.n_modes()), lateral.modes_below(2 * M_PI * out.checks.cutoff_hz));
    out.checks.n_modes_used = n_used;
    out.mode_damping = kept_mode_damping(damping, lateral, n_used);
    const BeamResponseModel model(rest, lateral, loads, probes, n_used);
    sweep_response(model, range, f1, out.roll_outer_diameter, out, checking);
    out.assumptions.push_back(kept_modes_assumption(out.checks, "lateral modes at rest"));
    out.solve_seconds = clock.lap();
    return out;
}


// The beam network's forced response (ModelLevel::response); the scene
// outlives it (the driver's call).
class BeamResponse : public LevelResponse {
public:
    BeamResponse(const Scene& scene, const BeamModelOptions& options) : scene_(scene), options_(options) {}
    // The beam level's run at rest is the lateral problem's already (RestModes).
    ResponseResult respond(const ResponseSetup& setup, ResponseChecking checking, RestModes) override {
        return run_beam_response(scene_, setup, options_, checking);
    }

private:
    const Scene& scene_;
    BeamModelOptions options_;
};

}  // namespace

std::unique_ptr<LevelResponse> BeamLevel::response(const Scene& scene, const BeamModelOptions& options) {
    return std::make_unique<BeamResponse>(scene, options);
}

}  // namespace coremodal
