// From a core's durability fit to the roll weight it allows at a failure
// probability: the population mean at confidence C ({22}, {23}), the upper
// standard deviation at C ({25}, {26}), λ from the failure probability P
// ({27}) and the reduced curve ({28}, {32}) with its safety factor ({29},
// {30}). M. Ilomäki, "On the durability of cores and rest roll dynamics".
//
// All in log10 y, with the regression's n - 2 degrees of freedom; how this
// reads the paper's {22} and {25} (written for one sample with n - 1) is in
// docs/how-to/durability.md, "Confidence with two fitted parameters".
#pragma once

#include "durability/power_law_fit.hpp"

namespace coremodal {

// The confidence level of the paper's examples ({23}, {26}: "for example 99 %").
inline constexpr double kDefaultConfidence = 0.99;

// Table 3's relative standard deviations and failure probabilities.
inline constexpr double kTable3RelativeDeviations[] = {0.05, 0.10, 0.15};
inline constexpr double kTable3Probabilities[] = {0.5, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6};

// λ of {27}: how many standard deviations (negative) reach failure probability
// p; requires 0 < p <= 0.5 (λ = 0 at 0.5: the mean itself).
double reduction_factor(double p);

// {30}: the safety factor 1 / (1 + λ S_Crelative) of a normal distribution in
// y with relative deviation s_relative ({29}); Table 3. Requires
// 1 + λ s_relative > 0 (else the reduced mean is not a positive weight).
double safety_factor(double lambda, double s_relative);

// The standard error of the fitted mean log10 y at x: S_log sqrt(1/n +
// (log10 x - centroid)^2 / Sxx). At the centroid it is S_log/sqrt(n), the
// S/sqrt(n - 1) of {22} (whose S divides by n).
double mean_standard_error(const PowerLawFit& fit, double x);

// {22}, {23}: the mean log10 y at x lowered to confidence C,
// log10 y(x) - t2 · standard error, t2 with n - 2 degrees of freedom.
double confident_mean_log_weight(const PowerLawFit& fit, double x, double confidence);

// {25}, {26}: the upper limit at confidence C of the standard deviation of
// log10 y, sqrt((n - 2)/h1) · S_log (the paper's sqrt(n/h1) · S with S
// dividing by n, at n - 2 degrees of freedom).
double upper_standard_deviation(const PowerLawFit& fit, double confidence);

// {28} in log10 y: the reduced curve at x for failure probability p,
// confident mean + λ · S_C; the same line {32} draws with S_C for S_log
// ({31} draws it once more, shifted in x instead: docs/how-to/durability.md).
double reduced_log_weight(const PowerLawFit& fit, double x, double confidence, double p);

// The safety factor of the reduced curve over the confident mean, 10^(-λ S_C)
// (constant in x), and {30}'s value for the same spread, S_Crelative =
// ln(10) S_C (the relative standard deviation of y to first order).
struct SafetyFactors {
    double lambda = 0;
    double upper_sd_log = 0;          // S_C
    double log_space = 1;             // what the reduced curve applies
    double relative_deviation = 0;    // ln(10) S_C
    double paper_eq30 = 1;            // 1/(1 + λ S_Crelative); 0 when that is not positive
};
SafetyFactors safety_factors(const PowerLawFit& fit, double confidence, double p);

// The two-sided confidence and prediction limits of log10 y at x for level
// C (the bands of Fig. 17): t with n - 2 degrees of freedom at (1 + C)/2.
struct Band {
    double lower = 0, upper = 0;
};
Band confidence_band(const PowerLawFit& fit, double x, double confidence);
Band prediction_band(const PowerLawFit& fit, double x, double confidence);

// The two-sided confidence intervals at level C of the fitted parameters:
// b1 and log10 b0 (Student's t, n - 2) and S_log (χ², n - 2). These are what a
// repeated experiment recovers the true values within, C of the time.
struct ParameterIntervals {
    Band b1, log_b0, s_log;
};
ParameterIntervals parameter_intervals(const PowerLawFit& fit, double confidence);

}  // namespace coremodal
