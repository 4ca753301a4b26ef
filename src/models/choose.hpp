// Which model level solves a scene: "auto" and the reasons a level cannot.
#pragma once

#include "models/model_level.hpp"
#include "scene/level_traits.hpp"
#include "scene/scene.hpp"

#include <memory>
#include <optional>
#include <string>

namespace coremodal {

// Why the harmonic level cannot solve the scene's contact: a chuck with a
// one-sided contact (not expanded), or nothing. The 3D solid and the
// coupled harmonics can.
std::optional<std::string> one_sided_contact_reason(const Scene& scene);

// Why the harmonic level cannot solve the scene (a user [mesh] file, a
// segmented expanding element, a one-sided contact: each breaks the symmetry about the axis), or
// nothing when it can.
std::optional<std::string> why_not_axisymmetric(const Scene& scene);

// Why the coupled-harmonic level (models/coupled) fits a scene the harmonic
// level cannot solve: its only departures from a body of revolution are
// segmented expanding elements held by a spring layer, a one-sided contact
// (a chuck not expanded) and the paper web's line; or nothing (a body of
// revolution, a [mesh] file, a bonded segment).
std::optional<std::string> why_coupled(const Scene& scene);

// An InputError naming the case file and why_not_axisymmetric's reason,
// for a scene the harmonic level cannot solve (`run` and `check` refuse it alike).
void require_axisymmetric(const Scene& scene);

// The level a run of the scene uses: its `model`, with "auto" resolved to
// the cheapest level that represents the whole scene (DESIGN.md): harmonic
// when the scene is a body of revolution, coupled when only segmented
// expanding elements on a spring layer, a one-sided contact or the web
// break the symmetry, else the solid.
ModelChoice chosen_level(const Scene& scene);

// The level a spinning run of the scene uses: chosen_level, except that
// where "auto" picks a level that cannot spin (the coupled harmonics), the
// solid spins the scene in co-rotating coordinates.
ModelChoice chosen_spinning_level(const Scene& scene);

// The level chosen_level picks and why, in words (`coremodal check`);
// `given`: where the scene's model key came from.
std::string level_choice_text(const Scene& scene, const std::string& given);

// The level chosen_level(scene) names (solid, harmonic, coupled or beam).
std::unique_ptr<ModelLevel> make_model_level(const Scene& scene);
// The level object of a resolved level (not ModelChoice::automatic), e.g.
// chosen_spinning_level's.
std::unique_ptr<ModelLevel> make_model_level(ModelChoice level);

}  // namespace coremodal
