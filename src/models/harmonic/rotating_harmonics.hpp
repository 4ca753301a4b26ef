// The harmonic level of a spinning scene ([rotation], docs/theory/rotation-harmonic.md): per
// wave number n the spinning operator set (spinning_harmonic.hpp) solved by
// the quadratic solver (eigensolve/gyroscopic_solver.hpp: SLEPc PEP, every
// mode verified by its residual, complete by the inertia of the Hermitian
// Q(omega)), the modes of every n merged in frequency order, each labelled
// on the revolved section (its largest real snapshot, with the solid's
// classifier) and marked forward or backward (travelling with the spin or
// against it: whirl for n = 1, the travelling wave for n >= 2).
//
// Which wave numbers and how many modes of each: fixed once, at rest, as the
// harmonic level searches (n = 0, 1, 2, ... until two harmonics in a row
// have no mode among the lowest `window` and their lowest frequency rises),
// so that every speed solves the same problems and modes can be followed by
// MAC from speed to speed within each n.
//
// How each speed is solved (SpinSolver): by default in a basis fixed per n
// (eigensolve/projected_gyroscopic.hpp: the modes at rest of n and the
// static responses to their spin forces), every mode verified by its
// residual on the full problem and the set proven complete by the inertia
// of the full Q(omega) at every speed (or carried from an earlier speed by
// Weyl's bound, ProjectedGyroscopic::count_statistics); where either fails, that n at that
// speed is solved whole (SLEPc PEP, solve_gyroscopic), as `full` does always.
#pragma once

#include "eigensolve/projected_damped.hpp"
#include "eigensolve/projected_gyroscopic.hpp"
#include "geometry/section_mesh.hpp"
#include "models/harmonic/spinning_harmonic.hpp"
#include "modes/classify.hpp"
#include "modes/rotating_mode.hpp"
#include "scene/scene.hpp"

#include <memory>
#include <vector>

namespace coremodal {

enum class SpinSolver { projected, full };
// Labelling a mode (the classifier on the revolved section) costs more than
// solving it in the projected basis; a sweep labels a track once.
enum class Labels { every_mode, none };

class RotatingHarmonics {
public:
    // The section, its materials and the spinning operator sets of the wave
    // numbers the lowest `window` modes at rest (pairs counted twice) need;
    // with the centrifugal term (the prestress solved once) when
    // `centrifugal_stiffening`.
    RotatingHarmonics(const Scene& scene, int window, bool centrifugal_stiffening = false,
                      SpinSolver solver = SpinSolver::projected);
    ~RotatingHarmonics();

    // The lowest `window` modes at spin speed f_rot (Hz), ascending; each
    // RotatingMode's `block` is its wave number n and its shape the values
    // of its problem's DOFs (a, b), so MAC compares modes of one n only.
    // Labels::none leaves every label empty (label_of gives it later).
    // With `only_block` >= 0 only that wave number is solved (all its modes,
    // not cut to the window): a critical speed's refinement follows one track.
    std::vector<RotatingMode> modes_at(double speed_hz, Labels labels = Labels::every_mode, int only_block = -1) const;
    // Tells the projected solver the sweep's top speed (Hz): a wave number
    // without modes below the rigid line at rest is proven to have none up
    // to it (ProjectedGyroscopic::prove_rigid_line_clear), one count per
    // speed fewer.
    void sweep_up_to(double speed_hz);
    // The label modes_at gives a mode of this level.
    ModeLabel label_of(const RotatingMode& mode) const;

    // [damping] (effects on demand: only when the scene names it): per wave
    // number the set with the damping terms (damped_harmonic_terms) and the
    // projected solver's damped branch over it, in a basis of the same size
    // as the undamped one's (eigensolve/projected_damped.hpp).
    void include_damping(const OperatorDamping& damping);
    // A damped mode and its shape on its problem's DOFs, in RotatingMode::shape's order.
    struct DampedShape {
        DampedMode mode;
        Eigen::VectorXcd shape;
    };
    // The damped modes of wave number n at speed f_rot (Hz), ascending damped
    // frequency (include_damping first); each mode's backward_error is its
    // relative residual on the full damped set.
    std::vector<DampedShape> damped_modes_at(double speed_hz, int n) const;

    long n_dofs() const;                      // the largest problem's DOFs
    std::vector<int> wave_numbers() const;    // the n solved at every speed
    double max_relative_residual() const { return max_residual_; }
    // The centrifugal prestress, when the term is included.
    const CentrifugalPrestress* prestress() const { return prestress_.get(); }
    // Problems (one n at one speed) solved whole, and in all.
    long n_full_solves() const { return n_full_solves_; }
    // The projected solver's completeness counts over every wave number
    // (ProjectedGyroscopic::CountStatistics; gamma the largest).
    ProjectedGyroscopic::CountStatistics count_statistics() const;
    long n_solves() const { return n_solves_; }

private:
    struct Harmonic;
    ModeLabel label(const SpinningHarmonic& h, const FamilyValues& re, const FamilyValues& im, double omega) const;
    const Scene& scene_;
    int window_;
    SectionMesh section_;
    RevolvedMesh revolved_;
    std::vector<int> frame_nodes_;
    std::unique_ptr<ModeClassifier> classifier_;
    std::vector<std::unique_ptr<Harmonic>> harmonics_;
    std::unique_ptr<CentrifugalPrestress> prestress_;
    double lambda_scale_ = 1;
    mutable double max_residual_ = 0;
    mutable long n_full_solves_ = 0, n_solves_ = 0;
};

}  // namespace coremodal
