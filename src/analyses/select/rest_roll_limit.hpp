// The width half of the core-selection chart: the widest reel whose rest
// roll still meets a stand's speed and amplitude limits, by the verdict of
// `coremodal limits` (analyses/limits) at the beam level, calibrated to the
// stand's chuck factor k (docs/how-to/durability.md, "The width the rest roll
// allows").
//
// A candidate (core grade, stand, reel width) becomes a Scene: the core with
// its rest roll at the stand's rest_roll_diameter, held rigidly over the
// chucks' supporting length at both ends, at the beam level. A rigid clamp
// is stiffer than a chuck; the stand's k (I-6, Ilomäki: k = f1/f2) says by
// how much. The calibration scales the axial moduli E_z of core and rest
// paper by one factor so that the beam's first bending frequency at rest is
// I-7's with that k over the free span width - 2 li: the limits machinery
// then sees the roll's f1 the stand gives it, with its mass, gravity sag,
// bow and gyroscopic terms, and computes every criterion it has (I-5,
// König, the order-1 and order-2 critical speeds, the ±5 mm amplitude).
// König's formula alone is taken on the section as given: his experience
// factor already stands for the chucks.
#pragma once

#include "scene/scene.hpp"
#include "selection/selection_scene.hpp"

#include <string>
#include <vector>

namespace coremodal {

// The verdict's width is bracketed to this (m).
inline constexpr double kWidthTolerance = 1e-4;
// Wider than any paper machine: a rest roll that passes here has no width
// limit.
inline constexpr double kMaxSelectionWidth = 20.0;  // m
// The beam's f1 meets I-7's to this relative tolerance after calibration: far
// below the width's, so the verdict does not jitter between neighbouring widths.
inline constexpr double kCalibrationTolerance = 1e-7;

// A candidate's scene, calibrated: `stiffness_factor` is what E_z was scaled
// by.
struct CandidateScene {
    Scene scene;
    Scene as_given;  // before the calibration: König's formula reads its section
    double stiffness_factor = 1;
    double target_f1_hz = 0;  // I-7 with the stand's k
};
CandidateScene candidate_scene(const CoreGrade& core, const Stand& stand, const SelectionScene& selection,
                               double width);

// The rest roll's verdict at one reel width and web speed.
struct RestRollVerdict {
    double f1_hz = 0;           // the calibrated beam's first bending frequency at rest
    double safe_speed_m_s = 0;  // the lowest limiting criterion's web speed
    std::string governing;      // its name ("I-5 x0.7", "Koenig K-1/K-2", "amplitude limit", ...)
    std::string next;           // the next lowest limiting criterion, and its speed
    double next_speed_m_s = 0;
    double stiffness_factor = 1;  // the calibration's E_z factor
    bool passes = false;
};
RestRollVerdict rest_roll_verdict(const CoreGrade& core, const Stand& stand, const SelectionScene& selection,
                                  double width, double web_speed);

// I-5 with I-7 and the stand's k solved for the width in closed form: the
// quick estimate (and the starting point of the search below).
double i7_max_width(const CoreGrade& core, const Stand& stand, const SelectionScene& selection, double web_speed);

// The largest reel width at which rest_roll_verdict passes, bracketed to
// kWidthTolerance (a passing width and a failing one kWidthTolerance apart);
// kMaxSelectionWidth when it passes even there, 0 when it fails at the
// narrowest roll the stand holds. `at_limit`: the verdict at the width
// returned.
double max_width_for_speed(const CoreGrade& core, const Stand& stand, const SelectionScene& selection, double web_speed,
                           RestRollVerdict* at_limit = nullptr);

// What the width verdict assumes, for the console and report.md.
std::vector<std::string> rest_roll_assumptions();

}  // namespace coremodal
