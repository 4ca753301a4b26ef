// `coremodal schema [--winder | --fit]`: print the JSON Schema (draft-07) of
// the case file, generated from the key table (scene/case_json_schema.hpp),
// of a two-drum winder file (winder/winder_scene.hpp) or of a fit's
// measurements file (analyses/fit/measurements.hpp), for editors with TOML
// support; docs/case-files.md, "Editor support: the JSON Schema", says how
// to use it. Stdout, or the file named by --output (that file only). The
// scheme of the JSON the commands write is docs/schemas/summary.schema.json.
#include "app/commands.hpp"
#include "common/error.hpp"
#include "analyses/fit/measurements.hpp"
#include "scene/case_json_schema.hpp"
#include "winder/winder_scene.hpp"

#include <fstream>
#include <iostream>
#include <memory>
#include <string>

namespace coremodal {
namespace {

struct SchemaOptions {
    std::string output;
    bool winder = false, fit = false;
};

int print_schema(const SchemaOptions& o) {
    const std::string& output = o.output;
    const std::string schema = o.winder ? winder_json_schema() : o.fit ? fit_json_schema() : case_json_schema();
    if (output.empty()) {
        std::cout << schema;
        return std::cout ? 0 : 1;
    }
    std::ofstream file(output, std::ios::binary | std::ios::trunc);
    if (!(file << schema) || !(file.flush()))
        throw InputError("cannot write the schema to '" + output + "'; expected a writable file path");
    std::cout << "wrote the " << (o.winder ? "winder file" : o.fit ? "measurements file" : "case-file")
              << " JSON Schema to " << output << "\n";
    return 0;
}

}  // namespace

Command add_schema_command(CLI::App& app) {
    auto o = std::make_shared<SchemaOptions>();
    CLI::App* cmd = app.add_subcommand(
        "schema", "Print the case file's JSON Schema (draft-07) for editors with TOML support (taplo, Even Better TOML)");
    cmd->add_option("-o,--output", o->output, "write it to this file (replaced) instead of stdout");
    CLI::Option* winder = cmd->add_flag("--winder", o->winder, "the schema of a two-drum winder file ([winder])");
    cmd->add_flag("--fit", o->fit, "the schema of a fit's measurements file (parameters, [[measurement]])")
        ->excludes(winder);
    return {cmd, [o] { return print_schema(*o); }, false};
}

}  // namespace coremodal
