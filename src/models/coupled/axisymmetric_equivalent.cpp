#include "models/coupled/axisymmetric_equivalent.hpp"

#include "common/error.hpp"
#include "common/format.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace coremodal {

double pad_coverage(const ExpandingElement& e) {
    return e.segments == 0 ? 1.0 : e.segments * e.segment_angle / (2 * std::numbers::pi);
}

namespace {

// The coverage of one chuck's pads, or 1 when it has none (InputError where
// the equivalent cannot carry them).
double chuck_coverage(const Scene& scene, const ChuckSpec& chuck) {
    const auto segmented = [](const ExpandingElement& e) { return e.segments > 0; };
    if (std::none_of(chuck.expanding.begin(), chuck.expanding.end(), segmented)) return 1.0;
    const std::string where = scene.source_file + ": the " + chuck.name + " chuck's segmented expanding elements: ";
    const ExpandingElement& first = *std::find_if(chuck.expanding.begin(), chuck.expanding.end(), segmented);
    if (first.segments < 3)
        throw InputError(
            where + std::to_string(first.segments) +
            " pads load the bore unequally in x and y (sum of cos 2 theta_k = " + std::to_string(first.segments) +
            ", not 0), so no axisymmetric band is equivalent for the spinning criteria; expected "
            "segments >= 3, or model = \"coupled\" with `coremodal run` (no verdict)");
    for (const ExpandingElement& e : chuck.expanding)
        if (e.segments != first.segments || std::abs(e.segment_angle - first.segment_angle) > 1e-12)
            throw InputError(where +
                             "pads of different counts or spans (or a full band beside pads) share one "
                             "spring layer, whose stiffness the equivalent scales by one coverage; "
                             "expected every element of the chuck with the same segments and "
                             "segment_angle");
    if (chuck.interface.kind != InterfaceKind::spring || chuck.interface.contact != ContactKind::uniform)
        throw InputError(where +
                         "the equivalent scales a spring layer's stiffness by the pads' coverage; "
                         "expected interface = \"spring\" on an expanded chuck");
    return pad_coverage(first);
}

}  // namespace

AxisymmetricEquivalent axisymmetric_equivalent(const Scene& scene) {
    AxisymmetricEquivalent out{scene, 1.0, ""};
    std::string what;
    for (ChuckSpec& chuck : out.scene.supports.chucks) {
        const double c = chuck_coverage(scene, chuck);
        if (c == 1.0) continue;
        const int n = chuck.expanding.front().segments;
        for (ExpandingElement& e : chuck.expanding) e.segments = 0, e.segment_angle = 0;
        chuck.interface.normal_stiffness *= c;
        chuck.interface.tangential_stiffness *= c;
        out.coverage = std::min(out.coverage, c);
        what += (what.empty() ? "" : "; ") + std::string("the ") + chuck.name + " chuck's " + std::to_string(n) +
                " pads (coverage " + significant(100 * c, 3) + " %) as a full band with its contact stiffness x " +
                significant(c, 3);
    }
    if (!what.empty())
        out.assumption = "axisymmetric equivalent: " + what +
                         " (exact for the n = 1 lateral and tilting stiffness of N >= 3 equal pads: "
                         "sum over the pads of int cos^2 theta = coverage x pi; the pads' coupling of n = 1 to "
                         "n = |1 +- j N| left out)";
    return out;
}

}  // namespace coremodal
