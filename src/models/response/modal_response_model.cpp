#include "models/response/modal_response_model.hpp"

#include "models/response/response_levels.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "effects/excitation.hpp"
#include "eigensolve/tolerances.hpp"
#include "models/choose.hpp"
#include "models/solve_steps.hpp"
#include "modes/mode_shapes.hpp"
#include "modes/verification_check.hpp"

#include <algorithm>
#include <cmath>
#include <complex>

namespace coremodal {
namespace {

using cd = std::complex<double>;

// A ModalResponse with its loads and probes, for the sweep. It has only the
// kept modes (no complete basis of a mesh): "complete" is every basis mode
// with the static part of the rest, and the checks go against the direct solve.
class ModalResponseModel : public ResponseModel {
public:
    ModalResponseModel(const ModalLevelParts& parts, int n_used) : parts_(parts), n_used_(n_used) {
        for (const OrderLoad& l : parts_.loads.orders) {
            orders_.push_back(l.order);
            // K^-1 f(Omega) = K^-1 c + Omega^2 K^-1 s: two static solves per order for the whole sweep.
            static_parts_.push_back({parts_.response.complex_static_response(l.constant),
                                     parts_.response.complex_static_response(l.per_spin_squared)});
        }
    }

    const std::vector<int>& orders() const override { return orders_; }
    size_t n_probes() const override { return parts_.probes.size(); }
    bool has_complete_basis() const override { return false; }

    std::vector<Eigen::VectorXcd> solve(double speed_hz, ResponseMethod method) const override {
        const ModalResponse& r = parts_.response;
        const double spin = 2 * M_PI * speed_hz;
        std::vector<Eigen::VectorXcd> out;
        for (size_t k = 0; k < parts_.loads.orders.size(); ++k) {
            const OrderLoad& load = parts_.loads.orders[k];
            const Eigen::VectorXcd f = load.at(spin);
            const double omega = load.order * spin;
            if (method == ResponseMethod::direct) {
                out.push_back(r.direct(f, spin, omega));
                continue;
            }
            const Eigen::VectorXcd static_f = static_parts_[k].first + spin * spin * static_parts_[k].second;
            out.push_back(r.superpose(f, spin, omega, method == ResponseMethod::complete ? r.n_modes() : n_used_, static_f));
        }
        return out;
    }

    ProbeAmplitude at_probe(const std::vector<Eigen::VectorXcd>& x, size_t probe) const override {
        ProbeAmplitude a;
        const ProbeWeights& w = parts_.probes[probe];
        for (const Eigen::VectorXcd& xk : x) {
            a.per_order_m.push_back(orbit_semi_major(w.x.conjugate().dot(xk), w.y.conjugate().dot(xk)));
            a.total_m += a.per_order_m.back();
        }
        return a;
    }

    AnsweringMode answering_mode(size_t order_index, double speed_hz) const override {
        const ModalResponse& r = parts_.response;
        const OrderLoad& load = parts_.loads.orders[order_index];
        const double spin = 2 * M_PI * speed_hz;
        const Eigen::VectorXcd eta = r.modal_coordinates(load.at(spin), spin, load.order * spin, n_used_);
        const ProbeWeights& w = parts_.probes.front();
        int best = 0;
        double best_share = -1;
        for (int j = 0; j < n_used_; ++j) {
            const Eigen::VectorXcd phi = r.modes().col(j).cast<cd>();
            const double share = std::abs(eta(j)) * std::hypot(std::abs(w.x.conjugate().dot(phi)), std::abs(w.y.conjugate().dot(phi)));
            if (share > best_share) best_share = share, best = j;
        }
        return {parts_.labels[static_cast<size_t>(best)], r.mode_frequency_hz(best)};
    }

private:
    const ModalLevelParts& parts_;
    int n_used_;
    std::vector<int> orders_;
    std::vector<std::pair<Eigen::VectorXcd, Eigen::VectorXcd>> static_parts_;  // per order: K^-1 c, K^-1 s
};

}  // namespace

void finish_modal_response(const ModalLevelParts& parts, const ResponseRange& range, double f1_hz, ResponseResult& out,
                           ResponseChecking checking) {
    COREMODAL_ASSERT(!parts.loads.orders.empty());  // the reader refuses an [excitation] that excites nothing
    const ModalResponse& response = parts.response;
    out.n_dofs = response.n_dofs();
    for (const std::string& a : parts.damping.assumptions) out.assumptions.push_back(a);
    for (const std::string& a : parts.loads.assumptions) out.assumptions.push_back(a);
    for (const OrderLoad& l : parts.loads.orders) out.orders.push_back(l.order), out.order_sources.push_back(l.sources);
    if (parts.loads.sag.size() > 0)
        out.sag_m = std::abs(parts.probes.front().x.conjugate().dot(parts.loads.sag.cast<cd>()));
    out.ovality_split = parts.loads.ovality_split;
    out.checks.n_modes_all = response.n_modes();
    const int n_used =
        std::max(std::min(parts.min_kept, response.n_modes()), response.modes_below(2 * M_PI * out.checks.cutoff_hz));
    out.checks.n_modes_used = n_used;
    out.mode_damping = kept_mode_damping(parts.damping, response, n_used);
    const ModalResponseModel model(parts, n_used);
    sweep_response(model, range, f1_hz, out.roll_outer_diameter, out, checking);
    out.assumptions.push_back(kept_modes_assumption(out.checks, parts.modes_words) + " (K^-1 f less the kept modes' part)");
}

void add_ovality_load(LevelLoads& out, const Eigen::VectorXcd& per_unit_split, const std::string& reach) {
    add_order_load(out.orders, 2, out.ovality_split * per_unit_split, Eigen::VectorXcd::Zero(per_unit_split.size()),
                   OvalityGravity::kName);
    out.assumptions.push_back(
        "ovality: the core's wall is oval through its thickness (r = R + delta cos 2 theta, delta = ovality / 4), "
        "the rest paper round; eps = " + significant(out.ovality_split, 3) +
        " splits the stiffness of the core's cells; the order-2 load is eps K_core u_sag " + reach);
}

void sort_orders(LevelLoads& out) {
    std::sort(out.orders.begin(), out.orders.end(), [](const OrderLoad& a, const OrderLoad& b) { return a.order < b.order; });
}

ResponseResult start_mesh_level_response(const Scene& scene, const ResponseSetup& setup, const ResponseLevel& level,
                                         const std::string& solver) {
    if (mpi_size() > 1)
        throw InputError(scene.source_file + ": the forced response at the " + to_string(scene.model) +
                         " level runs in one process; run it without mpirun");
    ResponseResult out = response_result_for(scene, setup, level);
    out.solver = solver;
    return out;
}

ResponseResult start_mesh_level_response(const Scene& scene, const ResponseSetup& setup, const ResponseLevel& level,
                                         const std::string& solver, LevelModes& rest) {
    ResponseResult out = start_mesh_level_response(scene, setup, level, solver);
    rest = make_model_level(scene)->solve(scene, Printer{false});
    // A response in modes that are not verified is no response: no --keep-going here.
    require_verified("the modes at rest of " + scene.name + " (" + to_string(scene.model) + " level)",
                     verification_failures(rest.modes, rest.verification, scene.analysis.tolerance), false);
    const double f1 = first_bending_hz(rest);
    out.speeds_at_rest = roll_speeds(scene, f1, f1 > 0 ? "" : "no bending mode");
    return out;
}

ModalBasis modal_basis_below(const Scene& scene, const OperatorSet& operators, double cutoff_hz, int min_modes,
                             const std::string& problem) {
    SolveRequest request = solve_request(scene);
    request.lambda_min.reset(), request.lambda_max.reset();  // the lowest modes, whatever band the case asks for
    const double lambda_cut = std::pow(2 * M_PI * cutoff_hz, 2);
    request.n_modes = std::max<int>(min_modes, static_cast<int>(count_eigenvalues_below(operators, lambda_cut)));
    const SolvedModes solved = solve_for_case(scene, operators, request, [](const std::string&) {}, problem);
    ModalBasis basis;
    const std::vector<double> first = gather_to_root(solved.vectors.front());
    basis.Phi.resize(static_cast<Eigen::Index>(first.size()), static_cast<Eigen::Index>(solved.vectors.size()));
    basis.lambda = Eigen::Map<const Eigen::VectorXd>(solved.eigenvalues.data(), basis.Phi.cols());
    for (size_t j = 0; j < solved.vectors.size(); ++j) {
        const std::vector<double> values = gather_to_root(solved.vectors[j]);
        basis.Phi.col(static_cast<Eigen::Index>(j)) = Eigen::Map<const Eigen::VectorXd>(values.data(), basis.Phi.rows());
    }
    return basis;
}

LateralDampingPlan plan_basis_damping(const DampingSpec& spec, const LevelModes& rest, const ModalBasis& basis,
                                      const std::vector<ModeLabel>& labels, double lambda_scale,
                                      const std::function<bool(const ModeLabel&)>& in_response,
                                      const std::string& lateral_words) {
    std::vector<NumberedRestMode> numbered;
    for (const Mode& m : rest.modes) numbered.push_back({m.label, m.frequency_hz, in_response(m.label)});
    std::vector<BasisMode> modes;
    for (Eigen::Index j = 0; j < basis.lambda.size(); ++j) {
        const double lambda = basis.lambda(j), tolerance = kClusterTolerance * std::max(std::abs(lambda), lambda_scale);
        BasisMode b{lambda, labels[static_cast<size_t>(j)], {}};
        for (const Mode& m : rest.modes)
            if (in_response(m.label) && std::abs(m.eigenvalue - lambda) <= tolerance) b.rest_modes.push_back(m.index);
        modes.push_back(std::move(b));
    }
    return plan_modal_damping(spec, numbered, modes, lateral_words);
}

double first_bending_hz(const LevelModes& rest) {
    for (const Mode& m : rest.modes)
        if (m.label.type == "bending") return m.frequency_hz;
    return 0;
}

int highest_order(const ExcitationSpec& x) { return x.ovality_m > 0 && x.gravity ? 2 : 1; }

}  // namespace coremodal
