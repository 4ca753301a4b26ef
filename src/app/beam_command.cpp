// `coremodal beam [CASE.toml] [--li 250mm] [--k 0.85] [--f-free 52Hz] ... [--json]`:
// the quick formulas of DOMAIN.md section 3 for one core or rest roll, and
// Euler–Bernoulli and Timoshenko beam frequencies. No mesh, no PETSc:
// it answers in milliseconds. Formulas: beam/formulas.hpp; docs/beam.md.
#include "app/commands.hpp"
#include "analyses/run/run.hpp"
#include "common/format.hpp"
#include "beam/beam_theory.hpp"
#include "beam/chuck_calibration.hpp"
#include "beam/formulas.hpp"
#include "common/error.hpp"
#include "scene/case_file.hpp"
#include "scene/materials_library.hpp"
#include "scene/units.hpp"

#include <toml++/toml.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace coremodal {
namespace {

struct BeamOptions {
    std::string case_file;
    std::map<std::string, std::string> raw;  // option name ("li") -> text as given
    std::string calibration;                 // --calibration FILE (coremodal calibrate)
    bool json = false;
};

struct QuantityOption {
    const char* name;  // without the dashes
    Dimension dimension;
    const char* help;
};

const std::vector<QuantityOption>& quantity_options() {
    static const std::vector<QuantityOption> options = {
        {"di", Dimension::length, "core inner diameter Di, e.g. 76mm (overrides the case)"},
        {"do", Dimension::length, "core outer diameter Do, e.g. 106mm"},
        {"lc", Dimension::length, "full core length Lc, e.g. 2211mm"},
        {"dp", Dimension::length, "rest roll outer diameter Dp, e.g. 300mm (adds rest paper to a bare core)"},
        {"li", Dimension::length, "core end to the middle of the furthest expanding element, e.g. 250mm"},
        {"chuck-depth", Dimension::length, "chuck insertion depth for König's l (default: the clamp zones' "
                                           "inner edges of the case, else Li)"},
        {"ec", Dimension::pressure, "core flexural modulus Ec, e.g. 6.5GPa"},
        {"rho-c", Dimension::density, "core density, e.g. 920kg/m^3"},
        {"ep", Dimension::pressure, "rest paper modulus Ep, e.g. 5GPa"},
        {"rho-p", Dimension::density, "rest paper density, e.g. 1350kg/m^3"},
        {"k", Dimension::dimensionless, "chuck factor k for I-7 (default 1; about 0.85 for good expanding chucks)"},
        {"safe", Dimension::dimensionless, "safety factor of the safe web speed I-5 (default 0.7; 0.7-0.8)"},
        {"koenig-factor", Dimension::dimensionless,
         "experience factor of König's K-1/K-2 (default 0.66; 0.55 recommended for 150/176 cores)"},
        {"f-free", Dimension::frequency,
         "measured free-hanging first bending frequency at full length Lc: gives f2, and Ec (I-13/14) for a "
         "bare core or Ep (I-15) for a rest roll"},
        {"f-clamped", Dimension::frequency, "measured first bending frequency in the stand: with --f-free gives "
                                            "the chuck factor k = f1/f2 (I-6)"},
    };
    return options;
}

class Inputs {
public:
    explicit Inputs(const BeamOptions& o) : options_(o) {}
    std::optional<double> get(const std::string& name) const {
        auto it = options_.raw.find(name);
        if (it == options_.raw.end()) return std::nullopt;
        Dimension d = Dimension::dimensionless;
        for (const auto& q : quantity_options())
            if (name == q.name) d = q.dimension;
        try {
            return parse_quantity(it->second, d);
        } catch (const std::invalid_argument& e) {
            throw InputError("--" + name + " " + it->second + ": " + e.what());
        }
    }

private:
    const BeamOptions& options_;
};


std::string mm(double metres) { return significant(metres * 1e3, 5) + " mm"; }

OrthotropicMaterial library(const char* name) {
    const LibraryMaterial* m = find_library_material(name);
    COREMODAL_ASSERT(m != nullptr);
    return to_material(*m);
}

struct Report {
    Scene scene;
    RestRollSection section;
    BeamSection beam;
    double Ic = 0, Ac = 0, Ip = 0, Ap = 0;
    double Lc = 0, Li = 0, L = 0;
    std::string li_source;
    double k = 1, f1 = 0;
    std::string k_source;  // "" for --k or the default
    std::optional<CalibrationGroups> groups;
    double eb_cc = 0, eb_ff = 0, timo_cc = 0, timo_ff = 0;
    std::string koenig_formula;
    double koenig_factor = 0.66, koenig_l = 0, paper_thickness = 0;
    std::string koenig_l_source;
    CriticalSpeed koenig;
    double safe = 0.7, v_safe = 0;
    std::optional<double> f_free, f_clamped, f2, Q, Ec_measured, Ep_measured, k_measured;
    std::vector<std::string> notes;
};

// k from a calibration file (coremodal calibrate; docs/calibration.md).
void apply_calibration(const std::string& file, bool k_given, Report& r) {
    if (k_given) throw InputError("--k and --calibration both give the chuck factor; expected one of them");
    const Calibration c = read_calibration(file);
    if (!c.passed)
        throw InputError(file + ": this calibration failed its own check (largest f1 error " +
                         significant(100 * std::max(c.max_error_fit, c.max_error_held_out)) + " % against the stated " +
                         significant(100 * c.stated_error) + " %); expected a calibration that passed (docs/calibration.md)");
    r.groups = calibration_groups(r.beam, r.section.Ec * r.Ic, r.Li, r.L);
    r.k = calibrated_k(c, *r.groups, r.L, r.Li, r.section.Dp, r.notes);
    if (r.k > 1) {
        r.notes.push_back("calibrated k = " + significant(r.k) + " > 1 taken as 1 (the rigid clamp)");
        r.k = 1;
    }
    r.k_source = "calibration " + file + " (case '" + c.case_name + "', " + std::to_string(c.n_fit) +
                 " points, I-7 within " + significant(100 * c.stated_error) + " % of FE)";
}

Report compute(const BeamOptions& options) {
    const Inputs in(options);
    Report r;
    Scene& s = r.scene;
    if (!options.case_file.empty()) {
        s = parse_case_file(options.case_file);
        print_scene_warnings(s);
    } else {
        if (!in.get("di") || !in.get("do") || !in.get("lc"))
            throw InputError("coremodal beam needs a case file, or at least --di, --do and --lc "
                             "(e.g. coremodal beam --di 76mm --do 106mm --lc 2211mm --li 35mm)");
        s.name = "(command-line options)";
        s.core.material = library("paperboard_core");
        s.assumptions.push_back("core material 'paperboard_core' assumed (Ec 6.5 GPa, 920 kg/m^3; "
                                "shear modulus G_thetaz 1.8 GPa for Timoshenko); --ec, --rho-c override");
    }
    const double case_length = s.core.length;  // clamp zones are placed from its ends
    if (auto v = in.get("di")) s.core.inner_diameter = *v;
    if (auto v = in.get("do")) s.core.outer_diameter = *v;
    if (auto v = in.get("lc")) s.core.length = *v;
    if (auto v = in.get("ec")) s.core.material.E_z = *v;
    if (auto v = in.get("rho-c")) s.core.material.density = *v;
    if (auto v = in.get("dp")) {
        if (!s.rest_paper) {
            s.rest_paper = RestPaperSpec{};
            s.rest_paper->material = library("rest_paper");
            s.assumptions.push_back("rest paper material 'rest_paper' assumed (Ep 5 GPa, 1350 kg/m^3; "
                                    "G_thetaz 1.5 GPa for Timoshenko); --ep, --rho-p override");
        }
        s.rest_paper->outer_diameter = *v;
    }
    if (s.rest_paper) {
        if (auto v = in.get("ep")) s.rest_paper->material.E_z = *v;
        if (auto v = in.get("rho-p")) s.rest_paper->material.density = *v;
    } else if (in.get("ep") || in.get("rho-p")) {
        throw InputError("--ep and --rho-p need rest paper: give --dp or a case file with [rest_paper]");
    }

    RestRollSection& sec = r.section;
    sec = rest_roll_section(s);
    if (s.rest_paper && !(sec.Dp > sec.Do))
        throw InputError("rest roll diameter Dp = " + mm(sec.Dp) + " must exceed the core outer diameter Do = " +
                         mm(sec.Do));
    r.Ac = tube_area(sec.Do, sec.Di);  // checks Di < Do
    r.Ic = tube_inertia(sec.Do, sec.Di);
    if (s.rest_paper) r.Ap = tube_area(sec.Dp, sec.Do), r.Ip = tube_inertia(sec.Dp, sec.Do);
    r.beam = beam_section(s);

    // Span: Li from the option, else the clamp zones' centres, else 0 (free).
    r.Lc = s.core.length;
    const bool clamped = s.supports.kind == SupportKind::clamped && s.supports.clamps.size() == 2;
    if (auto v = in.get("li")) {
        r.Li = *v, r.li_source = "--li";
    } else if (clamped) {
        const auto& a = s.supports.clamps[0];
        const auto& b = s.supports.clamps[1];
        const double left = 0.5 * (a.z_start + a.z_end), right = case_length - 0.5 * (b.z_start + b.z_end);
        r.Li = 0.5 * (left + right);
        r.li_source = "centres of the clamp zones";
        if (std::abs(left - right) > 1e-9)
            r.notes.push_back("clamp zone centres differ (" + mm(left) + " and " + mm(right) +
                              " from their ends): Li is their mean, L the distance between them");
    } else if (s.supports.kind == SupportKind::chucks) {
        const double left = s.supports.chucks.at(0).li(), right = s.supports.chucks.at(1).li();
        r.Li = 0.5 * (left + right);
        r.li_source = "the chucks' furthest expanding elements";
        if (std::abs(left - right) > 1e-9)
            r.notes.push_back("chuck Li differ (" + mm(left) + " and " + mm(right) + "): Li is their mean");
    } else {
        r.Li = 0, r.li_source = "none given: free core, L = Lc";
    }
    r.L = free_span(r.Lc, r.Li);

    r.k = in.get("k").value_or(1.0);
    if (!options.calibration.empty()) apply_calibration(options.calibration, in.get("k").has_value(), r);
    r.f1 = ilomaki_first_bending_hz(bending_stiffness(sec), mass_per_length(sec), r.L, r.k);
    r.eb_cc = euler_bernoulli_first_bending_hz(r.beam, r.L);
    r.eb_ff = euler_bernoulli_first_bending_hz(r.beam, r.Lc);
    r.timo_cc = timoshenko_bending_hz(r.beam, r.L, BeamEnds::clamped_clamped, 1).at(0);
    r.timo_ff = timoshenko_bending_hz(r.beam, r.Lc, BeamEnds::free_free, 1).at(0);

    // König: l = core length minus the chuck insertion depth at both ends.
    r.koenig_factor = in.get("koenig-factor").value_or(0.66);
    if (auto v = in.get("chuck-depth")) {
        r.koenig_l = free_span(r.Lc, *v), r.koenig_l_source = "--chuck-depth";
    } else if (clamped && options.raw.count("li") == 0) {
        const double left = s.supports.clamps[0].z_end, right = case_length - s.supports.clamps[1].z_start;
        r.koenig_l = r.Lc - left - right, r.koenig_l_source = "between the clamp zones' inner edges";
        if (!(r.koenig_l > 0)) throw InputError("the clamp zones leave no free core length for König's l");
    } else if (s.supports.kind == SupportKind::chucks && options.raw.count("li") == 0) {
        r.koenig_l = r.Lc - s.supports.chucks.at(0).inserted_length - s.supports.chucks.at(1).inserted_length;
        r.koenig_l_source = "between the chucks' inserted ends";
    } else {
        r.koenig_l = r.L, r.koenig_l_source = "insertion depth taken as Li (give --chuck-depth)";
    }
    r.paper_thickness = 0.5 * (sec.Dp - sec.Do);
    const KoenigEstimate koenig = koenig_critical_speed(sec, r.koenig_l, r.koenig_factor);
    r.koenig_formula = koenig.thin_paper ? "K-1" : "K-2";
    r.koenig = koenig.speed;
    if (sec.Di > 0.12 && !options.raw.count("koenig-factor"))
        r.notes.push_back("König recommends the experience factor 0.55 for the 150/176 core "
                          "(give --koenig-factor 0.55); 0.66 was fitted to 76 mm cores");

    r.safe = in.get("safe").value_or(0.7);
    r.v_safe = safe_web_speed(r.f1, sec.Dp, r.safe);
    if (r.safe > 0.8) r.notes.push_back("safe = " + significant(r.safe) + " is above Ilomäki's range 0.7-0.8");

    r.f_free = in.get("f-free");
    r.f_clamped = in.get("f-clamped");
    if (r.f_clamped && !r.f_free) throw InputError("--f-clamped needs --f-free to give the chuck factor k = f1/f2");
    if (r.f_free) {
        r.f2 = free_free_at_free_span_hz(*r.f_free, r.Lc, r.Li);
        if (r.f_clamped) r.k_measured = chuck_factor(*r.f_clamped, *r.f2);
        if (s.rest_paper) {
            r.Ep_measured = rest_paper_modulus(*r.f_free, sec, r.Lc);
        } else {
            r.Q = iso_free_free_shear_factor(r.Lc, r.Ic, r.Ac);
            r.Ec_measured = iso_flexural_modulus(*r.f_free, sec.rho_c * r.Ac, r.Lc, r.Ic, r.Ac);
            if (r.Lc < 8 * sec.Di)
                r.notes.push_back("ISO 11093-8 asks for a sample of at least 8 x Di = " + mm(8 * sec.Di) +
                                  "; Lc = " + mm(r.Lc));
        }
    }
    return r;
}

// The scene's assumptions that the beam formulas use: the axial modulus and
// density (every formula), G_thetaz and nu_thetaz (Timoshenko's kappa G A).
std::vector<std::string> beam_assumptions(const Scene& s) {
    std::vector<std::string> out;
    for (const auto& a : s.assumptions) {
        const bool material_value = a.find("': ") != std::string::npos;
        const bool used = a.find("': E_z =") != std::string::npos || a.find("': density =") != std::string::npos ||
                          a.find("': G_thetaz =") != std::string::npos ||
                          a.find("': nu_thetaz =") != std::string::npos;
        if (!material_value || used) out.push_back(a);
    }
    return out;
}

std::string speed(double v) { return significant(v) + " m/s (" + significant(v * 60) + " m/min)"; }

void print_text(const Report& r, std::ostream& out) {
    const Scene& s = r.scene;
    const RestRollSection& sec = r.section;
    out << "coremodal beam: " << s.name;
    if (!s.source_file.empty()) out << " (" << s.source_file << ")";
    out << "\n\nSection\n";
    out << "  core        Di " << mm(sec.Di) << ", Do " << mm(sec.Do) << ", Lc " << significant(r.Lc) << " m, Ec "
        << format_quantity(sec.Ec, Dimension::pressure) << ", rho_c " << significant(sec.rho_c) << " kg/m^3\n";
    out << "              Ic " << significant(r.Ic) << " m^4, Ac " << significant(r.Ac) << " m^2\n";
    if (s.rest_paper) {
        out << "  rest paper  Dp " << mm(sec.Dp) << " (" << mm(r.paper_thickness) << " thick), Ep "
            << format_quantity(sec.Ep, Dimension::pressure) << ", rho_p " << significant(sec.rho_p) << " kg/m^3\n";
        out << "              Ip " << significant(r.Ip) << " m^4, Ap " << significant(r.Ap) << " m^2\n";
    } else {
        out << "  rest paper  none (bare core, Dp = Do)\n";
    }
    out << "  EcIc + EpIp = " << significant(r.beam.EI) << " N m^2, rho_c Ac + rho_p Ap = " << significant(r.beam.rho_A)
        << " kg/m, kappa G A = " << significant(r.beam.kappa_GA) << " N (Cowper; for Timoshenko)\n";
    out << "\nSpan\n";
    out << "  Li = " << mm(r.Li) << " (" << r.li_source << "), free span L = Lc - 2 Li = " << significant(r.L) << " m\n";
    out << "\nFirst bending frequency\n";
    out << "  I-7  f1 = k 22.373/(2 pi L^2) sqrt((EcIc + EpIp)/(rho_c Ac + rho_p Ap)), k = " << significant(r.k) << ":  "
        << significant(r.f1) << " Hz\n";
    if (!r.k_source.empty())
        out << "       k from the " << r.k_source << ": g1 = " << significant(r.groups->g1) << ", g2 = " << significant(r.groups->g2)
            << ", g3 = " << significant(r.groups->g3) << "\n";
    out << "                      Euler-Bernoulli   Timoshenko\n";
    char line[160];
    std::snprintf(line, sizeof line, "  clamped-clamped, L   %9.4g Hz   %9.4g Hz\n", r.eb_cc, r.timo_cc);
    out << line;
    std::snprintf(line, sizeof line, "  free-free, Lc        %9.4g Hz   %9.4g Hz\n", r.eb_ff, r.timo_ff);
    out << line;
    out << "\nSpeeds\n";
    out << "  König " << r.koenig_formula << " (rest paper " << mm(r.paper_thickness)
        << (r.koenig_formula == "K-1" ? " <= 10 mm" : " > 10 mm") << "), experience factor " << significant(r.koenig_factor)
        << ", l = " << significant(r.koenig_l) << " m (" << r.koenig_l_source << "):\n";
    out << "      f_krit = " << significant(r.koenig.f_krit_hz) << " Hz, v_krit = " << speed(r.koenig.v_krit_m_s) << "\n";
    out << "  I-5  safe web speed v_safe = safe pi Dp f1, safe = " << significant(r.safe) << ": " << speed(r.v_safe) << "\n";
    if (r.f_free) {
        out << "\nFree-hanging measurement f_free = " << significant(*r.f_free) << " Hz at Lc = " << significant(r.Lc) << " m\n";
        out << "  f2 = f_free Lc^2/(Lc - 2 Li)^2 = " << significant(*r.f2) << " Hz\n";
        if (r.k_measured)
            out << "  I-6  k = f1/f2 = " << significant(*r.f_clamped) << "/" << significant(*r.f2) << " = " << significant(*r.k_measured) << "\n";
        if (r.Ec_measured)
            out << "  I-13/14  Q = 82.66 Ic/(Ac L^2) + 1 = " << significant(*r.Q, 5)
                << ", Ec = 7.88e-8 f^2 M L^4 Q/Ic = " << format_quantity(*r.Ec_measured, Dimension::pressure)
                << " (M = rho_c Ac = " << significant(sec.rho_c * r.Ac) << " kg/m)\n";
        if (r.Ep_measured)
            out << "  I-15  Ep (I-7 with k = 1 at Lc, solved for Ep) = "
                << format_quantity(*r.Ep_measured, Dimension::pressure) << "\n";
    }
    const auto assumed = beam_assumptions(s);
    if (!r.notes.empty() || !assumed.empty()) {
        out << "\nNotes\n";
        for (const auto& n : r.notes) out << "  - " << n << "\n";
        for (const auto& a : assumed) out << "  - " << a << "\n";
    }
}

void print_json(const Report& r, std::ostream& out) {
    const Scene& s = r.scene;
    const RestRollSection& sec = r.section;
    toml::table section{{"Di_m", sec.Di},          {"Do_m", sec.Do},
                        {"Dp_m", sec.Dp},          {"Ec_Pa", sec.Ec},
                        {"rho_c_kg_m3", sec.rho_c}, {"Ic_m4", r.Ic},
                        {"Ac_m2", r.Ac},           {"EI_N_m2", r.beam.EI},
                        {"mass_per_length_kg_m", r.beam.rho_A}, {"kappa_GA_N", r.beam.kappa_GA},
                        {"rho_I_kg_m", r.beam.rho_I}};
    if (s.rest_paper) {
        section.insert("Ep_Pa", sec.Ep);
        section.insert("rho_p_kg_m3", sec.rho_p);
        section.insert("Ip_m4", r.Ip);
        section.insert("Ap_m2", r.Ap);
        section.insert("rest_paper_thickness_m", r.paper_thickness);
    }
    toml::table i7{{"k", r.k}, {"f1_hz", r.f1}};
    if (!r.k_source.empty()) {
        i7.insert("k_source", r.k_source);
        i7.insert("g1", r.groups->g1);
        i7.insert("g2", r.groups->g2);
        i7.insert("g3", r.groups->g3);
    }
    toml::table t{
        {"case", s.name},
        {"source_file", s.source_file},
        {"section", section},
        {"span", toml::table{{"Lc_m", r.Lc}, {"Li_m", r.Li}, {"Li_source", r.li_source}, {"L_m", r.L}}},
        {"i7", i7},
        {"euler_bernoulli", toml::table{{"clamped_clamped_L_hz", r.eb_cc}, {"free_free_Lc_hz", r.eb_ff}}},
        {"timoshenko", toml::table{{"clamped_clamped_L_hz", r.timo_cc}, {"free_free_Lc_hz", r.timo_ff}}},
        {"koenig", toml::table{{"formula", r.koenig_formula},
                               {"experience_factor", r.koenig_factor},
                               {"l_m", r.koenig_l},
                               {"l_source", r.koenig_l_source},
                               {"f_krit_hz", r.koenig.f_krit_hz},
                               {"v_krit_m_s", r.koenig.v_krit_m_s}}},
        {"safe_web_speed", toml::table{{"safe", r.safe}, {"Dp_m", sec.Dp}, {"f1_hz", r.f1}, {"v_safe_m_s", r.v_safe}}},
    };
    if (r.f_free) {
        toml::table m{{"f_free_hz", *r.f_free}, {"f2_hz", *r.f2}};
        if (r.f_clamped) m.insert("f_clamped_hz", *r.f_clamped), m.insert("k", *r.k_measured);
        if (r.Ec_measured) m.insert("Q", *r.Q), m.insert("Ec_Pa", *r.Ec_measured);
        if (r.Ep_measured) m.insert("Ep_Pa", *r.Ep_measured);
        t.insert("free_free_measurement", m);
    }
    toml::array notes, assumptions;
    for (const auto& n : r.notes) notes.push_back(n);
    for (const auto& a : beam_assumptions(s)) assumptions.push_back(a);
    t.insert("notes", notes);
    t.insert("assumptions", assumptions);
    out << toml::json_formatter{t} << "\n";
}

}  // namespace

Command add_beam_command(CLI::App& app) {
    auto options = std::make_shared<BeamOptions>();
    CLI::App* cmd = app.add_subcommand(
        "beam", "Beam formulas of a core or rest roll (Ilomäki I-5..I-15, König K-1/K-2, Euler-Bernoulli, "
                "Timoshenko); no mesh");
    cmd->add_option("case", options->case_file,
                    "case file (TOML); optional when --di, --do and --lc are given");
    for (const auto& q : quantity_options()) {
        const std::string name = q.name;
        cmd->add_option_function<std::string>(
               "--" + name, [options, name](const std::string& v) { options->raw[name] = v; }, q.help)
            ->type_name("VALUE");
    }
    cmd->add_option("--calibration", options->calibration,
                    "chuck factor k from a calibration.toml written by coremodal calibrate (instead of --k)")
        ->type_name("FILE");
    cmd->add_flag("--json", options->json, "print the results as one JSON object");
    cmd->footer("Values carry units (\"--li 250mm\", \"--f-free 52Hz\", \"--ep 1.8GPa\"); options override the "
                "case file. Formulas and limits: docs/beam.md.");
    auto run = [options] {
        const Report r = compute(*options);
        std::ostringstream text;
        if (options->json) print_json(r, text);
        else print_text(r, text);
        std::cout << text.str() << std::flush;
        return 0;
    };
    return {cmd, run, false};
}

}  // namespace coremodal
