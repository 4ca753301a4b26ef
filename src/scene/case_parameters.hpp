// Numeric case-file keys as parameters: their values now, and the scene (or
// the case file's text) with other values. The machinery of a [study] point
// (scene/case_sweep.hpp) for `coremodal sensitivity` and `coremodal fit`:
// every key a [study] can vary, checked against the schema the same way, set
// in the case's TOML document, read by the normal case reader.
//
//   CaseParameters c = CaseParameters::read("case.toml", {"core.material.G_rz"});
//   c.values()            -> {130e6}  (the file's value, else the library material's)
//   c.scene({260e6})      -> the scene with G_rz = 260 MPa (every check of a case file)
//   c.text({260e6})       -> a case file with that value written in, for `run` and `study`
#pragma once

#include "scene/scene.hpp"
#include "scene/units.hpp"

#include <toml++/toml.h>

#include <memory>
#include <string>
#include <vector>

namespace coremodal {

struct CaseParameter {
    std::string key;  // dotted key path, e.g. "supports.left.normal_stiffness"
    Dimension dimension = Dimension::dimensionless;
    double value = 0;    // SI: the case's value (its file, its library material, or what the reader derived)
    double min = 0, max = 0;  // the schema's admissible range (SI)
};

// Where a key was named, for messages: a node of another TOML file (a fit's
// measurements file) and that file's path; none: the key came from the
// command line.
struct KeySource {
    const toml::node* node = nullptr;
    std::string path;
};

class CaseParameters {
public:
    // Reads the case file and resolves each key. Throws InputError naming the
    // key's source (file:line:col) or the case file: an unknown key, a key
    // that is not a number with a unit, a value the case does not give and no
    // library material or derived value supplies. `model` and `mesh_level`
    // ("" = the case's) set the model level and the [mesh] level of every scene.
    static CaseParameters read(const std::string& case_file, const std::vector<std::string>& keys,
                               const std::vector<KeySource>& sources = {}, const std::string& model = "",
                               const std::string& mesh_level = "");
    static CaseParameters from_text(std::string text, const std::string& case_file,
                                    const std::vector<std::string>& keys, const std::vector<KeySource>& sources = {},
                                    const std::string& model = "", const std::string& mesh_level = "");

    const std::string& case_file() const;
    const std::vector<CaseParameter>& parameters() const;
    std::vector<double> values() const;  // the case's own values, in key order

    // The scene with the keys set to `values` (SI, key order). Throws
    // InputError (the case reader's message) for a combination it refuses.
    Scene scene(const std::vector<double>& values) const;
    // The case file's text with the keys set (values in SI numbers) and a
    // comment line on top; a case file ready for `run` and `study`.
    std::string text(const std::vector<double>& values, const std::string& comment) const;

    struct Impl;

private:
    std::shared_ptr<const Impl> impl_;
};

}  // namespace coremodal
