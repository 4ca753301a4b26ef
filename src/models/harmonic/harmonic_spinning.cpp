// The harmonic level's spinning model (models/spinning_model.hpp): per wave
// number n the projected quadratic solver of rotating_harmonics.hpp. A new
// track is labelled once (labelling every mode costs a snapshot each), a
// crossing's refinement solves one wave number, and with [damping] every
// mode gets its damped partner from the same wave number's damped problem.
#include "models/harmonic/harmonic_level.hpp"
#include "models/spinning_model.hpp"

#include "effects/damping.hpp"
#include "models/harmonic/harmonic_spinning_notes.hpp"
#include "models/harmonic/rotating_harmonics.hpp"
#include "modes/tracking.hpp"  // assign_maximum

#include <map>
#include <memory>

namespace coremodal {
namespace {

// Per mode of `modes`, the damped mode of its wave number that continues it:
// the one-to-one pairing of largest MAC (modes/tracking.hpp), at least
// kSameModeMac. A degenerate pair at rest is any mix of its two members; the
// damped pair spans the same plane, so the pairing gives each MAC >= 1/2.
std::vector<std::optional<DampedPartner>> match_damped_partners(const RotatingHarmonics& harmonics, double speed_hz,
                                                                const std::vector<RotatingMode>& modes) {
    std::vector<std::optional<DampedPartner>> out(modes.size());
    std::map<int, std::vector<size_t>> by_block;
    for (size_t i = 0; i < modes.size(); ++i) by_block[modes[i].block].push_back(i);
    for (const auto& [n, members] : by_block) {
        const std::vector<RotatingHarmonics::DampedShape> damped = harmonics.damped_modes_at(speed_hz, n);
        std::vector<std::vector<double>> weight(members.size(), std::vector<double>(damped.size()));
        for (size_t a = 0; a < members.size(); ++a)
            for (size_t b = 0; b < damped.size(); ++b)
                weight[a][b] =
                    modes[members[a]].frequency_hz > 0 ? complex_mac(modes[members[a]].shape, damped[b].shape) : 0.0;
        const std::vector<int> match = assign_maximum(weight);
        for (size_t a = 0; a < members.size(); ++a) {
            if (match[a] < 0 || weight[a][match[a]] < kSameModeMac) continue;
            const DampedMode& d = damped[match[a]].mode;
            out[members[a]] = DampedPartner{d.zeta, d.damped_frequency_hz, d.backward_error};
        }
    }
    return out;
}

class HarmonicSpinning : public SpinningModel {
public:
    HarmonicSpinning(const Scene& scene, const SpinningOptions& options)
        : reported_(static_cast<size_t>(scene.analysis.n_modes)),
          harmonics_(scene, static_cast<int>(reported_) + options.extra_tracked_modes,
                     options.rotation.centrifugal_stiffening),
          damped_(options.damping != nullptr) {
        harmonics_.sweep_up_to(options.rotation.speeds_hz.back());
        notes_ = spinning_notes(options.rotation, harmonics_);
        if (const DampingSpec* d = options.damping) harmonics_.include_damping(operator_damping_of(*d));
    }

    std::vector<RotatingMode> modes_at_rest() const override { return harmonics_.modes_at(0.0); }
    size_t reported() const override { return reported_; }
    std::vector<RotatingMode> modes_at(double speed_hz) const override {
        return harmonics_.modes_at(speed_hz, Labels::none);
    }
    LabelMode label_new_track() const override {
        return [this](const RotatingMode& m) { return harmonics_.label_of(m); };
    }
    BlockModesAtSpeed block_modes_at() const override {
        return [this](double speed, int n) { return harmonics_.modes_at(speed, Labels::none, n); };
    }
    DampedPartners damped_partners() const override {
        if (!damped_) return {};
        return [this](double speed, const std::vector<RotatingMode>& modes) {
            return match_damped_partners(harmonics_, speed, modes);
        };
    }
    long n_dofs() const override { return harmonics_.n_dofs(); }
    std::vector<std::string> notes() const override { return notes_; }
    std::string solver() const override;
    std::string completeness() const override;

private:
    const size_t reported_;
    RotatingHarmonics harmonics_;
    const bool damped_;
    std::vector<std::string> notes_;
};

std::string HarmonicSpinning::solver() const {
    return "per wave number n, the small Hermitian problem in a basis of its modes at rest and their static "
           "responses to the spin's forces, every mode's residual taken on the full problem; " +
           std::to_string(harmonics_.n_full_solves()) + " of " + std::to_string(harmonics_.n_solves()) +
           " problems (one n at one speed) solved whole with SLEPc PEP (TOAR) where the basis fell short";
}

std::string HarmonicSpinning::completeness() const {
    const ProjectedGyroscopic::CountStatistics counts = harmonics_.count_statistics();
    return "per wave number n and speed, the inertia of the full Hermitian Q(omega) = K - omega^2 M + i omega Omega "
           "G at the band edge and at the rigid line counts the modes between them (every eigenvalue of Q crosses "
           "zero downwards); of " +
           std::to_string(counts.speeds) + " counts at the band edge, " + std::to_string(counts.certified) +
           " came from an earlier speed's gap certificate (Weyl's bound on the pencil, "
           "docs/theory/rotation-harmonic.md), " +
           std::to_string(counts.certificates) + " made one (two counts; " + std::to_string(counts.certificate_failed) +
           " failed and counted again) and " + std::to_string(counts.counted) + " counted";
}

}  // namespace

std::unique_ptr<SpinningModel> HarmonicLevel::spinning(const Scene& scene, const SpinningOptions& options) {
    require_one_process_sweep(scene, ModelChoice::harmonic);
    return std::make_unique<HarmonicSpinning>(scene, options);
}

}  // namespace coremodal
