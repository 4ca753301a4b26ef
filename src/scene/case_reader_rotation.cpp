// [rotation]: the speeds the roll spins at and the excitation orders of a
// Campbell diagram (scene/case_reader.hpp, docs/how-to/campbell.md).
#include "scene/case_reader.hpp"

#include "scene/case_file.hpp"

#include "common/error.hpp"
#include "scene/toml_text.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal::case_reading {

namespace {

const std::vector<std::string_view> kSpeedKeys = {"speed", "speeds", "web_speed", "web_speeds"};
constexpr const char* kSpeedExpected =
    "exactly one of speed = \"1200 rpm\", speeds = [\"0 rpm\", \"4000 rpm\"] (with points = 41, or a list), "
    "web_speed = \"15 m/s\" or web_speeds = [...]";

}  // namespace

std::optional<RotationSpec> CaseReader::read_rotation(const Section& top, const Scene& scene) const {
    const std::optional<Section> rotation = section(top, "rotation", "rotation");
    if (!rotation) return std::nullopt;
    std::vector<std::string_view> given;
    for (std::string_view key : kSpeedKeys)
        if (get(*rotation, key)) given.push_back(key);
    if (given.empty()) fail(rotation->table->source(), "[rotation] gives no speed; expected " + std::string(kSpeedExpected));
    if (given.size() > 1)
        fail(*get(*rotation, given[1]), echo(*rotation, given[1], *get(*rotation, given[1])) + " and " +
                                            echo(*rotation, given[0], *get(*rotation, given[0])) +
                                            " are both given; expected " + kSpeedExpected);
    const std::string_view key = given.front();
    const bool list = key == "speeds" || key == "web_speeds";
    if (const toml::node* points = get(*rotation, "points"); points && !list)
        fail(*points, echo(*rotation, "points", *points) + " goes with speeds or web_speeds = [first, last]; "
                                                           "expected no points with " + std::string(key));
    RotationSpec spec;
    spec.from_web_speed = key.starts_with("web_");
    const Dimension d = spec.from_web_speed ? Dimension::speed : Dimension::frequency;
    spec.speeds_hz = list ? read_speed_list(*rotation, key, d) : std::vector<double>{*quantity(*rotation, key)};
    if (spec.from_web_speed)  // f_rot = v / (pi Dp): the roll's surface moves with the web
        for (double& v : spec.speeds_hz) v /= M_PI * roll_outer_diameter(scene);
    if (get(*rotation, "operating_speeds"))
        spec.operating_hz = read_operating_speeds(*rotation, key, spec, roll_outer_diameter(scene));
    if (get(*rotation, "excitation_orders")) spec.excitation_orders = read_excitation_orders(*rotation);
    if (const toml::node* c = get(*rotation, "centrifugal_stiffening")) spec.centrifugal_stiffening = *c->value<bool>();
    return spec;
}

std::vector<double> CaseReader::read_speed_list(const Section& rotation, std::string_view key, Dimension d) const {
    const toml::node& node = *get(rotation, key);
    const toml::array& array = *node.as_array();
    const std::string what = echo(rotation, key, node);
    // The bound of the table's own single-speed key ([traction] web_speed), else [rotation]'s.
    const std::string_view single = d == Dimension::speed ? "web_speed" : "speed";
    const KeySpec* own = find_key(rotation.schema, single);
    const KeySpec& bound = own ? *own : *find_key("rotation", single);
    if (array.empty()) fail(node, what + ": expected at least one speed");
    std::vector<double> values;
    for (const toml::node& item : array) {
        const double v = to_si(item, d, what);
        if (v < 0) fail(item, what + ": a speed must be zero or positive");
        if (v > bound.max)
            fail(item, what + ": " + format_quantity(v, d) + " is too large; expected at most " +
                           format_quantity(bound.max, d) + (item.is_number() ? std::string("; plain numbers are in ") + si_unit(d) : ""));
        if (!values.empty() && !(v > values.back()))
            fail(item, what + ": the speeds must increase from one to the next");
        values.push_back(v);
    }
    const std::optional<int> points = integer(rotation, "points");
    if (!points) return values;
    if (values.size() != 2)
        fail(*get(rotation, "points"), echo(rotation, "points", *get(rotation, "points")) + " needs " + what +
                                           " to be [first, last]; expected two speeds, or a list without points");
    std::vector<double> out(*points);
    for (int i = 0; i < *points; ++i) out[i] = values[0] + (values[1] - values[0]) * i / (*points - 1);
    return out;
}

// The operating range: two speeds in the sweep's own units, the lower first,
// inside the sweep (outside it no critical speed is computed, so "none inside
// the operating range" could not be said).
std::array<double, 2> CaseReader::read_operating_speeds(const Section& rotation, std::string_view sweep_key,
                                                        const RotationSpec& spec, double roll_diameter) const {
    const toml::node& node = *get(rotation, "operating_speeds");
    const std::string what = echo(rotation, "operating_speeds", node);
    const bool web = spec.from_web_speed;
    const std::string example = web ? "[\"5 m/s\", \"20 m/s\"]" : "[\"0 rpm\", \"4000 rpm\"]";
    if (!spec.sweep())
        fail(node, what + " goes with a sweep; expected speeds or web_speeds = [first, last] with points, not " +
                       std::string(sweep_key));
    const toml::array& items = *node.as_array();
    if (items.size() != 2)
        fail(node, what + ": expected two speeds [lowest, highest], e.g. " + example);
    const Dimension d = web ? Dimension::speed : Dimension::frequency;
    const std::string units = web ? " (web speeds, as " + std::string(sweep_key) + ")" : " (rotation speeds, as speeds)";
    std::array<double, 2> hz{};
    for (int i = 0; i < 2; ++i) {
        hz[i] = to_si(items[i], d, what + units);
        if (web) hz[i] /= M_PI * roll_diameter;  // f_rot = v / (pi Dp), as the sweep
    }
    if (!(hz[0] < hz[1]))
        fail(items[1], what + ": the lowest speed must come first and be below the highest; expected [lowest, highest], "
                              "e.g. " + example);
    // A relative tolerance: the same speed written in other units (4000 rpm, 66.67 Hz) rounds differently.
    const double first = spec.speeds_hz.front(), last = spec.speeds_hz.back(), slack = 1e-9 * last;
    const std::string sweep = echo(rotation, sweep_key, *get(rotation, sweep_key));
    for (int i = 0; i < 2; ++i)
        if (hz[i] < first - slack || hz[i] > last + slack)
            fail(items[i], what + ": " + std::string(i == 0 ? "the lowest" : "the highest") +
                               " speed lies outside the sweep " + sweep +
                               "; expected both inside it (critical speeds are found only within the sweep)");
    return hz;
}

std::vector<int> CaseReader::read_excitation_orders(const Section& rotation) const {
    const toml::node& node = *get(rotation, "excitation_orders");
    const std::string what = echo(rotation, "excitation_orders", node);
    std::vector<int> orders;
    for (const toml::node& item : *node.as_array()) {
        constexpr int kMaxOrder = 20;  // a roll's harmonics of interest are the first few
        if (!item.is_integer() || *item.value<std::int64_t>() < 1 || *item.value<std::int64_t>() > kMaxOrder)
            fail(item, what + ": expected whole numbers from 1 to " + std::to_string(kMaxOrder) + ", e.g. [1, 2]");
        const int k = static_cast<int>(*item.value<std::int64_t>());
        if (std::find(orders.begin(), orders.end(), k) != orders.end()) fail(item, what + ": order " + std::to_string(k) + " is given twice");
        orders.push_back(k);
    }
    if (orders.empty()) fail(node, what + ": expected at least one order, e.g. [1, 2]");
    return orders;
}

std::optional<RotationSpec> CaseReader::rotation(const toml::table& root, const Scene& scene) const {
    const Section top{&root, "", ""};
    return read_rotation(top, scene);
}

}  // namespace coremodal::case_reading

namespace coremodal {

double roll_outer_diameter(const Scene& scene) {
    return scene.rest_paper ? scene.rest_paper->outer_diameter : scene.core.outer_diameter;
}

RotatingCase parse_rotating_case_text(std::string_view text, const std::string& path) {
    RotatingCase out{parse_case_text(text, path), std::nullopt};  // every check, [rotation] included
    const toml::table root = parse_toml_input(text, path, "a valid TOML case file (docs/reference/case-files.md)");
    out.rotation = case_reading::CaseReader(path).rotation(root, out.scene);
    return out;
}

RotatingCase parse_rotating_case(const std::string& path) {
    return parse_rotating_case_text(read_input_file(path, "case file"), path);
}

}  // namespace coremodal
