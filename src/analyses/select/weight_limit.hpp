// A core grade's largest roll weight in a stand: its durability curve at the
// failure probability asked, scaled from the test chuck to the stand's chuck
// and by the winder (M. Ilomäki, "On the durability of cores and rest roll
// dynamics", eqs. {28} and {32}; docs/how-to/durability.md). Apart from the width
// limit (rest_roll_limit.hpp) so that it needs no solver: the fuzzer links it.
#pragma once

#include "selection/selection_scene.hpp"

#include <string>

namespace coremodal {

// The largest roll weight a core carries in a stand.
struct WeightLimit {
    double test_chuck_weight_n = 0;  // the reduced durability curve at the cycles asked, N
    double chuck_scale = 1;          // (stand chuck / test chuck)^exponent
    double winder_factor = 1;        // 1 two-drum, 0.8 centre (default)
    double weight_n = 0;             // the product
    std::string method;              // "{28} with C = 99 %" or "{32} (fitted values, no confidence)"
};
WeightLimit core_weight_limit(const CoreGrade& core, const Stand& stand, const SelectionScene& scene);

// A paper roll's mass (kg) from its diameter, width, paper density and core:
// mass_per_length of beam/formulas.hpp times the width.
double paper_roll_mass(const CoreGrade& core, double diameter, double width, double paper_density);

}  // namespace coremodal
