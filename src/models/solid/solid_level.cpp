// The solid level's steps 2–6, numbered as in a run: mesh, DOFs, the one
// OperatorSet, the solve, each eigenvector expanded on the mesh and named.
#include "models/solid/solid_level.hpp"

#include "assembly/chuck_supports.hpp"
#include "assembly/petsc_system.hpp"
#include "beam/eigenvalue_scale.hpp"
#include "common/error.hpp"
#include "common/heartbeat.hpp"
#include "common/stopwatch.hpp"
#include "eigensolve/modal_solver.hpp"
#include "geometry/tube_model.hpp"
#include "mesh/connectivity.hpp"
#include "mesh/gmsh_mesh.hpp"
#include "models/choose.hpp"
#include "models/harmonic/harmonic_level.hpp"
#include "models/part_materials.hpp"
#include "models/solid/gravity_contact.hpp"
#include "models/solid/mesh_resolution.hpp"
#include "models/solid/predicted_start.hpp"
#include "models/solve_steps.hpp"
#include "modes/classify.hpp"
#include "modes/mac.hpp"
#include "modes/mode_shapes.hpp"
#include "scene/mesh_rule.hpp"

#include <cmath>
#include <memory>
#include <set>
#include <thread>

namespace coremodal {
namespace {

std::vector<std::string> clamp_group_names(const Scene& scene) {
    std::vector<std::string> names;
    for (const auto& c : scene.supports.clamps) names.push_back("clamp_" + c.name);
    return names;
}

std::vector<std::string> chuck_group_names(const Scene& scene) {
    std::vector<std::string> names;
    for (const auto& c : scene.supports.chucks)
        for (const char* g : {"interface_%_core", "interface_%_chuck", "bearing_%"}) {
            std::string name = g;
            name.replace(name.find('%'), 1, c.name);
            names.push_back(name);
        }
    return names;
}

std::vector<int> clamped_nodes(const Scene& scene, const Mesh& mesh) {
    std::set<int> nodes;
    for (const auto& name : clamp_group_names(scene))
        for (int n : mesh.node_groups.at(name)) nodes.insert(n);
    return {nodes.begin(), nodes.end()};
}

// Nodes held by the ground (eliminated, or on springs to the ground) and the
// links that join parts (spring layers, ties): for the "part not held" check.
struct Holding {
    std::vector<int> held;
    std::vector<std::vector<int>> links;
};

Holding holding(const std::vector<int>& eliminated, const ChuckSupports& chucks) {
    Holding h{eliminated, {}};
    for (const NodeTie& t : chucks.ties) h.links.push_back({t.node, t.master});
    for (const CouplingElement& e : chucks.couplings) h.links.push_back(e.nodes);
    h.held.insert(h.held.end(), chucks.grounded.begin(), chucks.grounded.end());
    return h;
}

}  // namespace

DofMap solid_dofs(const Scene& scene, const Mesh& mesh, const ChuckSupports& chucks, LevelModes& out) {
    const std::string source = scene.mesh.file ? *scene.mesh.file : "generated mesh";
    std::vector<int> eliminated = clamped_nodes(scene, mesh);
    eliminated.insert(eliminated.end(), chucks.eliminated.begin(), chucks.eliminated.end());
    // In parallel, slabs (slab_node_order: why); in one process the mesh's
    // order, which the measured factor times were taken on.
    DofMap dofs = make_dof_map(mesh.n_nodes(), eliminated, chucks.ties,
                               mpi_size() > 1 ? slab_node_order(mesh) : std::vector<int>{});
    out.info = {.level = ModelChoice::solid,
                .element = cell_type_name(mesh.cell_type),
                .n_dofs = dofs.n_dofs,
                .n_nodes = mesh.n_nodes(),
                .n_elements = mesh.n_cells(),
                .n_eliminated_nodes = static_cast<long>(eliminated.size()),
                .mass_kg = 0,  // step 4 sums it
                .expected_mass_kg = scene.mass_from_dimensions(),
                .mesh_source = source,
                .harmonics = {}};
    const Holding held = holding(eliminated, chucks);
    for (const std::string& warning : unheld_parts(mesh, held.held, held.links))
        warn_about_model(source, warning, out.warnings);
    return dofs;
}

namespace {

// A model this large factors faster in as many processes as the machine has
// cores (MUMPS's distributed factor and block Lanczos, bench/results/log.md
// "Two processes"): case 03, 181,152 unknowns, 32.8 s under mpirun -n 2
// against 43.7 s in one process on 2 cores (AVX-512 machine; 40.4 against
// 44.7 s on a Zen 3 one); case 02, 101,760, 16.2 against 19.1 s.
constexpr int kProcessesHintDofs = 100000;

std::string processes_hint(int n_dofs) {
    const unsigned cores = std::thread::hardware_concurrency();
    if (mpi_size() > 1 || cores < 2 || n_dofs < kProcessesHintDofs) return "";
    return "      running in one process on " + std::to_string(cores) + " cores: `mpirun -n " + std::to_string(cores) +
           " coremodal run ...` splits the factorization (case 03's 181,152 unknowns on 2 cores: 10-25 % "
           "less time, by machine; bench/results/log.md, \"Two processes\")";
}

// Step 6: every eigenvector in the request's band expanded to the mesh's
// nodes, named, with its effective masses and signature.
std::vector<Mode> solid_modes(const Mesh& mesh, const DofMap& dofs, const OperatorSet& system,
                              const SolvedModes& solved, const SolveRequest& request, BodyHeld held) {
    const bool root = mpi_rank() == 0;
    const ModeClassifier classifier(mesh, roll_nodes(mesh), held);
    const std::optional<ModeSignatureSampler> signature =
        root ? std::optional<ModeSignatureSampler>(std::in_place, mesh) : std::nullopt;
    const EffectiveMassCalculator effective_mass(system.M(), mesh, dofs);
    std::vector<Mode> modes;
    for (size_t i = 0; i < solved.eigenvalues.size(); ++i) {
        const double lambda = solved.eigenvalues[i];
        if (!in_band(lambda, request)) continue;  // computed from the bottom, below the band
        Mode mode = numbered_mode(static_cast<int>(modes.size()) + 1, lambda, solved.relative_residuals[i]);
        mode.effective_mass = effective_mass(solved.vectors[i]);
        mode.shape = gather_node_displacements(solved.vectors[i], mesh, dofs);
        if (root) mode.label = classifier.classify(mode.shape, lambda, request.lambda_scale);
        if (root) mode.signature = (*signature)(mode.shape);
        modes.push_back(std::move(mode));
    }
    return modes;
}

// A chuck not expanded: the static state under gravity (active set, Cholesky),
// then its closed contact's springs added to K for the modes.
void linearise_about_gravity(const Scene& scene, const DofMap& dofs, const ChuckSupports& chucks,
                             OperatorSet& system, const Printer& say, LevelModes& out) {
    say("      static state under gravity (-y): one-sided contact by an active-set iteration");
    const Heartbeat beat("solving the static contact", say);
    const SupportEffects effects = support_effects(scene);
    const GravityContact contact = solve_gravity_contact(system, dofs, chucks, effects, say);
    add_couplings_to(system.K(), linearised_contact(chucks.contact_faces, contact.state, effects), dofs);
    for (const std::string& line : contact_state_lines(contact, scene.roll_mass() * effects.gravity->g)) {
        say("      " + line);
        out.assumptions.push_back(line);
    }
}

// Modes the prediction holds beyond the wanted ones: enough to see the gap
// above them, where the solve's one factorization is placed.
constexpr int kPredictedExtraModes = 6;

// On since the solves come in blocks (eigensolve/block_lanczos.hpp): one
// MUMPS LDL^T at the predicted edge is the operator and the count, in place
// of a CHOLMOD factor and a second (MUMPS) factor for the count. Case 03:
// 58 -> 39 s wall (bench/results/log.md, issue 19). With one-vector solves it
// did not pay (MUMPS's single solves are 1.7x CHOLMOD's); false returns to
// the negative shift and the separate count.
constexpr bool kPredictBandEdge = true;

// The same scene at the harmonic level, when it is a body of revolution on a
// generated mesh: the same section, exact in theta, one 2D problem per wave
// number (under a second for a rest roll). Its modes serve twice: their
// eigenvalues predict the band edge where the solve places its one LDL^T
// factor (eigensolve/modal_solver.hpp; held scenes asking for a count of
// modes), and their frequencies tell how well the solid's mesh resolves its
// modes around (mesh_resolution.hpp). Empty for a scene the harmonic level
// cannot take, or when it fails (the solve then uses a negative shift and a
// second factor for the count, and the mesh goes unchecked).
std::vector<Mode> harmonic_counterparts(const Scene& scene, const SolveRequest& request, const Printer& say,
                                        std::optional<RevolvedMesh>& revolved) {
    if (why_not_axisymmetric(scene)) return {};
    Scene axisymmetric = scene;
    axisymmetric.model = ModelChoice::harmonic;
    if (request.lambda_max) {
        // A band: the solid's modes lie at or above their exact frequencies,
        // so the counterparts of those in the band lie in it or below it.
        if (axisymmetric.analysis.f_min_hz) *axisymmetric.analysis.f_min_hz /= 2;
    } else {
        axisymmetric.analysis.n_modes = request.n_modes + kPredictedExtraModes;
    }
    Stopwatch watch;
    std::vector<Mode> modes;
    // A stage of its own in -log_view, apart from the solid's solve.
    static PetscLogStage stage = [] {
        PetscLogStage s;
        PetscLogStageRegister("Band edge predict", &s);
        return s;
    }();
    PetscLogStagePush(stage);
    try {
        HarmonicLevel level;
        modes = level.solve(axisymmetric, Printer{false}).modes;
        revolved = level.revolved();
    } catch (const std::exception& e) {
        PetscLogStagePop();
        say(std::string("      no solve at the harmonic level (band edge, mesh check): ") + e.what());
        return {};
    }
    PetscLogStagePop();
    say("      the harmonic level's " + std::to_string(modes.size()) + " modes (" + std::to_string(watch.lap()) +
        " s): band edge, mesh check");
    return modes;
}

// The eigenvalues that predict the band edge: none for a band, or for a free
// body, whose rigid modes keep the solver on its negative shift
// (modal_solver.cpp, predicted_shift).
std::vector<double> predicted_eigenvalues(const Scene& scene, const SolveRequest& request,
                                          const std::vector<Mode>& harmonic) {
    if (!kPredictBandEdge || request.lambda_max || scene.supports.kind == SupportKind::free) return {};
    std::vector<double> lambdas;
    for (const Mode& mode : harmonic) lambdas.push_back(mode.eigenvalue);
    return lambdas;
}

// On unless -predicted_start false: block Lanczos's first block from the
// harmonic level's modes at the solid's nodes (predicted_start.hpp; issue
// 39, measured in bench/results/log.md session 22).
std::shared_ptr<const std::vector<PetscVector>> predicted_start(const std::optional<RevolvedMesh>& revolved,
                                                                const std::vector<Mode>& harmonic, const Mesh& mesh,
                                                                const DofMap& dofs, Mat K, const Printer& say) {
    PetscBool on = PETSC_TRUE;
    COREMODAL_PETSC(PetscOptionsGetBool(nullptr, nullptr, "-predicted_start", &on, nullptr));
    if (!on || !revolved) return nullptr;
    auto vectors = std::make_shared<std::vector<PetscVector>>(harmonic_modes_on_solid(*revolved, harmonic, mesh, dofs, K));
    if (vectors->empty()) return nullptr;
    say("      block Lanczos starts from the harmonic level's modes at the solid's nodes (-predicted_start false: "
        "a random start)");
    return vectors;
}

// Rank 0's text on every rank.
std::string broadcast(std::string text) {
    int size = static_cast<int>(text.size());
    MPI_Bcast(&size, 1, MPI_INT, 0, PETSC_COMM_WORLD);
    text.resize(size);
    MPI_Bcast(text.data(), size, MPI_CHAR, 0, PETSC_COMM_WORLD);
    return text;
}

// Step 6b: the solid's modes against the harmonic level's (labels are on
// rank 0), a warning when the mesh does not resolve them (issue 33).
void check_mesh_resolution(const Scene& scene, const std::vector<Mode>& harmonic, LevelModes& out) {
    if (harmonic.empty()) return;
    std::string text;
    if (mpi_rank() == 0) {
        const MeshResolution r = compare_with_harmonic(out.modes, harmonic);
        text = mesh_resolution_text(r, scene).value_or("");
        if (!text.empty() && std::abs(r.error()) > kMeshGrossError)
            text = "GROSSLY UNRESOLVED: " + text + "; this mode's frequency is the mesh's, not the roll's";
    }
    text = broadcast(text);
    if (!text.empty()) warn_about_model(scene.source_file, text, out.warnings);
}

}  // namespace

Mesh make_solid_mesh(const Scene& scene) {
    GmshSession gmsh;
    if (scene.mesh.file && scene.supports.kind == SupportKind::chucks)
        throw InputError(scene.source_file + ": [mesh] file with [supports] type = \"chucks\": elastic chucks are "
                         "built into the generated mesh (core and chuck nodes must face each other); expected "
                         "no [mesh] file, or rigid clamps with a user mesh");
    if (scene.mesh.file) {
        Mesh mesh = read_msh_file(*scene.mesh.file);
        std::vector<std::string> parts = {"core"};
        if (scene.rest_paper) parts.push_back("rest_paper");
        require_groups(mesh, parts, clamp_group_names(scene), *scene.mesh.file,
                       scene.supports.kind == SupportKind::clamped ? "[supports] type = \"clamped\"" : "the scene");
        return mesh;
    }
    build_tube_model(make_tube_section(scene), scene.supports.clamps, scene.mesh.element);
    Mesh mesh = read_current_gmsh_mesh("generated mesh");
    require_groups(mesh, {"core"}, clamp_group_names(scene), "generated mesh", "the clamps");
    require_groups(mesh, {}, chuck_group_names(scene), "generated mesh", "the chucks");
    add_frame_nodes(scene, mesh);
    return mesh;
}

LevelModes SolidLevel::solve(const Scene& scene, const Printer& say) {
    Stopwatch stage;
    LevelModes out;
    // 2. Mesh: the section extruded into quadratic hexahedra (or the user's mesh).
    say("[2/7] meshing" + (scene.mesh.file ? " (reading " + *scene.mesh.file + ")" : std::string()));
    // The counts and why (issue 33, 12): in the output and, as an assumption, in the summary.
    if (const auto rule = mesh_rule_text(scene)) {
        say("      " + *rule);
        out.assumptions.push_back(*rule);
    }
    if (const auto coarse = explicit_mesh_warning(scene, true)) warn_about_model(scene.source_file, *coarse, out.warnings);
    {
        const Heartbeat beat("meshing", say);
        mesh_ = make_solid_mesh(scene);
    }
    const Mesh& mesh = *mesh_;
    out.timing.mesh = stage.lap();

    // 3. Degrees of freedom.
    const ChuckSupports chucks = chuck_supports(scene, mesh);
    const DofMap dofs = solid_dofs(scene, mesh, chucks, out);
    say("      " + std::to_string(mesh.n_cells()) + " " + out.info.element + " cells, " +
        std::to_string(mesh.n_nodes()) + " nodes, " + std::to_string(dofs.n_dofs) + " DOFs (" +
        std::to_string(out.info.n_eliminated_nodes) + " clamped nodes eliminated)");
    if (const std::string hint = processes_hint(dofs.n_dofs); !hint.empty()) say(hint);

    // 4. The one problem: the OperatorSet of the whole solid.
    say("[3/7] assembling stiffness and mass");
    OperatorSet system = [&] {
        const Heartbeat beat("assembling", say);
        return assemble_petsc(mesh, part_materials(scene, mesh.part_names, out.info.mesh_source), dofs,
                              chucks.couplings);
    }();
    out.info.mass_kg = system.model_mass;
    if (!chucks.contact_faces.empty()) linearise_about_gravity(scene, dofs, chucks, system, say, out);
    out.timing.assemble = stage.lap();

    // 5. Solve, verify, prove complete. The scale of the first elastic
    //    eigenvalue sets the shift (and what counts as rigid).
    SolveRequest request = solve_request(scene);
    // Which factors: the solver's progress lines say (one LDL^T at a
    // predicted band edge, or a negative shift and a second factor to count).
    say("[4/7] solving the eigenproblem (shift-and-invert)");
    std::optional<RevolvedMesh> revolved;
    const std::vector<Mode> harmonic =
        scene.mesh.file ? std::vector<Mode>{} : harmonic_counterparts(scene, request, say, revolved);
    request.predicted_eigenvalues = predicted_eigenvalues(scene, request, harmonic);
    request.predicted_vectors = predicted_start(revolved, harmonic, mesh, dofs, system.K(), say);
    say(shift_scale_text(scene));
    const SolvedModes solved = solve_for_case(scene, system, request, say, "");
    out.verification = solved.verification;
    out.timing.factor_and_solve = stage.lap();

    // 6. Name every mode and compute its effective masses.
    say("[5/7] classifying " + std::to_string(solved.eigenvalues.size()) + " modes");
    out.modes = solid_modes(mesh, dofs, system, solved, request, body_held(scene));
    check_mesh_resolution(scene, harmonic, out);
    out.timing.classify = stage.lap();
    return out;
}

LevelShapes SolidLevel::shapes() const { return {&*mesh_}; }

}  // namespace coremodal
