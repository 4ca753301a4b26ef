// `coremodal sensitivity CASE.toml [--parameters KEYS] [--output DIR]`:
// d ln f / d ln p of the case's modes (and k on chucks) for case-file keys,
// by default every material and contact constant (docs/how-to/calibration.md,
// "Sensitivities").
#include "analyses/sensitivity/sensitivity.hpp"
#include "app/commands.hpp"
#include "common/petsc_handle.hpp"
#include "output/results_folder.hpp"
#include "output/sensitivity_report.hpp"
#include "output/text_file.hpp"
#include "scene/case_file.hpp"

#include <iostream>

namespace coremodal {
namespace {

struct SensitivityCommandOptions {
    std::string case_file, output, model, mesh;
    std::vector<std::string> keys;
    bool force = false, quiet = false;
};

int run_sensitivity_command(const SensitivityCommandOptions& o) {
    const Scene scene = parse_case_file(o.case_file);
    const std::vector<std::string> keys = o.keys.empty() ? material_and_contact_keys(scene) : o.keys;
    const CaseParameters c = CaseParameters::read(o.case_file, keys, {}, o.model, o.mesh);
    sensitivity_level(c.scene(c.values()));  // refuses the solid level before any output is touched
    const std::filesystem::path out_dir = results_path(o.output, scene.name, "-sensitivity");
    claim_output(out_dir, o.force);
    if (!o.quiet && mpi_rank() == 0)
        std::cout << "sensitivity: " << keys.size() << " parameters of " << o.case_file << std::endl;
    const SensitivityResult r = eigen_sensitivities(c, c.values());
    if (mpi_rank() != 0) return 0;
    ResultsFolder folder(out_dir, o.force);
    write_text_file(folder.dir() / "sensitivity.csv", sensitivity_csv(r));
    write_text_file(folder.dir() / "report.md", sensitivity_report_markdown(scene.name, r));
    folder.commit();
    std::cout << sensitivity_console(r) << "sensitivity: " << out_dir.string() << "/report.md" << std::endl;
    return 0;
}

}  // namespace

Command add_sensitivity_command(CLI::App& app) {
    auto o = std::make_shared<SensitivityCommandOptions>();
    CLI::App* cmd = app.add_subcommand(
        "sensitivity", "d ln f / d ln p of the case's modes (and of the chuck factor k) for case-file keys, from "
                       "the eigenvalue derivative of the assembled operators (beam and harmonic levels)");
    cmd->add_option("case", o->case_file, "case file (TOML)")->required();
    cmd->add_option("-p,--parameters", o->keys,
                    "case-file keys as a [study] names them, e.g. core.material.G_rz supports.left.normal_stiffness "
                    "(default: every material and contact constant)");
    add_results_options(cmd, o->output, o->force, "-sensitivity");
    add_model_option(cmd, o->model);
    cmd->add_option("-m,--mesh", o->mesh, "mesh level, overriding the case's [mesh]: coarse, default, fine, very_fine");
    cmd->add_flag("-q,--quiet", o->quiet, "no progress lines");
    add_unused_option(cmd, "--no-plots", false, "it draws no pictures");
    cmd->footer("Writes sensitivity.csv and report.md (docs/how-to/calibration.md, \"Sensitivities\").");
    return {cmd, [o] { return run_sensitivity_command(*o); }, true};
}

}  // namespace coremodal
