// Eigenvalue sensitivities d ln f / d ln p of a scene's modes to case-file
// keys (docs/how-to/calibration.md, "Sensitivities"). For an M-normalised mode φ,
//
//     dλ/dp = φᵀ (∂K/∂p − λ ∂M/∂p) φ,      d ln f / d ln p = p dλ/dp / (2λ),
//
// with ∂K/∂p and ∂M/∂p the central difference of the ASSEMBLED operators at
// p(1 ± h): the scenes at p(1 ± h) are the case file with the key set (as a
// study point), assembled on the same DOFs. Exact for a parameter the operators
// are linear in (a density, a spring stiffness) and O(h²) otherwise (a modulus
// through the inverted compliance). One solve, at p; no re-solves. When a key
// changes the DOFs themselves (an element count that follows a length), the
// frequencies are re-solved at p(1 ± h) and differenced (`method` says which).
//
// Levels: beam (the Timoshenko network) and harmonic (one operator pair per
// wave number n). The chuck factor's sensitivity is d ln k = d ln f1 − d ln f2,
// f2 the free–free roll over the free span at the same level.
#pragma once

#include "modes/label_tracking.hpp"
#include "scene/case_parameters.hpp"
#include "scene/model_choice.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

struct SensitivityOptions {
    // Relative step of the operators' central difference. 1e-3: the O(h²)
    // error of a modulus (1e-6 relative) is far below what a sensitivity is
    // used for, and the difference φᵀ(K₊ − K₋)φ keeps ~12 digits.
    double step = 1e-3;
    bool chuck_factor = true;  // also f2 and k, for scenes on chucks
};

struct ModeSensitivity {
    ModeKey key;              // "bending n=1 m=0"
    double frequency_hz = 0;
    std::vector<double> dlnf_dlnp;  // per parameter
};

struct SensitivityResult {
    ModelChoice level = ModelChoice::beam;  // beam or harmonic
    std::vector<CaseParameter> parameters;
    std::vector<double> values;        // the parameters' values differentiated at (SI)
    std::vector<std::string> methods;  // per parameter: "operators" or "re-solved"
    std::vector<ModeSensitivity> modes;  // the scene's distinct elastic modes, ascending
    // Scenes on chucks: f2 (free–free over the free span) and k = f1 / f2.
    std::optional<ModeSensitivity> f2;
    std::optional<double> k;
    std::vector<double> dlnk_dlnp;
    // The mode of the scene with this key, if any.
    const ModeSensitivity* find(const ModeKey& key) const;
};

// Sensitivities of the scene at `values` (SI, key order of `c`). Levels other
// than beam and harmonic ("solid"; "auto" resolves as `run` does) are refused
// with an InputError. Collective over PETSC_COMM_WORLD at the harmonic level.
SensitivityResult eigen_sensitivities(const CaseParameters& c, const std::vector<double>& values,
                                      const SensitivityOptions& options = {});

// Every material and contact constant of a scene, as case-file keys: the
// core's and the rest paper's material constants (orthotropic: E_r ... density;
// isotropic: E, nu, density), and on chucks with a spring interface the
// contact's normal and tangential stiffness and the chuck's E and density
// (supports.left: the right chuck mirrors it unless the case gives it).
std::vector<std::string> material_and_contact_keys(const Scene& scene);

// The level a scene is differentiated at: the level a run would use
// (models/choose.hpp). InputError for a level without sensitivities (the
// solid, the coupled harmonics).
ModelChoice sensitivity_level(const Scene& scene);

}  // namespace coremodal
