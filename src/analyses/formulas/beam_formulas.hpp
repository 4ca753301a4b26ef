// `coremodal beam`'s analysis: the quick formulas of Ilomäki and König & Müller for
// one core or rest roll (Ilomäki I-5..I-15, König K-1/K-2) and Euler–Bernoulli
// and Timoshenko beam frequencies, from a case file and/or values given on
// the command line. No mesh, no PETSc. Formulas: beam/formulas.hpp; docs/theory/beam.md.
#pragma once

#include "beam/beam_theory.hpp"
#include "beam/chuck_calibration.hpp"
#include "beam/formulas.hpp"
#include "scene/scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The values given (SI units), each overriding the case file's; none given: the case's.
struct BeamFormulaInputs {
    std::string case_file;    // "" = the scene from di, do and lc alone
    std::string calibration;  // calibration.toml for k ("" = none)
    std::optional<double> di, do_, lc, dp, li, chuck_depth, ec, rho_c, ep, rho_p;
    std::optional<double> k, safe, koenig_factor, f_free, f_clamped;
    std::optional<double> web_speed, zeta;  // the single-mode amplification at that web speed (I-2...4)
};

// I-2...4 at one web speed: the roll's first bending mode alone, driven at
// f_rot = v / (pi Dp) by a load of constant amplitude (docs/how-to/response.md for
// the whole network).
struct SingleModeAmplification {
    double web_speed_m_s = 0, f_rot_hz = 0, ratio = 0, zeta = 0, d = 0;
    bool zeta_assumed = false;
};

struct BeamFormulas {
    Scene scene;
    RestRollSection section;
    BeamSection beam;
    double Ic = 0, Ac = 0, Ip = 0, Ap = 0;
    double Lc = 0, Li = 0, L = 0;
    std::string li_source;
    double k = 1, f1 = 0;
    std::string k_source;  // "" for --k or the default
    // Neither --k nor --calibration: k = 1, the rigid clamp at Li. An upper
    // bound, said in the output (the chucks and the stand give 0.7-0.85).
    bool k_assumed = false;
    std::optional<CalibrationGroups> groups;
    double eb_cc = 0, eb_ff = 0, timo_cc = 0, timo_ff = 0;
    std::string koenig_formula;
    double koenig_factor = 0, koenig_l = 0, paper_thickness = 0;
    std::string koenig_l_source;
    CriticalSpeed koenig;
    double safe = 0, v_safe = 0;
    std::optional<SingleModeAmplification> amplification;
    std::optional<double> f_free, f_clamped, f2, Q, Ec_measured, Ep_measured, k_measured;
    std::vector<std::string> notes;
};

// InputError for inputs that do not make a roll (e.g. Dp <= Do, --f-clamped without --f-free).
BeamFormulas beam_formulas(const BeamFormulaInputs& inputs);

// The scene's assumptions that the beam formulas use: the axial modulus and
// density (every formula), G_thetaz and nu_thetaz (Timoshenko's kappa G A).
std::vector<std::string> beam_formula_assumptions(const Scene& scene);

}  // namespace coremodal
