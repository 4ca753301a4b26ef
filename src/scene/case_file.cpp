// Case file (TOML) -> Scene. Every check of user input lives here; each
// failure is an InputError that points at the line and column of the value.
//
// Reading goes table by table: the keys of each table are first checked
// against the schema (case_schema.hpp: unknown keys, value kinds), then the
// values are read, converted to SI, range-checked and checked against each other.
// The reader (CaseReader) is scene/case_reader.hpp, one file per concept.
#include "scene/case_file.hpp"

#include "common/error.hpp"
#include "scene/case_name.hpp"
#include "scene/case_reader.hpp"
#include "scene/toml_text.hpp"

#include <toml++/toml.h>

#include <filesystem>

namespace coremodal {
namespace case_reading {

Scene CaseReader::read(const toml::table& root) {
    const Section top = open(root, "", "");
    Scene scene;
    scene.source_file = path_;
    scene.name = text(top, "name").value_or(std::filesystem::path(path_).stem().string());
    if (const std::string problem = case_name_problem(scene.name); !problem.empty()) {
        if (const toml::node* given = get(top, "name"))
            fail(*given, echo(top, "name", *given) + " " + problem + "; " + kCaseNameExpected);
        throw InputError(path_ + ": the case's name is its file name, '" + scene.name + "', which " + problem +
                         "; give the case a name = \"...\" (" + kCaseNameExpected + ")");
    }
    scene.description = text(top, "description").value_or("");
    if (const auto word = choice(top, "model", model_choice_words())) scene.model = *parse_model_choice(*word);
    scene.core = read_core(top, scene);
    scene.rest_paper = read_rest_paper(top, scene);
    scene.supports = read_supports(top, scene);
    scene.web = read_web(top, scene);
    scene.analysis = read_analysis(top);
    scene.mesh = read_mesh(top, scene);
    read_rotation(top, scene);  // checked with every key; parse_rotating_case keeps it
    read_response_setup(top, scene);  // likewise; parse_response_case keeps it
    std::vector<std::string> traction_assumptions;  // `coremodal traction` echoes them; run does not
    read_traction(top, traction_assumptions);       // checked; scene/traction_case.hpp keeps it
    read_limits(top, scene);          // likewise; parse_limits_case keeps it
    scene.warnings = warnings_;
    return scene;
}

}  // namespace case_reading

Scene parse_case_table(const toml::table& root, const std::string& path) {
    if (const toml::node* winder = root.get("winder"))
        throw InputError(path + ":" + std::to_string(winder->source().begin.line) +
                         ": [winder] is a two-drum winder file, not a roll's case file; run it with "
                         "`coremodal winder " + path + "` (docs/how-to/winder.md)");
    if (const toml::node* selection = root.get("selection"))
        throw InputError(path + ":" + std::to_string(selection->source().begin.line) +
                         ": [selection] is a core-selection file, not a roll's case file; run it with "
                         "`coremodal select " + path + "` (docs/how-to/durability.md)");
    if (const toml::node* traction = root.get("traction"); traction && !root.get("core"))
        throw InputError(path + ":" + std::to_string(traction->source().begin.line) +
                         ": [traction] without [core] is a roller's traction file, not a roll's case file; run it "
                         "with `coremodal traction " + path + "` (docs/how-to/traction.md)");
    return case_reading::CaseReader(path).read(root);
}

Scene parse_case_text(std::string_view text, const std::string& path) {
    const toml::table root = parse_toml_input(text, path, "a valid TOML case file (docs/reference/case-files.md)");
    try {
        return parse_case_table(root, path);
    } catch (const InputError& e) {  // a key echoed in a message: the user's characters
        throw InputError(restore_characters(e.what()));
    }
}

Scene parse_case_file(const std::string& path) { return parse_case_text(read_input_file(path, "case file"), path); }

}  // namespace coremodal
