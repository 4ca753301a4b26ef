// `coremodal batch`: batch-theory case files in parallel processes. (Being built: issue 4.)
#include "app/commands.hpp"

namespace coremodal {

Command add_batch_command(CLI::App& app) {
    CLI::App* cmd = app.add_subcommand("batch", "Run many case files");
    cmd->allow_extras();
    return {cmd, [] { throw std::runtime_error("coremodal batch is not available yet"); return 1; }, false};
}

}  // namespace coremodal
