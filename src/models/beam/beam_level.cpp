// The beam level's step 2: build and solve the network, its modes as Modes.
#include "models/beam/beam_level.hpp"

#include "common/format.hpp"

#include <cstdio>

namespace coremodal {
namespace {

ModelInfo model_info(const Scene& scene, const BeamModelResult& beam) {
    return {.level = ModelChoice::beam,
            .element = "timoshenko3",
            .n_dofs = beam.n_dofs,
            .n_nodes = beam.network.n_nodes(),
            .n_elements = beam.network.n_elements(),
            .n_eliminated_nodes = beam.n_held_nodes,
            .mass_kg = beam.network.mass(),
            .expected_mass_kg = scene.mass_from_dimensions(),
            .mesh_source = "beam network (" + std::to_string(beam.network.beams.size()) + " beams)",
            .harmonics = {}};
}

Timing timing(const BeamModelTiming& t) {
    Timing out;
    out.mesh = t.build;
    out.assemble = 0;  // done problem by problem inside the solve
    out.factor_and_solve = t.solve;
    out.classify = t.classify;
    return out;
}

// A body shorter than this many diameters is no beam: its section deforms
// (ovalling, breathing) in modes the beam level cannot see (docs/theory/beam.md).
constexpr double kMinBeamSlenderness = 1.0;

// What the user should know about this run of the beam level.
std::vector<std::string> beam_level_warnings(const Scene& scene, const BeamModelResult& beam) {
    std::vector<std::string> out;
    if (scene.mesh.file) out.push_back("[mesh] file is not used by model = \"beam\"");
    const double outer = scene.rest_paper ? scene.rest_paper->outer_diameter : scene.core.outer_diameter;
    if (scene.core.length < kMinBeamSlenderness * outer)
        out.push_back("[core] length = " + significant(scene.core.length) + " m is less than the outer diameter " +
                      significant(outer) + " m: no beam; the section deforms in modes this level cannot see "
                      "(ovalling, breathing); expected model = \"harmonic\" or \"solid\" for such a body");
    const int asked = scene.analysis.n_modes;
    if (!scene.analysis.f_max_hz && static_cast<int>(beam.modes.size()) < asked)
        out.push_back("[analysis] modes = " + std::to_string(asked) + " asks for more modes than the beam model has: " +
                      std::to_string(beam.n_dofs) + " free degrees of freedom, so all its " +
                      std::to_string(beam.modes.size()) + " modes are reported");
    return out;
}

}  // namespace

Mode report_mode(const BeamMode& b, int index) {
    Mode m;
    m.index = index;
    m.eigenvalue = b.eigenvalue;
    m.frequency_hz = b.frequency_hz;
    m.label = b.label;
    m.relative_residual = b.relative_residual;
    m.effective_mass = b.effective_mass;
    for (Eigen::Index node = 0; node < b.shape.size() / beam_dof::per_node; ++node)
        for (int d : {beam_dof::ux, beam_dof::uy, beam_dof::uz}) m.shape.push_back(b.shape(beam_dof::per_node * node + d));
    return m;
}

LevelModes BeamLevel::solve(const Scene& scene, const Printer& say) {
    // 2. The beam network and its modes (no mesh: [mesh] does not apply).
    say("[2/4] beam model: building and solving the Timoshenko beam network");
    beam_ = solve_beam_model(scene);
    const BeamModelResult& beam = *beam_;
    LevelModes out;
    out.info = model_info(scene, beam);
    for (const std::string& w : beam_level_warnings(scene, beam)) warn_about_model(scene.source_file, w, out.warnings);
    out.assumptions = beam.assumptions;
    say("      " + std::to_string(out.info.n_elements) + " beam elements, " + std::to_string(out.info.n_nodes) +
        " nodes, " + std::to_string(out.info.n_dofs) + " DOFs in " + std::to_string(beam.n_problems) +
        " independent problems" + (beam.mirrored_planes ? " (bending planes mirrored)" : ""));
    for (const BeamMode& m : beam.modes) out.modes.push_back(report_mode(m, static_cast<int>(out.modes.size()) + 1));
    out.verification = beam.verification;
    out.timing = timing(beam.timing_s);
    return out;
}

LevelShapes BeamLevel::shapes() const { return {nullptr, &*beam_}; }

std::string BeamLevel::console_note() const {
    char line[160];
    const BeamModelTiming& t = beam_->timing_s;
    std::snprintf(line, sizeof line,
                  "beam model: %.3f ms (build %.3f, assemble and solve %.3f, label %.3f; a first call, "
                  "repeated calls are faster: bench/results/log.md)\n",
                  1e3 * (t.build + t.solve + t.classify), 1e3 * t.build, 1e3 * t.solve, 1e3 * t.classify);
    return line;
}

}  // namespace coremodal
