// [damping]: the base damping of every mode (one ratio from ratio,
// log_decrement or a measured decay, or Rayleigh's alpha M + beta K), ratios
// per mode family and per single mode on top of it, and structural damping:
// a loss factor for every part and per part (loss_factor, [damping.loss_factors]) (scene/response_spec.hpp,
// docs/how-to/response.md). Every mistake stops the reader with file:line:col, the
// key and what is expected. Mode numbers are checked against the modes at
// rest by the run (models/response/response_damping.cpp), which alone knows
// them.
#include "scene/case_reader.hpp"

#include "common/error.hpp"
#include "common/format.hpp"
#include "scene/damping_input.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal::case_reading {

namespace {

constexpr const char* kDampingExpected =
    "exactly one of ratio = 0.01, log_decrement = 0.06, decay = { amplitude_ratio = 3.2, cycles = 10 } or "
    "rayleigh = { zeta = 0.01, frequencies = [\"20 Hz\", \"200 Hz\"] }, and/or a loss factor: loss_factor = 0.03 "
    "or [damping.loss_factors] core = 0.03";
constexpr const char* kRayleighExpected =
    "either alpha and beta (1/s and s, plain numbers), e.g. { alpha = 0.5, beta = 1e-5 }, or zeta at two "
    "frequencies, e.g. { zeta = 0.01, frequencies = [\"20 Hz\", \"200 Hz\"] }";
const std::vector<std::string_view> kBaseKeys = {"ratio", "log_decrement", "decay", "rayleigh"};

}  // namespace

DampingSpec CaseReader::read_damping(const Section& damping) const {
    DampingSpec spec;
    // The loss factors first: they may be all the damping there is. Their
    // ranges (0 <= eta <= 1) are the schema's, checked with file:line:col.
    spec.loss_factor = quantity(damping, "loss_factor").value_or(0.0);
    if (const std::optional<Section> parts = section(damping, "loss_factors", "loss_factors"))
        for (std::string_view part : kLossFactorParts)
            if (const std::optional<double> eta = quantity(*parts, part)) spec.part_loss_factors[std::string(part)] = *eta;
    read_damping_base(damping, spec);
    for (std::string_view family : kDampingFamilies)
        if (const std::optional<double> zeta = quantity(damping, family))
            spec.families.push_back({std::string(family), *zeta});
    spec.modes = read_damping_modes(damping);
    return spec;
}

void CaseReader::read_damping_base(const Section& damping, DampingSpec& spec) const {
    std::vector<std::string_view> given;
    for (std::string_view key : kBaseKeys)
        if (get(damping, key)) given.push_back(key);
    const bool structural = spec.loss_factor > 0 || std::any_of(spec.part_loss_factors.begin(), spec.part_loss_factors.end(),
                                                                [](const auto& p) { return p.second > 0; });
    if (given.empty() && structural) {  // structural damping alone: no viscous ratio
        spec.source = "[damping] no viscous damping: the loss factors alone";
        return;
    }
    if (given.empty())
        fail(damping.table->source(), "[damping] gives no damping for the modes it does not name; expected " +
                                          std::string(kDampingExpected));
    if (given.size() > 1)
        fail(*get(damping, given[1]), echo(damping, given[1], *get(damping, given[1])) + " and " +
                                          echo(damping, given[0], *get(damping, given[0])) + " are both given; expected " +
                                          kDampingExpected);
    if (given[0] == "ratio") {
        spec.ratio = *quantity(damping, "ratio");
        spec.source = "[damping] ratio = " + format_quantity(spec.ratio, Dimension::dimensionless);
    } else if (given[0] == "log_decrement") {
        const double delta = *quantity(damping, "log_decrement");
        spec.ratio = zeta_from_log_decrement(delta);  // I-1 with N = 1
        spec.source = "[damping] log_decrement = " + format_quantity(delta, Dimension::dimensionless) +
                      ": zeta = delta / (2 pi) (I-1)";
    } else if (given[0] == "decay") {
        const Section decay = *section(damping, "decay", "decay");
        const double ratio = required(decay, "amplitude_ratio", "X0/XN, the amplitude ratio over the cycles, e.g. 3.2");
        const double cycles = required(decay, "cycles", "N, the cycles of the decay, e.g. 10");
        spec.ratio = zeta_from_decay(ratio, cycles);  // I-1
        spec.source = "[damping] decay: amplitude ratio " + format_quantity(ratio, Dimension::dimensionless) + " over " +
                      format_quantity(cycles, Dimension::dimensionless) + " cycles: zeta = ln(X0/XN) / (2 pi N) (I-1)";
        if (!(spec.ratio < 1))
            fail(*get(damping, "decay"), "[damping] decay gives zeta = " + format_quantity(spec.ratio, Dimension::dimensionless) +
                                             ", critical damping or more; expected a decay over more cycles (zeta < 1)");
    } else {
        spec.rayleigh = read_rayleigh(damping, spec.source);
    }
}

RayleighSpec CaseReader::read_rayleigh(const Section& damping, std::string& source) const {
    const Section r = *section(damping, "rayleigh", "rayleigh");
    const bool coefficients = get(r, "alpha") || get(r, "beta");
    const bool at_two = get(r, "zeta") || get(r, "frequencies");
    if (coefficients && at_two)
        fail(*get(r, get(r, "zeta") ? "zeta" : "frequencies"),
             "[damping.rayleigh] mixes alpha/beta with zeta/frequencies; expected " + std::string(kRayleighExpected));
    if (!coefficients && !at_two)
        fail(r.table->source(), "[damping.rayleigh] gives no damping; expected " + std::string(kRayleighExpected));
    RayleighSpec spec;
    if (coefficients) {
        spec.alpha = quantity(r, "alpha").value_or(0.0);
        spec.beta = quantity(r, "beta").value_or(0.0);
        if (!(spec.alpha > 0 || spec.beta > 0))
            fail(*get(r, get(r, "alpha") ? "alpha" : "beta"),
                 "[damping.rayleigh] alpha and beta are both 0: no damping; expected " + std::string(kRayleighExpected));
        source = "[damping] rayleigh: alpha = " + format_quantity(spec.alpha, Dimension::dimensionless) +
                 " 1/s, beta = " + format_quantity(spec.beta, Dimension::dimensionless) + " s";
        return spec;
    }
    const double zeta = required(r, "zeta", "the damping ratio at both frequencies, e.g. zeta = 0.01");
    const toml::node* node = get(r, "frequencies");
    if (!node) fail(r.table->source(), "[damping.rayleigh] frequencies is missing; expected two frequencies, e.g. "
                                       "frequencies = [\"20 Hz\", \"200 Hz\"]");
    const std::string what = echo(r, "frequencies", *node);
    const toml::array& items = *node->as_array();
    if (items.size() != 2) fail(*node, what + ": expected two frequencies, e.g. [\"20 Hz\", \"200 Hz\"]");
    const double f1 = to_si(items[0], Dimension::frequency, what), f2 = to_si(items[1], Dimension::frequency, what);
    if (!(f1 > 0)) fail(items[0], what + ": a frequency must be above 0 (alpha M damps a mode at rest infinitely)");
    if (!(f2 > f1)) fail(items[1], what + ": expected two different frequencies, the lower first");
    const RayleighSpec d = rayleigh_at_two_frequencies(zeta, 2 * M_PI * f1, 2 * M_PI * f2);
    spec.alpha = d.alpha, spec.beta = d.beta;
    source = "[damping] rayleigh: zeta = " + format_quantity(zeta, Dimension::dimensionless) + " at " +
             format_quantity(f1, Dimension::frequency) + " and " + format_quantity(f2, Dimension::frequency) +
             ": alpha = " + format_quantity(d.alpha, Dimension::dimensionless) + " 1/s, beta = " +
             format_quantity(d.beta, Dimension::dimensionless) + " s";
    return spec;
}

std::vector<DampingSpec::ModeRatio> CaseReader::read_damping_modes(const Section& damping) const {
    const toml::node* node = get(damping, "modes");
    if (!node) return {};
    std::vector<DampingSpec::ModeRatio> out;
    const toml::array& items = *node->as_array();
    for (size_t i = 0; i < items.size(); ++i) {
        const std::string display = "[damping.modes #" + std::to_string(i + 1) + "]";
        const Section e = open(*items[i].as_table(), display, "modes");
        const std::optional<int> mode = integer(e, "mode");
        if (!mode)
            fail(e.table->source(), display + " mode is missing; expected the mode's number as in modes.csv of the "
                                              "scene at rest, e.g. { mode = 1, ratio = 0.02 }");
        const double ratio = required(e, "ratio", "the mode's relative damping, e.g. { mode = 1, ratio = 0.02 }");
        for (const DampingSpec::ModeRatio& m : out)
            if (m.mode == *mode)
                fail(*get(e, "mode"), display + " mode = " + std::to_string(*mode) + " is given twice; expected one "
                                                                                      "ratio per mode");
        out.push_back({*mode, ratio, location(get(e, "mode")->source()) + display});
    }
    return out;
}

}  // namespace coremodal::case_reading

namespace coremodal {

std::string describe_damping(const DampingSpec& d) {
    std::string out = "  damping of every mode not named below: " + d.source + "\n";
    if (d.rayleigh)
        out += "    (Rayleigh: D = alpha M + beta K; mode j: zeta_j = alpha / (2 omega_j) + beta omega_j / 2)\n";
    for (const DampingSpec::FamilyRatio& f : d.families)
        out += "  damping of every " + f.family + " mode: zeta = " + format_quantity(f.ratio, Dimension::dimensionless) + "\n";
    for (const DampingSpec::ModeRatio& m : d.modes)
        out += "  damping of mode " + std::to_string(m.mode) + " at rest (shared by a degenerate partner): zeta = " +
               format_quantity(m.ratio, Dimension::dimensionless) + "\n";
    if (const std::string words = loss_factor_words(d); !words.empty())
        out += "  structural damping (stiffness K_p (1 + i eta_p)): " + words + "\n";
    return out;
}

std::string loss_factor_words(const DampingSpec& d) {
    const bool given = d.loss_factor > 0 || std::any_of(d.part_loss_factors.begin(), d.part_loss_factors.end(),
                                                        [](const auto& part) { return part.second > 0; });
    if (!given) return "";
    std::string out = "loss factor " + significant(d.loss_factor, 4) + " (every part)";
    for (const auto& [part, eta] : d.part_loss_factors) out += "; " + part + " " + significant(eta, 4);
    return out;
}

}  // namespace coremodal
