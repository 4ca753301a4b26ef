#include "traction/traction_sweep.hpp"

#include <cmath>

namespace coremodal {
namespace {

PlainRollerComparison plain_roller(const TractionSpec& grooved) {
    TractionSpec plain = grooved;
    plain.grooves = Grooves{};
    PlainRollerComparison out;
    const EffectiveClearance h = effective_clearance(plain);
    out.clearance = h.clearance;
    if (!(h.clearance > 0)) {  // two perfectly smooth surfaces: the air separates them at any speed above 0
        for (double v : plain.web_speeds) {  // at rest the capstan equation {1}, else nothing
            out.traction.push_back(v > 0 ? 0.0 : plain.tension * (1.0 - std::exp(-plain.friction * plain.wrap)));
            out.effective_friction.push_back(v > 0 ? 0.0 : plain.friction);
        }
        return out;
    }
    out.zero_traction_speed = zero_traction_speed(plain);
    for (double v : plain.web_speeds) {
        const TractionPoint p = traction_at(plain, h, v);
        out.traction.push_back(p.traction);
        out.effective_friction.push_back(p.effective_friction);
    }
    return out;
}

}  // namespace

TractionSweep run_traction_sweep(const TractionSpec& spec) {
    TractionSweep out;
    out.clearance = effective_clearance(spec);
    for (double v : spec.web_speeds) {
        out.points.push_back(traction_at(spec, out.clearance, v));
        if (!out.points.back().valid) ++out.n_invalid;
        if (!out.points.back().contact) ++out.n_no_contact;
    }
    out.zero_traction_speed = zero_traction_speed(spec);
    out.centripetal_limit_speed = centripetal_limit_speed(spec);
    if (spec.tension_difference) out.slip_speed = slip_speed(spec, *spec.tension_difference);
    if (spec.grooves.shape != GrooveShape::none) out.plain = plain_roller(spec);
    return out;
}

std::optional<double> groove_speed_gain(const TractionSweep& sweep) {
    if (!sweep.plain || !(sweep.plain->zero_traction_speed > 0)) return std::nullopt;
    return sweep.zero_traction_speed / sweep.plain->zero_traction_speed;
}

}  // namespace coremodal
