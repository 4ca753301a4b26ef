#include "output/beam_formulas_report.hpp"

#include "common/format.hpp"
#include "output/summary_json.hpp"
#include "scene/units.hpp"

#include <cstdio>

namespace coremodal {
namespace {

void print_section(const BeamFormulas& r, std::ostream& out) {
    const Scene& s = r.scene;
    const RestRollSection& sec = r.section;
    out << "\n\nSection\n";
    out << "  core        Di " << millimetres(sec.Di, 5) << ", Do " << millimetres(sec.Do, 5) << ", Lc "
        << significant(r.Lc) << " m, Ec " << format_quantity(sec.Ec, Dimension::pressure) << ", rho_c "
        << significant(sec.rho_c) << " kg/m^3\n";
    out << "              Ic " << significant(r.Ic) << " m^4, Ac " << significant(r.Ac) << " m^2\n";
    if (s.rest_paper) {
        out << "  rest paper  Dp " << millimetres(sec.Dp, 5) << " (" << millimetres(r.paper_thickness, 5)
            << " thick), Ep " << format_quantity(sec.Ep, Dimension::pressure) << ", rho_p " << significant(sec.rho_p)
            << " kg/m^3\n";
        out << "              Ip " << significant(r.Ip) << " m^4, Ap " << significant(r.Ap) << " m^2\n";
    } else {
        out << "  rest paper  none (bare core, Dp = Do)\n";
    }
    out << "  EcIc + EpIp = " << significant(r.beam.EI) << " N m^2, rho_c Ac + rho_p Ap = " << significant(r.beam.rho_A)
        << " kg/m, kappa G A = " << significant(r.beam.kappa_GA) << " N (Cowper; for Timoshenko)\n";
    out << "\nSpan\n";
    out << "  Li = " << millimetres(r.Li, 5) << " (" << r.li_source
        << "), free span L = Lc - 2 Li = " << significant(r.L) << " m\n";
}

void print_frequencies(const BeamFormulas& r, std::ostream& out) {
    out << "\nFirst bending frequency\n";
    out << "  I-7  f1 = k 22.373/(2 pi L^2) sqrt((EcIc + EpIp)/(rho_c Ac + rho_p Ap)), k = " << significant(r.k) << ":  "
        << significant(r.f1) << " Hz\n";
    if (r.k_assumed)
        out << "       k = 1 assumed: the core rigidly clamped at Li, no chuck or stand compliance; an upper bound. "
               "Elastic chucks in a stand give k ~ 0.7-0.85 (docs/reference/material-sources.md: case 07 0.744, case 08 0.768): give "
               "--k, --calibration, or `coremodal run` / `coremodal limits` on the stand for a computed k\n";
    if (!r.k_source.empty())
        out << "       k from the " << r.k_source << ": g1 = " << significant(r.groups->g1) << ", g2 = " << significant(r.groups->g2)
            << ", g3 = " << significant(r.groups->g3) << "\n";
    out << "                      Euler-Bernoulli   Timoshenko\n";
    out << "  clamped-clamped, L   " << formatted("%9.4g", r.eb_cc) << " Hz   " << formatted("%9.4g", r.timo_cc) << " Hz\n";
    out << "  free-free, Lc        " << formatted("%9.4g", r.eb_ff) << " Hz   " << formatted("%9.4g", r.timo_ff) << " Hz\n";
}

void print_speeds(const BeamFormulas& r, std::ostream& out) {
    out << "\nSpeeds\n";
    out << "  König " << r.koenig_formula << " (rest paper " << millimetres(r.paper_thickness, 5)
        << (r.koenig_formula == "K-1" ? " <= 10 mm" : " > 10 mm") << "), experience factor "
        << significant(r.koenig_factor) << ", l = " << significant(r.koenig_l) << " m (" << r.koenig_l_source << "):\n";
    out << "      f_krit = " << significant(r.koenig.f_krit_hz) << " Hz, v_krit = " << web_speed(r.koenig.v_krit_m_s)
        << "\n";
    out << "  I-5  safe web speed v_safe = safe pi Dp f1, safe = " << significant(r.safe) << ": " << web_speed(r.v_safe)
        << "\n";
    if (const auto& a = r.amplification)
        out << "  I-2..4 at " << web_speed(a->web_speed_m_s) << ": f_rot = " << significant(a->f_rot_hz)
            << " Hz, r = f_rot/f1 = " << significant(a->ratio) << ", zeta = " << significant(a->zeta)
            << (a->zeta_assumed ? " (assumed)" : "")
            << ": d = 1/sqrt((1 - r^2)^2 + (2 zeta r)^2) = " << significant(a->d) << "\n";
}

void print_measurement(const BeamFormulas& r, std::ostream& out) {
    if (!r.f_free) return;
    out << "\nFree-hanging measurement f_free = " << significant(*r.f_free) << " Hz at Lc = " << significant(r.Lc) << " m\n";
    out << "  f2 = f_free Lc^2/(Lc - 2 Li)^2 = " << significant(*r.f2) << " Hz\n";
    if (r.k_measured)
        out << "  I-6  k = f1/f2 = " << significant(*r.f_clamped) << "/" << significant(*r.f2) << " = " << significant(*r.k_measured) << "\n";
    if (r.Ec_measured)
        out << "  I-13/14  Q = 82.66 Ic/(Ac L^2) + 1 = " << significant(*r.Q, 5)
            << ", Ec = 7.88e-8 f^2 M L^4 Q/Ic = " << format_quantity(*r.Ec_measured, Dimension::pressure)
            << " (M = rho_c Ac = " << significant(r.section.rho_c * r.Ac) << " kg/m)\n";
    if (r.Ep_measured)
        out << "  I-15  Ep (I-7 with k = 1 at Lc, solved for Ep) = "
            << format_quantity(*r.Ep_measured, Dimension::pressure) << "\n";
}

}  // namespace

void print_beam_formulas_text(const BeamFormulas& r, std::ostream& out) {
    out << "coremodal beam: " << r.scene.name;
    if (!r.scene.source_file.empty()) out << " (" << r.scene.source_file << ")";
    print_section(r, out);
    print_frequencies(r, out);
    print_speeds(r, out);
    print_measurement(r, out);
    const auto assumed = beam_formula_assumptions(r.scene);
    if (!r.notes.empty() || !assumed.empty()) {
        out << "\nNotes\n";
        for (const auto& n : r.notes) out << "  - " << n << "\n";
        for (const auto& a : assumed) out << "  - " << a << "\n";
    }
}

void print_beam_formulas_json(const BeamFormulas& r, double seconds, std::ostream& out) {
    const Scene& s = r.scene;
    const RestRollSection& sec = r.section;
    Json section{{"Di_m", sec.Di},          {"Do_m", sec.Do},
                        {"Dp_m", sec.Dp},          {"Ec_Pa", sec.Ec},
                        {"rho_c_kg_m3", sec.rho_c}, {"Ic_m4", r.Ic},
                        {"Ac_m2", r.Ac},           {"EI_N_m2", r.beam.EI},
                        {"mass_per_length_kg_m", r.beam.rho_A}, {"kappa_GA_N", r.beam.kappa_GA},
                        {"rho_I_kg_m", r.beam.rho_I}};
    if (s.rest_paper) {
        section["Ep_Pa"] = (sec.Ep);
        section["rho_p_kg_m3"] = (sec.rho_p);
        section["Ip_m4"] = (r.Ip);
        section["Ap_m2"] = (r.Ap);
        section["rest_paper_thickness_m"] = (r.paper_thickness);
    }
    Json i7{{"k", r.k}, {"f1_hz", r.f1}};
    if (r.k_assumed) i7["k_assumed"] = "k = 1: the rigid clamp at Li, an upper bound (no chuck or stand compliance)";
    if (!r.k_source.empty()) {
        i7["k_source"] = (r.k_source);
        i7["g1"] = (r.groups->g1);
        i7["g2"] = (r.groups->g2);
        i7["g3"] = (r.groups->g3);
    }
    // The same head and I-5 shape as every command's summary.json (output/summary_json.hpp).
    Json t = summary_head("beam", s.name, s.source_file, s.description);
    t["section"] = section;
    t["span"] = Json{{"Lc_m", r.Lc}, {"Li_m", r.Li}, {"Li_source", r.li_source}, {"L_m", r.L}};
    t["i7"] = i7;
    t["euler_bernoulli"] = Json{{"clamped_clamped_L_hz", r.eb_cc}, {"free_free_Lc_hz", r.eb_ff}};
    t["timoshenko"] = Json{{"clamped_clamped_L_hz", r.timo_cc}, {"free_free_Lc_hz", r.timo_ff}};
    t["koenig"] = Json{{"formula", r.koenig_formula}, {"experience_factor", r.koenig_factor}, {"l_m", r.koenig_l},
                       {"l_source", r.koenig_l_source}, {"f_krit_hz", r.koenig.f_krit_hz},
                       {"v_krit_m_s", r.koenig.v_krit_m_s}};
    RollSpeeds speeds;
    speeds.f1_hz = r.f1;
    speeds.dp_m = sec.Dp;
    speeds.safe = {SafeSpeed{r.safe, r.v_safe}};
    t["speeds"] = safe_web_speed_json(speeds);
    if (const auto& a = r.amplification)
        t["single_mode_amplification"] = Json{{"web_speed_m_s", a->web_speed_m_s}, {"f_rot_hz", a->f_rot_hz},
                                              {"r", a->ratio}, {"zeta", a->zeta}, {"zeta_assumed", a->zeta_assumed},
                                              {"d", a->d}};
    if (r.f_free) {
        Json m{{"f_free_hz", *r.f_free}, {"f2_hz", *r.f2}};
        if (r.f_clamped) m["f_clamped_hz"] = (*r.f_clamped), m["k"] = (*r.k_measured);
        if (r.Ec_measured) m["Q"] = (*r.Q), m["Ec_Pa"] = (*r.Ec_measured);
        if (r.Ep_measured) m["Ep_Pa"] = (*r.Ep_measured);
        t["free_free_measurement"] = (m);
    }
    t["notes"] = string_array(r.notes);
    t["assumptions"] = string_array(beam_formula_assumptions(s));
    t["timing_s"] = Json{{"total", seconds}};
    out << json_text(t);
}

}  // namespace coremodal
