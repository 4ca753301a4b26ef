#include "scene/level_traits.hpp"

#include "common/error.hpp"

#include <algorithm>
#include <array>

namespace coremodal {
namespace {

constexpr const char* kOneProblem = "";
constexpr const char* kNoCounts = "";

const std::array<LevelTraits, 4> kLevels{{
    {.level = ModelChoice::beam,
     .title = "Beam",
     .axisymmetric_only = false,
     .spins = true,
     .why_not_spinning = "",
     .spins_in_rotating_frame = false,
     .centrifugal = false,
     .response_needs_revolution = false,
     .pencil_critical_speeds = true,
     .through_wall_shear = false,
     .sensitivities = true,
     .converge_ladder = true,
     .converge_reference = false,
     .meshed = false,
     .campbell_damping = false,
     .dofs_counted = "DOFs",
     .problems_line = kOneProblem,
     .inertia_counts = kNoCounts,
     .count_owners = kNoCounts,
     .response_heading = "Beam level, ",
     .response_equation = "(K - w^2 M + i w (W G + D)) x = f"},
    {.level = ModelChoice::harmonic,
     .title = "Harmonic",
     .axisymmetric_only = true,
     .spins = true,
     .why_not_spinning = "",
     .spins_in_rotating_frame = false,
     .centrifugal = true,
     .response_needs_revolution = false,
     .pencil_critical_speeds = false,
     .through_wall_shear = true,
     .sensitivities = true,
     .converge_ladder = true,
     .converge_reference = false,
     .meshed = true,
     .campbell_damping = true,
     .dofs_counted = "DOFs per wave number n",
     .problems_line = "one 2D problem per wave number n (modes with n >= 1 come in pairs turned by 90°/n)",
     .inertia_counts = "inertia counts, one per harmonic at its own shift (listed above), summed with pairs twice",
     .count_owners = "harmonics'",
     .response_heading = "Harmonic level (wave number n = 1), ",
     .response_equation = "(K - w^2 M + w W G + i w D) a = p (wave number n = 1)"},
    {.level = ModelChoice::coupled,
     .title = "Coupled",
     .axisymmetric_only = false,
     .spins = false,
     .why_not_spinning = "the coupled harmonics have no spinning terms yet",
     .spins_in_rotating_frame = false,
     .centrifugal = false,
     .response_needs_revolution = false,
     .pencil_critical_speeds = false,
     .through_wall_shear = true,
     .sensitivities = false,
     .converge_ladder = false,
     .converge_reference = false,
     .meshed = true,
     .campbell_damping = false,
     .dofs_counted = "DOFs",
     .problems_line = "coupled harmonics (segmented chucks, a chuck not expanded, the web), one problem per "
                      "independent set of wave numbers (docs/theory/coupled.md)",
     .inertia_counts = "inertia counts, one per independent set of the coupled harmonics, summed",
     .count_owners = "independent sets'",
     .response_heading = "",
     .response_equation = ""},
    {.level = ModelChoice::solid,
     .title = "Solid",
     .axisymmetric_only = false,
     .spins = true,
     .why_not_spinning = "",
     .spins_in_rotating_frame = true,
     .centrifugal = true,
     .response_needs_revolution = true,
     .pencil_critical_speeds = false,
     .through_wall_shear = true,
     .sensitivities = false,
     .converge_ladder = true,
     .converge_reference = true,
     .meshed = true,
     .campbell_damping = false,
     .dofs_counted = "DOFs",
     .problems_line = kOneProblem,
     .inertia_counts = kNoCounts,
     .count_owners = kNoCounts,
     .response_heading = "Solid level, ",
     .response_equation = "(K - w^2 M + i w (W G + D)) x = f"},
}};

}  // namespace

const LevelTraits& level_traits(ModelChoice level) {
    const auto* found = std::find_if(kLevels.begin(), kLevels.end(), [&](const LevelTraits& t) { return t.level == level; });
    COREMODAL_ASSERT(found != kLevels.end());  // "auto" is resolved by chosen_level first
    return *found;
}

}  // namespace coremodal
