// A core's winding–unwinding simulator results (cycles to delamination
// against the roll weight of each test) as a CSV file with units in its
// header and the test chuck said in `#` lines above it (docs/how-to/durability.md,
// "The data file"):
//
//   # 76x15 mm cores, simulator runs of 2025 (made-up example)
//   # chuck_length = 100 mm
//   # chuck_type = non-expanding
//   cycles,max_roll_weight [kN]
//   0.5,31.2
//   3.5,24.0
//
// Cycles count from 0.5 (a core that fails before the first unwinding has
// lasted half a cycle: M. Ilomäki, "On the durability of cores and rest roll
// dynamics", Fig. 13). Weights in N, kN, kg or t (a mass is the roll's
// weight divided by standard gravity).
#pragma once

#include <string>
#include <vector>

namespace coremodal {

// Standard gravity (CGPM 1901), between a roll's mass and its weight.
inline constexpr double kStandardGravityForWeight = 9.80665;

// The chuck types the file may name.
inline constexpr const char* kChuckTypes[] = {"expanding", "non-expanding"};

struct DurabilityData {
    std::string source;           // the file as named
    double chuck_length_m = 0;    // the test chuck's cylindrical supporting length
    std::string chuck_type;       // one of kChuckTypes
    std::string weight_name;      // the weight column's name ("max_roll_weight")
    std::string weight_unit;      // its unit as written ("kN")
    double weight_unit_newton = 1;  // one weight unit in N (1 kg: 9.80665 N)
    std::vector<double> cycles;   // x_i >= 0.5
    std::vector<double> weights;  // y_i > 0, in weight_unit
    std::vector<int> lines;       // the file line of each point
};

// Parses `text` (named `source` in messages). Throws InputError
// "source:line:col: ..." naming the column and what is expected for: a
// missing or unknown chuck line, a header without a unit, a row without two
// numbers, NaN or infinity, cycles below 0.5, a weight that is not positive,
// fewer than three points, all points at one cycle count.
DurabilityData parse_durability_data(const std::string& text, const std::string& source);
DurabilityData read_durability_data(const std::string& path);

// The factor to N of a weight unit (N, kN, kg, t), or 0 when not one of them.
double weight_unit_in_newton(const std::string& unit);

}  // namespace coremodal
