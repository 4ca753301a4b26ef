// The solid level of a spinning scene ([rotation], docs/theory/rotation-solid.md): the
// solid level's mesh, DOF map and operator set with the spin terms,
// assembled once; at each speed the quadratic solver
// (eigensolve/gyroscopic_solver.hpp: SLEPc PEP, every mode verified by its
// residual, complete by the inertia of the Hermitian Q(omega)) on the whole
// solid. Each mode is labelled on the mesh (its largest real snapshot, with
// the solid run's classifier) and marked forward or backward (whirl for
// n = 1, the travelling wave's direction for n >= 2).
//
// Two frames (SpinFrame):
// - stationary, for a body of revolution: the material carried through each
//   point at Omega d/dtheta (element_gyroscopic; K_Omega = K_sigma1 - M_L);
//   a forward mode by the circularity of its x/y motion at the roll's nodes.
// - rotating, for a scene that is not one (segmented expanding elements, a
//   user mesh) but whose non-spinning parts look the same from every angle
//   (models/solid/rotating_frame.hpp): the co-rotating equations, constant
//   in time there; each mode's frequency is brought to the stationary frame
//   by its dominant circumferential harmonic on the roll's surface.
// A one-sided contact under gravity, or a bearing stiffer in x than in y,
// is refused with the reason (time-periodic in both frames).
#pragma once

#include "assembly/dof_map.hpp"
#include "assembly/operator_set.hpp"
#include "assembly/chuck_supports.hpp"
#include "eigensolve/gyroscopic_solver.hpp"
#include "eigensolve/zero_frequency_speeds.hpp"
#include "mesh/mesh.hpp"
#include "models/spinning_model.hpp"  // ZeroFrequencyModes
#include "modes/classify.hpp"
#include "modes/mac.hpp"
#include "modes/rotating_mode.hpp"
#include "scene/scene.hpp"

#include <memory>
#include <string>
#include <vector>

namespace coremodal {

enum class SpinFrame { automatic, stationary, rotating };

// What a spinning solid includes beyond the gyroscopic term.
struct SolidSpinOptions {
    // automatic: stationary for a body of revolution, rotating otherwise.
    // A test may ask for the rotating frame on a body of revolution (both
    // must then give the same stationary frequencies).
    SpinFrame frame = SpinFrame::automatic;
    // [rotation] centrifugal_stiffening (the case file's default is true):
    // Term::centrifugal, K_Omega = K_sigma1 - M_L (effects/rotation.hpp),
    // from a static solve under the centrifugal load (models/solid/centrifugal_prestress).
    bool centrifugal_stiffening = false;
};

class RotatingSolid {
public:
    // Meshes and assembles the scene with its gyroscopic term (and the
    // centrifugal term when asked); the lowest `window` modes are solved at
    // every speed. InputError for a scene that is not a body of revolution (above).
    RotatingSolid(const Scene& scene, int window, SolidSpinOptions options = {});

    // The lowest `window` modes at spin speed f_rot (Hz), ascending; each
    // RotatingMode's shape is the complex signature of its displacement on
    // the core's outer surface (modes/mac.hpp: the MAC of two signatures is
    // that of the two fields there), so that a sweep keeps a few thousand
    // numbers per mode and speed, not the whole mesh's.
    std::vector<RotatingMode> modes_at(double speed_hz) const;

    // Rotating frame: every speed below max_speed_hz where a mode's
    // rotating-frame frequency is zero, exact (the pencil (K, M_P -
    // K_sigma1)) and proven complete by the inertia of K(Omega_max).
    ZeroFrequencyModes zero_frequency_modes(double max_speed_hz) const;
    // The same for a rotating-frame frequency of r f_rot, r = ratio >= 0
    // (the pencil (K, B_r); r = 0 is zero_frequency_modes): each mode with
    // its signed harmonic, its crossing's order and whirl.
    ZeroFrequencyModes frequency_ratio_modes(double max_speed_hz, int ratio) const;

    const OperatorSet& operators() const { return operators_; }
    long n_dofs() const { return dofs_.n_dofs; }
    double max_relative_residual() const { return max_residual_; }
    // The rigid motions the centrifugal static solve pinned (a free scene), for the run's notes.
    const std::vector<std::string>& pinned_rigid_motions() const { return pinned_; }
    bool rotating_frame() const { return frame_ == SpinFrame::rotating; }
    // Rotating frame: the smallest share of its dominant harmonic of any
    // mode returned so far (1 in the stationary frame).
    double min_harmonic_share() const { return min_share_; }

private:
    RotatingMode named_mode(const std::vector<double>& re, const std::vector<double>& im, double omega,
                            double speed_hz) const;
    void assemble(const Scene& scene, const ChuckSupports& chucks, bool centrifugal_stiffening);
    std::vector<RotatingMode> stationary_frame_modes(const GyroscopicModes& solved, double speed_hz) const;
    std::vector<RotatingMode> rotating_frame_modes(const GyroscopicModes& solved, double speed_hz) const;
    ZeroFrequencyMode pencil_mode(const ZeroFrequencySpeed& z, int ratio) const;

    const Scene& scene_;
    int window_;
    Mesh mesh_;
    DofMap dofs_;
    OperatorSet operators_;
    std::vector<int> roll_nodes_;
    std::unique_ptr<ModeClassifier> classifier_;
    std::unique_ptr<ModeSignatureSampler> signature_;
    double lambda_scale_ = 1;
    std::vector<std::string> pinned_;
    SpinFrame frame_ = SpinFrame::stationary;
    std::vector<int> surface_nodes_;  // rotating frame: where the harmonics are read
    int max_wave_number_ = 0;
    mutable double min_share_ = 1;
    mutable double max_residual_ = 0;
};

// InputError naming the case file when the scene cannot spin at the solid
// level in either frame (a one-sided contact under gravity): before any work.
void require_spinnable_by_solid(const Scene& scene);

}  // namespace coremodal
