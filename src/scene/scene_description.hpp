// A resolved scene as text: every value a run will use, in SI with its unit,
// and where it came from (the case file, a default, the command line, or
// computed from other keys); then the effects the run simulates and the
// assumptions made. `coremodal check` prints it (app/check_command.cpp);
// it needs nothing but the Scene, so a run's own output can reuse it.
#pragma once

#include "scene/response_spec.hpp"
#include "scene/scene.hpp"

#include <set>
#include <string>
#include <string_view>

namespace coremodal {

// Which keys were given, as dotted paths in the style of a study's keys
// (docs/how-to/studies.md): "core.wall", "core.material.E_z", "supports.left",
// "supports.left.expanding.1.width" (items of an array of tables from 1).
struct KeySources {
    std::set<std::string> in_file;
    std::set<std::string> on_command_line;  // e.g. "model", "mesh.level"

    bool in_file_has(std::string_view path) const { return in_file.contains(std::string(path)); }
};

// The key paths of a case file's text. Reads the TOML only (nothing is
// validated; parse_case_text does that): text that is not TOML gives none.
KeySources key_sources(std::string_view case_text);

// One line per resolved value, "  [core] outer_diameter = 0.106 m   from wall = 0.015 m",
// grouped by table; every value a default filled in says so.
std::string describe_scene(const Scene& scene, const KeySources& sources);

// The effects the run simulates (Scene::effects(), the summary's vocabulary),
// one line each with what it is in this scene.
std::string describe_effects(const Scene& scene);

// The scene's assumptions (library values, chuck defaults), one per line.
std::string describe_assumptions(const Scene& scene);

// [damping], [excitation] and [response] as the forced response will use
// them (docs/how-to/response.md), one line each: the damping's base, families and
// single modes, the excitation, the speeds, the limit and the probes.
std::string describe_response(const ResponseSetup& setup);

}  // namespace coremodal
