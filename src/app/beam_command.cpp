// `coremodal beam [CASE.toml] [--li 250mm] [--k 0.85] [--f-free 52Hz] ... [--json]`:
// the quick formulas of Ilomäki and König & Müller for one core or rest roll, and
// Euler–Bernoulli and Timoshenko beam frequencies. No mesh, no PETSc:
// it answers in milliseconds. The command line only: the analysis is
// analyses/formulas/beam_formulas.hpp, the output output/beam_formulas_report.hpp.
#include "analyses/formulas/beam_formulas.hpp"
#include "app/commands.hpp"
#include "common/error.hpp"
#include "output/beam_formulas_report.hpp"
#include "scene/units.hpp"

#include <chrono>
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
    const char* name;                                 // without the dashes
    std::optional<double> BeamFormulaInputs::*value;  // where it goes
    Dimension dimension;
    const char* help;
};

const std::vector<QuantityOption>& quantity_options() {
    using In = BeamFormulaInputs;
    static const std::vector<QuantityOption> options = {
        {"di", &In::di, Dimension::length, "core inner diameter Di, e.g. 76mm (overrides the case)"},
        {"do", &In::do_, Dimension::length, "core outer diameter Do, e.g. 106mm"},
        {"lc", &In::lc, Dimension::length, "full core length Lc, e.g. 2211mm"},
        {"dp", &In::dp, Dimension::length, "rest roll outer diameter Dp, e.g. 300mm (adds rest paper to a bare core)"},
        {"li", &In::li, Dimension::length, "core end to the middle of the furthest expanding element, e.g. 250mm"},
        {"chuck-depth", &In::chuck_depth, Dimension::length, "chuck insertion depth for König's l (default: the clamp zones' "
                                           "inner edges of the case, else Li)"},
        {"ec", &In::ec, Dimension::pressure, "core flexural modulus Ec, e.g. 6.5GPa"},
        {"rho-c", &In::rho_c, Dimension::density, "core density, e.g. 920kg/m^3"},
        {"ep", &In::ep, Dimension::pressure, "rest paper modulus Ep, e.g. 5GPa"},
        {"rho-p", &In::rho_p, Dimension::density, "rest paper density, e.g. 1350kg/m^3"},
        {"k", &In::k, Dimension::dimensionless, "chuck factor k for I-7 (default 1; about 0.85 for good expanding chucks)"},
        {"safe", &In::safe, Dimension::dimensionless, "safety factor of the safe web speed I-5 (default 0.7; 0.7-0.8)"},
        {"web-speed", &In::web_speed, Dimension::speed, "a web speed, e.g. 15m/s: the single-mode amplification d(r) there (I-2...4)"},
        {"zeta", &In::zeta, Dimension::dimensionless, "relative damping for --web-speed (default 0.01; cores 0.005-0.02)"},
        {"koenig-factor", &In::koenig_factor, Dimension::dimensionless,
         "experience factor of König's K-1/K-2 (default 0.66; 0.55 recommended for 150/176 cores)"},
        {"f-free", &In::f_free, Dimension::frequency,
         "measured free-hanging first bending frequency at full length Lc: gives f2, and Ec (I-13/14) for a "
         "bare core or Ep (I-15) for a rest roll"},
        {"f-clamped", &In::f_clamped, Dimension::frequency, "measured first bending frequency in the stand: with --f-free gives "
                                            "the chuck factor k = f1/f2 (I-6)"},
    };
    return options;
}

// The values given, parsed with their units (InputError naming the option).
BeamFormulaInputs parse_inputs(const BeamOptions& options) {
    BeamFormulaInputs in;
    in.case_file = options.case_file;
    in.calibration = options.calibration;
    for (const QuantityOption& q : quantity_options()) {
        const auto given = options.raw.find(q.name);
        if (given == options.raw.end()) continue;
        try {
            in.*q.value = parse_quantity(given->second, q.dimension);
        } catch (const std::invalid_argument& e) {
            throw InputError("--" + given->first + " " + given->second + ": " + e.what());
        }
    }
    return in;
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
                "case file. Formulas and limits: docs/theory/beam.md.");
    auto run = [options] {
        const auto start = std::chrono::steady_clock::now();
        const BeamFormulas r = beam_formulas(parse_inputs(*options));
        const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::ostringstream text;
        if (options->json) print_beam_formulas_json(r, seconds, text);
        else print_beam_formulas_text(r, text);
        std::cout << text.str() << std::flush;
        return 0;
    };
    return {cmd, run, false};
}

}  // namespace coremodal
