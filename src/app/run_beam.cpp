// run_beam_scene in four steps: build and solve the beam model, report the
// modes as a RunReport, compare with beam theory, write.
#include "app/run_beam.hpp"

#include "app/run_case.hpp"
#include "app/run_steps.hpp"

#include "beam/beam_model.hpp"
#include "beam/formulas.hpp"
#include "common/format.hpp"
#include "common/petsc_handle.hpp"
#include "common/stopwatch.hpp"
#include "output/results_folder.hpp"
#include "output/run_markdown.hpp"
#include "output/summary.hpp"
#include "output/text_file.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace coremodal {
namespace {

ModelInfo model_info(const Scene& scene, const BeamModelResult& beam) {
    return {"beam",
            "timoshenko3",
            beam.n_dofs,
            beam.network.n_nodes(),
            beam.network.n_elements(),
            beam.n_held_nodes,
            beam.network.mass(),
            scene.mass_from_dimensions(),
            "beam network (" + std::to_string(beam.network.beams.size()) + " beams)",
            ""};
}

Timing timing(const BeamModelTiming& t, double total) {
    Timing out;
    out.mesh = t.build;
    out.assemble = 0;  // done problem by problem inside the solve
    out.factor_and_solve = t.solve;
    out.classify = t.classify;
    out.total = total;
    return out;
}

// The beam each node belongs to (the core for a node a bonded chuck shares).
std::vector<std::string> node_beams(const BeamNetwork& net) {
    std::vector<std::string> name(net.n_nodes(), "frame");
    for (auto beam = net.beams.rbegin(); beam != net.beams.rend(); ++beam)
        for (int n : beam->nodes) name[n] = beam->name;
    return name;
}

// One row per mode and node: z and the six motions (M-normalised).
void write_beam_shapes_csv(const std::string& path, const BeamModelResult& beam) {
    std::ofstream f(path);
    f << "mode,node,beam,z_m,ux,uy,uz,rx,ry,rz\n";
    f.precision(10);
    const std::vector<std::string> beams = node_beams(beam.network);
    for (size_t i = 0; i < beam.modes.size(); ++i)
        for (int n = 0; n < beam.network.n_nodes(); ++n) {
            f << i + 1 << ',' << n << ',' << beams[n] << ',' << beam.network.node_z[n];
            for (int d = 0; d < beam_dof::per_node; ++d) f << ',' << beam.modes[i].shape(beam_dof::per_node * n + d);
            f << '\n';
        }
    if (!f) throw std::runtime_error("cannot write " + path);
}

void write_beam_results(const RunReport& report, const BeamModelResult& beam, const std::filesystem::path& dir,
                        bool force) {
    ResultsFolder folder(dir, force);
    write_summary_json(folder.file("summary.json"), report);
    write_modes_csv(folder.file("modes.csv"), report);
    write_beam_shapes_csv(folder.file("beam_shapes.csv"), beam);
    RunPictures none;
    none.problem = "the beam model level has no mesh to draw (its mode shapes are in beam_shapes.csv)";
    write_text_file(folder.file("report.md"), run_report_markdown(report, none));
    folder.commit();
}

// A body shorter than this many diameters is no beam: its section deforms
// (ovalling, breathing) in modes the beam level cannot see (docs/beam.md).
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

RunReport run_beam_scene(Scene scene, const RunOptions& options) {
    const bool root = mpi_rank() == 0;
    const auto say = [&](const std::string& line) {
        if (root && !options.quiet) std::cout << "  " << line << std::endl;
    };
    Stopwatch total;
    RunReport report = new_report(std::move(scene));
    const std::filesystem::path out_dir =
        options.output_dir ? std::filesystem::path(*options.output_dir) : std::filesystem::path("results") / report.scene.name;

    // 2. The beam network and its modes (no mesh: [mesh] does not apply).
    say("[2/4] beam model: building and solving the Timoshenko beam network");
    const BeamModelResult beam = solve_beam_model(report.scene);
    report.model = model_info(report.scene, beam);
    for (const std::string& w : beam_level_warnings(report.scene, beam)) {
        if (root) std::cerr << "coremodal: warning: " << report.scene.source_file << ": " << w << std::endl;
        report.warnings.push_back(w);
    }
    report.scene.assumptions.insert(report.scene.assumptions.end(), beam.assumptions.begin(), beam.assumptions.end());
    say("      " + std::to_string(report.model.n_elements) + " beam elements, " + std::to_string(report.model.n_nodes) +
        " nodes, " + std::to_string(report.model.n_dofs) + " DOFs in " + std::to_string(beam.n_problems) +
        " independent problems" + (beam.mirrored_planes ? " (bending planes mirrored)" : ""));

    // 3. Modes as the writers know them, and the beam-theory comparison.
    say("[3/4] comparing with beam theory");
    for (const BeamMode& m : beam.modes) report.modes.modes.push_back(report_mode(m, int(report.modes.modes.size()) + 1));
    report.modes.verification = beam.verification;
    check_rigid_modes(report);
    report.beam = compare_with_beam(report.scene, report.modes.modes);
    if (report.scene.supports.kind == SupportKind::chucks)  // f2: the beam network of the free span
        report.chuck = chuck_factor(report.scene, report.beam.fe_first_bending_hz, options.chuck_factor_by_fe);
    report.peak_memory_mb = peak_memory_mb();
    report.timing_s = timing(beam.timing_s, total.seconds());

    // 4. Write: console table, then the results folder (complete or not at all).
    if (root && !options.quiet) {
        print_mode_table(std::cout, report);
        print_verification_and_beam(std::cout, report);
        char line[160];
        const BeamModelTiming& t = beam.timing_s;
        std::snprintf(line, sizeof line,
                      "beam model: %.3f ms (build %.3f, assemble and solve %.3f, label %.3f; a first call, "
                      "repeated calls are faster: docs/performance.md)\n",
                      1e3 * (t.build + t.solve + t.classify), 1e3 * t.build, 1e3 * t.solve, 1e3 * t.classify);
        std::cout << line;
    }
    if (root && options.write_results) {
        say("[4/4] writing " + out_dir.string());
        write_beam_results(report, beam, out_dir, options.force);
    }
    return report;
}

}  // namespace coremodal
