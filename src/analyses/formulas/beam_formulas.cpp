// beam_formulas in steps: the scene (case file and overrides), the section,
// the span, the frequencies, König's speed, the safe speed, a measurement.
#include "analyses/formulas/beam_formulas.hpp"

#include "effects/damping.hpp"

#include "beam/speeds.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "scene/case_file.hpp"
#include "scene/materials_library.hpp"
#include "common/warnings.hpp"

#include <cmath>

namespace coremodal {
namespace {

// Two support positions closer than this are the same (m): far below any
// length a case file gives.
constexpr double kSameLength = 1e-9;
// ISO 11093-8 asks for a free-hanging sample at least this many inner
// diameters long.
constexpr double kIsoMinSampleDiameters = 8;

std::string mm(double metres) { return significant(metres * 1e3, 5) + " mm"; }

OrthotropicMaterial library(const char* name) {
    const LibraryMaterial* m = find_library_material(name);
    COREMODAL_ASSERT(m != nullptr);
    return to_material(*m);
}

// The case's scene (or a bare core from di, do, lc), the values given set;
// `case_length`: its length before --lc (the clamp zones are placed from its ends).
Scene scene_of(const BeamFormulaInputs& in, double& case_length) {
    Scene s;
    if (!in.case_file.empty()) {
        s = parse_case_file(in.case_file);
        print_warnings(s.warnings);
    } else {
        if (!in.di || !in.do_ || !in.lc)
            throw InputError("coremodal beam needs a case file, or at least --di, --do and --lc "
                             "(e.g. coremodal beam --di 76mm --do 106mm --lc 2211mm --li 35mm)");
        s.name = "(command-line options)";
        s.core.material = library("paperboard_core");
        s.assumptions.push_back("core material 'paperboard_core' assumed (Ec 6.5 GPa, 920 kg/m^3; "
                                "shear modulus G_thetaz 1.8 GPa for Timoshenko); --ec, --rho-c override");
    }
    case_length = s.core.length;
    if (in.di) s.core.inner_diameter = *in.di;
    if (in.do_) s.core.outer_diameter = *in.do_;
    if (in.lc) s.core.length = *in.lc;
    if (in.ec) s.core.material.E_z = *in.ec;
    if (in.rho_c) s.core.material.density = *in.rho_c;
    if (in.dp) {
        if (!s.rest_paper) {
            s.rest_paper = RestPaperSpec{};
            s.rest_paper->material = library("rest_paper");
            s.assumptions.push_back("rest paper material 'rest_paper' assumed (Ep 5 GPa, 1350 kg/m^3; "
                                    "G_thetaz 1.5 GPa for Timoshenko); --ep, --rho-p override");
        }
        s.rest_paper->outer_diameter = *in.dp;
    }
    if (s.rest_paper) {
        if (in.ep) s.rest_paper->material.E_z = *in.ep;
        if (in.rho_p) s.rest_paper->material.density = *in.rho_p;
    } else if (in.ep || in.rho_p) {
        throw InputError("--ep and --rho-p need rest paper: give --dp or a case file with [rest_paper]");
    }
    return s;
}

void add_section(BeamFormulas& r) {
    const Scene& s = r.scene;
    RestRollSection& sec = r.section;
    sec = rest_roll_section(s);
    if (s.rest_paper && !(sec.Dp > sec.Do))
        throw InputError("rest roll diameter Dp = " + mm(sec.Dp) + " must exceed the core outer diameter Do = " +
                         mm(sec.Do));
    r.Ac = tube_area(sec.Do, sec.Di);  // checks Di < Do
    r.Ic = tube_inertia(sec.Do, sec.Di);
    if (s.rest_paper) r.Ap = tube_area(sec.Dp, sec.Do), r.Ip = tube_inertia(sec.Dp, sec.Do);
    r.beam = beam_section(s);
}

bool two_clamps(const Scene& s) { return s.supports.kind == SupportKind::clamped && s.supports.clamps.size() == 2; }

// Ilomäki's Li: from the option, else the clamp zones' centres, else the
// chucks' furthest expanding elements, else 0 (free). `case_length`: the
// length the clamp zones were placed on, from both ends.
void add_span(const BeamFormulaInputs& in, double case_length, BeamFormulas& r) {
    const Scene& s = r.scene;
    r.Lc = s.core.length;
    if (in.li) {
        r.Li = *in.li, r.li_source = "--li";
    } else if (two_clamps(s)) {
        const auto& a = s.supports.clamps[0];
        const auto& b = s.supports.clamps[1];
        const double left = 0.5 * (a.z_start + a.z_end), right = case_length - 0.5 * (b.z_start + b.z_end);
        r.Li = 0.5 * (left + right);
        r.li_source = "centres of the clamp zones";
        if (std::abs(left - right) > kSameLength)
            r.notes.push_back("clamp zone centres differ (" + mm(left) + " and " + mm(right) +
                              " from their ends): Li is their mean, L the distance between them");
    } else if (s.supports.kind == SupportKind::chucks) {
        const double left = s.supports.chucks.at(0).li(), right = s.supports.chucks.at(1).li();
        r.Li = 0.5 * (left + right);
        r.li_source = "the chucks' furthest expanding elements";
        if (std::abs(left - right) > kSameLength)
            r.notes.push_back("chuck Li differ (" + mm(left) + " and " + mm(right) + "): Li is their mean");
    } else {
        r.Li = 0, r.li_source = "none given: free core, L = Lc";
    }
    r.L = free_span(r.Lc, r.Li);
}

// k from a calibration file (coremodal calibrate; docs/how-to/calibration.md).
void apply_calibration(const std::string& file, bool k_given, BeamFormulas& r) {
    if (k_given) throw InputError("--k and --calibration both give the chuck factor; expected one of them");
    const Calibration c = read_calibration(file);
    if (!c.passed)
        throw InputError(file + ": this calibration failed its own check (largest f1 error " +
                         significant(100 * std::max(c.max_error_fit, c.max_error_held_out)) + " % against the stated " +
                         significant(100 * c.stated_error) + " %); expected a calibration that passed (docs/how-to/calibration.md)");
    r.groups = calibration_groups(r.beam, r.section.Ec * r.Ic, r.Li, r.L);
    r.k = calibrated_k(c, *r.groups, r.L, r.Li, r.section.Dp, r.notes);
    if (r.k > 1) {
        r.notes.push_back("calibrated k = " + significant(r.k) + " > 1 taken as 1 (the rigid clamp)");
        r.k = 1;
    }
    r.k_source = "calibration " + file + " (case '" + c.case_name + "', " + std::to_string(c.n_fit) +
                 " points, I-7 within " + significant(100 * c.stated_error) + " % of FE)";
}

void add_frequencies(const BeamFormulaInputs& in, BeamFormulas& r) {
    r.k = in.k.value_or(1.0);
    r.k_assumed = !in.k && in.calibration.empty();
    if (!in.calibration.empty()) apply_calibration(in.calibration, in.k.has_value(), r);
    r.f1 = ilomaki_first_bending_hz(bending_stiffness(r.section), mass_per_length(r.section), r.L, r.k);
    r.eb_cc = euler_bernoulli_first_bending_hz(r.beam, r.L);
    r.eb_ff = euler_bernoulli_first_bending_hz(r.beam, r.Lc);
    r.timo_cc = timoshenko_bending_hz(r.beam, r.L, BeamEnds::clamped_clamped, 1).at(0);
    r.timo_ff = timoshenko_bending_hz(r.beam, r.Lc, BeamEnds::free_free, 1).at(0);
}

// König: l = core length minus the chuck insertion depth at both ends
// (beam/speeds.hpp's koenig_span), --chuck-depth, else Li.
void add_koenig(const BeamFormulaInputs& in, double case_length, BeamFormulas& r) {
    const Scene& s = r.scene;
    r.koenig_factor = in.koenig_factor.value_or(kKoenigExperience);
    const std::optional<KoenigSpan> span = koenig_span(s);
    if (in.chuck_depth) {
        r.koenig_l = free_span(r.Lc, *in.chuck_depth), r.koenig_l_source = "--chuck-depth";
    } else if (two_clamps(s) && !in.li) {
        // koenig_span's rule, with each clamp zone at its distance from its end of the core.
        r.koenig_l = r.Lc - s.supports.clamps[0].z_end - (case_length - s.supports.clamps[1].z_start);
        r.koenig_l_source = span->source;
        if (!(r.koenig_l > 0)) throw InputError("the clamp zones leave no free core length for König's l");
    } else if (s.supports.kind == SupportKind::chucks && !in.li) {
        r.koenig_l = span->length_m, r.koenig_l_source = span->source;
    } else {
        r.koenig_l = r.L, r.koenig_l_source = "insertion depth taken as Li (give --chuck-depth)";
    }
    r.paper_thickness = 0.5 * (r.section.Dp - r.section.Do);
    const KoenigEstimate koenig = koenig_critical_speed(r.section, r.koenig_l, r.koenig_factor);
    r.koenig_formula = koenig.thin_paper ? "K-1" : "K-2";
    r.koenig = koenig.speed;
    if (r.section.Di > kKoenigLargeCore && !in.koenig_factor)
        r.notes.push_back("König recommends the experience factor " + significant(kKoenigExperienceLargeCore) +
                          " for the 150/176 core (give --koenig-factor " + significant(kKoenigExperienceLargeCore) +
                          "); " + significant(kKoenigExperience) + " was fitted to 76 mm cores");
}

void add_safe_speed(const BeamFormulaInputs& in, BeamFormulas& r) {
    const double lowest = kSafeFactors[0], highest = kSafeFactors[1];
    r.safe = in.safe.value_or(lowest);
    r.v_safe = safe_web_speed(r.f1, r.section.Dp, r.safe);
    if (r.safe > highest)
        r.notes.push_back("safe = " + significant(r.safe) + " is above Ilomäki's range " + significant(lowest) + "-" +
                          significant(highest));
}

// The field's middle damping ratio (Ilomäki I-1...I-4: 0.005-0.02), when
// --web-speed comes without --zeta (noted as assumed).
constexpr double kAssumedZeta = 0.01;

// I-2...4 at --web-speed: r = f_rot / f1, d(r).
void add_amplification(const BeamFormulaInputs& in, BeamFormulas& r) {
    if (in.zeta && !in.web_speed) throw InputError("--zeta needs --web-speed: the amplification is at a web speed");
    if (!in.web_speed) return;
    if (in.zeta && !(*in.zeta > 0 && *in.zeta < 1)) throw InputError("--zeta must lie between 0 and 1 (cores: 0.005-0.02)");
    SingleModeAmplification a;
    a.web_speed_m_s = *in.web_speed;
    a.f_rot_hz = *in.web_speed / (M_PI * r.section.Dp);
    a.ratio = a.f_rot_hz / r.f1;
    a.zeta = in.zeta.value_or(kAssumedZeta);
    a.zeta_assumed = !in.zeta;
    a.d = amplification(a.ratio, a.zeta);
    if (a.zeta_assumed)
        r.notes.push_back("zeta = " + significant(a.zeta) + " assumed for the amplification (cores and rest rolls: "
                          "0.005-0.02, Ilomäki; docs/reference/references.md); give --zeta");
    r.amplification = a;
}

// A free-hanging measurement: f2, k (with --f-clamped), Ec or Ep.
void add_measurement(const BeamFormulaInputs& in, BeamFormulas& r) {
    r.f_free = in.f_free;
    r.f_clamped = in.f_clamped;
    if (r.f_clamped && !r.f_free) throw InputError("--f-clamped needs --f-free to give the chuck factor k = f1/f2");
    if (!r.f_free) return;
    const RestRollSection& sec = r.section;
    r.f2 = free_free_at_free_span_hz(*r.f_free, r.Lc, r.Li);
    if (r.f_clamped) r.k_measured = chuck_factor(*r.f_clamped, *r.f2);
    if (r.scene.rest_paper) {
        r.Ep_measured = rest_paper_modulus(*r.f_free, sec, r.Lc);
        return;
    }
    r.Q = iso_free_free_shear_factor(r.Lc, r.Ic, r.Ac);
    r.Ec_measured = iso_flexural_modulus(*r.f_free, sec.rho_c * r.Ac, r.Lc, r.Ic, r.Ac);
    if (r.Lc < kIsoMinSampleDiameters * sec.Di)
        r.notes.push_back("ISO 11093-8 asks for a sample of at least 8 x Di = " +
                          mm(kIsoMinSampleDiameters * sec.Di) + "; Lc = " + mm(r.Lc));
}

}  // namespace

BeamFormulas beam_formulas(const BeamFormulaInputs& in) {
    BeamFormulas r;
    double case_length = 0;
    r.scene = scene_of(in, case_length);
    add_section(r);
    add_span(in, case_length, r);
    add_frequencies(in, r);
    add_koenig(in, case_length, r);
    add_safe_speed(in, r);
    add_amplification(in, r);
    add_measurement(in, r);
    return r;
}

// The scene's assumptions that the beam formulas use: the axial modulus and
// density (every formula), G_thetaz and nu_thetaz (Timoshenko's kappa G A).
std::vector<std::string> beam_formula_assumptions(const Scene& s) {
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

}  // namespace coremodal
