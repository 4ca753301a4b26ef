// The solid level's spinning model (models/spinning_model.hpp): the quadratic
// solver on the whole solid at every speed (rotating_solid.hpp). In
// co-rotating coordinates (a scene that is not a body of revolution) it also
// hands out the pencils of the exact critical speeds, and after the sweep
// says how well each mode's dominant harmonic brought it to the stationary
// frame.
#include "models/solid/solid_level.hpp"
#include "models/spinning_model.hpp"

#include "common/format.hpp"
#include "models/solid/rotating_solid.hpp"
#include "models/solid/solid_spinning_notes.hpp"

#include <memory>

namespace coremodal {
namespace {

class SolidSpinning : public SpinningModel, public ZeroFrequencyPencils {
public:
    SolidSpinning(const Scene& scene, const SpinningOptions& options)
        : reported_(static_cast<size_t>(scene.analysis.n_modes)),
          solid_(scene, static_cast<int>(reported_) + options.extra_tracked_modes,
                 {.centrifugal_stiffening = options.rotation.centrifugal_stiffening}),
          notes_(spinning_notes(options.rotation, solid_)) {}

    std::vector<RotatingMode> modes_at_rest() const override { return solid_.modes_at(0.0); }
    size_t reported() const override { return reported_; }
    std::vector<RotatingMode> modes_at(double speed_hz) const override { return solid_.modes_at(speed_hz); }
    const ZeroFrequencyPencils* zero_frequency_pencils() const override {
        return solid_.rotating_frame() ? this : nullptr;
    }
    ZeroFrequencyModes zero_frequency_modes(double max_speed_hz) const override {
        return solid_.zero_frequency_modes(max_speed_hz);
    }
    ZeroFrequencyModes frequency_ratio_modes(double max_speed_hz, int ratio) const override {
        return solid_.frequency_ratio_modes(max_speed_hz, ratio);
    }
    long n_dofs() const override { return solid_.n_dofs(); }
    std::vector<std::string> notes() const override { return notes_; }
    std::vector<std::string> notes_after_sweep() const override;
    std::string solver() const override {
        return "SLEPc PEP (TOAR, shift-and-invert with an LU factor of K + tau Omega G + tau^2 M) on the whole solid";
    }
    std::string completeness() const override {
        return "the inertia of the Hermitian Q(omega) = K - omega^2 M + i omega Omega G at the band edge counts the "
               "modes below it (every eigenvalue of Q crosses zero downwards)";
    }

private:
    const size_t reported_;
    const RotatingSolid solid_;
    const std::vector<std::string> notes_;
};

std::vector<std::string> SolidSpinning::notes_after_sweep() const {
    if (!solid_.rotating_frame()) return {};
    return {
        "the dominant harmonic's share of a mode's energy on the roll's surface, the smallest over every mode "
        "reported at every speed above 0: " +
        significant(solid_.min_harmonic_share(), 3) +
        " (1 for a body of revolution; below 1 the segments mix harmonics k and k +- their number, and the "
        "stationary frequency is that of the dominant one; below 1/2 a mode has no one stationary frequency, "
        "but one at f - k f_rot for each harmonic k it carries)"};
}

}  // namespace

std::unique_ptr<SpinningModel> SolidLevel::spinning(const Scene& scene, const SpinningOptions& options) {
    require_one_process_sweep(scene, ModelChoice::solid);
    return std::make_unique<SolidSpinning>(scene, options);
}

}  // namespace coremodal
