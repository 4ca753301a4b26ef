#include "case_harness.hpp"

#include "beam/beam_model.hpp"
#include "common/error.hpp"
#include "scene/case_file.hpp"
#include "scene/scene_description.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace coremodal::fuzz {
namespace {

void check(bool ok, const std::string& what) {
    if (!ok) throw std::logic_error("fuzz invariant broken: " + what);
}

void check_modes(const BeamModelResult& result) {
    for (const BeamMode& mode : result.modes) {
        check(std::isfinite(mode.eigenvalue), "an eigenvalue that is not a finite number");
        check(std::isfinite(mode.frequency_hz), "a frequency that is not a finite number");
    }
}

}  // namespace

Outcome run_case_text(std::string_view text, const std::string& path) {
    Scene scene;
    try {
        scene = parse_case_text(text, path);
    } catch (const InputError&) {
        return Outcome::invalid;
    }
    // What `coremodal check` prints for a valid scene must never fail.
    const std::string described = describe_scene(scene, key_sources(text)) + describe_effects(scene) +
                                  describe_assumptions(scene);
    check(!described.empty(), "an empty scene description");
    try {
        check_modes(solve_beam_model(scene));
    } catch (const InputError&) {
        return Outcome::not_solvable;
    } catch (const SolveError&) {
        return Outcome::not_solvable;
    }
    return Outcome::solved;
}

}  // namespace coremodal::fuzz
