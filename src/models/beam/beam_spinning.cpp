// The beam level's spinning model (models/spinning_model.hpp): the modes at
// rest are those of `coremodal run` (solve_beam_model), the modes at a speed
// the network's dense Hermitian linearization (beam/rotating_modes.hpp),
// each labelled. No per-block solve, no damping, no co-rotating pencils.
#include "models/beam/beam_level.hpp"
#include "models/spinning_model.hpp"

#include "beam/rotating_modes.hpp"
#include "models/beam/beam_spinning_notes.hpp"

#include <complex>
#include <memory>

namespace coremodal {
namespace {

class BeamSpinning : public SpinningModel {
public:
    BeamSpinning(const Scene& scene, const SpinningOptions& options)
        : rest_(solve_beam_model(scene)),
          network_(rest_.network, rest_.lambda_scale),
          window_(static_cast<int>(rest_.modes.size()) + options.extra_tracked_modes),
          notes_(spinning_notes(options.rotation)) {}

    std::vector<RotatingMode> modes_at_rest() const override {
        std::vector<RotatingMode> out;
        for (const BeamMode& m : rest_.modes) {
            RotatingMode r;
            r.frequency_hz = m.frequency_hz;
            r.label = m.label;
            r.relative_residual = m.relative_residual;
            r.shape = m.shape.cast<std::complex<double>>();
            out.push_back(std::move(r));
        }
        return out;
    }
    size_t reported() const override { return rest_.modes.size(); }
    std::vector<RotatingMode> modes_at(double speed_hz) const override { return network_.modes_at(speed_hz, window_); }
    long n_dofs() const override { return network_.n_free_dofs(); }
    std::vector<std::string> notes() const override { return notes_; }
    std::string solver() const override {
        return "dense: exact linearization of the quadratic problem (Hermitian, size 2n, in the modes at rest)";
    }
    std::string completeness() const override {
        return "every eigenvalue of the Hermitian linearization is computed (dense); at rest the modes are those of "
               "`coremodal run` (inertia count)";
    }

private:
    const BeamModelResult rest_;  // network_ keeps a pointer to its network
    const RotatingNetwork network_;
    const int window_;
    const std::vector<std::string> notes_;
};

}  // namespace

std::unique_ptr<SpinningModel> BeamLevel::spinning(const Scene& scene, const SpinningOptions& options) {
    return std::make_unique<BeamSpinning>(scene, options);
}

}  // namespace coremodal
