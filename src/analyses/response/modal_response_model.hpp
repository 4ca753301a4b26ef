// What the harmonic and solid levels' forced responses share
// (harmonic_response.cpp, solid_response.cpp): a ModalResponse with its
// loads and probes as the sweep's ResponseModel, and the last steps of the
// run once the level has its basis, damping, loads and probes.
#pragma once

#include "analyses/response/modal_response.hpp"
#include "analyses/response/response_damping.hpp"
#include "analyses/response/response_loads.hpp"
#include "analyses/response/response_sweep.hpp"
#include "models/model_level.hpp"

#include <Eigen/Dense>

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
void finish_modal_response(const ModalLevelParts& parts, const ResponseRange& range, double f1_hz, ResponseResult& out);

// The first bending frequency among a level's modes at rest (0: none).
double first_bending_hz(const LevelModes& rest);

// The highest order the excitation loads (effects/excitation.hpp): 2 with an
// oval core under gravity, else 1.
int highest_order(const ExcitationSpec& x);

}  // namespace coremodal
