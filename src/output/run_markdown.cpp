#include "output/run_markdown.hpp"

#include "beam/beam_theory.hpp"
#include "beam/formulas.hpp"
#include "beam/iso_test.hpp"
#include "common/format.hpp"
#include "scene/level_traits.hpp"

#include <cmath>
#include <sstream>

namespace coremodal {
namespace {

std::string hz(double f) { return formatted("%.4f", f); }

// Effective masses below this share of the model mass are round-off of an
// exact zero (symmetry) and print as 0, as in the console table.
constexpr double kNegligibleMassShare = 1e-9;

std::string bearing_text(const BearingSpec& b) {
    if (b.rigid) return "rigid bearings";
    std::string s = "elastic bearings: radial " + significant(b.radial_stiffness) + " N/m, tilting " +
                    significant(b.tilting_stiffness) + " N m/rad";
    if (b.frame_mass) s += ", frame mass " + significant(*b.frame_mass) + " kg";
    if (b.frame_stiffness) s += " on " + significant(*b.frame_stiffness) + " N/m";
    return s;
}

std::string chuck_text(const ChuckSpec& c) {
    std::string s = c.name + ": inserted " + millimetres(c.inserted_length) + ", Li " + millimetres(c.li()) + ", " +
                    std::to_string(c.expanding.size()) + " expanding element(s), ";
    if (c.interface.kind == InterfaceKind::bonded)
        s += "bonded";
    else
        s += std::string(c.interface.expanded ? "expanded" : "not expanded") +
             (c.interface.contact == ContactKind::one_sided ? ", one-sided contact under gravity" : " spring contact");
    return s + ", " + bearing_text(c.bearing);
}

std::string supports_text(const Scene& s) {
    std::ostringstream t;
    const char* separator = " ";
    switch (s.supports.kind) {
    case SupportKind::free: return "free (free-free, six rigid-body modes)";
    case SupportKind::clamped:
        t << "clamped:";
        for (const ClampSpec& c : s.supports.clamps) {
            t << separator << c.name << " z = " << significant(c.z_start) << "…" << significant(c.z_end) << " m";
            separator = "; ";
        }
        break;
    case SupportKind::chucks:
        t << "chucks:";
        for (const ChuckSpec& c : s.supports.chucks) {
            t << separator << chuck_text(c);
            separator = "; ";
        }
        break;
    }
    return t.str();
}

void scene_section(std::ostream& out, const Scene& s) {
    out << "## Scene\n\n| part | dimensions | material |\n|---|---|---|\n";
    out << "| core | ID " << millimetres(s.core.inner_diameter) << " × wall "
        << millimetres(0.5 * (s.core.outer_diameter - s.core.inner_diameter)) << " × length "
        << significant(s.core.length) << " m (OD " << millimetres(s.core.outer_diameter) << ") | "
        << s.core.material.name << ", E_z " << significant(s.core.material.E_z / 1e9) << " GPa, "
        << significant(s.core.material.density) << " kg/m³ |\n";
    out << "| rest paper | ";
    if (s.rest_paper)
        out << "OD " << millimetres(s.rest_paper->outer_diameter) << " ("
            << millimetres(0.5 * (s.rest_paper->outer_diameter - s.core.outer_diameter)) << " thick) | "
            << s.rest_paper->material.name << ", E_z " << significant(s.rest_paper->material.E_z / 1e9) << " GPa, "
            << significant(s.rest_paper->material.density) << " kg/m³ |\n";
    else
        out << "none (bare core) | |\n";
    out << "| supports | " << supports_text(s) << " | |\n\n";
}

void model_section(std::ostream& out, const RunReport& r) {
    const ModelInfo& m = r.model;
    const LevelTraits& level = level_traits(m.level);
    const Verification& v = r.modes.verification;
    out << "## Model and verification\n\n";
    out << "- model: " << m.level << ", " << m.element << ", " << m.n_elements << " elements, " << m.n_nodes
        << " nodes, " << m.n_dofs << " " << level.dofs_counted << " ("
        << m.n_eliminated_nodes << " clamped nodes eliminated); mesh: "
        << m.mesh_source;
    if (level.meshed && !r.scene.mesh.file) out << ", level " << r.scene.mesh.level;
    out << "\n";
    if (!m.harmonics.empty()) out << "- " << level.problems_line << ": " << m.harmonics << "\n";
    out << "- mass: model " << significant(m.mass_kg, 6) << " kg, from the dimensions "
        << significant(m.expected_mass_kg, 6) << " kg";
    if (m.expected_mass_kg > 0) out << " (" << formatted("%+.2e", m.mass_kg / m.expected_mass_kg - 1) << ")";
    out << "\n";
    const auto effects = r.scene.effects();
    if (!effects.empty()) {
        out << "- effects:";
        for (size_t i = 0; i < effects.size(); ++i) out << (i ? ", " : " ") << effects[i];
        out << "\n";
    }
    out << "- largest relative residual " << formatted("%.1e", v.max_relative_residual) << ", largest |XᵀMX − I| "
        << formatted("%.1e", v.max_orthonormality_error) << "\n";
    if (const auto& p = v.factor_precision)
        out << "- factor of K − σM: **" << p->used << " precision** (`-factor_precision " << p->asked << "`: " << p->why
            << "); count: " << p->count << "\n";
    const AnalysisSpec& a = r.scene.analysis;
    if (a.f_max_hz && r.modes.modes.empty())
        out << "- **no modes between " << significant(a.f_min_hz.value_or(0.0)) << " and " << significant(*a.f_max_hz)
            << " Hz**: an empty band, proven by the inertia count (as many eigenvalues below its upper edge as "
               "below its lower edge)\n";

    // Modes accounted for below the shift: found, and counted below a band.
    const long found = v.modes_found_below_shift();
    const std::string counted = v.eigenvalues_below_band > 0
                                    ? " and " + std::to_string(v.eigenvalues_below_band) + " counted below the band"
                                    : std::string();
    if (m.harmonics.empty())
        out << "- inertia count: " << v.negative_pivots_at_shift << " eigenvalues below "
            << significant(eigenvalue_hz(v.check_shift)) << " Hz, " << found << " modes found there" << counted
            << ": **" << (v.complete ? "complete" : "INCOMPLETE") << "**\n\n";
    else
        out << "- " << level.inertia_counts << ": " << v.negative_pivots_at_shift << " eigenvalues, " << found << " modes found" << counted << ": **"
            << (v.complete ? "complete" : "INCOMPLETE") << "**\n\n";
}

void mode_section(std::ostream& out, const RunReport& r) {
    const double mass = r.model.mass_kg;
    bool any_mass = false;
    for (const Mode& m : r.modes.modes) {
        const EffectiveMass& e = m.effective_mass;
        any_mass = any_mass || e.x > 0 || e.y > 0 || e.z > 0;
    }
    any_mass = any_mass && mass > 0;
    out << "## Modes\n\n| mode | f [Hz] | type | n | m | share | residual |";
    if (any_mass) out << " eff. mass x / y / z [% of model mass] |";
    out << "\n|---:|---:|---|---:|---:|---:|---:|" << (any_mass ? "---:|" : "") << "\n";
    const double negligible = kNegligibleMassShare * mass;
    auto share = [&](double v) { return v < negligible ? std::string("0") : significant(100 * v / mass, 3); };
    for (const Mode& m : r.modes.modes) {
        out << "| " << m.index << " | " << hz(m.frequency_hz) << " | " << m.label.type << " | " << m.label.n << " | "
            << m.label.m << " | " << formatted("%.2f", m.label.dominant_share) << " | "
            << formatted("%.1e", m.relative_residual) << " |";
        if (any_mass)
            out << " " << share(m.effective_mass.x) << " / " << share(m.effective_mass.y) << " / "
                << share(m.effective_mass.z) << " |";
        out << "\n";
    }
    out << "\nType: the family holding the largest share of the kinetic energy (`share`; below "
        << significant(kMinDominantShare) << " the mode is `mixed`); n: waves around, m: axial nodes.\n\n";
}

void beam_section(std::ostream& out, const RunReport& r) {
    const BeamComparison& b = r.beam;
    out << "## Beam theory\n\nFirst bending frequency, " << b.ends << ", span " << significant(b.span_m) << " m:\n\n";
    out << "| | f1 [Hz] | FE / this |\n|---|---:|---:|\n";
    if (b.fe_found())
        out << "| FE (mode " << b.fe_mode_index << ") | " << hz(b.fe_first_bending_hz) << " | |\n";
    else
        out << "| FE | none: " << b.fe_missing << " | |\n";
    auto row = [&](const char* name, double f, double ratio) {
        out << "| " << name << " | " << hz(f) << " | " << (b.fe_found() ? formatted("%.4f", ratio) : std::string("-"))
            << " |\n";
    };
    row("Euler–Bernoulli (I-7, k = 1)", b.euler_bernoulli_hz, b.fe_over_euler_bernoulli);
    row("Timoshenko (beam FE)", b.timoshenko_hz, b.fe_over_timoshenko);
    out << "\n";
}

void chuck_section(std::ostream& out, const ChuckFactor& k) {
    out << "## Chuck factor\n\nk = f1/f2 (I-6): f1 of this scene, f2 the free–free first bending frequency of the "
           "same roll cut to the free span L = Lc − Li,left − Li,right.\n\n";
    out << "| quantity | value |\n|---|---:|\n";
    out << "| Li left / right | " << millimetres(k.li_left_m) << " / " << millimetres(k.li_right_m) << " |\n";
    out << "| free span L | " << significant(k.free_span_m) << " m |\n";
    out << "| f1 (FE, this scene) | " << (k.f1_hz > 0 ? hz(k.f1_hz) + " Hz" : std::string("none")) << " |\n";
    out << "| f2 (FE, free–free over L) | " << (k.f2_fe_hz > 0 ? hz(k.f2_fe_hz) + " Hz" : std::string("not computed"))
        << " |\n";
    out << "| f2 (Timoshenko beam, free–free over L) | " << hz(k.f2_beam_hz) << " Hz |\n";
    out << "| **k = f1/f2 (FE)** | " << (k.chuck_factor > 0 ? "**" + formatted("%.4f", k.chuck_factor) + "**" : "-")
        << " |\n";
    out << "| k with the beam f2 | " << (k.f1_hz > 0 ? formatted("%.4f", k.chuck_factor_beam) : std::string("-"))
        << " |\n\n";
}

// A free bare core: the flexural modulus ISO 11093-8 would report (I-13/I-14).
void iso_section(std::ostream& out, const IsoFlexuralTest& t) {
    out << "## Virtual ISO 11093-8 test\n\nThe flexural modulus the standard's free-hanging test reports from "
           "this run's first bending frequency, Ec = 7.88e-8 · f² · M · L⁴ · Q / Ic (I-13: N/mm² with M in kg/m, L in mm, Ic in mm⁴), "
           "Q = 82.66 · Ic / (Ac · L²) + 1 (I-14), beside the wall's E_z put in (docs/how-to/calibration.md).\n\n"
        << "| quantity | value |\n|---|---:|\n"
        << "| f_free (FE, first bending) | " << hz(t.f_free_hz) << " Hz |\n"
        << "| M = ρc·Ac | " << significant(t.mass_per_length) << " kg/m |\n"
        << "| L | " << significant(t.length_m) << " m |\n"
        << "| Q (I-14) | " << formatted("%.5f", t.Q) << " |\n"
        << "| **Ec by ISO 11093-8 (I-13)** | **" << significant(t.flexural_modulus_pa / 1e6, 5) << " N/mm²** |\n"
        << "| E_z put in | " << significant(t.E_z_pa / 1e6, 5) << " N/mm² |\n"
        << "| difference Ec / E_z − 1 | " << formatted("%+.2f", 100 * t.difference) << " % |\n\n";
    for (const std::string& n : t.notes) out << "Note: " << n << ".\n\n";
}

// The answers first (report.html shows this table at the top): f1, k, the
// safe speeds and whether the mode count is proven; the sections below say
// how each was found.
void summary_section(std::ostream& out, const RunReport& r) {
    const RollSpeeds speeds = report_speeds(r);
    out << "## Summary\n\n| result | value |\n|---|---:|\n";
    out << "| first bending frequency f1 (FE) | "
        << (r.beam.fe_found() ? hz(r.beam.fe_first_bending_hz) + " Hz" : std::string("none found (see Beam theory)"))
        << " |\n";
    if (r.chuck && r.chuck->chuck_factor > 0)
        out << "| chuck factor k = f1/f2 (FE) | " << formatted("%.4f", r.chuck->chuck_factor) << " |\n";
    if (speeds.given()) {
        for (const SafeSpeed& v : speeds.safe)
            out << "| safe web speed, I-5 with safe = " << significant(v.safe) << " | " << web_speed(v.v_safe_m_s)
                << " |\n";
        if (speeds.koenig)
            out << "| König's critical speed v_krit | " << web_speed(speeds.koenig->speed.v_krit_m_s) << " |\n";
    } else {
        out << "| safe web speed | not given: " << speeds.not_given << " |\n";
    }
    out << "| modes found | " << r.modes.modes.size() << ", "
        << (r.modes.verification.complete ? "none missed" : "INCOMPLETE") << " (see Model and verification)"
        << " |\n\n";
}

void speed_section(std::ostream& out, const RunReport& r) {
    const Scene& s = r.scene;
    const RollSpeeds speeds = report_speeds(r);
    out << "## Speeds\n\n";
    if (!speeds.given()) {
        out << "Not given: " << speeds.not_given << ".\n\n";
        return;
    }
    out << "Safe web speed (I-5) v_safe = safe · π · Dp · f1, with f1 = " << hz(speeds.f1_hz)
        << " Hz (FE) and Dp = " << millimetres(speeds.dp_m) << " ("
        << (s.rest_paper ? "the rest paper's outer diameter" : "the core's outer diameter; no rest paper") << "):\n\n";
    out << "| safe | v_safe |\n|---:|---:|\n";
    for (const SafeSpeed& v : speeds.safe)
        out << "| " << significant(v.safe) << " | " << web_speed(v.v_safe_m_s) << " |\n";
    out << "\nIlomäki: safe 0.8 at most, 0.7 without a safety cage; it keeps the mid-span vibration within "
           "about ±5 mm.\n\n";
    if (!speeds.koenig) return;
    const KoenigSpeeds& k = *speeds.koenig;
    out << "König's critical speed ("
        << (k.formula == "K-1" ? "K-1, rest paper up to 10 mm" : "K-2, rest paper over 10 mm") << "; experience factor "
        << significant(k.experience) << ", l = " << significant(k.span.length_m) << " m " << k.span.source
        << "): f_krit = " << significant(k.speed.f_krit_hz) << " Hz, v_krit = " << web_speed(k.speed.v_krit_m_s) << ".";
    if (k.v_krit_large_core_m_s)
        out << " König recommends " << significant(kKoenigExperienceLargeCore)
            << " for the 150/176 core (0.66 was fitted to 76 mm cores): v_krit × 0.55/0.66 = "
            << web_speed(*k.v_krit_large_core_m_s) << ".";
    out << "\n\n";
}

void rigid_section(std::ostream& out, const std::vector<ModeShift>& shifts) {
    out << "## Rigid against elastic chucks\n\nThe same scene on rigid clamps over the expanding elements; modes "
           "paired by type, n and order.\n\n";
    out << "| type | n | m | elastic mode | f [Hz] | rigid mode | f [Hz] | shift |\n"
           "|---|---:|---:|---:|---:|---:|---:|---:|\n";
    for (const ModeShift& m : shifts) {
        auto side = [](int index, double f) {
            return index ? std::to_string(index) + " | " + hz(f) : std::string("- | -");
        };
        out << "| " << m.type << " | " << m.n << " | " << m.m << " | " << side(m.elastic_index, m.elastic_hz) << " | "
            << side(m.rigid_index, m.rigid_hz) << " | "
            << (m.elastic_index && m.rigid_index ? formatted("%+.2f", m.shift_percent()) + " %" : std::string("-"))
            << " |\n";
    }
    out << "\n";
}

void picture_section(std::ostream& out, const RunPictures& p) {
    out << "## Pictures\n\n";
    if (!p.problem.empty()) {
        out << "No pictures: " << p.problem
            << ". Draw them later with `python3 -m coremodal run-plot DIR --modes 7,8` or open modes.xdmf in "
               "ParaView.\n\n";
        return;
    }
    if (!p.spectrum.empty()) out << "![frequencies by mode type](" << p.spectrum << ")\n\n";
    for (const ModePicture& m : p.modes) out << "![mode " << m.mode << "](" << m.file << ")\n\n";
    if (!p.frames.empty())  // the first bending mode swinging (run_pictures.hpp)
        out << "Mode " << p.frames_mode << " swinging" << (p.animation.empty() ? "" : " ([animated](" + p.animation + "))")
            << ":\n\n![mode " << p.frames_mode << " swinging](" << p.frames << ")\n\n";
}

void timing_section(std::ostream& out, const RunReport& r, const RunPictures& p) {
    const Timing& t = r.timing_s;
    out << "## Timings and resources\n\n| stage | wall time [s] |\n|---|---:|\n";
    auto row = [&](const char* name, double s) { out << "| " << name << " | " << formatted("%.2f", s) << " |\n"; };
    row("mesh", t.mesh);
    row("assemble", t.assemble);
    row("factor and solve (with verification)", t.factor_and_solve);
    row("classify", t.classify);
    if (r.chuck) row("chuck factor (free-span solve)", t.chuck_factor);
    row("total (before writing)", t.total);
    if (p.time_s > 0) row("pictures (python)", p.time_s);
    out << "\nPeak memory " << significant(r.peak_memory_mb) << " MB over " << r.mpi_ranks << " MPI rank"
        << (r.mpi_ranks == 1 ? "" : "s") << ".\n\n";
}

void notes_section(std::ostream& out, const RunReport& r) {
    if (!r.warnings.empty()) {
        out << "## Warnings\n\n";
        for (const auto& w : r.warnings) out << "- " << w << "\n";
        out << "\n";
    }
    if (!r.scene.assumptions.empty()) {
        out << "## Assumptions\n\n";
        for (const auto& a : r.scene.assumptions) out << "- " << a << "\n";
        out << "\n";
    }
}

}  // namespace

std::string run_report_markdown(const RunReport& r, const RunPictures& pictures) {
    std::ostringstream out;
    out << "# " << r.scene.name << "\n\n";
    if (!r.scene.description.empty()) out << r.scene.description << "\n\n";
    out << "coremodal " COREMODAL_VERSION " run of `" << r.scene.source_file << "`; every number below is also in "
        << "summary.json, modes.csv and modes.h5.\n\n";
    summary_section(out, r);
    scene_section(out, r.scene);
    model_section(out, r);
    mode_section(out, r);
    beam_section(out, r);
    if (r.chuck) chuck_section(out, *r.chuck);
    if (const auto iso = iso_flexural_test(r.scene, r.beam.fe_first_bending_hz)) iso_section(out, *iso);
    speed_section(out, r);
    if (!r.rigid_comparison.empty()) rigid_section(out, r.rigid_comparison);
    picture_section(out, pictures);
    timing_section(out, r, pictures);
    notes_section(out, r);
    return out.str();
}

}  // namespace coremodal
