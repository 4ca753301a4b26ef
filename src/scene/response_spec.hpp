// [damping], [excitation] and [response] of a case file (docs/how-to/response.md):
// the forced response of a spinning roll to its own imperfections, and the
// safe web speed read off the amplitude limit. Like [rotation], the tables
// are read beside the Scene, not into it: the case reader checks them with
// every other key (every command refuses a wrong one), and the commands
// that simulate the response read them with parse_response_case. Only a
// scene with [response] simulates damping and excitation; [excitation]
// without [response] is refused (it would simulate nothing), and so is
// [damping] without [response] or [rotation] (a Campbell sweep damps its modes).
#pragma once

#include "scene/rotation_spec.hpp"
#include "scene/scene.hpp"

#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace coremodal {

// Rayleigh damping D = alpha M + beta K (effects/damping.hpp: the modal
// ratio it gives each mode).
struct RayleighSpec {
    double alpha = 0;  // 1/s, the mass-proportional part
    double beta = 0;   // s, the stiffness-proportional part
};

// The mode families a [damping] ratio can name: the words the mode labels use
// (modes/classify at the solid and harmonic levels; the beam level names
// bending, axial and torsion).
inline const std::vector<std::string_view> kDampingFamilies = {"bending", "torsion", "axial", "breathing", "ovalling"};

// The damping of the modes at rest: a base for every mode that is not named
// (one relative damping ratio zeta, or Rayleigh's alpha M + beta K), and
// ratios per mode family and per mode on top of it (a mode's own ratio wins
// over its family's, its family's over the base).
struct DampingSpec {
    double ratio = 0;    // the base zeta, 0 < zeta < 1; 0 when `rayleigh` is the base
    std::string source;  // how the file gave the base: "ratio = 0.01", "log_decrement = 0.06 (I-1: ...)"
    std::optional<RayleighSpec> rayleigh;  // the base as a matrix, instead of `ratio`
    struct FamilyRatio {
        std::string family;  // one of kDampingFamilies
        double ratio = 0;
    };
    std::vector<FamilyRatio> families;
    struct ModeRatio {
        int mode = 0;  // 1-based, as in modes.csv of the scene at rest
        double ratio = 0;
        std::string where;  // "FILE:LINE:COL: [damping.modes #1]": the run checks the number against the modes at rest
    };
    std::vector<ModeRatio> modes;
    // Structural damping: a loss factor eta for every part ([damping]
    // loss_factor) and per part ([damping.loss_factors] core, rest_paper,
    // chucks), effects/damping.hpp StructuralDamping. With no viscous base
    // (ratio ... rayleigh) the loss factors are the only damping (ratio 0).
    double loss_factor = 0;
    std::map<std::string, double> part_loss_factors;
};

// The parts a loss factor can name ([damping.loss_factors]).
inline const std::vector<std::string_view> kLossFactorParts = {"core", "rest_paper", "chucks"};
// The loss factors in words, the one wording of `check`'s echo and the
// response's summary, assumptions and notes: "loss factor 0.03 (every part);
// core 0.02", or "" without (no part has eta > 0).
std::string loss_factor_words(const DampingSpec& d);
// [damping] as `check` echoes it, a line per base, family, mode and loss factor.
std::string describe_damping(const DampingSpec& d);

// The shape of a bow (straightness deviation) along the core, scaled to the
// bow at mid-core: a half sine over the core length, or the roll's first
// bending mode at rest in its stand.
enum class BowShape { half_sine, first_mode };
const char* bow_shape_name(BowShape s);  // "half_sine", "first_mode"

// What excites the spinning roll (effects/excitation.hpp states each load).
struct ExcitationSpec {
    double bow_m = 0;  // straightness deviation at mid-core (ISO 11093-5), m
    BowShape bow_shape = BowShape::half_sine;
    double unbalance_kg_m = 0;  // a point unbalance at mid-core, kg m
    double eccentricity_m = 0;  // the rest paper's mass centre off the axis, uniform along the roll, m
    double ovality_m = 0;       // roundness deviation of the core, D_max - D_min, m
    bool gravity = true;        // gravity acts (vertical): with ovality, an order-2 load
};

// Where and how fast: the rotation speeds (from web speeds at Dp, or given
// as rotation speeds), the amplitude limit and the probes.
struct ResponseRange {
    std::vector<double> speeds_hz;  // f_rot, ascending, > 0
    bool from_web_speed = false;
    double limit_m = 0;  // the amplitude limit (semi-major axis of the mid-span orbit)
    struct Probe {
        std::string name;  // "mid-span" or "z = 1.2 m"
        double z_m = 0;    // from the core's left end
    };
    std::vector<Probe> probes;  // the first is the one the safe speed is read at
};

// The default amplitude limit: Ilomaki's +-5 mm at mid-span (Ilomäki:
// the field's limit, which I-5's factor 0.7-0.8 is meant to keep).
inline constexpr double kDefaultAmplitudeLimit = 5e-3;  // m
inline constexpr std::string_view kMidSpan = "mid-span";

struct ResponseSetup {
    DampingSpec damping;
    ExcitationSpec excitation;
    ResponseRange response;
};

// The case at `path`, its [rotation] and its response setup (none without
// [response]). Throws InputError as parse_case_file does.
struct ResponseCase {
    Scene scene;
    std::optional<RotationSpec> rotation;
    std::optional<ResponseSetup> response;
    std::optional<DampingSpec> damping;  // [damping], with [response] or alone with [rotation] (campbell)
};
ResponseCase parse_response_case(const std::string& path);
ResponseCase parse_response_case_text(std::string_view text, const std::string& path);

}  // namespace coremodal
