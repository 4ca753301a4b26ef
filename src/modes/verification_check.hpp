// Whether a mode set is verified, said as the reasons it is not: a residual
// that is not finite or above its limit, an inertia count that does not
// match the modes found, a frequency that is not a finite number, a model
// whose mass does not match its dimensions. A run whose verification fails
// ends with these reasons and a non-zero exit, unless the user asked to keep
// going (`--keep-going`): then they are its warnings (issue 33, item 7).
#pragma once

#include "modes/mode_set.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The largest relative residual ||K x - lambda M x|| / (||K|| ||x||) a
// verified mode may have, unless the case's [analysis] tolerance is looser.
// A backward-stable solve of a well-posed problem gives 1e-12 and less
// (measured on the shipped cases: docs/validation/models.md); 1e-6 is the quadratic solver's bound
// (eigensolve/gyroscopic_solver.cpp), a residual above it a solve that did
// not converge or a problem round-off has swamped.
constexpr double kMaxVerifiedResidual = 1e-6;

// The mass a generated model may differ from the scene's dimensions by: the
// quadratic cells' curved edges give the circle's area to ~1e-5 on the
// coarsest mesh (around = 8); a missing or doubled part differs by percents.
constexpr double kMassTolerance = 1e-2;

// The reasons `modes` are not verified; empty when they are. `tolerance` is
// the case's [analysis] tolerance.
std::vector<std::string> verification_failures(const std::vector<Mode>& modes, const Verification& v,
                                               double tolerance);

// "mass of the model X kg does not match Y kg from the dimensions" when they
// differ by more than kMassTolerance; nothing when they agree or the
// expected mass is unknown (0: a user's mesh).
std::optional<std::string> mass_mismatch(double model_kg, double expected_kg);

// For a command that verified modes: throws SolveError naming `what` and
// every failure, with what to do, unless `keep_going`; then returns the
// warnings to report ("verification failed: ...; the results are kept
// because of --keep-going"). Returns nothing when `failures` is empty.
std::vector<std::string> require_verified(const std::string& what, const std::vector<std::string>& failures,
                                          bool keep_going);

}  // namespace coremodal
