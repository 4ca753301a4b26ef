// `coremodal beam`: beam-theory formulas, no mesh. (Being built: issue 4.)
#include "app/commands.hpp"

namespace coremodal {

Command add_beam_command(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("beam", "Beam-theory formulas of a case (no mesh)");
    cmd->allow_extras();
    return {cmd, [] { throw std::runtime_error("coremodal beam is not available yet"); return 1; }, false};
}

}  // namespace coremodal
