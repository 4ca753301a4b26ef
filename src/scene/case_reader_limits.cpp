// [limits]: one verdict over the rest-roll diameters (scene/limits_spec.hpp,
// docs/how-to/limits.md). Every mistake stops the reader with file:line:col, the key
// and what is expected.
#include "scene/case_reader.hpp"

#include "scene/case_file.hpp"
#include "scene/case_table.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "scene/toml_text.hpp"

namespace coremodal::case_reading {
namespace {

// Rest-roll diameters in the unit people give them in.

}  // namespace

std::optional<LimitsSpec> CaseReader::read_limits(const Section& top, const Scene& scene) const {
    const std::optional<Section> limits = section(top, "limits", "limits");
    if (!limits) return std::nullopt;
    if (scene.supports.kind == SupportKind::free)
        fail(limits->table->source(),
             "[limits] needs a roll held in its stand; expected [supports] type = "
             "\"clamped\" or \"chucks\" (a free roll has no safe web speed)");
    LimitsSpec spec;
    if (get(*limits, "diameters")) read_limits_diameters(*limits, scene, spec);
    spec.points = integer(*limits, "points").value_or(kDefaultLimitsPoints);
    spec.target_web_speed_m_s = quantity(*limits, "web_speed");
    spec.limit_m = quantity(*limits, "limit");
    if (const toml::node* b = get(*limits, "band")) spec.band = *b->value<bool>();
    return spec;
}

// [largest, smallest]: within the case's roll (the rest paper's outer
// diameter) and not below the bare core (its outer diameter).
void CaseReader::read_limits_diameters(const Section& limits, const Scene& scene, LimitsSpec& spec) const {
    const toml::node& node = *get(limits, "diameters");
    const toml::array& array = *node.as_array();
    const std::string what = echo(limits, "diameters", node);
    if (array.size() != 2) fail(node, what + ": expected two rest-roll diameters, [largest, smallest]");
    const double largest = to_si(*array.get(0), Dimension::length, what);
    const double smallest = to_si(*array.get(1), Dimension::length, what);
    const double roll = roll_outer_diameter(scene), core = scene.core.outer_diameter;
    // The diameters are compared at the precision they are printed with.
    constexpr double kSlack = 1e-9;
    if (largest > roll + kSlack)
        fail(*array.get(0), what + ": " + millimetres(largest, 5) + " is beyond the case's roll; " +
                                "expected at most the rest paper's outer diameter " + millimetres(roll, 5) +
                                " (raise [rest_paper] thickness instead)");
    if (smallest < core - kSlack)
        fail(*array.get(1), what + ": " + millimetres(smallest, 5) + " is below the core; " +
                                "expected at least the core's outer diameter " + millimetres(core, 5));
    if (!(largest > smallest))
        fail(node, what +
                       ": expected [largest, smallest] with the largest first "
                       "and above the smallest");
    spec.largest_diameter_m = largest, spec.smallest_diameter_m = smallest;
}

std::optional<LimitsSpec> CaseReader::limits(const toml::table& root, const Scene& scene) const {
    const Section top{&root, "", ""};
    return read_limits(top, scene);
}

}  // namespace coremodal::case_reading

namespace coremodal {

LimitsCase parse_limits_case_text(std::string_view text, const std::string& path) {
    const ResponseCase response = parse_response_case_text(text, path);  // every check, [limits] included
    const toml::table root = parse_toml_input(text, path, "a valid TOML case file (docs/reference/case-files.md)");
    LimitsCase out{response.scene, response.response, std::nullopt};
    try {
        out.limits = case_reading::CaseReader(path).limits(root, out.scene);
    } catch (const InputError& e) {  // a key echoed in a message: the user's characters
        throw InputError(restore_characters(e.what()));
    }
    return out;
}

LimitsCase parse_limits_case(const std::string& path) {
    return parse_limits_case_text(read_input_file(path, "case file"), path);
}

}  // namespace coremodal
