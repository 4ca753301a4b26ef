// The coupled-harmonic model level (model = "coupled", docs/theory/coupled.md,
// "Coupled harmonics"): a scene whose bodies are bodies of revolution but
// whose chucks hold the bore with segmented expanding elements, or rest on
// it where gravity closes a chuck not expanded (the static state first:
// models/coupled/contact_static), or whose roll the web pulls on one line.
// The harmonics n = 0 ... N (both families) of the r–z section are the unknowns,
// coupled by these attachments (models/coupled/coupled_system) into a few independent
// sets, each one sparse symmetric generalized problem solved with
// shift-and-invert and proven complete by its inertia; N grows in steps of the coupling reach
// N_s until the wanted frequencies stop moving (kCoupledTolerance). Modes
// are summed over the harmonics onto the revolved section and named there
// as at the harmonic level.
//
// A scene nothing couples (no segmented element, contact or web: the chuck
// factor's free span, a scene of full bands) is left to the harmonic level, which solves
// the same independent harmonics one at a time.
#pragma once

#include "models/coupled/coupled_modes.hpp"
#include "models/model_level.hpp"

#include <memory>
#include <optional>

namespace coremodal {

// N is accepted when one more coupling step (N + N_s) moves none of the
// wanted frequencies by more than this fraction. Harmonics only add
// freedom (the spaces are nested), so each frequency falls monotonically
// with N. The pads' edges make k(theta) jump, so the harmonic content of
// the bore's motion decays algebraically and N converges slowly: on case
// 10 the step changes fall from 4.6e-4 (N = 13) to 7.9e-5 (N = 22) and
// 9e-6 (N = 40), and the truncation error left at a step is about 1.5 times
// the step (docs/theory/coupled.md). 1e-4 leaves ~1.5e-4, half the solid's
// circumferential error at its default 32 elements around (3e-4 on case 10).
inline constexpr double kCoupledTolerance = 1e-4;
// The largest amplitude a local harmonic may have at its zone's edge,
// relative to the mode's largest, before the reach is doubled. The
// eigenvalue's error measured 1 to 44 times this squared (docs/theory/coupled.md,
// "Local harmonics"): below 4e-6, 25 times inside kCoupledTolerance.
inline constexpr double kZoneEdgeTolerance = 3e-4;

// One step of the search for N: the truncation and what moved.
struct CoupledStep {
    int n_max = 0;
    long n_dofs = 0;
    std::vector<double> frequencies_hz;  // the wanted modes'
    double max_change = 0;  // largest relative change of a wanted frequency from the step before (0 for the first)
    double seconds = 0;
    double zone_edge = 0;  // zone_edge_amplitude of the local harmonics (0 without)
};

// One CoupledLevel that solves a sequence of like scenes (the verdict's
// rest-roll diameters: the same chucks, a different roll) starts each
// search for N one step below where the last one stopped, with the whole
// harmonics it had grown to: the step that may stop the search is then the
// first one compared, and the criterion to stop is the same as from N_s + 1.
class CoupledLevel : public ModelLevel {
public:
    int steps() const override { return 7; }
    LevelModes solve(const Scene& scene, const Printer& say) override;
    LevelShapes shapes() const override;
    // The steps of the search for N (empty when the harmonic level solved the scene).
    const std::vector<CoupledStep>& convergence() const { return steps_; }

private:
    std::optional<RevolvedMesh> revolved_;
    std::unique_ptr<ModelLevel> axisymmetric_;  // when nothing couples
    std::vector<CoupledStep> steps_;
    std::optional<int> last_whole_;  // LocalHarmonics::n_full where the last search stopped
};

}  // namespace coremodal
