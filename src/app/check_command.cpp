// `coremodal check CASE.toml`: read and validate a case exactly as `run`
// does, then say what `run` would simulate — every resolved value and where
// it came from, the effects, the model level and why — without meshing,
// solving or starting PETSc. Exit 0: valid; 1: the error `run` would give.
#include "analyses/batch/batch.hpp"  // is_winder_file, is_selection_file, is_fit_file
#include "analyses/fit/measurements.hpp"
#include "app/commands.hpp"
#include "models/choose.hpp"  // level_choice_text, require_axisymmetric
#include "common/warnings.hpp"
#include "scene/case_file.hpp"
#include "scene/mesh_levels.hpp"
#include "scene/response_spec.hpp"
#include "scene/scene_description.hpp"
#include "scene/toml_text.hpp"
#include "output/traction_report.hpp"
#include "output/winder_report.hpp"
#include "scene/traction_case.hpp"
#include "selection/selection_scene.hpp"
#include "winder/winder_scene.hpp"

#include <iostream>
#include <set>

namespace coremodal {
namespace {

struct CheckOptions {
    std::string case_file;
    std::string model;       // "" = the case's
    std::string mesh_level;  // "" = the case's
};

// The model level `run` would use, and why (models/choose.hpp).
std::string model_choice(const Scene& scene, const KeySources& sources) {
    const std::string given = sources.on_command_line.contains("model") ? "--model " + to_string(scene.model)
                              : sources.in_file_has("model")            ? "model = \"" + to_string(scene.model) + "\" in the file"
                                                                        : "the default: the file has no model key";
    return level_choice_text(scene, given);
}

// A two-drum winder file (docs/how-to/winder.md): its own reader, its beam model.
int check_winder(const CheckOptions& options) {
    const WinderScene scene = read_winder_file(options.case_file);
    std::cout << options.case_file << ": valid two-drum winder file \"" << scene.name << "\"\n\n"
              << "model level: beam (drums, rolls and rider as Timoshenko beams, nips as distributed springs; "
                 "--model and --mesh do not apply); run it with `coremodal winder`\n\n"
              << "resolved scene (SI units):\n"
              << winder_scene_description(scene);
    return 0;
}

// A file for `coremodal traction` alone (docs/how-to/traction.md): its [traction] only.
int check_traction(const CheckOptions& options, const TractionCase& tc) {
    print_warnings(tc.warnings);
    std::cout << options.case_file << ": valid traction file \"" << tc.name << "\"\n\n"
              << "model: Rice & Gans' web-to-roller traction (closed forms; --model and --mesh do not apply); run it "
                 "with `coremodal traction`\n\n"
              << "resolved roller and web (SI units):\n"
              << traction_check_text(tc);
    return 0;
}

// A core-selection file (docs/how-to/durability.md): its own reader, beam formulas.
int check_selection(const CheckOptions& options) {
    const SelectionScene scene = read_selection_file(options.case_file);
    std::cout << options.case_file << ": valid core-selection file \"" << scene.name << "\": " << scene.cores.size()
              << " core grade(s), " << scene.stands.size() << " stand(s), " << scene.reels.size()
              << " reel(s); run it with `coremodal select` (--model and --mesh do not apply)\n";
    if (!scene.defaults.empty()) std::cout << "\ndefaults used (not in the file):\n";
    for (const std::string& d : scene.defaults) std::cout << "  " << d << "\n";
    return 0;
}

// A fit's measurements file (docs/how-to/calibration.md, "Fitting the model"): its
// own reader; the cases it names are checked by `coremodal check` on each.
int check_fit(const CheckOptions& options) {
    const FitInput in = read_fit_input(options.case_file);
    std::cout << options.case_file << ": valid fit measurements file: " << in.parameters.size() << " parameter(s), "
              << in.measurements.size() << " measurement(s); run it with `coremodal fit`\n\nmeasured cases:\n";
    std::set<std::string> cases;
    for (const Measurement& m : in.measurements) cases.insert(m.case_file);
    for (const std::string& c : cases) std::cout << "  " << c << "\n";
    return 0;
}

int check_case(const CheckOptions& options) {
    if (is_winder_file(options.case_file)) return check_winder(options);
    if (is_selection_file(options.case_file)) return check_selection(options);
    if (is_fit_file(options.case_file)) return check_fit(options);
    const std::optional<TractionCase> traction = read_traction_case(options.case_file);
    if (traction && !traction->has_roll) return check_traction(options, *traction);
    // The same reading as run_case's step 1, so that the same errors come out.
    Scene scene = parse_case_file(options.case_file);
    print_warnings(scene.warnings);  // on stderr, as `run` says them
    KeySources sources = key_sources(read_input_file(options.case_file, "case file"));
    if (!options.mesh_level.empty()) {
        apply_mesh_level(scene, options.mesh_level);
        sources.on_command_line.insert("mesh.level");
    }
    if (!options.model.empty()) {
        scene.model = model_option(options.model);
        sources.on_command_line.insert("model");
    }
    if (level_traits(chosen_level(scene)).axisymmetric_only) require_axisymmetric(scene);

    std::cout << options.case_file << ": valid case \"" << scene.name << "\"\n\n"
              << "model level: " << model_choice(scene, sources) << "\n\n"
              << "effects the run simulates:\n"
              << describe_effects(scene) << "\n"
              << "resolved scene (SI units; last column: where each value comes from):\n"
              << describe_scene(scene, sources) << "\n"
              << "assumptions (the run summary echoes them):\n"
              << describe_assumptions(scene);
    if (const std::optional<ResponseSetup> response = parse_response_case(options.case_file).response)
        std::cout << "\nforced response (docs/how-to/response.md):\n" << describe_response(*response);
    if (traction)
        std::cout << "\nweb-to-roller traction ([traction], docs/how-to/traction.md; `coremodal traction` runs it):\n"
                  << traction_check_text(*traction);
    return 0;
}

}  // namespace

Command add_check_command(CLI::App& app) {
    auto options = std::make_shared<CheckOptions>();
    CLI::App* cmd = app.add_subcommand(
        "check", "Read and validate a case file; print the resolved scene, its effects and the model level (no solve)");
    cmd->add_option("case", options->case_file, "case file (TOML)")->required();
    cmd->add_option("-m,--mesh", options->mesh_level, "mesh level, as for run: coarse, default, fine, very_fine");
    cmd->add_option("--model", options->model, "model level, as for run: solid, harmonic, coupled, auto, beam")
        ->check(CLI::IsMember(model_words()));
    return {cmd, [options] { return check_case(*options); }, false};
}

}  // namespace coremodal
