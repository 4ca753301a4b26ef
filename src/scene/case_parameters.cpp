// Numeric case-file keys as parameters (case_parameters.hpp): resolved like a
// [study]'s keys (case_sweeping::resolve_key_path), set like a study point's
// (CaseSweep::Impl::set), read by the case reader.
#include "scene/case_parameters.hpp"

#include "common/error.hpp"
#include "scene/case_file.hpp"
#include "scene/case_sweep_impl.hpp"
#include "scene/case_table.hpp"
#include "scene/materials_library.hpp"
#include "scene/toml_text.hpp"

#include <sstream>

namespace coremodal {

using case_sweeping::KeyPath;

struct CaseParameters::Impl {
    std::string path, text, model, mesh_level;
    std::vector<CaseParameter> parameters;
    std::vector<KeyPath> paths;

    toml::table document() const {
        toml::table doc = parse_toml_text(text, path);
        if (!model.empty()) doc.insert_or_assign("model", model);
        if (!mesh_level.empty()) {  // as a [study]'s mesh: the level's counts, the case's element
            toml::table mesh{{"level", mesh_level}};
            if (const auto element = doc["mesh"]["element"].value<std::string>()) mesh.insert("element", *element);
            doc.insert_or_assign("mesh", std::move(mesh));
        }
        return doc;
    }
};

namespace {

// A number, or a quantity in text ("130 MPa"), in SI.
std::optional<double> number_of(const toml::node& node, Dimension dimension) {
    if (const auto v = node.value<double>()) return *v;
    if (const auto s = node.value<std::string_view>()) return parse_quantity(*s, dimension);
    return std::nullopt;
}

// The value a library material gives `key`, if it is a library material with that key.
std::optional<double> library_value(std::string_view material, std::string_view key) {
    const LibraryMaterial* entry = find_library_material(material);
    if (!entry) return std::nullopt;
    for (const LibraryValue& v : entry->values)
        if (v.key == key) return v.value;
    return std::nullopt;
}

// The stiffness the case reader derived for a chuck's contact (from the
// expansion pressure, or the normal stiffness times Mindlin's ratio).
std::optional<double> derived_value(const Scene& scene, const KeyPath& path) {
    if (path.size() != 3 || path[0].key != "supports") return std::nullopt;
    for (const ChuckSpec& chuck : scene.supports.chucks) {
        if (chuck.name != path[1].key) continue;
        if (path[2].key == "normal_stiffness") return chuck.interface.normal_stiffness;
        if (path[2].key == "tangential_stiffness") return chuck.interface.tangential_stiffness;
    }
    return std::nullopt;
}

// The key's value now: in the file, else the library material's, else what
// the reader derived. None when the case gives it no value.
std::optional<double> current_value(const toml::table& doc, const KeyPath& path, Dimension dimension,
                                    const Scene& scene) {
    const toml::node* node = &doc;
    std::string material;  // the library material the path went through, if any
    for (size_t i = 0; i + 1 < path.size() && node; ++i) {
        const auto& step = path[i];
        if (step.item > 0) {
            node = node->as_array() ? node->as_array()->get(static_cast<size_t>(step.item - 1)) : nullptr;
            continue;
        }
        const toml::node* child = node->as_table() ? node->as_table()->get(step.key) : nullptr;
        if (step.key == "material") {
            material = !child ? std::string(default_material(step.schema))
                              : child->is_string() ? std::string(*child->value<std::string_view>())
                                                   : std::string((*child->as_table())["base"].value_or<std::string_view>(""));
            if (!child || child->is_string()) return library_value(material, path.back().key);
        }
        node = child;
    }
    if (node && node->is_table())
        if (const toml::node* leaf = node->as_table()->get(path.back().key)) return number_of(*leaf, dimension);
    if (!material.empty()) return library_value(material, path.back().key);
    return derived_value(scene, path);
}

std::string location(const KeySource& source, const std::string& fallback) {
    if (!source.node) return fallback + ": ";
    const auto& at = source.node->source().begin;
    return source.path + ":" + std::to_string(at.line) + ":" + std::to_string(at.column) + ": ";
}

}  // namespace

CaseParameters CaseParameters::read(const std::string& case_file, const std::vector<std::string>& keys,
                                    const std::vector<KeySource>& sources, const std::string& model,
                                    const std::string& mesh_level) {
    return from_text(read_input_file(case_file, "case file"), case_file, keys, sources, model, mesh_level);
}

CaseParameters CaseParameters::from_text(std::string text, const std::string& case_file,
                                         const std::vector<std::string>& keys, const std::vector<KeySource>& sources,
                                         const std::string& model, const std::string& mesh_level) {
    auto impl = std::make_shared<Impl>();
    impl->path = case_file;
    impl->text = std::move(text);
    impl->model = model;
    impl->mesh_level = mesh_level;
    const toml::table doc = impl->document();
    const Scene base = parse_case_table(doc, case_file);
    const toml::value<std::string> placeholder{std::string()};  // where a command-line key is "named"
    for (size_t i = 0; i < keys.size(); ++i) {
        const KeySource source = i < sources.size() ? sources[i] : KeySource{};
        const std::string where_path = source.node ? source.path : "command line";
        const auto [path, spec] = case_sweeping::resolve_key_path(doc, keys[i], source.node ? *source.node : placeholder,
                                                                  where_path, "parameter");
        const std::string what = location(source, "command line") + "parameter key = \"" + keys[i] + "\"";
        if (spec->kind != ValueKind::quantity)
            throw InputError(what + " is not a number; expected a key with a number value (a modulus, a "
                                    "stiffness, a length, a density, ...)");
        const std::optional<double> value = current_value(doc, path, spec->dimension, base);
        if (!value || *value <= 0)
            throw InputError(what + ": the case " + case_file + " gives it no positive value to start from; "
                                    "expected the key written in the case file with a positive value");
        impl->parameters.push_back({keys[i], spec->dimension, *value, spec->min, spec->max});
        impl->paths.push_back(path);
    }
    CaseParameters c;
    c.impl_ = std::move(impl);
    return c;
}

const std::string& CaseParameters::case_file() const { return impl_->path; }
const std::vector<CaseParameter>& CaseParameters::parameters() const { return impl_->parameters; }

std::vector<double> CaseParameters::values() const {
    std::vector<double> v;
    for (const CaseParameter& p : impl_->parameters) v.push_back(p.value);
    return v;
}

namespace {

toml::table with_values(const CaseParameters::Impl& impl, const std::vector<double>& values) {
    COREMODAL_ASSERT(values.size() == impl.paths.size());
    toml::table doc = impl.document();
    for (size_t i = 0; i < values.size(); ++i) CaseSweep::Impl::set(doc, impl.paths[i], values[i]);
    return doc;
}

}  // namespace

Scene CaseParameters::scene(const std::vector<double>& values) const {
    Scene scene = parse_case_table(with_values(*impl_, values), impl_->path);
    return scene;
}

std::string CaseParameters::text(const std::vector<double>& values, const std::string& comment) const {
    std::ostringstream out;
    out << "# " << comment << "\n\n" << with_values(*impl_, values) << "\n";
    return out.str();
}

}  // namespace coremodal
