// Running a sweep ([study] or [calibration]): every point through run_scene,
// in this process or in child processes (study_workers.hpp), modes tracked
// from point to point by MAC (docs/how-to/studies.md). The study's files are
// output/study_report.hpp.
//
// A point is "the case's document with some keys changed -> Scene ->
// run_scene -> RunReport": whatever model level or support the scene asks for
// (rigid clamps, elastic chucks, a beam model) is what the point runs.
#pragma once

#include "analyses/response/response.hpp"
#include "beam/chuck_calibration.hpp"
#include "modes/tracking.hpp"
#include "scene/case_sweep.hpp"

#include <filesystem>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// A point of a study over a case with [response] (docs/how-to/studies.md,
// docs/how-to/response.md): what its forced response says about the safe speed,
// beside I-5 and König from the same f1 at rest.
struct StudyResponse {
    double limit_m = 0;             // the amplitude limit at the first probe
    double max_web_speed_m_s = 0;   // the response's last speed: "not reached up to"
    bool limit_reached = false;     // within the response's speeds
    bool below_range = false;       // already at the first speed
    std::optional<double> v_limit_m_s;     // web speed where the amplitude first reaches the limit
    std::optional<double> implied_factor;  // f_rot / f1 there
    double max_amplitude_m = 0, max_amplitude_web_speed_m_s = 0;
    std::optional<double> v_i5_07_m_s, v_i5_08_m_s;  // I-5 at kSafeFactors 0.7 and 0.8
    std::optional<double> v_koenig_m_s;              // König's v_krit (K-1/K-2, experience factor 0.66)
};

struct StudyPoint {
    int index = 0;  // 0-based; printed 1-based
    std::vector<int> value_index;  // per parameter
    std::string description;       // "core.length = 3 m, ..."
    bool ok = false;
    std::string error;             // why the point failed (refused input or solve)
    double time_s = 0;
    std::string model_level;       // RunReport model.level
    std::string supports;          // "free", "clamped" or "chucks"
    long n_dofs = 0;

    std::vector<ModeSummary> modes;  // the run's modes without their shapes
    std::optional<double> f1_hz;     // first bending mode
    std::optional<double> li_m, span_m, f_i7_hz, k;  // chuck factor (beam/chuck_calibration.hpp)
    double diameter_m = 0;           // rest roll outer diameter (the core's without rest paper)
    std::optional<double> v_safe_m_s;  // safe_factor * pi * D * f1 (supported scenes)
    std::optional<CalibrationGroups> chuck_groups;  // g1, g2, g3 of the calibration law (supported scenes)
    std::optional<StudyResponse> response;          // a case with [response] (analyses/response)

    // Tracking: the groups of `modes` and their tracks.
    std::optional<int> predecessor;  // the point tracked from (nearest earlier successful one)
    std::vector<ModeGroup> groups;
    std::vector<TrackStep> tracks;
};

struct StudyResult {
    std::vector<StudyPoint> points;
    double time_s = 0;
    int n_failed() const;
};

struct StudyRunOptions {
    bool quiet = false;  // no progress lines
    // Points run at the same time, each in a child process of this program
    // (`coremodal study --worker-point`, analyses/study/study_workers.hpp): one point's
    // factor-and-solve keeps about one core busy, so two at a time use a
    // 2-core machine. 1 = one after the other in this process (always so
    // under MPI, and for a sweep read from text rather than a file).
    unsigned jobs = 1;
    std::string program = "/proc/self/exe";  // the coremodal executable for the children
};

// One point in this process: run_scene on its scene, and the run's part of
// `p` filled (ok or error, modes, f1, model level, DOFs, time); with a
// response setup, the forced response too (p.response; its failure fails
// the point). This is what a worker child does.
void run_point(Scene scene, StudyPoint& p, const std::optional<ResponseSetup>& response = std::nullopt);

// The response a point of a sweep in `table` runs: a [study] point runs its
// case's forced response; a [calibration] point only fits k, so none.
std::optional<ResponseSetup> response_of_point(const std::string& table, std::optional<ResponseSetup> response);

// The study's summary of a forced response.
StudyResponse study_response(const ResponseResult& r);

// The values a point's scene gives with its f1: D, v_safe, Li, L, k and the
// calibration groups (beam/chuck_calibration.hpp).
void derive_point_values(StudyPoint& p, const Scene& scene, const SweepOptions& options);

// The jobs a sweep runs with: `requested` (0: the number of cores), at most
// the number of points, and 1 under MPI.
unsigned jobs_for(unsigned requested, const CaseSweep& sweep);

// Runs every point (collective over PETSC_COMM_WORLD), printing one progress
// line per point on rank 0, in the order the points finish. A point whose input is refused or whose solve
// fails is recorded and the study goes on. Throws InputError only when no
// point can be read at all.
StudyResult run_sweep(const CaseSweep& sweep, const StudyRunOptions& options, std::ostream& progress);

// Assigns track ids along the sweep's predecessor tree (modes/tracking.hpp).
void track_modes(const CaseSweep& sweep, StudyResult& result);

// What `study` and `calibrate` share: the plan printed on rank 0 ("study: 40
// points of ... results in DIR") unless quiet, every point run, and on rank 0
// the modes tracked (labels and signatures live there).
StudyResult run_and_track(const CaseSweep& sweep, const std::string& command, const std::filesystem::path& out_dir,
                          bool quiet, unsigned jobs);

// Where a safe-speed curve crosses the web speed: the rest roll diameter
// below which the roll must be changed (docs/how-to/studies.md, König's chart).
struct SpeedCrossing {
    std::string curve;           // "core.length = 3 m" ("" for a single curve)
    std::vector<double> change_diameters_m;  // v_safe = web speed, v_safe falling as D falls
    double d_min_m = 0, d_max_m = 0;
    double v_min_m_s = 0, v_max_m_s = 0;
};
std::vector<SpeedCrossing> safe_speed_crossings(const CaseSweep& sweep, const StudyResult& result, double web_speed_m_s);

// Indices of the parameters that change the rest roll diameter (found from the results).
std::vector<int> diameter_parameters(const CaseSweep& sweep, const StudyResult& result);

}  // namespace coremodal
