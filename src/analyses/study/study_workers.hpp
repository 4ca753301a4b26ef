// Study points in child processes, several at a time (as `coremodal batch`
// runs cases): each child is this program run as
//   coremodal study CASE --worker-table T --worker-point I --worker-output FILE [--mesh L] -q
// which reads the same sweep, runs point I in its own process (run_point) and
// writes the run's part of the point to FILE (point_record). A crash or an
// out-of-memory in one point cannot take down the study.
#pragma once

#include "analyses/study/study.hpp"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The run's part of a point as JSON (nlohmann-json): ok, error, time, model
// level, DOFs, f1, every mode with its label and signature (each double
// written so that it reads back bit for bit).
std::string point_record(const StudyPoint& p);
// Reads it back into `p`. Throws std::runtime_error for text that is not a
// record ("not a study point record ...") or lacks one of its fields
// ("study point record: ...").
void read_point_record(const std::string& text, StudyPoint& p);

// Runs the points `todo` of the sweep, at most `jobs` at a time, each in a
// child process of `program`; calls `finished(i)` (one at a time) as each
// ends. A child that fails to start, crashes or writes no record leaves its
// point failed with the reason (the first error line of its output).
void run_points_in_children(const CaseSweep& sweep, const std::vector<int>& todo, unsigned jobs,
                            const std::string& program, std::vector<StudyPoint>& points,
                            const std::function<void(int)>& finished);

// What a worker child is asked to do: point `point` of the sweep in `table`
// of `case_file` (its record goes to --worker-output: app/study_command).
struct WorkerPoint {
    std::string case_file;
    std::string table = "study";
    std::optional<std::string> mesh_level;
    std::string model;  // --model of the parent; "" = the case's
    int point = -1;
};

// The worker child's whole work but the writing: reads the sweep, runs the
// point in this process (run_point) and returns it, also when the point
// fails (with its error), for the caller to write its point_record on rank
// 0. Throws InputError for a point that is not in the sweep.
StudyPoint run_worker_point(const WorkerPoint& worker);

}  // namespace coremodal
