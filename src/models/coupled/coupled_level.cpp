// The coupled-harmonic level's steps 2–6, numbered as in a run: the
// section, then the coupled problem for growing N until it has converged,
// then the modes named on the revolved section.
#include "models/coupled/coupled_level.hpp"

#include "assembly/chuck_supports.hpp"
#include "common/error.hpp"
#include "common/blas_threads.hpp"
#include "common/format.hpp"
#include "common/stopwatch.hpp"
#include "eigensolve/tolerances.hpp"
#include "geometry/tube_model.hpp"
#include "models/choose.hpp"
#include "models/coupled/contact_static.hpp"
#include "models/harmonic/harmonic_level.hpp"
#include "models/harmonic/harmonic_shapes.hpp"
#include "models/part_materials.hpp"
#include "models/solve_steps.hpp"
#include "modes/classify.hpp"
#include "modes/mac.hpp"
#include "modes/mode_shapes.hpp"

#include <algorithm>
#include <cmath>

namespace coremodal {

namespace {

// The wanted eigenvalues: the lowest `modes` (with a pair's partner), or the band's.
std::vector<double> wanted(const CoupledModes& m, const Scene& scene, const SolveRequest& request) {
    std::vector<double> out;
    for (double lambda : m.eigenvalues) {
        if (request.lambda_max) {
            if (in_band(lambda, request)) out.push_back(lambda);
        } else if (static_cast<int>(out.size()) < scene.analysis.n_modes ||
                   std::abs(lambda - out.back()) <= kClusterTolerance * std::abs(out.back())) {
            out.push_back(lambda);  // a pair is never cut in half
        }
    }
    return out;
}

// Room above the last step's band edge: eigenvalues that the extra
// harmonics leave where they were (e.g. the axial mode) must stay inside.
constexpr double kEdgeMargin = 1e-6;

// The largest relative change of a wanted frequency between two truncations
// (infinite when their counts differ). Rigid modes (f ~ 0) are compared on
// the scale of the first elastic one.
double max_change(const std::vector<double>& a, const std::vector<double>& b, double lambda_scale) {
    if (a.size() != b.size()) return INFINITY;
    double change = 0;
    const double floor_hz = eigenvalue_hz(lambda_scale);
    for (size_t i = 0; i < a.size(); ++i) {
        const double fa = eigenvalue_hz(a[i]), fb = eigenvalue_hz(b[i]);
        change = std::max(change, std::abs(fa - fb) / std::max(fb, floor_hz));
    }
    return change;
}

std::string convergence_text(const std::vector<CoupledStep>& steps) {
    std::string text;
    for (const CoupledStep& s : steps) {
        text += (text.empty() ? "" : "; ") + std::string("N=") + std::to_string(s.n_max) + ": " +
                std::to_string(s.n_dofs) + " DOFs, f1 " + significant(s.frequencies_hz.empty() ? 0.0 : s.frequencies_hz.front(), 7) +
                " Hz";
        if (&s != &steps.front()) text += ", max change " + significant(s.max_change, 2);
    }
    return text;
}

// What couples the harmonics, for the run's level line.
std::string coupling_text(const Attachments& attached) {
    std::string text;
    if (!attached.pads.empty())
        text = std::to_string(attached.pads.size()) + " segmented element(s) couple n to n +- j*" +
               std::to_string(attached.step());
    if (attached.web)
        text += std::string(text.empty() ? "" : "; ") + "the web's line at theta = " +
                significant(attached.web->theta * 180 / M_PI, 4) + " deg couples every n to every m";
    if (attached.one_sided)
        text += std::string(text.empty() ? "" : "; ") + "the one-sided contact's arc couples every n to every m";
    return text;
}

// A chuck not expanded: the static state under gravity with the harmonics
// n = 0 ... kContactStaticHarmonics (models/coupled/contact_static), and its
// closed points' linearised layer for the modes at every N.
ContactLayer linearised_contact_layer(const Scene& scene, const SectionMesh& section,
                                      const std::vector<PartMaterial>& materials, const Printer& say, LevelModes& out) {
    say("      static state under gravity (-y): one-sided contact by an active-set iteration, harmonics n = 0 ... " +
        std::to_string(kContactStaticHarmonics) + " (those even about the vertical)");
    CoupledContactState state = solve_coupled_contact(scene, section, materials, kContactStaticHarmonics, say);
    for (const std::string& line : contact_state_lines(state.contact, scene.roll_mass() * kStandardGravity)) {
        say("      " + line);
        out.assumptions.push_back(line);
    }
    return std::move(state.layer);
}

// What one coupled problem is posed on: the scene, its section and
// materials, and what couples the harmonics.
struct CoupledProblem {
    const Scene& scene;
    const SectionMesh& section;
    const std::vector<PartMaterial>& materials;
    const Attachments& attached;
    const SolveRequest& request;
};

// Adding harmonics only lowers eigenvalues (nested spaces), so every
// wanted mode at this N lies below the last step's band edge: each
// independent set is asked for its modes below that edge only (a band,
// counted first), not for all the modes asked of the whole.
SolveRequest step_request(const CoupledProblem& p, const std::optional<CoupledModes>& previous) {
    SolveRequest r = p.request;
    if (previous && !p.request.lambda_max && !wanted(*previous, p.scene, p.request).empty()) {
        r.lambda_min = -p.request.lambda_scale;  // below any rigid mode
        r.lambda_max = wanted(*previous, p.scene, p.request).back() * (1 + kEdgeMargin);
    }
    return r;
}

// The highest dominant harmonic of the wanted modes (the vectors live on rank 0).
int top_harmonic(const CoupledModes& modes, size_t n_wanted) {
    int n_top = 0;
    if (mpi_rank() == 0)
        for (size_t k = 0; k < n_wanted; ++k) n_top = std::max(n_top, modes.dominant_n(k));
    MPI_Bcast(&n_top, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    return n_top;
}

// The console line of one step of the search for N.
std::string step_line(const CoupledStep& step, size_t n_wanted, bool first, bool local, bool complete) {
    return "      N = " + std::to_string(step.n_max) + ": " + std::to_string(step.n_dofs) + " DOFs, " +
           std::to_string(n_wanted) + " modes from " +
           significant(step.frequencies_hz.empty() ? 0.0 : step.frequencies_hz.front(), 7) + " Hz" +
           (first ? std::string() : ", largest change " + significant(step.max_change, 2)) +
           (local ? ", zone edge " + significant(step.zone_edge, 2) : std::string()) + ", " +
           significant(step.seconds, 2) + " s" + (complete ? "" : " (INCOMPLETE)");
}

// The first N of the search: N_s + 1, or one step below where the level's
// last search stopped (a like scene: the same coupling reach), so that the
// first step that can stop the search is that N.
int first_harmonic(int reach, const std::optional<int>& last) {
    const int first = reach + 1;
    if (!last || *last - reach < first || (*last - first) % reach != 0) return first;
    return *last - reach;
}

// 3-5. The coupled problem for N = N_s + 1, 2 N_s + 1, ... (or from
// first_n): solved, verified, counted, until one more step moves no wanted
// frequency by kCoupledTolerance and N reaches every wanted mode's dominant
// harmonic plus N_s. Each step is recorded in `steps`; `local` grows with
// the wanted modes' harmonics.
CoupledModes grow_harmonics(const CoupledProblem& p, int first_n, std::optional<LocalHarmonics>& local,
                            std::vector<CoupledStep>& steps, const Printer& say, Timing& timing) {
    const int reach = p.attached.step();
    std::optional<CoupledModes> previous, current;
    for (int n_max = first_n;; n_max += reach) {
        if (n_max > kMaxHarmonic)
            throw SolveError("the coupled harmonics have not converged to " + significant(kCoupledTolerance, 2) +
                             " by N = " + std::to_string(kMaxHarmonic) + " (" + convergence_text(steps) +
                             "); ask for fewer modes or use model = \"solid\"");
        Stopwatch lap;
        current = solve_coupled(p.scene, p.section, p.materials, n_max, step_request(p, previous), p.attached, local);
        timing.factor_and_solve += lap.seconds();
        CoupledStep step{n_max, current->dofs.n_dofs, {}, 0, lap.seconds()};
        const std::vector<double> w = wanted(*current, p.scene, p.request);
        for (double lambda : w) step.frequencies_hz.push_back(eigenvalue_hz(lambda));
        const int n_top = top_harmonic(*current, w.size());
        step.max_change = previous ? max_change(wanted(*previous, p.scene, p.request), w, p.request.lambda_scale) : 0;
        if (local && mpi_rank() == 0) step.zone_edge = zone_edge_amplitude(*current, p.section, *local, w.size());
        MPI_Bcast(&step.zone_edge, 1, MPI_DOUBLE, 0, PETSC_COMM_WORLD);
        say(step_line(step, w.size(), !previous, local.has_value(), current->verification.complete));
        steps.push_back(step);
        const bool zone_enough = step.zone_edge <= kZoneEdgeTolerance;
        if (previous && step.max_change <= kCoupledTolerance && n_max >= n_top + reach && zone_enough) break;
        if (local) {
            // The spaces stay nested: the whole harmonics and the reach only grow.
            local->n_full = std::max(local->n_full, n_top);
            if (!zone_enough) local->reach_2 *= 2;
        }
        previous = std::move(current);
    }
    return std::move(*current);
}

// The run's model lines for the converged problem.
ModelInfo coupled_model_info(const Scene& scene, const SectionMesh& section, const CoupledModes& modes,
                             const std::vector<CoupledStep>& steps) {
    ModelInfo info;
    info.level = ModelChoice::coupled;
    info.element = "quad8";
    info.n_dofs = modes.dofs.n_dofs;
    info.n_nodes = section.n_nodes();
    info.n_elements = section.n_cells();
    for (const auto& [name, nodes] : section.node_groups)
        if (name.rfind("clamp_", 0) == 0) info.n_eliminated_nodes += static_cast<long>(nodes.size());
    info.mass_kg = modes.mass_kg;
    info.expected_mass_kg = scene.mass_from_dimensions();
    info.mesh_source = "generated section";
    info.harmonics = "coupled n = 0 ... " + std::to_string(modes.dofs.n_max) + " (both families for n >= 1), " +
                     std::to_string(modes.n_coupling_entries) + " coupling entries; " + convergence_text(steps);
    return info;
}

// The assumption the coupling and its truncation make, echoed in the run.
std::string coupling_assumption(const Attachments& attached, int n_max, const CoupledStep& last) {
    return std::string("coupled harmonics: ") +
           (attached.pads.empty() ? "" : "each segmented element's spring layer acts on its pads only (k(theta) = k on "
                                         "the pads, 0 between), integrated exactly in theta; ") +
           (attached.web ? "the web's springs act on one line of the roll's surface, exactly at its angle; " : "") +
           (attached.one_sided ? "the one-sided contact's linearised layer acts at its closed points (" +
                                     std::to_string(kContactPointsAround) + " angles around x " +
                                     std::to_string(kContactGaussAlong) + " Gauss points along each edge); "
                               : "") +
           "harmonics n = 0 ... " + std::to_string(n_max) + ", N grown in steps of " +
           std::to_string(attached.step()) + " until one step moved no wanted frequency by more than " +
           significant(kCoupledTolerance, 2) + " (last step: " + significant(last.max_change, 2) + ")";
}

// The assumption the local harmonics make, echoed in the run.
std::string local_harmonics_assumption(const LocalHarmonics& local, const CoupledStep& last) {
    return "coupled harmonics: n = 0 ... " + std::to_string(local.n_full) + " on the whole section, n >= " +
           std::to_string(local.n_full + 1) + " only within " + significant(local.reach(2) * 1e3, 3) +
           " mm x 2/n of the pads along z (what the pads stir there dies out with distance; held beyond): the "
           "largest amplitude at that edge is " + significant(last.zone_edge, 2) + " of the mode's largest (at most " +
           significant(kZoneEdgeTolerance, 2) + ", else the reach doubles)";
}

// 6. Every wanted mode named on the revolved mesh with the solid's
// classifier; effective masses from the rigid fields.
std::vector<Mode> named_modes(const Scene& scene, const CoupledModes& modes, const SolveRequest& request,
                              const RevolvedMesh& revolved) {
    const bool root = mpi_rank() == 0;
    const std::vector<int> frame_nodes = frame_nodes_of(scene, revolved.mesh);
    const ModeClassifier classifier(revolved.mesh, roll_nodes(revolved.mesh), body_held(scene));
    const std::optional<ModeSignatureSampler> signature =
        root ? std::optional<ModeSignatureSampler>(std::in_place, revolved.mesh) : std::nullopt;
    const std::vector<double> w = wanted(modes, scene, request);
    std::vector<Mode> out;
    for (size_t k = 0, kept = 0; k < modes.eigenvalues.size() && kept < w.size(); ++k) {
        const double lambda = modes.eigenvalues[k];
        if (!in_band(lambda, request)) continue;
        Mode mode = numbered_mode(static_cast<int>(++kept), lambda, modes.residuals[k]);
        if (root) {
            const auto& g = modes.gamma[k];
            mode.effective_mass.x = g[0] * g[0];
            mode.effective_mass.y = g[1] * g[1];
            mode.effective_mass.z = g[2] * g[2];
            mode.effective_mass.rz = g[3] * g[3];
            mode.shape = coupled_revolved_shape(revolved, modes, k, frame_nodes);
            mode.label = classifier.classify(mode.shape, lambda, request.lambda_scale);
            mode.signature = (*signature)(mode.shape);
        }
        out.push_back(std::move(mode));
    }
    return out;
}

}  // namespace

LevelModes CoupledLevel::solve(const Scene& scene, const Printer& say) {
    Stopwatch stage;
    if (scene.mesh.file)
        throw InputError(scene.source_file + ": model = \"coupled\": a [mesh] file; the coupled level meshes the "
                                             "scene's own r-z section; expected model = \"solid\"");
    Attachments attached = attachments(scene);
    if (attached.step() == 0) {
        // Nothing couples: the harmonics are independent, which the harmonic level solves one at a time.
        say("[2/7] no segmented expanding element and no web: nothing couples the harmonics; the harmonic level "
            "solves them");
        axisymmetric_ = std::make_unique<HarmonicLevel>();
        return axisymmetric_->solve(scene, say);
    }
    LevelModes out;

    // 2. Mesh: the r–z section (the harmonic level's) and its revolution, for showing the modes.
    // Why this level (the run's level line; `check` prints the same).
    const std::string why = why_coupled(scene).value_or("segmented expanding elements or the web");
    say("[2/7] coupled harmonics: " + why + "; " + coupling_text(attached));
    say("      meshing the r-z section");
    const SectionMesh section = make_section_mesh(make_tube_section(scene), scene.supports.clamps);
    revolved_ = revolve_section(section, std::min(scene.mesh.n_around, kMaxDisplayAround));
    add_frame_nodes(scene, revolved_->mesh);
    const std::vector<PartMaterial> materials = part_materials(scene, section.part_names, "generated section");
    if (attached.one_sided) attached.contact = linearised_contact_layer(scene, section, materials, say, out);
    out.timing.mesh = stage.lap();

    // 3-5. The coupled problem, N grown until the wanted frequencies stop moving.
    say("[3/7] " + std::to_string(section.n_cells()) + " quad8 cells, " + std::to_string(section.n_nodes()) +
        " nodes: n = 0 ... N coupled, stiffness and mass assembled per independent set");
    say(std::string("[4/7] solving one eigenproblem per independent set (SLEPc Krylov-Schur, shift-and-invert with ") +
        shift_invert_factor_package(PETSC_COMM_WORLD) + "; MUMPS LDL^T for the count)");
    const SolveRequest request = solve_request(scene);
    say(shift_scale_text(scene));
    const std::optional<int> last_n = steps_.empty() ? std::nullopt : std::optional<int>(steps_.back().n_max);
    steps_.clear();
    // The coupled sets' factors have small fronts (the section is 2D): OpenBLAS's
    // second thread costs more than it saves (case 10, 2026-11-26, load ~1:
    // 16.8 s wall and 16.4 s CPU on one thread, 19.9 s and 32.1 s on two).
    const SingleThreadBlas one_thread;
    std::optional<LocalHarmonics> local = local_harmonics(attached, section);
    if (local && last_whole_) local->n_full = std::max(local->n_full, *last_whole_);
    const CoupledModes modes = grow_harmonics({scene, section, materials, attached, request},
                                              first_harmonic(attached.step(), last_n), local, steps_, say, out.timing);
    if (local) last_whole_ = local->n_full;
    out.verification = modes.verification;
    out.info = coupled_model_info(scene, section, modes, steps_);
    out.assumptions.push_back("model level coupled: " + why);
    out.assumptions.push_back(coupling_assumption(attached, modes.dofs.n_max, steps_.back()));
    if (local) out.assumptions.push_back(local_harmonics_assumption(*local, steps_.back()));
    stage.lap();

    // 6. Name every mode on the revolved mesh.
    say("[5/7] classifying the modes");
    out.modes = named_modes(scene, modes, request, *revolved_);
    out.timing.classify = stage.lap();
    return out;
}

LevelShapes CoupledLevel::shapes() const {
    if (axisymmetric_) return axisymmetric_->shapes();
    return {&revolved_->mesh};
}

}  // namespace coremodal
