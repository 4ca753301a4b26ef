// The solid level of a spinning scene ([rotation], docs/rotation.md): the
// solid level's mesh, DOF map and operator set with the cells' gyroscopic
// term (element/element.hpp, element_gyroscopic), assembled once; at each
// speed the quadratic solver (eigensolve/gyroscopic_solver.hpp: SLEPc PEP,
// every mode verified by its residual, complete by the inertia of the
// Hermitian Q(omega)) on the whole solid. Each mode is labelled on the mesh
// (its largest real snapshot, with the solid run's classifier) and marked
// forward or backward by the circularity of its x/y motion at the roll's
// nodes (whirl for n = 1, the travelling wave's direction for n >= 2).
//
// The gyroscopic term is the stationary frame's (the material carried
// through each point at Omega d/dtheta), right for a body of revolution
// only: a scene that is not one (segmented expanding elements, a one-sided
// contact, a user mesh) is refused, since its spinning parts would carry
// their asymmetry round with them (time-periodic coefficients in the
// stationary frame). Every scene the solid level spins, the harmonic level
// spins too: the solid's spinning modes check that level's on the same
// scene and give the 3D shapes.
#pragma once

#include "assembly/dof_map.hpp"
#include "assembly/operator_set.hpp"
#include "beam/rotating_modes.hpp"
#include "mesh/mesh.hpp"
#include "modes/classify.hpp"
#include "modes/mac.hpp"
#include "scene/scene.hpp"

#include <memory>
#include <string>
#include <vector>

namespace coremodal {

// What a spinning solid includes beyond the gyroscopic term.
struct SolidSpinOptions {
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

    long n_dofs() const { return dofs_.n_dofs; }
    double max_relative_residual() const { return max_residual_; }
    // The rigid motions the centrifugal static solve pinned (a free scene), for the run's notes.
    const std::vector<std::string>& pinned_rigid_motions() const { return pinned_; }

private:
    RotatingMode named_mode(Vec real, Vec imag, double omega, double speed_hz) const;

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
    mutable double max_residual_ = 0;
};

// InputError naming the case file when the scene is not a body of
// revolution (models/choose, why_not_axisymmetric): the check above, before any work.
void require_spinnable_by_solid(const Scene& scene);

}  // namespace coremodal
