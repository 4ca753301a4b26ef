// [damping], [excitation] and [response]: the forced response of a spinning
// roll (scene/response_spec.hpp, docs/how-to/response.md). Every mistake stops the
// reader with file:line:col, the key and what is expected.
#include "scene/case_reader.hpp"

#include "scene/case_file.hpp"
#include "scene/case_table.hpp"

#include "common/error.hpp"
#include "scene/toml_text.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal::case_reading {

namespace {

constexpr const char* kResponseSpeedsExpected =
    "exactly one of web_speeds = [\"5 m/s\", \"20 m/s\"] (with points = 400, or a list) or speeds = [\"100 rpm\", "
    "\"2000 rpm\"]";
const std::vector<std::string_view> kBowShapes = {"half_sine", "first_mode"};
// The ovality enters to first order in (D_max - D_min) / Do (effects/excitation.hpp);
// beyond a tenth of the diameter the tube is no longer "slightly" oval.
constexpr double kMaxOvalityPerDiameter = 0.1;

}  // namespace

std::optional<ResponseSetup> CaseReader::read_response_setup(const Section& top, const Scene& scene) const {
    const std::optional<Section> damping = section(top, "damping", "damping");
    const std::optional<Section> excitation = section(top, "excitation", "excitation");
    const std::optional<Section> response = section(top, "response", "response");
    if (!response) {
        if (excitation)
            fail(excitation->table->source(), "[excitation] is used only by the forced response; expected a [response] "
                                              "table too (web_speeds = [\"5 m/s\", \"20 m/s\"], points = 400), or no "
                                              "[excitation] (docs/how-to/response.md)");
        // [damping] also damps the modes of a Campbell sweep ([rotation]; docs/how-to/campbell.md).
        if (damping && !section(top, "rotation", "rotation"))
            fail(damping->table->source(), "[damping] is used only by the forced response and the Campbell diagram; "
                                           "expected a [response] table (web_speeds = [\"5 m/s\", \"20 m/s\"], points = "
                                           "400) or a [rotation] table too, or no [damping] (docs/how-to/response.md)");
        if (damping) read_damping(*damping);  // checked with every key
        return std::nullopt;
    }
    if (!damping)
        fail(response->table->source(), "[response] needs [damping]; expected e.g. [damping] ratio = 0.01 (cores and "
                                        "rest rolls: 0.005-0.02), or log_decrement, decay or rayleigh (docs/how-to/response.md)");
    if (!excitation)
        fail(response->table->source(), "[response] needs [excitation]; expected e.g. [excitation] bow = \"0.5 mm\", "
                                        "unbalance = \"2 kg*mm\", ovality = \"0.3 mm\" (docs/how-to/response.md)");
    if (scene.supports.kind == SupportKind::free)
        fail(response->table->source(), "[response] needs a roll held in its stand; expected [supports] type = "
                                        "\"clamped\" or \"chucks\" (a free roll has no resonance to pass and no sag)");
    ResponseSetup setup;
    setup.damping = read_damping(*damping);
    setup.excitation = read_excitation(*excitation, scene);
    setup.response = read_response_range(*response, scene);
    return setup;
}

ExcitationSpec CaseReader::read_excitation(const Section& excitation, const Scene& scene) const {
    ExcitationSpec spec;
    spec.bow_m = quantity(excitation, "bow").value_or(0.0);
    if (const std::optional<std::string> shape = choice(excitation, "bow_shape", kBowShapes))
        spec.bow_shape = *shape == "first_mode" ? BowShape::first_mode : BowShape::half_sine;
    spec.unbalance_kg_m = quantity(excitation, "unbalance").value_or(0.0);
    spec.eccentricity_m = quantity(excitation, "eccentricity").value_or(0.0);
    spec.ovality_m = quantity(excitation, "ovality").value_or(0.0);
    if (const toml::node* g = get(excitation, "gravity")) spec.gravity = *g->value<bool>();
    if (spec.eccentricity_m > 0 && !scene.rest_paper)
        fail(*get(excitation, "eccentricity"), echo(excitation, "eccentricity", *get(excitation, "eccentricity")) +
                                                   " is the rest paper's; expected a [rest_paper] table, or unbalance "
                                                   "for a bare core");
    if (spec.ovality_m > kMaxOvalityPerDiameter * scene.core.outer_diameter)
        fail(*get(excitation, "ovality"), echo(excitation, "ovality", *get(excitation, "ovality")) +
                                              " is more than a tenth of the core's outer diameter " +
                                              format_quantity(scene.core.outer_diameter, Dimension::length) +
                                              "; the load is linear in a slight ovality; expected at most " +
                                              format_quantity(kMaxOvalityPerDiameter * scene.core.outer_diameter, Dimension::length));
    const bool order_one = spec.bow_m > 0 || spec.unbalance_kg_m > 0 || spec.eccentricity_m > 0;
    if (!order_one && !(spec.ovality_m > 0 && spec.gravity))
        fail(excitation.table->source(),
             "[excitation] gives nothing that excites the roll; expected at least one of bow = \"0.5 mm\", unbalance = "
             "\"2 kg*mm\", eccentricity = \"0.5 mm\" or ovality = \"0.3 mm\" with gravity = true");
    return spec;
}

ResponseRange CaseReader::read_response_range(const Section& response, const Scene& scene) const {
    const bool speeds = get(response, "speeds") != nullptr, web = get(response, "web_speeds") != nullptr;
    if (!speeds && !web) fail(response.table->source(), "[response] gives no speeds; expected " + std::string(kResponseSpeedsExpected));
    if (speeds && web)
        fail(*get(response, "speeds"), echo(response, "speeds", *get(response, "speeds")) + " and " +
                                           echo(response, "web_speeds", *get(response, "web_speeds")) +
                                           " are both given; expected " + kResponseSpeedsExpected);
    const std::string_view key = web ? "web_speeds" : "speeds";
    ResponseRange range;
    range.from_web_speed = web;
    range.speeds_hz = read_speed_list(response, key, web ? Dimension::speed : Dimension::frequency);
    if (!(range.speeds_hz.front() > 0))
        fail(*get(response, key), echo(response, key, *get(response, key)) +
                                      ": the roll must turn; expected speeds above 0 (at rest there is no response)");
    if (web)  // f_rot = v / (pi Dp): the roll's surface moves with the web
        for (double& v : range.speeds_hz) v /= M_PI * roll_outer_diameter(scene);
    range.limit_m = quantity(response, "limit").value_or(kDefaultAmplitudeLimit);
    range.probes = read_probes(response, scene);
    return range;
}

std::vector<ResponseRange::Probe> CaseReader::read_probes(const Section& response, const Scene& scene) const {
    const double length = scene.core.length;
    const toml::node* node = get(response, "probes");
    if (!node) return {{std::string(kMidSpan), 0.5 * length}};
    const std::string what = echo(response, "probes", *node);
    std::vector<ResponseRange::Probe> out;
    for (const toml::node& item : *node->as_array()) {
        ResponseRange::Probe probe{std::string(kMidSpan), 0.5 * length};
        if (!(item.is_string() && *item.value<std::string_view>() == kMidSpan)) {
            probe.z_m = to_si(item, Dimension::length, what + " (\"mid-span\" or a position from the core's left end)");
            if (probe.z_m < 0 || probe.z_m > length)
                fail(item, what + ": " + format_quantity(probe.z_m, Dimension::length) +
                               " is off the core; expected \"mid-span\" or a position from 0 to the core length " +
                               format_quantity(length, Dimension::length));
            probe.name = "z = " + format_quantity(probe.z_m, Dimension::length);
        }
        for (const ResponseRange::Probe& p : out)
            if (p.z_m == probe.z_m) fail(item, what + ": " + probe.name + " is given twice");
        out.push_back(probe);
    }
    if (out.empty()) fail(*node, what + ": expected at least one probe, e.g. [\"mid-span\"]");
    return out;
}

std::optional<ResponseSetup> CaseReader::response(const toml::table& root, const Scene& scene) const {
    const Section top{&root, "", ""};
    return read_response_setup(top, scene);
}

std::optional<DampingSpec> CaseReader::damping(const toml::table& root) const {
    const Section top{&root, "", ""};
    const std::optional<Section> damping = section(top, "damping", "damping");
    return damping ? std::optional<DampingSpec>(read_damping(*damping)) : std::nullopt;
}

}  // namespace coremodal::case_reading

namespace coremodal {

const char* bow_shape_name(BowShape s) { return s == BowShape::first_mode ? "first_mode" : "half_sine"; }

ResponseCase parse_response_case_table(const toml::table& root, const std::string& path) {
    ResponseCase out{parse_case_table(root, path), std::nullopt, std::nullopt};  // every check, the new tables included
    const case_reading::CaseReader reader(path);
    out.rotation = reader.rotation(root, out.scene);
    out.response = reader.response(root, out.scene);
    out.damping = reader.damping(root);
    return out;
}

ResponseCase parse_response_case_text(std::string_view text, const std::string& path) {
    const RotatingCase rotating = parse_rotating_case_text(text, path);  // every check, the new tables included
    ResponseCase out{rotating.scene, rotating.rotation, std::nullopt};
    const toml::table root = parse_toml_input(text, path, "a valid TOML case file (docs/reference/case-files.md)");
    const case_reading::CaseReader reader(path);
    out.response = reader.response(root, out.scene);
    out.damping = reader.damping(root);
    return out;
}

ResponseCase parse_response_case(const std::string& path) {
    return parse_response_case_text(read_input_file(path, "case file"), path);
}

}  // namespace coremodal
