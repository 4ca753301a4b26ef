// The message a case text is refused with, for tests of the case reader.
#pragma once

#include "common/error.hpp"
#include "scene/case_file.hpp"

#include <string>

namespace coremodal::testing {

// The InputError of parse_case_text on `text` (as file cases/x.toml), or
// "(no error)" when the text is accepted.
inline std::string error_of(const std::string& text) {
    try {
        parse_case_text(text, "cases/x.toml");
    } catch (const InputError& e) {
        return e.what();
    }
    return "(no error)";
}

}  // namespace coremodal::testing
