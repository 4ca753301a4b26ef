// Which core for which reel in which stand: each core grade's largest roll
// weight (its durability curve at the failure probability asked, scaled
// from the test chuck to the stand's chuck and by the winder), its largest
// reel width at which the rest roll still meets the stand's speed and
// amplitude limit, the chart of the two (the form of Figs. 18–19 of M.
// Ilomäki, "On the durability of cores and rest roll dynamics") and the
// verdict on each reel asked. docs/how-to/durability.md, "Choosing a core".
#pragma once

#include "analyses/select/rest_roll_limit.hpp"
#include "analyses/select/weight_limit.hpp"
#include "selection/selection_scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace coremodal {

struct CoreInStand {
    bool fits = true;               // the stand's chucks take this core (else nothing below is set)
    WeightLimit weight;
    double max_mass_kg = 0;         // weight / standard gravity
    double speed_width_m = 0;       // widest rest roll that meets the speed and amplitude limits (the verdict)
    RestRollVerdict speed_verdict;  // the verdict at speed_width_m: its governing criterion
    double i7_width_m = 0;          // I-5 with I-7 alone: the quick estimate, for comparison
    double weight_width_m = 0;      // widest reel of the stand's roll_diameter within the weight
    double max_width_m = 0;         // the smaller: the chart's corner
    std::string governing;          // "speed" or "weight"
    double core_mass_per_m = 0;     // kg/m
};

struct ReelVerdict {
    bool fits = true;        // the stand's chucks take the core
    double mass_kg = 0;      // per core (the core's own mass differs)
    bool weight_ok = false, speed_ok = false;
    double safe_speed_m_s = 0;
    std::string speed_governing;  // the verdict's lowest criterion at the reel's width
    bool passes() const { return fits && weight_ok && speed_ok; }
};
struct ReelCheck {
    std::size_t stand = 0;
    double web_speed = 0;
    std::vector<ReelVerdict> cores;        // per core grade
    std::optional<std::size_t> lightest;   // lightest passing core (mass per metre)
    std::optional<std::size_t> cheapest;   // cheapest passing core with a price
};

struct SelectionResult {
    std::vector<std::vector<CoreInStand>> table;  // [stand][core]
    std::vector<ReelCheck> reels;
    std::vector<std::string> assumptions;  // of the width verdict (rest_roll_assumptions)
};
SelectionResult select_cores(const SelectionScene& scene);

}  // namespace coremodal
