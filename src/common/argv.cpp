#include "common/argv.hpp"

namespace coremodal {
namespace {

bool is_petsc_option(const std::string& a) {
    return a.size() > 2 && a[0] == '-' && a[1] != '-' && a.find('_') != std::string::npos;
}
bool is_option_value(const std::string& a) {
    return !a.empty() && a[0] != '-' && a.find(".toml") == std::string::npos;
}

}  // namespace

SplitArguments split_petsc_arguments(int argc, const char* const* argv) {
    SplitArguments s;
    s.ours.push_back(argv[0]);
    s.petsc.push_back(argv[0]);
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (is_petsc_option(a)) {
            s.petsc.push_back(a);
            if (i + 1 < argc && is_option_value(argv[i + 1])) s.petsc.push_back(argv[++i]);
        } else {
            s.ours.push_back(a);
        }
    }
    return s;
}

}  // namespace coremodal
