#include "scene/case_name.hpp"

namespace coremodal {

std::string case_name_problem(const std::string& name) {
    if (name.empty()) return "is empty";
    if (name == "." || name == "..") return "is '" + name + "', which as a folder name means a folder of the path (results/ itself or its parent), not a name of its own";
    if (name.find('/') != std::string::npos || name.find('\\') != std::string::npos)
        return "is a path, not a name (it would write outside results/)";
    for (const char c : name)
        if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) return "holds a control character";
    if (name.front() == '-') return "starts with '-' (it would read as an option on a command line)";
    if (name.size() > kMaxCaseNameBytes)
        return "is " + std::to_string(name.size()) + " bytes long, more than the " +
               std::to_string(kMaxCaseNameBytes) + " a folder name can take here";
    return "";
}

}  // namespace coremodal
