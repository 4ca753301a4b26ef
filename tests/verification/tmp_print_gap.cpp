#include "tube_scenes.hpp"
#include <catch2/catch.hpp>
#include <iostream>
using namespace coremodal;
using namespace coremodal::testing;
TEST_CASE("tmp print gap", "[tmpgap]") {
    Scene s = with_chucks(paper_core(1.0, 32, 24), InterfaceKind::spring);
    for (ChuckSpec& c : s.supports.chucks) {
        c.bearing.rigid = false; c.bearing.radial_stiffness = 2e8; c.bearing.tilting_stiffness = 2e6;
        c.bearing.frame_mass = 20.0; c.bearing.frame_stiffness = 5e7;
    }
    s.analysis.n_modes = 14;
    const RunReport solid = solve_quietly(s);
    s.model = "harmonic";
    const RunReport h = solve_quietly(s);
    for (size_t i = 0; i < h.modes.modes.size(); ++i)
        std::cout << i + 1 << " " << h.modes.modes[i].label.type << " n" << h.modes.modes[i].label.n << " m" << h.modes.modes[i].label.m << " " << h.modes.modes[i].frequency_hz << " " << solid.modes.modes[i].frequency_hz << " " << 100 * (solid.modes.modes[i].frequency_hz / h.modes.modes[i].frequency_hz - 1) << " %\n";
}
