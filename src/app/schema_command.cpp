// `coremodal schema [--winder | --fit | --selection]`: print the JSON Schema
// (draft-07) of the case file, generated from the key table
// (scene/case_json_schema.hpp), of a two-drum winder file
// (winder/winder_scene.hpp), of a fit's measurements file
// (analyses/fit/measurements.hpp) or of a core-selection file
// (selection/selection_scene.hpp), for editors with TOML
// support; docs/reference/case-files.md, "Editor support: the JSON Schema", says how
// to use it. Stdout, or the file named by --output (that file only), under
// the rules of results folders (output/results_folder.hpp): an earlier
// schema coremodal wrote is replaced, any other file, a folder or a symbolic
// link is refused before anything is written, and the file appears complete
// or not at all (written beside it, then renamed into place).
// The scheme of the JSON the commands write is docs/schemas/summary.schema.json.
#include "app/commands.hpp"
#include "common/error.hpp"
#include "analyses/fit/measurements.hpp"
#include "scene/case_json_schema.hpp"
#include "selection/selection_scene.hpp"
#include "winder/winder_scene.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <nlohmann/json.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <memory>
#include <string>
#include <utility>

namespace coremodal {
namespace {

namespace fs = std::filesystem;

[[noreturn]] void refuse(const fs::path& path, const std::string& why, const std::string& what_to_do) {
    throw InputError("schema output '" + path.string() + "' " + why + ": " + what_to_do);
}

// A schema coremodal wrote: JSON with a "$schema" and a title that starts
// "coremodal " (the case file's, the winder, fit and selection files').
bool written_by_coremodal(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    const nlohmann::json j = nlohmann::json::parse(in, nullptr, /*allow_exceptions=*/false);
    return j.is_object() && j.contains("$schema") && j.contains("title") && j["title"].is_string() &&
           j["title"].get<std::string>().starts_with("coremodal ");
}

// Before anything is written: what may be at `path`.
void check_schema_target(const fs::path& path) {
    std::error_code ec;
    const fs::file_status status = fs::symlink_status(path, ec);
    const std::string another = "give a new file name, e.g. case.schema.json";
    if (fs::is_symlink(status))
        refuse(path, "is a symbolic link", "coremodal neither replaces links nor writes through them; " + another +
                                               ", or remove the link yourself");
    if (fs::is_directory(status)) refuse(path, "is a folder", another + " inside it");
    if (fs::exists(status) && !fs::is_regular_file(status)) refuse(path, "is not a regular file", another);
    if (fs::exists(status) && !written_by_coremodal(path))
        refuse(path, "exists and is not a schema coremodal wrote",
               "coremodal never overwrites your files; " + another + ", or move or remove it yourself");
    const fs::path folder = path.has_parent_path() ? path.parent_path() : fs::path(".");
    if (!fs::is_directory(folder, ec)) refuse(path, "cannot be written", "the folder '" + folder.string() + "' does not exist");
}

// `text` into a new file beside `path`, then renamed over it: never half a schema.
void write_complete(const fs::path& path, const std::string& text) {
    fs::path partial = path;
    partial += ".partial-" + std::to_string(::getpid());
    const int fd = ::open(partial.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0644);
    if (fd < 0) refuse(path, "cannot be written", std::string(std::strerror(errno)) + "; choose a folder you can write to");
    size_t done = 0;
    while (done < text.size()) {
        const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += static_cast<size_t>(n);
    }
    const int error = done < text.size() ? errno : 0;
    const bool closed = ::close(fd) == 0;
    if (error || !closed || std::rename(partial.c_str(), path.c_str()) != 0) {
        const std::string reason = std::strerror(error ? error : errno);
        ::unlink(partial.c_str());
        refuse(path, "cannot be written", reason + "; nothing was written");
    }
}

struct SchemaOptions {
    std::string output;
    bool winder = false, fit = false, selection = false;
};

// Which file the schema describes, in words, and the schema.
std::pair<std::string, std::string> chosen_schema(const SchemaOptions& o) {
    if (o.winder) return {"winder file", winder_json_schema()};
    if (o.fit) return {"measurements file", fit_json_schema()};
    if (o.selection) return {"core-selection file", selection_json_schema()};
    return {"case-file", case_json_schema()};
}

int print_schema(const SchemaOptions& o) {
    const std::string& output = o.output;
    const auto [what, schema] = chosen_schema(o);
    if (output.empty()) {
        std::cout << schema;
        return std::cout ? 0 : 1;
    }
    check_schema_target(output);
    write_complete(output, schema);
    std::cout << "wrote the " << what << " JSON Schema to " << output << "\n";
    return 0;
}

}  // namespace

Command add_schema_command(CLI::App& app) {
    auto o = std::make_shared<SchemaOptions>();
    CLI::App* cmd = app.add_subcommand(
        "schema", "Print the case file's JSON Schema (draft-07) for editors with TOML support (taplo, Even Better TOML)");
    cmd->add_option("-o,--output", o->output,
                    "write it to this file instead of stdout (a new file, or one coremodal schema wrote before; "
                    "never another file or through a symbolic link)");
    CLI::Option* winder = cmd->add_flag("--winder", o->winder, "the schema of a two-drum winder file ([winder])");
    CLI::Option* fit =
        cmd->add_flag("--fit", o->fit, "the schema of a fit's measurements file (parameters, [[measurement]])")
            ->excludes(winder);
    cmd->add_flag("--selection", o->selection, "the schema of a core-selection file ([selection], coremodal select)")
        ->excludes(winder)
        ->excludes(fit);
    return {cmd, [o] { return print_schema(*o); }, false};
}

}  // namespace coremodal
