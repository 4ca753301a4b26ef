// `coremodal schema`: print the case file's JSON Schema (draft-07), generated
// from the key table (scene/case_json_schema.hpp), for editors with TOML
// support; docs/case-files.md, "Editor support: the JSON Schema", says how
// to use it. Stdout, or the file named by --output (that file only).
#include "app/commands.hpp"
#include "common/error.hpp"
#include "scene/case_json_schema.hpp"

#include <fstream>
#include <iostream>
#include <memory>
#include <string>

namespace coremodal {
namespace {

int print_schema(const std::string& output) {
    const std::string schema = case_json_schema();
    if (output.empty()) {
        std::cout << schema;
        return std::cout ? 0 : 1;
    }
    std::ofstream file(output, std::ios::binary | std::ios::trunc);
    if (!(file << schema) || !(file.flush()))
        throw InputError("cannot write the schema to '" + output + "'; expected a writable file path");
    std::cout << "wrote the case-file JSON Schema to " << output << "\n";
    return 0;
}

}  // namespace

Command add_schema_command(CLI::App& app) {
    auto output = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand(
        "schema", "Print the case file's JSON Schema (draft-07) for editors with TOML support (taplo, Even Better TOML)");
    cmd->add_option("-o,--output", *output, "write it to this file (replaced) instead of stdout");
    return {cmd, [output] { return print_schema(*output); }, false};
}

}  // namespace coremodal
