#include "output/converge_report.hpp"

#include "models/ladder/refinement_ladder.hpp"
#include "common/format.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace coremodal {
namespace {

std::string error_percent(double fraction) {
    if (fraction >= 0.1) return formatted("%.0f %%", fraction * 100);
    if (fraction >= 0.01) return formatted("%.1f %%", fraction * 100);
    if (fraction >= 1e-3) return formatted("%.2f %%", fraction * 100);
    return formatted("%.2g %%", fraction * 100);
}

// Seconds for the tables: two decimals, one from 10 s; below 0.01 s (a beam
// level takes about a millisecond) two significant digits.
std::string seconds(double s) {
    if (s >= 10) return formatted("%.1f", s);
    if (s >= 0.01 || s <= 0) return formatted("%.2f", s);
    return formatted("%.2g", s);
}

std::string role_title(const std::string& role) {
    if (role == "f1") return "f1 (first bending)";
    if (role.empty()) return "";
    return "first " + role;
}

void markdown_levels(std::ostringstream& s, const ModelStudy& m) {
    const TrackedMode* f1 = find_role(m, "f1");
    const TrackedMode* oval = find_role(m, "ovalling");
    // The beam builds a network instead of a mesh and assembles inside its
    // solve (problem by problem): its columns say so.
    const bool beam = !m.traits.meshed;
    if (beam)
        s << "| k | elements (core/network) | DOFs | runs | network [s] | assemble+solve [s] | labels [s] | "
             "total [s] | CPU [s] | peak memory [MiB] |";
    else
        s << "| k | mesh (wall/paper/around/along) | DOFs | runs | mesh [s] | assemble [s] | factor+solve [s] | "
             "total [s] | CPU [s] | peak memory [MiB] |";
    if (f1) s << " f1 [Hz] | error f1 |";
    if (oval) s << " ovalling [Hz] | error ovalling |";
    s << "\n|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|";
    if (f1) s << "---:|---:|";
    if (oval) s << "---:|---:|";
    s << "\n";
    for (std::size_t i = 0; i < m.levels.size(); ++i) {
        const LevelResult& l = m.levels[i];
        const Timing& t = l.median_s;
        s << "| " << l.step.k << " | " << l.step.counts << " | " << l.n_dofs << " | " << l.runs << " | "
          << seconds(t.mesh) << " | " << (beam ? seconds(t.factor_and_solve) : seconds(t.assemble)) << " | "
          << (beam ? seconds(t.classify) : seconds(t.factor_and_solve)) << " | " << seconds(t.total) << " | "
          << seconds(l.median_cpu_s) << " | " << formatted("%.0f", l.peak_memory_mb) << " |";
        for (const TrackedMode* t : {f1, oval}) {
            if (!t) continue;
            s << ' ' << optional_number(t->frequency_hz[i], "%.4f") << " | "
              << (t->relative_error[i] ? error_percent(*t->relative_error[i]) : std::string("–")) << " |";
        }
        s << "\n";
        if (!l.complete) s << "\n(k = " << l.step.k << ": the inertia count found missing modes)\n";
    }
}

void markdown_extrapolation(std::ostringstream& s, const ModelStudy& m) {
    s << "\n| mode | role | finest [Hz] | extrapolated f0 [Hz] | error estimate | f0 known to | order p | "
         "asymptotic | note |\n|---|---|---:|---:|---:|---:|---:|---|---|\n";
    for (const auto& t : m.modes) {
        s << "| " << t.key.text() << " | " << role_title(t.role) << " | "
          << optional_number(t.frequency_hz.back(), "%.4f") << " | ";
        if (!t.richardson) {
            s << "– | – | – | – | – | missing at some level (labels differ) |\n";
            continue;
        }
        const Richardson& r = *t.richardson;
        s << formatted("%.4f", r.f0) << " | " << error_percent(r.error_estimate / std::abs(r.f0)) << " | "
          << (r.f0_uncertainty ? error_percent(*r.f0_uncertainty / std::abs(r.f0)) : std::string("–")) << " | "
          << (r.extrapolated ? formatted("%.2f", r.order) : std::string("–")) << " | " << (r.asymptotic ? "yes" : "no")
          << " | " << r.note << " |\n";
    }
    for (const auto& [role, why] : m.unseen_roles)
        if (!find_role(m, role)) s << "| – | " << role_title(role) << " | – | not in this model | – | – | – | – | " << why << " |\n";
    s << "\nerror estimate = |f(finest) − f0| / f0; \"f0 known to\" = |f0 − f0 of the triple one level coarser| / f0.\n";
}

void markdown_targets(std::ostringstream& s, const ModelStudy& m) {
    s << "\n| mode | target | cheapest level reaching it | DOFs | time [s] |\n|---|---:|---|---:|---:|\n";
    for (const std::string role : {"f1", "ovalling"}) {
        const TrackedMode* t = find_role(m, role);
        if (!t) continue;
        for (double target : kAccuracyTargets) {
            s << "| " << role_title(role) << " | " << error_percent(target) << " | ";
            const auto i = first_level_within(*t, target);
            if (i) {
                const LevelResult& l = m.levels[*i];
                s << l.step.label << " | " << l.n_dofs << " | " << seconds(l.median_s.total) << " |\n";
            } else if (const auto p = predict_level_for(m, *t, target)) {
                s << "none of the ladder; predicted k ≈ " << formatted("%.1f", p->k) << " | ≈ " << formatted("%.3g", p->n_dofs)
                  << " | " << (p->time_s ? "≈ " + formatted("%.3g", *p->time_s) : std::string("–")) << " |\n";
            } else {
                s << "none of the ladder (not asymptotic, or below what f0 is known to) | – | – |\n";
            }
        }
    }
    s << "\nA level reaches a target when its error against f0 plus the uncertainty of f0 is within it. "
         "Predictions extend the observed order and time scaling beyond the ladder (uniform refinement).\n";
}

void markdown_cost(std::ostringstream& s, const ModelStudy& m) {
    if (m.levels.empty()) return;
    const LevelResult& l = m.levels.back();
    const Timing& t = l.median_s;
    const double total = t.total > 0 ? t.total : 1;
    if (!m.traits.meshed) {
        s << "\nWhere the time goes at the finest level (" << l.step.label << ", " << l.n_dofs << " DOFs, median of "
          << l.runs << " runs): building the beam network " << seconds(t.mesh) << " s ("
          << error_percent(t.mesh / total) << "), assembly, eigensolve and inertia count "
          << seconds(t.factor_and_solve) << " s (" << error_percent(t.factor_and_solve / total)
          << "), labels and effective masses " << seconds(t.classify) << " s (" << error_percent(t.classify / total)
          << "); total " << seconds(t.total) << " s. Peak memory " << formatted("%.0f", l.peak_memory_mb)
          << " MiB is the whole process's resident set (PETSc, the "
          << "solid ladder's freed heap): the beam itself needs well under a MiB.\n";
        if (m.time_exponent) s << "\nObserved scaling over the levels after the coarsest: time ~ DOFs^"
                               << formatted("%.2f", *m.time_exponent) << ".\n";
        return;
    }
    s << m.traits.cost_note;
    s << "\nWhere the time goes at the finest level (" << l.step.label << ", " << l.n_dofs << " DOFs, median of "
      << l.runs << (l.runs == 1 ? " run" : " runs") << "): mesh " << seconds(t.mesh) << " s ("
      << error_percent(t.mesh / total) << "), assembly " << seconds(t.assemble) << " s ("
      << error_percent(t.assemble / total) << "), factorization and solve " << seconds(t.factor_and_solve) << " s ("
      << error_percent(t.factor_and_solve / total) << "), classification " << seconds(t.classify) << " s ("
      << error_percent(t.classify / total) << "); total " << seconds(t.total) << " s, peak memory "
      << formatted("%.0f", l.peak_memory_mb) << " MiB.\n";
    const SolverBreakdown& b = l.median_solver_s;
    if (b.factor_s + b.solve_s + b.orthogonalize_s > 0) {
        const double rest = std::max(0.0, t.factor_and_solve - b.factor_s - b.solve_s - b.orthogonalize_s);
        s << "\nInside factorization and solve (PETSc event log): factorizations " << seconds(b.factor_s) << " s ("
          << error_percent(b.factor_s / total) << " of the total), triangular solves " << seconds(b.solve_s) << " s ("
          << error_percent(b.solve_s / total) << "), orthogonalization of the Krylov basis "
          << seconds(b.orthogonalize_s) << " s (" << error_percent(b.orthogonalize_s / total)
          << "), the rest of the eigensolver (M products, projected "
          << "problem, residual checks) " << seconds(rest) << " s (" << error_percent(rest / total) << ").\n";
    }
    if (m.time_exponent && m.memory_exponent)
        s << "\nObserved scaling over the levels after the coarsest: time ~ DOFs^" << formatted("%.2f", *m.time_exponent)
          << ", peak memory ~ DOFs^" << formatted("%.2f", *m.memory_exponent) << ".\n";
}

// The harmonic level against the solid level by level: at equal k both mesh
// the same r–z section, so the difference is exactly the solid's
// circumferential discretization error at that level (the solid is the
// stiffer: a positive difference).
void markdown_same_section(std::ostringstream& s, const ModelStudy& harmonic, const ModelStudy& solid) {
    bool header = false;
    for (const std::string role : {"f1", "ovalling"}) {
        const TrackedMode* h = find_role(harmonic, role);
        const TrackedMode* so = find_role(solid, role);
        if (!h || !so) continue;
        for (std::size_t i = 0; i < solid.levels.size(); ++i)
            for (std::size_t j = 0; j < harmonic.levels.size(); ++j) {
                if (harmonic.levels[j].step.k != solid.levels[i].step.k || !so->frequency_hz[i] || !h->frequency_hz[j])
                    continue;
                if (!header) {
                    s << "\nLevel by level on the same section: the difference is the solid's own circumferential "
                         "discretization error at that level (its level k has " << solid.levels[i].step.mesh.n_around / solid.levels[i].step.k
                      << " × k elements around). It stiffens the solid; but the solid's quadratic arcs only approximate "
                         "the circle, so where that error is tiny (bending) the difference can take either sign at the "
                         "10⁻⁴ level:\n\n| mode | k | solid [Hz] | harmonic [Hz] | (solid − harmonic) / harmonic |\n"
                         "|---|---:|---:|---:|---:|\n";
                    header = true;
                }
                const double fs = *so->frequency_hz[i], fh = *h->frequency_hz[j];
                s << "| " << role_title(role) << " | " << solid.levels[i].step.k << " | " << formatted("%.4f", fs)
                  << " | " << formatted("%.4f", fh) << " | " << formatted("%+.3g", 100 * (fs - fh) / fh) << " % |\n";
            }
    }
}

// One line per role: where each model level converges and how far apart.
void markdown_model_errors(std::ostringstream& s, const ConvergeStudy& study) {
    const ModelStudy* solid = find_reference(study.models);
    if (!solid) return;
    const std::vector<ModelError> errors = model_errors(study.models);
    for (const auto& m : study.models) {
        if (m.traits.reference) continue;
        const bool harmonic = m.traits.same_section;
        s << "\n## Model error: " << m.model << " against solid\n\n";
        if (harmonic)
            s << "The harmonic level solves the solid's own r–z section (level k meshes the same section as the "
                 "solid's level k) exactly in theta. The difference between the two extrapolated values is therefore "
                 "not a modelling error: it is the part of the solid's circumferential discretization error that its "
                 "extrapolation did not remove (the solid refines around together with the section), plus both "
                 "extrapolations' noise; ideally it is zero. A difference within what both are known to is agreement; "
                 "where the harmonic f0 is better known, it is the better value of the two.\n\n";
        else
            s << "Each level converges to its own model's answer; the difference between the two extrapolated values "
                 "is the model error, which no refinement of the " << m.model << " removes.\n\n";
        const char* error_words = harmonic ? "difference " : "model error ";
        for (const auto& [role, type] : kModeRoles) {
            const TrackedMode* own = find_role(m, role);
            const TrackedMode* ref = find_role(*solid, role);
            const auto e = std::find_if(errors.begin(), errors.end(),
                                        [&, role = role](const ModelError& x) { return x.model == m.model && x.role == role; });
            s << "- " << role_title(role) << ": ";
            if (e != errors.end()) {
                s << m.model << " level converges to " << formatted("%.4f", e->f0_hz) << " Hz (" << e->id
                  << "), the solid to " << formatted("%.4f", e->solid_f0_hz) << " Hz (" << e->solid_id
                  << "): " << error_words << formatted("%+.3g", 100 * e->relative)
                  << " % (both extrapolations known to " << error_percent(e->known_to) << ")\n";
                continue;
            }
            const auto unseen = std::find_if(m.unseen_roles.begin(), m.unseen_roles.end(),
                                             [&, role = role](const auto& u) { return u.first == role; });
            if (unseen != m.unseen_roles.end()) {
                s << "not in this model (" << unseen->second << ")";
                if (ref && ref->richardson) s << "; the solid converges to " << formatted("%.4f", ref->richardson->f0) << " Hz";
                s << "\n";
            } else if (!own || !own->richardson) {
                s << "the " << m.model << " level has no extrapolated value (not among its modes, or not tracked at "
                     "every level)\n";
            } else {
                s << m.model << " level converges to " << formatted("%.4f", own->richardson->f0)
                  << " Hz; the solid has no extrapolated value (not among its modes)\n";
            }
        }
        if (harmonic) markdown_same_section(s, m, *solid);
    }
}

// The opening paragraph: case, modes per run, how timings were taken, and
// how busy the machine was.
void markdown_header(std::ostringstream& s, const ConvergeStudy& study) {
    s << "# Convergence study: " << study.case_name << "\n\n";
    s << "Case file `" << study.source_file << "`; modes asked per run:";
    for (std::size_t i = 0; i < study.models.size(); ++i)
        s << (i ? ", " : " ") << study.models[i].model << " " << study.models[i].n_modes;
    s << "; timings are medians of the runs in each table's \"runs\" column (" << study.repeats
      << " per solid or harmonic level, one for a level whose first run took longer than " << formatted("%.0f", study.repeat_limit_s)
      << " s; " << kBeamRunsPerLevel << " per beam level, whose runs take about a millisecond, or as many as fit in "
      << formatted("%g", kBeamLevelBudget) << " s). Model levels: ";
    for (std::size_t i = 0; i < study.models.size(); ++i) s << (i ? ", " : "") << study.models[i].model;
    s << ". Ladders: " << seconds(study.ladder_time_s) << " s; whole study (with named-level checks): "
      << seconds(study.total_time_s) << " s on " << study.n_cores
      << " cores, load average " << formatted("%.1f", study.load_start) << " at the start and "
      << formatted("%.1f", study.load_end) << " at the end (a load above the number of cores means other processes "
      << "shared the machine and the wall times are longer than on an idle one; CPU time is less affected).\n";
}

// The named mesh levels (--check-levels) against the solid's extrapolated values.
void markdown_checks(std::ostringstream& s, const ConvergeStudy& study) {
    if (study.checks.empty()) return;
    s << "\n## Named mesh levels against the extrapolated values (solid)\n\n"
         "| level | mesh (wall/paper/around/along) | DOFs | total [s] | peak memory [MiB] | f1 [Hz] | error f1 | "
         "ovalling [Hz] | error ovalling |\n|---|---|---:|---:|---:|---:|---:|---:|---:|\n";
    const ModelStudy* solid = find_reference(study.models);
    for (const auto& c : study.checks) {
        s << "| " << c.name << " | " << c.mesh << " | " << c.result.n_dofs << " | "
          << seconds(c.result.median_s.total) << " | " << formatted("%.0f", c.result.peak_memory_mb) << " |";
        const auto distinct = distinct_modes(c.result.modes);
        for (const std::string role : {"f1", "ovalling"}) {
            const TrackedMode* t = solid ? find_role(*solid, role) : nullptr;
            const DistinctMode* d = nullptr;
            if (t)
                for (const auto& x : distinct)
                    if (x.key == t->key) d = &x;
            if (!d || !t->richardson) {
                s << " – | – |";
                continue;
            }
            s << ' ' << formatted("%.4f", d->frequency_hz) << " | "
              << error_percent(std::abs(d->frequency_hz - t->richardson->f0) / t->richardson->f0) << " |";
        }
        s << "\n";
    }
}

}  // namespace

std::string converge_markdown(const ConvergeStudy& study, const std::string& plot_note) {
    std::ostringstream s;
    markdown_header(s, study);
    for (const auto& m : study.models) {
        s << "\n## Model level: " << m.model << "\n\n" << m.ladder_note << "\n\n";
        markdown_levels(s, m);
        s << "\n### Extrapolated frequencies (Richardson, three finest levels)\n";
        markdown_extrapolation(s, m);
        s << "\n### Accuracy targets\n";
        markdown_targets(s, m);
        s << "\n### Cost\n";
        markdown_cost(s, m);
    }
    markdown_model_errors(s, study);
    markdown_checks(s, study);
    if (!study.notes.empty()) {
        s << "\n## Notes\n\n";
        for (const auto& n : study.notes) s << "- " << n << "\n";
    }
    s << "\n## Error against time\n\n";
    if (plot_note.empty())
        s << "![relative error of f1 and of the first ovalling mode against run time](error_vs_time.png)\n";
    else
        s << "(no picture: " << plot_note << ")\n";
    return s.str();
}

}  // namespace coremodal
