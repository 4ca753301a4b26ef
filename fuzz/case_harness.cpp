#include "case_harness.hpp"

#include "analyses/fit/measurements.hpp"
#include "beam/beam_model.hpp"
#include "common/error.hpp"
#include "scene/case_file.hpp"
#include "scene/case_parameters.hpp"
#include "scene/response_spec.hpp"
#include "scene/scene_description.hpp"
#include "scene/traction_case.hpp"
#include "scene/toml_text.hpp"
#include "analyses/select/weight_limit.hpp"
#include "traction/traction_sweep.hpp"
#include "winder/winder_model.hpp"
#include "winder/winder_modes.hpp"
#include "winder/winder_scene.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace coremodal::fuzz {
namespace {

void check(bool ok, const std::string& what) {
    if (!ok) throw std::logic_error("fuzz invariant broken: " + what);
}

void check_modes(const BeamModelResult& result) {
    for (const BeamMode& mode : result.modes) {
        check(std::isfinite(mode.eigenvalue), "an eigenvalue that is not a finite number");
        check(std::isfinite(mode.frequency_hz), "a frequency that is not a finite number");
    }
}

// A [winder] file: its reader, then its model at the smallest and largest
// roll diameter (the whole sweep would cost a fuzzer 50 solves an input).
// The model is made small first: its dense solve grows as the cube of the
// DOFs, and case 11's 664 took over 10 s under the sanitizers — a "hang" to
// libFuzzer. Fewer elements and at most two rolls keep every branch of the
// model's construction.
Outcome run_winder_text(std::string_view text, const std::string& path) {
    WinderScene scene;
    try {
        scene = read_winder_text(text, path);
    } catch (const InputError&) {
        return Outcome::invalid;
    }
    scene.drums.elements = std::min(scene.drums.elements, 6);
    scene.rider.elements = std::min(scene.rider.elements, 4);
    scene.rolls.count = std::min(scene.rolls.count, 2);
    try {
        for (double d : {scene.rolls.diameter_start, scene.rolls.diameter_end}) {
            const WinderModes modes = solve_winder_modes(build_winder_model(scene, d), scene.damping,
                                                         scene.sweep.max_frequency);
            for (const WinderMode& m : modes.modes)
                check(std::isfinite(m.frequency_hz), "a winder frequency that is not a finite number");
        }
    } catch (const InputError&) {
        return Outcome::not_solvable;
    } catch (const SolveError&) {
        return Outcome::not_solvable;
    }
    return Outcome::solved;
}

// The case a fuzzed measurements file's parameters are resolved against (its
// own `case = ...` files are on disk, not in the input): Ilomäki's rest roll
// of cases/validation/ilomaki-web-cut.toml with an elastic bearing and the
// web of case 15, so that every family of key a fit may vary is there.
constexpr std::string_view kFitCase = R"(name = "fit-case"
model = "beam"
[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "2211 mm"
material = "paperboard_core"
[rest_paper]
thickness = "4 mm"
material = "rest_paper"
[supports]
type = "chucks"
[supports.left]
inserted_length = "106 mm"
clearance = "0.5 mm"
shaft_diameter = "60 mm"
shaft_length = "150 mm"
expansion_pressure = "6 bar"
[[supports.left.expanding]]
center = "70 mm"
width = "60 mm"
[supports.left.bearing]
radial_stiffness = "200 kN/mm"
tilting_stiffness = "1 MN*m/rad"
frame_mass = "80 kg"
frame_stiffness = "50 kN/mm"
[web]
tension = "300 N/m"
span = "1.2 m"
angle = "0 deg"
thickness = "80 um"
modulus = "5 GPa"
[analysis]
modes = 4
)";

// How far a fit moves a parameter without bounds of its own (analyses/fit/fit.cpp).
constexpr double kFitBoundFactor = 10.0;

// A fit's measurements file (`coremodal fit`): its reader, then each
// parameter resolved against kFitCase and the scene at the two ends of the
// range the fit would search, each read (or refused) and solved at the beam
// level: the places a fit's search can take a case to.
Outcome run_fit_text(std::string_view text, const std::string& path) {
    FitInput in;
    try {
        in = parse_fit_input(std::string(text), path);
    } catch (const InputError&) {
        return Outcome::invalid;
    }
    for (const Measurement& m : in.measurements) {
        check(std::isfinite(m.frequency_hz) && m.frequency_hz > 0, "a measured frequency that is not positive");
        check(std::isfinite(m.uncertainty_hz) && m.uncertainty_hz > 0, "an uncertainty that is not positive");
        check(!m.case_file.empty(), "a measurement without its case");
    }
    Outcome outcome = Outcome::solved;
    for (size_t j = 0; j < in.parameters.size(); ++j) {
        const FitParameterSpec& spec = in.parameters[j];
        try {
            const CaseParameters c = CaseParameters::from_text(std::string(kFitCase), "fit-case.toml", {spec.key},
                                                               {KeySource{in.parameter_nodes[j], path}}, "beam");
            const CaseParameter& p = c.parameters().front();
            const double low = spec.min.value_or(std::max(p.min, p.value / kFitBoundFactor));
            const double high = spec.max.value_or(std::min(p.max, p.value * kFitBoundFactor));
            for (double v : {low, high}) check_modes(solve_beam_model(c.scene({v})));
        } catch (const InputError&) {
            outcome = Outcome::not_solvable;
        } catch (const SolveError&) {
            outcome = Outcome::not_solvable;
        }
    }
    return outcome;
}

// A [selection] file: its reader (durability files named relative to
// `path`), then every stand's weight limit and the reels' masses, all finite.
Outcome run_selection_text(std::string_view text, const std::string& path) {
    SelectionScene scene;
    try {
        scene = read_selection_text(std::string(text), path);
    } catch (const InputError&) {
        return Outcome::invalid;
    }
    // The weight limits and reel masses; the width limit runs the limits
    // verdict (analyses/limits: the solver stack this project does not
    // link), so it is left to the tests of analyses/select.
    try {
        for (const Stand& stand : scene.stands)
            for (const CoreGrade& core : scene.cores) {
                if (!stand.takes(core.name)) continue;
                const WeightLimit w = core_weight_limit(core, stand, scene);
                check(std::isfinite(w.weight_n) && w.weight_n >= 0, "a weight limit that is not finite");
                const double mass = paper_roll_mass(core, stand.roll_diameter, 1.0, scene.paper_density);
                check(std::isfinite(mass) && mass > 0, "a roll mass per metre that is not finite and positive");
            }
        for (const Reel& reel : scene.reels)
            for (const CoreGrade& core : scene.cores)
                check(std::isfinite(paper_roll_mass(core, reel.diameter, reel.width, scene.paper_density)),
                      "a reel mass that is not finite");
    } catch (const InputError&) {
        return Outcome::not_solvable;
    }
    return Outcome::solved;
}

// A file with [traction] (docs/how-to/traction.md): its reader (the whole scene too
// when it describes a roll), then the model at every speed: finite,
// non-negative traction, f_e between 0 and f, a zero-traction speed.
Outcome run_traction_text(std::string_view text, const std::string& path) {
    std::optional<TractionCase> tc;
    try {
        tc = read_traction_case_text(text, path);
    } catch (const InputError&) {
        return Outcome::invalid;
    }
    const TractionSweep sweep = run_traction_sweep(tc->spec);
    for (const TractionPoint& p : sweep.points) {
        check(std::isfinite(p.traction) && p.traction >= 0, "a traction that is not a finite number >= 0");
        check(p.effective_friction >= 0 && p.effective_friction <= tc->spec.friction * (1 + 1e-12),
              "an effective friction outside [0, f]");
    }
    check(sweep.zero_traction_speed >= 0 && std::isfinite(sweep.zero_traction_speed),
          "a zero-traction speed that is not a finite number >= 0");
    return Outcome::solved;
}

// Only name, description and [traction]: a file for `coremodal traction` alone.
bool is_traction_text(std::string_view text) {
    try {
        const toml::table root = parse_toml_text(text, "fuzz.toml");
        if (!root.contains("traction")) return false;
        for (const auto& [key, value] : root)
            if (key.str() != "name" && key.str() != "description" && key.str() != "traction") return false;
        return true;
    } catch (const std::exception&) {
        return false;  // not TOML: the case reader says why
    }
}

// Which reader a fuzzed text is for, by its top-level tables: a winder file
// has [winder], a selection file [selection], a fit's measurements file
// [[measurement]] or parameters, a traction file [traction] alone, a case
// file anything else (its reader says what is wrong).
enum class InputKind { case_file, winder, fit, selection, traction };

InputKind kind_of(std::string_view text) {
    try {
        const toml::table root = parse_toml_text(text, "fuzz.toml");
        if (root.contains("winder")) return InputKind::winder;
        if (root.contains("selection")) return InputKind::selection;
        if (!root.contains("core") && (root.contains("measurement") || root.contains("parameters")))
            return InputKind::fit;
    } catch (const std::exception&) {
        // not TOML: the case reader says why
    }
    return is_traction_text(text) ? InputKind::traction : InputKind::case_file;
}

}  // namespace

Outcome run_case_text(std::string_view text, const std::string& path) {
    switch (kind_of(text)) {
        case InputKind::winder: return run_winder_text(text, path);
        case InputKind::fit: return run_fit_text(text, path);
        case InputKind::selection: return run_selection_text(text, path);
        case InputKind::traction: return run_traction_text(text, path);
        case InputKind::case_file: break;
    }
    Scene scene;
    try {
        scene = parse_case_text(text, path);
    } catch (const InputError&) {
        return Outcome::invalid;
    }
    // What `coremodal check` prints for a valid scene must never fail.
    const std::string described = describe_scene(scene, key_sources(text)) + describe_effects(scene) +
                                  describe_assumptions(scene);
    check(!described.empty(), "an empty scene description");
    // Likewise the forced response's tables (read again: the scene reader checked them).
    if (const std::optional<ResponseSetup> response = parse_response_case_text(text, path).response)
        check(!describe_response(*response).empty(), "an empty response description");
    try {
        check_modes(solve_beam_model(scene));
    } catch (const InputError&) {
        return Outcome::not_solvable;
    } catch (const SolveError&) {
        return Outcome::not_solvable;
    }
    return Outcome::solved;
}

}  // namespace coremodal::fuzz
