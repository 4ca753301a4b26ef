// A level's modes of a scene at parameter values p, and how their
// eigenvalues move when the scene's operators change (`coremodal
// sensitivity`, analyses/sensitivity; docs/how-to/calibration.md,
// "Sensitivities"). For an M-normalised mode φ of eigenvalue λ,
//
//     dλ = φᵀ (K₊ − K₋) φ − λ φᵀ (M₊ − M₋) φ
//
// over the operators assembled for the scenes at p(1 ± h) on the DOFs of
// the scene at p. The level holds its eigenvectors and its assembly; the
// analysis differences parameters and never names a level.
#pragma once

#include "modes/label_tracking.hpp"
#include "scene/scene.hpp"

#include <functional>
#include <optional>
#include <vector>

namespace coremodal {

// Per distinct mode: dλ between the scenes `plus` and `minus`, or nothing
// when their operators do not live on the DOFs of the scene at p (a key that
// changes an element count): the analysis then re-solves and differences
// the frequencies.
using EigenvalueChange = std::function<std::optional<std::vector<double>>(const Scene& plus, const Scene& minus)>;

struct Linearised {
    std::vector<DistinctMode> modes;  // of the scene at p
    std::vector<double> eigenvalues;  // per distinct mode
    EigenvalueChange delta_lambda;
};

// The eigenvalue of each distinct mode, from the level's full mode list.
std::vector<double> eigenvalues_of(const std::vector<DistinctMode>& modes, const std::vector<Mode>& all);

}  // namespace coremodal
