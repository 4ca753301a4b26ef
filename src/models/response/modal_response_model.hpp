// What the harmonic and solid levels' forced responses share
// (harmonic_response.cpp, solid_response.cpp): a ModalResponse with its
// loads and probes as the sweep's ResponseModel, and the last steps of the
// run once the level has its basis, damping, loads and probes.
#pragma once

#include "models/response/modal_response.hpp"
#include "models/response/response_damping.hpp"
#include "models/response/response_levels.hpp"
#include "models/response/response_loads.hpp"
#include "models/response/response_sweep.hpp"
#include "assembly/operator_set.hpp"
#include "models/model_level.hpp"

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

namespace coremodal {

// The loads of [excitation] on a level's unknowns, per order.
struct LevelLoads {
    std::vector<OrderLoad> orders;  // ascending order; only orders with a load
    Eigen::VectorXd sag;            // the static sag along x per DOF, m; empty without gravity
    double ovality_split = 0;
    std::vector<std::string> assumptions;
};

// The order-2 load eps K_core u_sag of an oval core under gravity, given per
// unit eps (out.ovality_split is eps), with its assumption; `reach` says how
// the level carries it ("in wave number n = 1 ...").
void add_ovality_load(LevelLoads& out, const Eigen::VectorXcd& per_unit_split, const std::string& reach);
// The orders ascending, as the sweep reports them.
void sort_orders(LevelLoads& out);

// A probe as weights on the unknowns: u_x = x . a and u_y = y . a (the
// harmonic level's one plane: y = -i x, a forward circle).
struct ProbeWeights {
    Eigen::VectorXcd x, y;
};

// The harmonic and solid levels' last steps (3-5 of response.hpp) on `out`:
// the kept modes (up to out.checks.cutoff_hz, at least min_kept), their
// damping, the orders and the sag at the first probe, the sweep, the peaks,
// the safe speed and the checks against the direct solve. `modes_words`
// names the basis in the run's assumption ("modes at rest of wave number n = 1").
struct ModalLevelParts {
    const ModalResponse& response;
    const LateralDampingPlan& damping;
    const LevelLoads& loads;
    std::vector<ProbeWeights> probes;
    std::vector<ModeLabel> labels;  // per basis mode
    int min_kept = 2;
    std::string modes_words;
};
void finish_modal_response(const ModalLevelParts& parts, const ResponseRange& range, double f1_hz, ResponseResult& out,
                           ResponseChecking checking = ResponseChecking::full);

// Step 1 of the harmonic and solid levels (scene.model resolved): one
// process, the result's level-independent fields and `solver`, the level's
// run at rest into `rest` (the modes as modes.csv numbers them) and I-5
// from its first bending frequency.
ResponseResult start_mesh_level_response(const Scene& scene, const ResponseSetup& setup, const ResponseLevel& level,
                                         const std::string& solver, LevelModes& rest);
// The same without the run at rest (RestModes::lateral): the caller sets
// speeds_at_rest from its own basis.
ResponseResult start_mesh_level_response(const Scene& scene, const ResponseSetup& setup, const ResponseLevel& level,
                                         const std::string& solver);

// The lowest modes at rest of `operators` up to cutoff_hz (at least
// min_modes), M-orthonormal, solved as the level's run solves them (SLEPc,
// verified, complete by inertia); `problem` names it in the solver's errors.
ModalBasis modal_basis_below(const Scene& scene, const OperatorSet& operators, double cutoff_hz, int min_modes,
                             const std::string& problem);

// [damping] on a basis whose mode j is the mode (or pair) at rest of its
// eigenvalue among those `in_response` takes; `lateral_words` as plan_modal_damping's.
LateralDampingPlan plan_basis_damping(const DampingSpec& spec, const LevelModes& rest, const ModalBasis& basis,
                                      const std::vector<ModeLabel>& labels, double lambda_scale,
                                      const std::function<bool(const ModeLabel&)>& in_response,
                                      const std::string& lateral_words);

// The first bending frequency among a level's modes at rest (0: none).
double first_bending_hz(const LevelModes& rest);

// The highest order the excitation loads (effects/excitation.hpp): 2 with an
// oval core under gravity, else 1.
int highest_order(const ExcitationSpec& x);

}  // namespace coremodal
