// What `coremodal converge` writes: converge.csv (one row per model x level x
// tracked mode), converge.json (everything, for the plot), converge.md (the
// report), error_vs_time.png (python: converge-plot), and the summary on the
// console. converge_report.cpp holds the tables and the folder,
// converge_markdown.cpp the report, converge_summary.cpp the console lines.
#pragma once

#include "analyses/converge/converge.hpp"
#include "analyses/converge/converge_study.hpp"

#include <filesystem>
#include <ostream>
#include <string>

namespace coremodal {

std::string converge_csv(const ConvergeStudy& study);
std::string converge_json(const ConvergeStudy& study);
// The report; embeds error_vs_time.png when plot_note is empty, else prints the note.
std::string converge_markdown(const ConvergeStudy& study, const std::string& plot_note);

// The results folder (atomically, ResultsFolder): converge.csv and
// converge.json, then the picture from them, then converge.md. A missing
// picture is a warning on stderr and a note in the report, not an error.
struct ConvergeWriting {
    bool force = false;  // an earlier result is removed, not kept as .previous
    bool quiet = false;  // no "results: ..." line
    bool plots = true;   // draw error_vs_time.png
};
void write_converge_results(const ConvergeStudy& study, const std::filesystem::path& out, const ConvergeWriting& how,
                            std::ostream& progress);

// The console summary: extrapolated frequencies of the role modes, the
// levels reaching each accuracy target, the model errors, the times.
void print_converge_summary(const ConvergeStudy& study, std::ostream& out);

// What `coremodal converge` gives run_converge (ConvergeOptions::claim and
// ::write): claim_output before any work; after it, with write_results,
// write_converge_results, and the console summary unless quiet.
void attach_converge_writers(ConvergeOptions& options);

}  // namespace coremodal
