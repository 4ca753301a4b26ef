#include "output/converge_report.hpp"

#include "analyses/converge/ladder_runs.hpp"
#include "common/format.hpp"

#include <cmath>
#include <cstdio>

namespace coremodal {

namespace {

// "  f1 within  1 %: k=2 ... (0.3 s)  0.1 %: ...": the cheapest level per
// accuracy target, or the predicted one beyond the ladder.
void print_targets(const ModelStudy& m, const TrackedMode& t, std::ostream& out) {
    out << "  " << t.role << " within";
    for (double target : kAccuracyTargets) {
        const auto i = first_level_within(t, target);
        out << "  " << formatted("%g", target * 100) << " %: ";
        if (i) {
            out << m.levels[*i].step.label << " (" << progress_seconds(m.levels[*i].median_s.total, "%.1f") << " s)";
        } else if (const auto p = predict_level_for(m, t, target)) {
            out << "not in the ladder (k ~ " << formatted("%.1f", p->k) << ", ~" << formatted("%.2g", p->n_dofs)
                << " DOFs" << (p->time_s ? ", ~" + formatted("%.2g", *p->time_s) + " s" : std::string()) << ")";
        } else {
            out << "not in the ladder";
        }
    }
    out << "\n";
}

void print_model(const ModelStudy& m, std::ostream& out) {
    out << "\n" << m.model << ": extrapolated frequencies (three finest levels)\n";
    for (const auto& t : m.modes) {
        if (t.role.empty() || !t.richardson) continue;
        const Richardson& r = *t.richardson;
        char line[256];
        std::snprintf(line, sizeof line, "  %-10s %-24s f0 %12.4f Hz  error of finest %9.2e  order %s  %s\n",
                      t.role.c_str(), t.key.text().c_str(), r.f0, r.error_estimate / std::abs(r.f0),
                      r.extrapolated ? formatted("%.2f", r.order).c_str() : "-",
                      r.asymptotic ? "asymptotic" : "NOT asymptotic");
        out << line;
    }
    for (const std::string role : {"f1", "ovalling"})
        for (const auto& t : m.modes)
            if (t.role == role) print_targets(m, t, out);
}

}  // namespace

void print_converge_summary(const ConvergeStudy& study, std::ostream& out) {
    for (const auto& m : study.models) print_model(m, out);
    const std::vector<ModelError> errors = model_errors(study.models);
    for (const ModelError& e : errors)
        out << "\nmodel error, " << e.model << " " << e.role << ": " << e.model << " converges to "
            << formatted("%.4f", e.f0_hz) << " Hz, the solid to " << formatted("%.4f", e.solid_f0_hz) << " Hz: "
            << formatted("%+.3g", 100 * e.relative) << " %";
    if (!errors.empty()) out << "\n";
    out << "\nladders " << formatted("%.1f", study.ladder_time_s) << " s, whole study " << formatted("%.1f", study.total_time_s)
        << " s" << std::endl;
}

}  // namespace coremodal
