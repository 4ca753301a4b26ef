// Step 7 of a run, at any model level: the first bending mode against beam
// theory, the chuck factor (a run of the derived free-span scene), and the
// check that a free scene shows its six rigid modes.
#include "analyses/run/run.hpp"

#include "beam/beam_theory.hpp"
#include "common/error.hpp"
#include "common/format.hpp"
#include "common/petsc_handle.hpp"
#include "scene/free_span.hpp"
#include "scene/mesh_levels.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {
namespace {

// The free-free roll over the free span (scene/free_span.hpp) on a coarse
// mesh. Its first bending mode is smooth (no clamp edge), so
// it converges at h^4: the coarse level is within 0.1 % of the converged
// value (case 01: 133.46 against 133.36 Hz), far inside the uncertainty of
// any k, at a fraction of the scene's cost; finer scene meshes do not
// coarsen it further.
Scene coarse_free_span_scene(const Scene& scene) {
    Scene free = free_span_scene(scene, 8);  // 6 rigid modes and the bending pair
    free.name = scene.name + "-free-span";
    const MeshLevel& coarse = *find_mesh_level("coarse");
    free.mesh.n_wall = std::min(scene.mesh.n_wall, coarse.n_wall);
    free.mesh.n_rest_paper = std::min(scene.mesh.n_rest_paper, coarse.n_rest_paper);
    free.mesh.n_around = std::min(scene.mesh.n_around,
                                  elements_around(coarse, free.core.inner_diameter, free.core.outer_diameter));
    const double span = free.core.length;
    free.mesh.n_along = std::min(
        static_cast<int>(std::lround(scene.mesh.n_along * span / scene.core.length)),
        elements_along(span, free.core.outer_diameter,
                       free.mesh.n_around, coarse.axial_aspect)
            .value_or(kMaxElementsAlong));
    free.mesh.n_along = std::max(free.mesh.n_along, kMinElementsAlong);
    return free;
}

// A lateral resonance of the roll: its first circumferential harmonic
// (n = 1), whether the roll bends in it ("bending") or moves almost as a body
// on compliant chucks, bearings or contact arcs ("support",
// modes/classify.hpp). Where a roll on soft supports crosses from one label
// to the other is a threshold of the classifier, not physics: both count.
bool is_lateral(const Mode& m) { return m.label.n == 1 && (m.label.type == "bending" || m.label.type == "support"); }

// In words, for the console, report.md and summary.json.
std::string why_no_bending_mode(const AnalysisSpec& analysis, const std::vector<Mode>& modes) {
    const long rigid = std::count_if(modes.begin(), modes.end(), [](const Mode& m) { return m.label.type == "rigid"; });
    const long lateral = std::count_if(modes.begin(), modes.end(), is_lateral);
    if (lateral > 0)
        return "the " + std::to_string(lateral) + " lateral (n = 1) modes found are all in the horizontal plane (f1 is "
               "the first in the vertical plane, docs/theory/chucks.md); " +
               (analysis.f_max_hz ? "widen the band" : "ask for more modes");
    if (analysis.f_max_hz) {
        const std::string band = "between " + significant(analysis.f_min_hz.value_or(0.0)) + " and " +
                                 significant(*analysis.f_max_hz) + " Hz";
        return modes.empty() ? "no modes " + band
                             : "no bending mode among the " + std::to_string(modes.size()) + " modes " + band +
                                   " (widen the band)";
    }
    return "no bending mode among the " + std::to_string(modes.size()) + " modes found (" + std::to_string(rigid) +
           " rigid); ask for more modes";
}

// Below this share of the largest sideways effective mass of any mode (a
// rigid translation's, on a free body) a mode has no plane of its own:
// effective masses that vanish by symmetry (antisymmetric modes, a free
// body's bending) come out of the products as round-off, 1e-20 of a
// symmetric mode's (case 07: 3.7e-20 kg against 72 kg).
constexpr double kNoPlaneFraction = 1e-9;

// f1, and with it k = f1 / f2, is the roll's first lateral resonance in the
// vertical plane (y-z; gravity acts along -y), docs/theory/chucks.md: a stand whose
// chucks hold the roll less stiffly sideways than vertically (a chuck not
// expanded sits on its contact arc) has a lower horizontal one, and a k that
// took whichever came first would change plane from scene to scene. The plane
// is the one the mode's effective mass is in: y at least x. Its label does
// not matter (is_lateral): a label must never change k. A mode with no
// translational effective mass (an antisymmetric one, or a level that gives
// none) has no plane to tell; when no lateral mode has one, the first lateral
// mode is f1.
const Mode* first_vertical_lateral(const std::vector<Mode>& modes) {
    double largest = 0;
    for (const auto& m : modes) largest = std::max(largest, m.effective_mass.x + m.effective_mass.y);
    const auto has_plane = [&](const Mode& m) {
        return m.effective_mass.x + m.effective_mass.y > kNoPlaneFraction * largest;
    };
    const Mode* first = nullptr;
    bool any_plane = false;
    for (const auto& m : modes) {
        if (!is_lateral(m)) continue;
        if (!first) first = &m;
        any_plane = any_plane || has_plane(m);
        if (has_plane(m) && m.effective_mass.y >= m.effective_mass.x) return &m;
    }
    return any_plane ? nullptr : first;
}

}  // namespace

ChuckFactor chuck_factor(const Scene& scene, double f1, bool by_model) {
    const auto& chucks = scene.supports.chucks;
    ChuckFactor k;
    k.li_left_m = chucks.at(0).li();
    k.li_right_m = chucks.at(1).li();
    k.li_m = (k.li_left_m + k.li_right_m) / 2;
    k.free_span_m = scene.core.length - k.li_left_m - k.li_right_m;
    k.f1_hz = f1;
    if (by_model) {
        // The derived scene's own beam comparison is the same Timoshenko beam
        // (the section, free-free over the free span): taken from it, not
        // solved twice.
        const BeamComparison free = analyse_derived_scene(coarse_free_span_scene(scene)).beam;
        k.f2_fe_hz = free.fe_first_bending_hz;
        k.f2_beam_hz = free.timoshenko_hz;
    } else {
        k.f2_beam_hz = timoshenko_bending_hz(beam_section(scene), k.free_span_m, BeamEnds::free_free, 1).at(0);
    }
    k.chuck_factor = k.f2_fe_hz > 0 ? f1 / k.f2_fe_hz : 0;
    k.chuck_factor_beam = f1 / k.f2_beam_hz;
    return k;
}

BeamComparison compare_with_beam(const Scene& scene, const std::vector<Mode>& modes) {
    BeamComparison b;
    const BeamSection section = beam_section(scene);
    const bool free = scene.supports.kind == SupportKind::free;
    b.span_m = beam_span(scene);
    b.ends = free ? "free-free" : "clamped-clamped";
    b.euler_bernoulli_hz = euler_bernoulli_first_bending_hz(section, b.span_m);
    b.timoshenko_hz =
        timoshenko_bending_hz(section, b.span_m, free ? BeamEnds::free_free : BeamEnds::clamped_clamped, 1).at(0);
    if (const Mode* m = first_vertical_lateral(modes)) {
        b.fe_first_bending_hz = m->frequency_hz;
        b.fe_mode_index = m->index;
        b.fe_over_timoshenko = m->frequency_hz / b.timoshenko_hz;
        b.fe_over_euler_bernoulli = m->frequency_hz / b.euler_bernoulli_hz;
        return b;
    }
    b.fe_missing = why_no_bending_mode(scene.analysis, modes);
    return b;
}

void check_rigid_modes(const RunReport& report) {
    const Scene& s = report.scene;
    // A user mesh may hold parts that touch nothing (warned about: six rigid modes each).
    // (A web holds a scene without supports: it has fewer rigid modes.)
    if (s.supports.kind != SupportKind::free || s.web || s.mesh.file || s.analysis.f_min_hz.value_or(0.0) > 0) return;
    const std::vector<Mode>& modes = report.modes.modes;
    const int expected = std::min<int>(kFreeBodyRigidModes, static_cast<int>(modes.size()));
    int rigid = 0, lowest_rigid = 0;
    for (size_t i = 0; i < modes.size(); ++i) {
        rigid += modes[i].label.type == "rigid";
        lowest_rigid += modes[i].label.type == "rigid" && static_cast<int>(i) < expected;
    }
    // Modes are named on rank 0 only: its verdict holds for every rank, so
    // that all stop together (a rank alone in a collective would wait forever).
    int ok = rigid == expected && lowest_rigid == expected;
    MPI_Bcast(&ok, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    MPI_Bcast(&rigid, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    if (ok) return;
    throw SolveError(s.source_file + ": the free scene's lowest modes should be its six rigid-body motions "
                     "(docs/validation/models.md), but " + std::to_string(rigid) + " of the lowest " +
                     std::to_string(modes.size()) + " are rigid: round-off in the stiffness matrix is as large as "
                     "the body's lowest elastic eigenvalues, so they cannot be told apart. A core " +
                     significant(s.core.length) + " m long and " + significant(s.core.outer_diameter) +
                     " m across is beyond what double precision resolves at this model level; expected a body at "
                     "least about a hundredth as long as its diameter");
}

}  // namespace coremodal
