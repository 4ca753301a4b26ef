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

// An ISO 11093-8 free-hanging sample: a free 76x15 paperboard tube, 1.5 m
// (case 01's tube), at `model`, asking `modes` modes; `tail` adds tables
// (e.g. a [mesh] level).
inline std::string iso_sample_case(const std::string& model, int modes, const std::string& tail = "") {
    return "name = \"iso\"\nmodel = \"" + model + R"("
[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "1.5 m"
material = "paperboard_core"
[analysis]
modes = )" + std::to_string(modes) + "\n" + tail;
}

// Ilomaki's rotation tester's core (case 12) at the beam level: a 76x15
// wide-ply core, 2211 mm, clamped over 70 mm at each end; f1 ~ 69 Hz. The
// spinning scenes' program tests add [rotation] or [response] to it.
inline const std::string kClampedTesterCore = R"(name = "small"
model = "beam"
[core]
inner_diameter = "76 mm"
wall = "15 mm"
length = "2211 mm"
material = { base = "paperboard_core", E_z = "6500 MPa" }
[supports]
type = "clamped"
[supports.left]
length = "70 mm"
[analysis]
modes = 6
)";

}  // namespace coremodal::testing
