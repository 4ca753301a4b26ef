// The inside of a CaseSweep, shared by the file that reads the sweep table
// (case_sweep_reader.cpp) and the file that applies a point's values to the
// case's document (case_sweep.cpp). Private to scene/.
#pragma once

#include "scene/case_schema.hpp"
#include "scene/case_sweep.hpp"

#include <toml++/toml.h>

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace coremodal {
namespace case_sweeping {

// One step of a key path: a key in a table, or (after an array of tables
// such as expanding) a 1-based item number.
struct PathStep {
    std::string key;
    int item = 0;  // > 0: the item number, key unused
    std::string schema;  // schema table the key belongs to
};
using KeyPath = std::vector<PathStep>;

using Value = std::variant<std::string, double, std::int64_t, bool>;

// Reads and checks the sweep table `table` of the case's document `root`
// into `out` (options, parameters, their key paths and values). Throws
// InputError: FILE:LINE:COL: what; expected.
void read_sweep_table(const toml::table& root, const std::string& path, std::string_view table,
                      CaseSweep::Impl& out, const std::optional<std::string>& mesh_override);

// A dotted key path ("core.material.G_rz") checked against the schema and the
// case's document `root` as a sweep checks it; `where` is the node that names
// the key, in the file `where_path` (a [study] table, a fit's measurements
// file). Throws InputError FILE:LINE:COL: display key = "...": what; expected.
std::pair<KeyPath, const KeySpec*> resolve_key_path(const toml::table& root, const std::string& key,
                                                    const toml::node& where, const std::string& where_path,
                                                    const std::string& display);

}  // namespace case_sweeping

struct CaseSweep::Impl {
    std::string path, text, name, table;
    std::vector<std::string> warnings;  // of the case as written (Scene::warnings)
    bool from_file = false;
    std::vector<SweepParameter> parameters;
    std::vector<std::vector<case_sweeping::KeyPath>> paths;  // per parameter, per key
    std::vector<std::vector<case_sweeping::Value>> values;   // per parameter, per value
    SweepOptions options;
    bool replace_mesh = false;  // set [mesh] level = options.mesh_level in every point

    void apply_options(toml::table& doc) const;
    static void set(toml::table& doc, const case_sweeping::KeyPath& path, const case_sweeping::Value& value);
};

}  // namespace coremodal
