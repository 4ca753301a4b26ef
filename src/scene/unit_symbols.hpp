// Every unit symbol the quantity parser (scene/units.hpp) accepts for a
// dimension, common or not: the JSON Schema's unit patterns
// (scene/case_json_schema.hpp). Apart from units.hpp, which most of the code
// includes, so that adding this did not rebuild it all.
#pragma once

#include "scene/units.hpp"

#include <string_view>
#include <vector>

namespace coremodal {

// As printed ("kg/m^3"); the reader also takes "kg/m3" and "kg/m³"
// (units.cpp, normalise_unit). Defined in units.cpp, beside the unit table.
std::vector<std::string_view> unit_symbols(Dimension d);

}  // namespace coremodal
