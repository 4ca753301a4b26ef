#include "analyses/converge/model_study.hpp"

#include "scene/level_traits.hpp"
#include "numerics/power_law.hpp"

#include <cmath>

namespace coremodal {
namespace {

// The extrapolation from the finest levels that all have the mode, and each
// level's error against its f0.
void extrapolate(TrackedMode& t, const std::vector<LevelResult>& levels) {
    std::vector<double> h, f;
    for (std::size_t i = levels.size(); i-- > 0 && t.frequency_hz[i];) {
        h.insert(h.begin(), levels[i].step.h);
        f.insert(f.begin(), *t.frequency_hz[i]);
    }
    if (f.size() >= 3) t.richardson = richardson(h, f);
    for (const auto& value : t.frequency_hz)
        t.relative_error.push_back(value && t.richardson
                                       ? std::optional<double>(std::abs(*value - t.richardson->f0) /
                                                               std::abs(t.richardson->f0))
                                       : std::nullopt);
}

}  // namespace

std::vector<TrackedMode> track_modes(const std::vector<LevelResult>& levels) {
    std::vector<std::vector<DistinctMode>> distinct;
    for (const auto& level : levels) distinct.push_back(distinct_modes(level.modes));
    std::vector<TrackedMode> tracked;
    for (LabelTrack& track : track_by_label(distinct, kModeRoles)) {
        TrackedMode t;
        t.key = std::move(track.key);
        t.role = std::move(track.role);
        t.frequency_hz = std::move(track.frequency_hz);
        extrapolate(t, levels);
        tracked.push_back(std::move(t));
    }
    return tracked;
}

LadderTraits ladder_traits(ModelChoice level) {
    const LevelTraits& t = level_traits(level);
    LadderTraits out{.reference = t.converge_reference, .meshed = t.meshed, .same_section = t.axisymmetric_only};
    if (!t.meshed)
        out.timing_parts = "mesh: building the beam network; factor_and_solve: assembly, eigensolve and inertia count "
                           "(assemble is inside it, 0 here); classify: labels and effective masses";
    if (t.axisymmetric_only) {  // one 2D problem per wave number n
        out.timing_parts = "mesh: the r-z section and its revolution (for naming the modes); assemble and "
                           "factor_and_solve: summed over the wave numbers n (eigensolves and inertia counts); "
                           "n_dofs: the largest one-harmonic problem";
        out.cost_note = "\n" + std::string(t.title) +
                        " level: mesh = the r–z section and its revolution (for naming the modes); assembly and "
                        "factorization and solve sum over the wave numbers n solved or counted; DOFs = the largest "
                        "one-harmonic problem.\n";
    }
    return out;
}

ModelStudy analyse_levels(ModelChoice level, std::string ladder_note, std::vector<LevelResult> levels) {
    ModelStudy s;
    s.model = to_string(level);
    s.traits = ladder_traits(level);
    s.ladder_note = std::move(ladder_note);
    s.levels = std::move(levels);
    s.modes = track_modes(s.levels);
    // The coarsest level's time is mostly fixed costs (start-up, gmsh): leave
    // it out of the scaling fit when there are enough levels without it.
    const std::size_t skip = s.levels.size() >= 3 ? 1 : 0;
    std::vector<double> dofs, time, memory;
    for (std::size_t i = skip; i < s.levels.size(); ++i) {
        dofs.push_back(double(s.levels[i].n_dofs));
        time.push_back(s.levels[i].median_s.total);
        memory.push_back(s.levels[i].peak_memory_mb);
    }
    s.time_exponent = power_law_exponent(dofs, time);
    s.memory_exponent = power_law_exponent(dofs, memory);
    return s;
}

const TrackedMode* find_role(const ModelStudy& model, const std::string& role) {
    for (const auto& t : model.modes)
        if (t.role == role) return &t;
    return nullptr;
}

std::optional<std::size_t> first_level_within(const TrackedMode& mode, double target) {
    if (!mode.richardson) return std::nullopt;
    const double f0 = std::abs(mode.richardson->f0);
    const double uncertainty = mode.richardson->f0_uncertainty.value_or(0.0) / f0;
    for (std::size_t i = 0; i < mode.relative_error.size(); ++i)
        if (mode.relative_error[i] && *mode.relative_error[i] + uncertainty <= target) return i;
    return std::nullopt;
}

std::optional<TargetPrediction> predict_level_for(const ModelStudy& model, const TrackedMode& mode, double target) {
    if (!mode.richardson || !mode.richardson->extrapolated || !mode.richardson->asymptotic || model.levels.empty())
        return std::nullopt;
    const Richardson& r = *mode.richardson;
    const double f0 = std::abs(r.f0);
    const double room = target - r.f0_uncertainty.value_or(0.0) / f0;
    const double finest_error = r.error_estimate / f0;
    if (room <= 0 || finest_error <= 0) return std::nullopt;
    const LevelResult& finest = model.levels.back();
    TargetPrediction p;
    p.k = finest.step.k * std::pow(finest_error / room, 1.0 / r.order);
    p.n_dofs = double(finest.n_dofs) * std::pow(p.k / finest.step.k, model.refined_dimensions);
    if (model.time_exponent)
        p.time_s = finest.median_s.total * std::pow(p.n_dofs / double(finest.n_dofs), *model.time_exponent);
    return p;
}

}  // namespace coremodal
