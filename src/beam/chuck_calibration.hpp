// The chuck factor k of a scene, and its calibration as a function of
// dimensionless groups (docs/how-to/calibration.md).
//
// k = f1 / f_I-7(k = 1): the first bending frequency of the roll in the stand
// over the Euler–Bernoulli clamped–clamped (= free–free) frequency of formula
// I-7 over the free span L = Lc − 2 Li (Ilomäki I-6, I-7: his
// k = f1/f2 with f2 from beam theory).
//
// The fitted law (Dunkerley's summation: flexibilities in series add their
// inverse squared frequencies, so each group enters 1/k^2 linearly):
//
//     1 / k^2 = c0 + c1 g1 + c2 g2 + c3 g3
//     g1 = (EI / (Ec Ic)) (Li / L)   support rotation: the chuck region (length Li,
//                                    scaled by the core's own bending stiffness)
//                                    against the span's bending compliance L / EI
//     g2 = EI / (kappa G A L^2)      shear: Timoshenko's shear flexibility of the span
//     g3 = Ep Ip / EI                the share of the bending stiffness in the rest
//                                    paper, which the chuck holds only through the
//                                    paper's soft transverse shear (a share that is
//                                    not clamped at all bends like a pinned beam,
//                                    k^2 = (pi/4.73)^4 = 0.19)
//
// EI = Ec Ic + Ep Ip, kappa G A as in beam_theory.hpp (Cowper, G_thetaz).
// c0 = 1, c1 = c2 = c3 = 0 is the rigid clamp at Li on a shear-stiff beam.
// docs/how-to/calibration.md compares this law with simpler ones on real runs.
#pragma once

#include "beam/beam_theory.hpp"
#include "scene/scene.hpp"

#include <array>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// Li of a scene: the mean of the clamp zones' centres, each from its own core
// end, or of the chucks' Li (ChuckSpec::li). None for a free scene.
std::optional<double> scene_li(const Scene& scene);

// Ec Ic of the core alone (N m^2).
double core_bending_stiffness(const Scene& scene);

// k against formula I-7 with k = 1 over L = Lc - 2 Li (the calibration
// quantity; the run report's ChuckFactor divides by f2 of the free span instead).
struct ChuckFactorI7 {
    double li_m = 0, span_m = 0;  // Li and L = Lc - 2 Li
    double f_i7_hz = 0;           // I-7 with k = 1 over L
    double k = 0;                 // f1 / f_i7
};
// None for a free scene, or when Li leaves no span.
std::optional<ChuckFactorI7> chuck_factor_of(const Scene& scene, double f1_hz);

constexpr int kCalibrationGroups = 3;

struct CalibrationGroups {
    double g1 = 0, g2 = 0, g3 = 0;
    double operator[](int i) const { return i == 0 ? g1 : i == 1 ? g2 : g3; }
};
CalibrationGroups calibration_groups(const BeamSection& section, double core_EI, double li_m, double span_m);
CalibrationGroups calibration_groups(const Scene& scene, double li_m, double span_m);

struct CalibrationSample {
    CalibrationGroups groups;
    double k = 0;
};

struct ChuckFactorLaw {
    std::array<double, kCalibrationGroups + 1> c{1, 0, 0, 0};  // 1/k^2 = c0 + c1 g1 + c2 g2 + c3 g3
    std::array<bool, kCalibrationGroups> fitted{true, true, true};  // false: constant over the samples
    double k(const CalibrationGroups& g) const;  // throws InputError if 1/k^2 <= 0
};

// Least squares on 1/k^2. A group that is the same at every sample (g3 = 0
// for bare cores) cannot be told from c0 and is left out (fitted = false,
// coefficient 0). Throws InputError for fewer samples than coefficients or
// when the groups that vary do not vary independently.
ChuckFactorLaw fit_chuck_factor(const std::vector<CalibrationSample>& samples);

// Where a calibration was made: the ranges of its points.
struct Range {
    double min = 0, max = 0;
    bool contains(double v, double relative_slack = kRangeSlack) const;
    // A point this close (relative) to the calibrated range is inside it:
    // values round-trip through the file with 17 digits.
    static constexpr double kRangeSlack = 1e-6;
};

// A calibration as kept in calibration.toml.
struct Calibration {
    ChuckFactorLaw law;
    std::string case_name, case_file;
    std::string supports;        // "clamped" or "chucks"
    Range g1, g2, g3, span_m, li_m, diameter_m;
    int n_fit = 0, n_held_out = 0;
    double rms_residual_k = 0, max_residual_k = 0;  // on the fitted points
    double max_error_fit = 0;       // max |f_I-7(k_fit) - f_FE| / f_FE on the fitted points
    double max_error_held_out = 0;  // the same on the held-out points
    double stated_error = 0.03;
    bool passed = false;            // both errors within stated_error
};

inline constexpr int kCalibrationFormatVersion = 1;

void write_calibration(const std::string& path, const Calibration& c);
// Throws InputError naming the file (and line) for a file that is not a
// calibration of this format.
Calibration read_calibration(const std::string& path);

// k for a new section and span from a calibration; notes say when the point
// lies outside the calibrated ranges.
double calibrated_k(const Calibration& c, const CalibrationGroups& g, double span_m, double li_m, double diameter_m,
                    std::vector<std::string>& notes);

}  // namespace coremodal
