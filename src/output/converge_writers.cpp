#include "output/converge_report.hpp"

#include "output/results_folder.hpp"

namespace coremodal {
namespace {

void claim_converge_output(const std::filesystem::path& out, const ConvergeOptions& o) { claim_output(out, o.force); }

void write_converge(const ConvergeStudy& study, const std::filesystem::path& out, const ConvergeOptions& o,
                    std::ostream& progress) {
    if (o.write_results) write_converge_results(study, out, {o.force, o.quiet, o.plots}, progress);
    if (!o.quiet) print_converge_summary(study, progress);
}

}  // namespace

void attach_converge_writers(ConvergeOptions& o) {
    o.claim = claim_converge_output;
    o.write = write_converge;
}

}  // namespace coremodal
