// Words joined for messages: "solid, harmonic, beam" (the case readers'
// "expected one of ...", the command line's).
#pragma once

#include <string>
#include <string_view>

namespace coremodal {

template <class Words>
std::string join(const Words& words, std::string_view separator = ", ") {
    std::string out;
    for (const auto& w : words) {
        if (!out.empty()) out += separator;
        out += w;
    }
    return out;
}

}  // namespace coremodal
