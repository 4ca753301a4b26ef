// Reading a case from a TOML document already parsed (and perhaps edited: a
// study point is the case's document with some keys changed,
// scene/case_sweep.hpp). Kept apart from case_file.hpp so that only the few
// files that hold a toml++ document pay for its header.
#pragma once

#include "scene/response_spec.hpp"
#include "scene/scene.hpp"

#include <toml++/toml.h>

#include <string>

namespace coremodal {

// As parse_case_text. Values inserted by an edit carry no line number; their
// messages name the file only.
Scene parse_case_table(const toml::table& root, const std::string& path);
// As parse_response_case_text (the scene, [rotation] and the response setup).
ResponseCase parse_response_case_table(const toml::table& root, const std::string& path);

}  // namespace coremodal
