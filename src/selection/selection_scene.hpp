// A core-selection file's [selection] table (docs/how-to/durability.md, "Choosing a
// core: coremodal select"): core grades with their durability, stands with
// their unwinder chuck, winder and speed, the paper, and the reels to check.
// All SI inside: m, Pa, kg/m^3, m/s, N. Defaults cite M. Ilomäki, "On the
// durability of cores and rest roll dynamics" ("Examples of choosing cores",
// "About choosing cores", I-5).
#pragma once

#include "durability/durability_data.hpp"
#include "durability/durability_limits.hpp"

#include <algorithm>
#include <optional>
#include <string>
#include <vector>

namespace coremodal {

// The winder type's share of the two-drum roll weight a core carries:
// "If the rolls are wound with a center winder instead of a two drum winder,
// the maximum tolerated roll weight is decreased 20 %" (Ilomäki).
inline constexpr double kCentreWinderFactor = 0.8;
// Weight ∝ (unwinder chuck length / test chuck length)^exponent: "If the
// cylindrical supporting length of a chuck is doubled, the maximum tolerated
// roll mass can be doubled if the chuck bending does not increase
// considerably" (Ilomäki): exponent 1.
inline constexpr double kChuckLengthExponent = 1.0;
// I-5's safety factor: 0.7 (0.8 or less; 0.7 without a safety cage) keeps
// the mid-span vibration within about ±5 mm (Ilomäki).
inline constexpr double kSelectionSafeFactor = 0.7;
// Figs. 18–19: 15 m/s web speed, failure probability of order 1e-5.
inline constexpr double kSelectionWebSpeed = 15.0;
inline constexpr double kSelectionProbability = 1e-5;
// Figs. 18-19: "±5 mm" mid-span vibration amplitude.
inline constexpr double kSelectionAmplitudeLimit = 5e-3;  // m
// One roll wound and unwound is one cycle (Fig. 13: a winding is half a cycle).
inline constexpr double kSelectionCycles = 1.0;

struct CoreGrade {
    std::string name;
    double inner_diameter = 0, outer_diameter = 0;  // m
    double flexural_modulus = 0;                    // Ec, Pa
    double density = 0;                             // kg/m^3
    std::optional<double> price_per_m;              // any currency per metre of core
    // The durability: a data file (fitted here, confidence applied) or the
    // fitted b0 (N), b1, S_log of a fit made elsewhere ({32}: no confidence).
    std::string data_file;                // "" when given as numbers
    std::optional<DurabilityData> data;
    double b0_newton = 0, b1 = 0, s_log = 0;
    double test_chuck_length = 0;         // m
};

struct Stand {
    std::string name;
    double chuck_length = 0;         // the unwinder chuck's cylindrical supporting length, m
    double li = 0;                   // core end to the middle of the chuck's expanding element, m
    double chuck_factor = 0;         // k of I-6 in this stand
    double web_speed = kSelectionWebSpeed;
    double safe_factor = kSelectionSafeFactor;
    double amplitude_limit = kSelectionAmplitudeLimit;  // m, mid-span, of the width verdict
    std::string winder = "two-drum";  // or "centre"
    double centre_winder_factor = kCentreWinderFactor;
    double chuck_length_exponent = kChuckLengthExponent;
    double rest_roll_diameter = 0;   // Dp of the rest roll at its smallest, m
    double roll_diameter = 0;        // the full reel of this stand's chart, m
    std::vector<std::string> cores;  // the grades its chucks take; empty: all
    bool takes(const std::string& core) const {
        return cores.empty() || std::find(cores.begin(), cores.end(), core) != cores.end();
    }
    double winder_factor() const { return winder == "centre" ? centre_winder_factor : 1.0; }
};

struct Reel {
    std::string stand;  // the stand it runs in
    double width = 0, diameter = 0;  // m
    std::optional<double> web_speed;  // m/s; the stand's when not given
};

struct SelectionScene {
    std::string name, source, description;
    double failure_probability = kSelectionProbability;
    double confidence = kDefaultConfidence;
    double cycles = kSelectionCycles;
    double paper_density = 0;        // kg/m^3 of the wound paper
    double rest_paper_modulus = 0;   // Ep, Pa
    double rest_paper_density = 0;   // kg/m^3
    std::vector<CoreGrade> cores;
    std::vector<Stand> stands;
    std::vector<Reel> reels;
    std::vector<std::string> defaults;  // "[selection] cycles = 1 (Ilomäki, Fig. 13)"
};

// Reads the [selection] table of a TOML file; errors name the file, line,
// column and key and say what is expected (InputError). Data files are
// named relative to the selection file and read (and checked) here.
SelectionScene read_selection_file(const std::string& path);
SelectionScene read_selection_text(const std::string& text, const std::string& path);

// The JSON Schema (draft-07) of a core-selection file, for `coremodal schema
// --selection` and editors: the reader's keys, their types, units and the
// ranges of plain numbers; what it cannot say (a stand's cores among the
// grades, a reel wider than its chucks) is the reader's.
std::string selection_json_schema();

}  // namespace coremodal
