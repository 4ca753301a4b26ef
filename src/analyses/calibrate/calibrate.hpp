// `coremodal calibrate`: the chuck factor k of every point of a
// [calibration] sweep, fitted as a function of dimensionless groups
// (beam/chuck_calibration.hpp), checked on held-out points (docs/how-to/calibration.md).
// Its files: output/calibration_report.hpp and beam/chuck_calibration.hpp (calibration.toml).
#pragma once

#include "analyses/study/study.hpp"
#include "beam/chuck_calibration.hpp"

#include <string>
#include <vector>

namespace coremodal {

// One point of the calibration table.
struct CalibrationRow {
    const StudyPoint* point = nullptr;
    bool used = false;      // has f1 and k (a supported scene with a bending mode)
    bool held_out = false;  // left out of the fit, for the check
    CalibrationGroups groups;
    double k_fe = 0, k_fit = 0;
    double f1_calibrated_hz = 0;  // I-7 with the fitted k
    double error = 0;             // |f1_calibrated - f1_FE| / f1_FE
    std::string note;             // why a point was not used
};

struct CalibrationOutcome {
    Calibration calibration;
    std::vector<CalibrationRow> rows;
};

// Every holdout_every-th usable point (the holdout_every-th, 2 holdout_every-th, ...)
// is held out; the rest are fitted. Throws InputError when too few points
// are usable (fewer than 4 to fit or none to hold out).
CalibrationOutcome calibrate_chuck_factor(const CaseSweep& sweep, const StudyResult& result);

}  // namespace coremodal
