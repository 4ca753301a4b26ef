#include "modes/verification_check.hpp"

#include "common/error.hpp"
#include "common/join.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace coremodal {
namespace {

std::string sci(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

}  // namespace

std::vector<std::string> verification_failures(const std::vector<Mode>& modes, const Verification& v,
                                               double tolerance) {
    std::vector<std::string> out;
    const double limit = std::max(kMaxVerifiedResidual, tolerance);
    if (!std::isfinite(v.max_relative_residual))
        out.push_back("the largest relative residual is " + sci(v.max_relative_residual) + ", not a finite number");
    else if (v.max_relative_residual > limit)
        out.push_back("the largest relative residual " + sci(v.max_relative_residual) + " is above " + sci(limit));
    if (!(v.max_orthonormality_error <= limit))
        out.push_back("the modes are not M-orthonormal: max |X'MX - I| = " + sci(v.max_orthonormality_error) +
                      " (above " + sci(limit) + ")");
    if (!v.complete)
        out.push_back("INCOMPLETE: the inertia count gives " + std::to_string(v.negative_pivots_at_shift) +
                      " eigenvalues below the check's shift, " + std::to_string(v.modes_below_shift) +
                      " modes were accounted for");
    const auto bad = std::find_if(modes.begin(), modes.end(),
                                  [](const Mode& m) { return !std::isfinite(m.frequency_hz) || m.frequency_hz < 0; });
    if (bad != modes.end())
        out.push_back("mode " + std::to_string(bad->index) + " has the frequency " + sci(bad->frequency_hz) + " Hz");
    return out;
}

std::optional<std::string> mass_mismatch(double model_kg, double expected_kg) {
    if (!(expected_kg > 0)) return std::nullopt;
    if (std::abs(model_kg - expected_kg) <= kMassTolerance * expected_kg) return std::nullopt;
    return "the model's mass " + sci(model_kg) + " kg does not match " + sci(expected_kg) +
           " kg from the dimensions (more than " + sci(100 * kMassTolerance) + " % apart)";
}

std::vector<std::string> require_verified(const std::string& what, const std::vector<std::string>& failures,
                                          bool keep_going) {
    if (failures.empty()) return {};
    const std::string reasons = join(failures, "; ");
    if (!keep_going)
        throw SolveError(what + ": verification failed: " + reasons +
                         ". Nothing was written. Check the case's stiffnesses and lengths for values that make a "
                         "part rigid or loose beyond what double precision resolves (coremodal check lists them); "
                         "--keep-going writes the results anyway, marked as not verified");
    return {"verification failed: " + reasons + "; the results are kept because of --keep-going and are NOT verified"};
}

}  // namespace coremodal
