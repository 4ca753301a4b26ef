// calibration.csv and the calibration's report.md (output/calibration_report.hpp).
#include "output/calibration_report.hpp"

#include "common/format.hpp"
#include "output/csv.hpp"
#include "output/study_report.hpp"  // parameter_column

#include <sstream>

namespace coremodal {
namespace {

}  // namespace

std::string calibration_csv(const CaseSweep& sweep, const CalibrationOutcome& outcome) {
    std::ostringstream out;
    out << "point";
    for (const SweepParameter& p : sweep.parameters()) out << "," << parameter_column(p);
    out << ",status,held_out,li_m,span_m,diameter_m,g1,g2,g3,f1_fe_hz,f_i7_k1_hz,k_fe,k_fit,residual_k,"
           "f1_calibrated_hz,error,note\n";
    const auto num = [](double v) { return significant(v, 10); };
    for (const CalibrationRow& r : outcome.rows) {
        const StudyPoint& p = *r.point;
        out << p.index + 1;
        for (size_t j = 0; j < sweep.parameters().size(); ++j) {
            const SweepParameter& par = sweep.parameters()[j];
            const auto v = static_cast<size_t>(p.value_index[j]);
            out << "," << (par.numeric ? num(par.si[v]) : csv_field(par.labels[v]));
        }
        if (!r.used) {
            out << "," << (p.ok ? "unused" : "failed") << ",,,,,,,,,,,,,,," << csv_field(r.note) << "\n";
            continue;
        }
        out << ",ok," << (r.held_out ? 1 : 0) << "," << num(*p.li_m) << "," << num(*p.span_m) << ","
            << num(p.diameter_m) << "," << num(r.groups.g1) << "," << num(r.groups.g2) << "," << num(r.groups.g3) << "," << num(*p.f1_hz)
            << "," << num(*p.f_i7_hz) << "," << num(r.k_fe) << "," << num(r.k_fit) << "," << num(r.k_fit - r.k_fe)
            << "," << num(r.f1_calibrated_hz) << "," << num(r.error) << ",\n";
    }
    return out.str();
}

std::string calibration_report_markdown(const CaseSweep& sweep, const StudyResult& result,
                                        const CalibrationOutcome& outcome, const std::vector<std::string>& pngs,
                                        const std::string& plot_problem) {
    const Calibration& c = outcome.calibration;
    std::ostringstream out;
    out << "# Chuck factor calibration: " << sweep.case_name() << "\n\n";
    out << "Case file `" << sweep.case_file() << "`; " << sweep.n_points() << " points ("
        << sweep.n_points() - result.n_failed() << " ok), " << c.n_fit << " fitted, " << c.n_held_out
        << " held out (one usable point in " << sweep.options().holdout_every << "); mesh "
        << (sweep.options().mesh_level.empty() ? std::string("as the case's [mesh]") : sweep.options().mesh_level)
        << ". Written by coremodal " COREMODAL_VERSION ".\n\n";
    out << "## The law\n\n    1/k^2 = c0 + c1 g1 + c2 g2 + c3 g3\n"
           "    g1 = (EI/(Ec Ic)) (Li/L)     support rotation\n"
           "    g2 = EI/(kappa G A L^2)     shear flexibility of the span\n"
           "    g3 = Ep Ip / EI             share of the bending stiffness in the rest paper\n\n"
           "k = f1_FE / f_I-7(k = 1) over L = Lc - 2 Li; EI = Ec Ic + Ep Ip (docs/how-to/calibration.md).\n\n";
    out << "| coefficient | value |\n|---|---|\n| c0 | " << significant(c.law.c[0], 6) << " |\n| c1 | " << significant(c.law.c[1], 6)
        << " |\n| c2 | " << significant(c.law.c[2], 6) << " |\n| c3 | " << significant(c.law.c[3], 6) << " |\n\n";
    for (int i = 0; i < kCalibrationGroups; ++i)
        if (!c.law.fitted[static_cast<size_t>(i)])
            out << "g" << i + 1 << " is the same at every point: not fitted (c" << i + 1
                << " = 0); the law holds only at that value.\n\n";
    out << "## Residuals and check\n\n";
    out << "- fitted points: rms residual in k " << significant(c.rms_residual_k, 3) << ", largest " << significant(c.max_residual_k, 3)
        << "; largest error of I-7 with the fitted k against the FE f1: " << percent(c.max_error_fit) << "\n";
    out << "- held-out points (not in the fit): largest error " << percent(c.max_error_held_out) << "\n";
    out << "- stated error: " << percent(c.stated_error) << " ([calibration] max_error): **"
        << (c.passed ? "PASSED" : "FAILED") << "**\n\n";
    out << "Valid for: L " << significant(c.span_m.min, 4) << " to " << significant(c.span_m.max, 4) << " m, Li " << significant(c.li_m.min * 1e3, 4)
        << " to " << significant(c.li_m.max * 1e3, 4) << " mm, D " << significant(c.diameter_m.min * 1e3, 4) << " to "
        << significant(c.diameter_m.max * 1e3, 4) << " mm, g1 " << significant(c.g1.min, 3) << " to " << significant(c.g1.max, 3) << ", g2 "
        << significant(c.g2.min, 3) << " to " << significant(c.g2.max, 3) << ", g3 " << significant(c.g3.min, 3) << " to " << significant(c.g3.max, 3)
        << ". `coremodal beam --calibration calibration.toml` "
        << "notes any value outside these ranges.\n\n";
    out << "## Table of k\n\n| # | point | held out | L [m] | D [mm] | g1 | g2 | g3 | f1 FE [Hz] | k FE | "
           "k fit | f1 I-7 [Hz] | error |\n|---|---|---|---|---|---|---|---|---|---|---|---|---|\n";
    for (const CalibrationRow& r : outcome.rows) {
        const StudyPoint& p = *r.point;
        out << "| " << p.index + 1 << " | " << p.description << " | ";
        if (!r.used) {
            out << "- | | | | | | | | | | " << r.note << " |\n";
            continue;
        }
        out << (r.held_out ? "yes" : "") << " | " << significant(*p.span_m) << " | " << significant(p.diameter_m * 1e3) << " | "
            << significant(r.groups.g1, 3) << " | " << significant(r.groups.g2, 3) << " | " << significant(r.groups.g3, 3) << " | " << significant(*p.f1_hz) << " | " << significant(r.k_fe, 4)
            << " | " << significant(r.k_fit, 4) << " | " << significant(r.f1_calibrated_hz) << " | " << percent(r.error) << " |\n";
    }
    out << "\n## Plots\n\n";
    if (!plot_problem.empty()) out << "Plots were not drawn: " << plot_problem << ".\n\n";
    for (const std::string& png : pngs) out << "![" << png << "](" << png << ")\n\n";
    out << "Files: `calibration.toml` (keep it; apply with `coremodal beam --calibration`), `calibration.csv` "
           "(the table of k), `study.csv` and `study.json` (the sweep, modes tracked), this report.\n";
    return out.str();
}

std::string calibration_console(const Calibration& c, const std::string& out_dir) {
    std::ostringstream out;
    out << "calibrate: 1/k^2 = " << significant(c.law.c[0]) << " + " << significant(c.law.c[1]) << " g1 + "
        << significant(c.law.c[2]) << " g2 + " << significant(c.law.c[3]) << " g3; " << c.n_fit
        << " points fitted (rms residual in k " << significant(c.rms_residual_k) << "), " << c.n_held_out
        << " held out: largest f1 error " << significant(100 * c.max_error_held_out) << " % (fitted "
        << significant(100 * c.max_error_fit) << " %), stated " << significant(100 * c.stated_error)
        << " %: " << (c.passed ? "passed" : "FAILED") << "\n"
        << "calibrate: " << out_dir << "/calibration.toml (apply with coremodal beam --calibration)\n";
    return out.str();
}

}  // namespace coremodal
