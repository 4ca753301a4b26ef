// The smallest case file the program tests run: quick to solve, simple to
// check against closed forms.
#pragma once

#include <string>

namespace coremodal::testing {

// A steel tube 0.5 m long with one hex20 through the wall, 8 around, 4 along:
// 792 DOFs, a second to solve. Steel keeps the closed forms simple.
inline const std::string kTinyCase = R"(name = "tiny"

[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "0.5 m"
material = { E = "210 GPa", nu = 0.3, density = "7850 kg/m^3" }

[analysis]
modes = 12

[mesh]
around = 8
along = 4
through_wall = 1
)";

}  // namespace coremodal::testing
