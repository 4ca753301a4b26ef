// `coremodal fit`: case-file parameters fitted to measured frequencies
// (docs/how-to/calibration.md, "Fitting the model to measured frequencies").
//
// Unknowns x = ln p (a modulus and a stiffness are positive and known to a
// factor, not to a number of pascals), within bounds. Residuals
// r_i = (f_i(p) − f_i,measured) / u_i with u_i the measurement's standard
// uncertainty; Jacobian J_ij = f_i · (d ln f_i / d ln p_j) / u_i, exact from
// the eigenvalue derivative (analyses/sensitivity). Levenberg–Marquardt
// (damping μ·diag(JᵀJ), steps clipped to the bounds). The covariance of x is
// (JᵀJ)⁻¹ from the singular values of J: a parameter's standard uncertainty
// is p·sqrt(C_jj) (from the measurement uncertainties alone, not rescaled by
// the residuals). A direction of x the data do not see (a singular value below
// kUnidentifiable of the largest) or a correlation above kHighCorrelation
// is reported as parameters the data cannot separate.
#pragma once

#include "analyses/fit/measurements.hpp"
#include "scene/case_parameters.hpp"
#include "scene/model_choice.hpp"

#include <Eigen/Dense>

#include <functional>
#include <string>
#include <vector>

namespace coremodal {

// Singular value of J (relative to the largest) below which a direction of
// ln p is not determined by the data: a change of 1 in ln p along it moves
// the residuals by less than 1e-4 of what the best-determined direction does,
// i.e. an uncertainty 1e4 times larger.
inline constexpr double kUnidentifiable = 1e-4;
// |correlation| above which two parameters are reported as hard to separate.
inline constexpr double kHighCorrelation = 0.98;

struct FitParameter {
    std::string key;
    Dimension dimension = Dimension::dimensionless;
    double start = 0, min = 0, max = 0;  // SI
    double value = 0;                    // fitted, SI
    std::optional<double> uncertainty;   // standard uncertainty (SI); none: not identifiable
    bool at_bound = false;
};

struct FittedMeasurement {
    Measurement measurement;
    double model_hz = 0;             // at the fitted values
    double start_hz = 0;             // at the start values
    std::vector<double> dlnf_dlnp;   // per fit parameter (0 where it does not enter the case)
    ModelChoice level = ModelChoice::beam;  // model level the case was solved at
};

struct FittedCase {
    std::string case_file, model;
    std::string calibrated_text;  // the case file with the fitted values
};

struct FitOutcome {
    std::vector<FitParameter> parameters;
    std::vector<FittedMeasurement> measurements;
    std::vector<FittedCase> cases;
    Eigen::MatrixXd correlation;           // of ln p
    std::vector<std::string> warnings;     // unidentifiable or correlated pairs, bounds, start values
    int iterations = 0;
    bool converged = false;
    double chi2 = 0, chi2_start = 0;       // sum of squared normalised residuals
};

using FitProgress = std::function<void(const std::string&)>;

// Throws InputError for a key no case has, a mode no case shows, a bad bound.
FitOutcome run_fit(const FitInput& input, const FitProgress& progress = {});

}  // namespace coremodal
