// The forced response of a spinning roll ([damping], [excitation],
// [response]; docs/how-to/response.md) at the beam, harmonic or solid level: the
// amplitude of the orbit at the probes against web speed, the resonance
// peaks with the modes that answer, and the safe web speed read off the
// amplitude limit beside Ilomaki's I-5.
//
// 1. Solve the scene at rest at its level: the first bending frequency f1
//    for I-5, the modes as modes.csv numbers them (for [damping]).
// 2. The lateral problem and its modes at rest: the beam network's two
//    bending planes, every mode (beam_response.cpp, lateral_response.hpp);
//    the harmonic level's wave number n = 1 or the whole solid, the modes
//    up to the cutoff (harmonic_response.cpp, solid_response.cpp,
//    modal_response.hpp); the loads per excitation order on it.
// 3. At every speed and order, x by modal superposition of the modes up to
//    kTruncationFactor times the highest load frequency, with the static part
//    of the others; the probes' orbits.
// 4. Peaks refined between grid speeds (golden section), labelled with the
//    mode that carries most of the probe's motion; the first speed where the
//    amplitude reaches the limit, refined by bisection (response_sweep.hpp).
// 5. Checks at a few speeds and at every peak: the truncated sum against the
//    complete basis (the truncation's effect), and the complete basis
//    against the direct solve of the full system (beam); the truncated sum
//    against the direct solve (harmonic, solid: no complete basis of a mesh).
#pragma once

#include "models/response/response_result.hpp"

namespace coremodal {

// At the scene's level ("auto" resolved as models/choose does): beam,
// harmonic or solid. Throws InputError for a scene the level cannot take;
// SolveError from the solvers.
ResponseResult run_forced_response(const Scene& scene, const ResponseSetup& setup, const BeamModelOptions& options = {},
                                   ResponseChecking checking = ResponseChecking::full,
                                   RestModes rest = RestModes::every_wave_number);

// The forced responses of one scene to setups that differ only in what
// changes neither K nor M (the viscous damping, the excitation; the same
// speeds, probes, highest order and the parts' damping): `coremodal limits`'
// damping and bow samples of its band. The harmonic level assembles, solves
// and labels its n = 1 basis, factors K and runs at rest once for all of
// them (each is then the single run's numbers, the same arithmetic); the
// other levels run each setup.
std::vector<ResponseResult> run_forced_responses(const Scene& scene, const std::vector<ResponseSetup>& setups,
                                                 ResponseChecking checking = ResponseChecking::full,
                                                 RestModes rest = RestModes::every_wave_number);

}  // namespace coremodal
