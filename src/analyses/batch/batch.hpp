// `coremodal batch`: many case files, each run as a child process of the same
// coremodal executable (`coremodal run CASE --output OUT/<stem> --quiet`), so
// that a crash or an error in one case cannot take down the others. The
// result table is written by output/batch_report.hpp.
#pragma once

#include "beam/speeds.hpp"

#include <optional>
#include <ostream>
#include <string>
#include <vector>

namespace coremodal {

// The safe web speed the batch table shows (Ilomäki I-5, v_safe = safe · π
// · Dp · f1, from summary.json's speeds): the conservative factor, no safety cage.
inline constexpr double kBatchSafeFactor = kSafeFactors[0];
static_assert(kBatchSafeFactor == 0.7);

struct BatchOptions {
    std::vector<std::string> inputs;             // case files and folders (every *.toml in them)
    std::string output_dir = "results/batch";    // written in place (start_folder_in_place)
    bool force = false;                          // an earlier batch there is removed, not kept as .previous
    unsigned jobs = 0;                           // 0: number of cores; never more than the cases
    std::optional<std::string> mesh_level;       // passed on as `run --mesh LEVEL`, except to
                                                 // cases with their own [mesh] file
    bool plots = true;                           // false: `--no-plots` passed on to every case
    std::string program = "/proc/self/exe";      // the coremodal executable to run the cases with
};

struct BatchCase {
    std::string file;        // case file as given or found
    std::string name;        // file stem (made unique): results in OUT/<name>, log OUT/<name>.log
    std::string result_dir;
    std::string log_file;
    bool ok = false;
    std::string error;       // first error line of a failed case
    std::string note;        // e.g. why --mesh was not passed on
    double time_s = 0;       // wall time of the child process
    // From OUT/<name>/summary.json, when the case succeeded:
    std::optional<double> f1_hz;               // beam.fe_first_bending_hz (first bending mode)
    std::optional<double> fe_over_timoshenko;  // beam.fe_over_timoshenko
    std::optional<double> chuck_factor;        // chuck.chuck_factor k = f1/f2 (scenes on elastic chucks)
    std::optional<double> diameter_m;          // speeds.dp_m: rest paper outer diameter, else the core's
    std::optional<double> v_safe_m_s;          // speeds: kBatchSafeFactor * pi * D * f1 (none for free-free)
};

// Case files named by the inputs: a folder stands for every *.toml in it
// (sorted by name), a file for itself. Throws InputError for a missing path or
// when no case file is found.
std::vector<std::string> batch_case_files(const std::vector<std::string>& inputs);

// Whether a case file names its own mesh ([mesh] file = ...); false when
// the file cannot be read or parsed (the child run will report that).
bool case_has_mesh_file(const std::string& case_file);
// Whether a case file describes a two-drum winder ([winder], docs/how-to/winder.md):
// batch runs it with `coremodal winder` rather than `coremodal run`.
bool is_winder_file(const std::string& case_file);
// Whether a file is a core-selection file ([selection], docs/how-to/durability.md):
// batch runs it with `coremodal select`.
bool is_selection_file(const std::string& case_file);
// Whether the file is for `coremodal traction` alone: [traction] and no roll
// ([core]) (docs/how-to/traction.md); batch runs it with that command.
bool is_traction_file(const std::string& case_file);
// Whether the file is a fit's measurements file ([[measurement]] or
// parameters, and no roll; docs/how-to/calibration.md): batch runs it with `coremodal fit`.
bool is_fit_file(const std::string& case_file);

// The batch's cases: one per case file (batch_case_files), named by its file
// stem (a stem seen before, the same name in two folders, gets -2, -3, ...),
// its results in OUT/<name> and its log in OUT/<name>.log.
std::vector<BatchCase> batch_cases(const BatchOptions& options);

// What the batch writes into OUT, for the marker of the folder the caller
// starts in place (output/results_folder.hpp: start_folder_in_place) before
// run_batch, so that finished cases can be read while the others run: the
// cases' folders with all in them, their logs, the tables. Anything else
// found there later is the user's, and keeps the folder from being replaced.
std::vector<std::string> batch_folder_contents(const std::vector<BatchCase>& cases);

// Runs every case, at most `jobs` at a time, printing one progress line per
// finished case to `progress`. Never throws for a failing case.
void run_batch(std::vector<BatchCase>& cases, const BatchOptions& options, std::ostream& progress);

// Fills the summary fields of `c` from the text of its summary.json (read
// with nlohmann-json). Throws std::runtime_error when the text is not JSON
// or lacks the beam keys.
void read_batch_summary(BatchCase& c, const std::string& summary_json);

}  // namespace coremodal
