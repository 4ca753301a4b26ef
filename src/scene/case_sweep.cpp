// [study] / [calibration] tables -> the points of a sweep, each a scene read
// by the normal case reader from the case's document with some keys changed.
// This file applies a point's values; the table is read in case_sweep_reader.cpp.
#include "scene/case_sweep.hpp"
#include "scene/case_sweep_impl.hpp"

#include "common/error.hpp"
#include "scene/case_file.hpp"
#include "scene/case_schema.hpp"
#include "scene/case_table.hpp"
#include "scene/toml_text.hpp"

#include <variant>

namespace coremodal {
namespace {

using case_sweeping::KeyPath;
using case_sweeping::PathStep;
using case_sweeping::Value;

// Setting one key of such a pair removes the other from the same table, so
// that a study can set rest_paper.thickness on a case that gives
// rest_paper.outer_diameter (the case reader accepts only one of them).
struct Alternative {
    std::string_view table, key, other;
};
constexpr Alternative kAlternatives[] = {
    {"core", "wall", "outer_diameter"},          {"core", "outer_diameter", "wall"},
    {"rest_paper", "thickness", "outer_diameter"}, {"rest_paper", "outer_diameter", "thickness"},
    {"clamp", "start", "center"},                {"clamp", "center", "start"},
    {"analysis", "modes", "band"},               {"analysis", "band", "modes"},
    {"chuck", "clearance", "body_diameter"},     {"chuck", "body_diameter", "clearance"},
    {"chuck", "normal_stiffness", "expansion_pressure"}, {"chuck", "expansion_pressure", "normal_stiffness"},
};

}  // namespace

void CaseSweep::Impl::apply_options(toml::table& doc) const {
    if (!options.model.empty()) doc.insert_or_assign("model", options.model);
    if (replace_mesh) {
        // A fresh [mesh]: the level's counts, not the case's own overrides.
        toml::table mesh{{"level", options.mesh_level}};
        if (const auto element = doc["mesh"]["element"].value<std::string>()) mesh.insert("element", *element);
        doc.insert_or_assign("mesh", std::move(mesh));
    }
    if (options.modes == 0) return;
    if (!doc.get("analysis")) doc.insert("analysis", toml::table{});
    toml::table& analysis = *doc["analysis"].as_table();
    analysis.erase("band");
    analysis.insert_or_assign("modes", options.modes);
}

void CaseSweep::Impl::set(toml::table& doc, const KeyPath& path, const Value& value) {
    toml::node* node = &doc;
    for (size_t i = 0; i + 1 < path.size(); ++i) {
        const PathStep& step = path[i];
        if (step.item > 0) {
            node = node->as_array()->get(static_cast<size_t>(step.item - 1));
            continue;
        }
        toml::table& table = *node->as_table();
        toml::node* child = table.get(step.key);
        // A material the file does not give is its library default, made editable below.
        if (!child && step.key == "material")
            child = &table.insert_or_assign(step.key, std::string(default_material(step.schema))).first->second;
        if (!child) child = &table.insert_or_assign(step.key, toml::table{}).first->second;
        // A library material by name becomes { base = "name" } so that one
        // value can be changed.
        if (child->is_string())
            child = &table.insert_or_assign(step.key, toml::table{{"base", *child->value<std::string>()}}).first->second;
        node = child;
    }
    toml::table& table = *node->as_table();
    const PathStep& leaf = path.back();
    std::visit([&](const auto& v) { table.insert_or_assign(leaf.key, v); }, value);
    for (const Alternative& a : kAlternatives)
        if (a.table == leaf.schema && a.key == leaf.key) table.erase(a.other);
}

CaseSweep CaseSweep::read(const std::string& path, std::string_view table,
                          const std::optional<std::string>& mesh_override) {
    CaseSweep sweep = from_text(read_input_file(path, "case file"), path, table, mesh_override);
    std::const_pointer_cast<Impl>(sweep.impl_)->from_file = true;
    return sweep;
}

CaseSweep CaseSweep::from_text(std::string text, const std::string& path, std::string_view table,
                               const std::optional<std::string>& mesh_override) {
    // The case itself first: every error of the base case is reported as for `run`.
    const Scene base = parse_case_text(text, path);
    auto impl = std::make_shared<Impl>();
    impl->path = path;
    impl->name = base.name;
    impl->warnings = base.warnings;
    impl->table = std::string(table);
    impl->text = std::move(text);
    const toml::table root = parse_toml_text(impl->text, path);
    case_sweeping::read_sweep_table(root, path, table, *impl, mesh_override);
    CaseSweep sweep;
    sweep.impl_ = std::move(impl);
    return sweep;
}

const std::string& CaseSweep::case_file() const { return impl_->path; }
const std::string& CaseSweep::case_name() const { return impl_->name; }
const std::vector<std::string>& CaseSweep::warnings() const { return impl_->warnings; }
const std::string& CaseSweep::table() const { return impl_->table; }
bool CaseSweep::from_file() const { return impl_->from_file; }
const std::vector<SweepParameter>& CaseSweep::parameters() const { return impl_->parameters; }
const SweepOptions& CaseSweep::options() const { return impl_->options; }

CaseSweep CaseSweep::with_model(const std::string& model) const {
    if (model.empty()) return *this;
    auto impl = std::make_shared<Impl>(*impl_);
    impl->options.model = model;
    CaseSweep sweep;
    sweep.impl_ = std::move(impl);
    return sweep;
}

int CaseSweep::n_points() const {
    int n = 1;
    for (const auto& v : impl_->values) n *= static_cast<int>(v.size());
    return n;
}

std::vector<int> CaseSweep::value_indices(int point) const {
    COREMODAL_ASSERT(point >= 0 && point < n_points());
    std::vector<int> index(impl_->values.size());
    for (size_t p = index.size(); p-- > 0;) {
        const int n = static_cast<int>(impl_->values[p].size());
        index[p] = point % n;
        point /= n;
    }
    return index;
}

std::optional<int> CaseSweep::predecessor(int point) const {
    if (point == 0) return std::nullopt;
    std::vector<int> index = value_indices(point);
    // Step back along the last parameter that is not at its first value.
    for (size_t p = index.size(); p-- > 0;) {
        if (index[p] == 0) continue;
        --index[p];
        int flat = 0;
        for (size_t q = 0; q < index.size(); ++q) flat = flat * static_cast<int>(impl_->values[q].size()) + index[q];
        return flat;
    }
    COREMODAL_ASSERT(false);
}

std::string CaseSweep::describe(int point) const {
    const std::vector<int> index = value_indices(point);
    std::string out;
    for (size_t p = 0; p < index.size(); ++p)
        out += (p ? ", " : "") + impl_->parameters[p].name + " = " + impl_->parameters[p].labels[index[p]];
    return out;
}

Scene CaseSweep::scene(int point) const { return response_case(point).scene; }

ResponseCase CaseSweep::response_case(int point) const {
    const std::vector<int> index = value_indices(point);
    // Parsed afresh for every point: toml++ does not copy source positions,
    // and the case reader's messages need them.
    toml::table doc = parse_toml_text(impl_->text, impl_->path);
    impl_->apply_options(doc);
    for (size_t p = 0; p < index.size(); ++p)
        for (const KeyPath& path : impl_->paths[p]) Impl::set(doc, path, impl_->values[p][index[p]]);
    try {
        ResponseCase c = parse_response_case_table(doc, impl_->path);
        c.scene.name = impl_->name;
        return c;
    } catch (const InputError& e) {
        throw InputError("point " + std::to_string(point + 1) + " (" + describe(point) + "): " + e.what());
    }
}

}  // namespace coremodal
