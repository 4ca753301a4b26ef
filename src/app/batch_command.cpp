// `coremodal batch DIR|FILES...`: many case files, each run by a child
// `coremodal run` process, a few at a time; a table of f1, the beam ratio and
// the safe web speed at the end (console, OUT/batch.csv, OUT/batch.md).
#include "analyses/batch/batch.hpp"
#include "app/commands.hpp"
#include "common/signals.hpp"
#include "output/batch_report.hpp"
#include "output/results_folder.hpp"
#include "output/text_file.hpp"

#include <filesystem>
#include <iostream>

namespace coremodal {

Command add_batch_command(CLI::App& app) {
    auto options = std::make_shared<BatchOptions>();
    auto mesh_level = std::make_shared<std::string>();
    CLI::App* cmd = app.add_subcommand(
        "batch", "Run many case files, each in its own process, and tabulate f1, FE/Timoshenko and v_safe");
    cmd->add_option("cases", options->inputs, "case files, or folders (every *.toml in them, sorted)")->required();
    cmd->add_option("-o,--output", options->output_dir,
                    "results folder: OUT/<case>/ and OUT/<case>.log per case, OUT/batch.csv and OUT/batch.md; "
                    "replaces only an earlier coremodal result, which is kept as OUT.previous (docs/reference/results.md)")
        ->capture_default_str();
    cmd->add_flag("--force", options->force, "remove the earlier result at --output instead of keeping it as .previous");
    cmd->add_option("-j,--jobs", options->jobs, "cases run at once (default: the number of cores)")
        ->check(CLI::Range(1u, 4096u));
    cmd->add_option("-m,--mesh", *mesh_level,
                    "mesh level for every case, overriding the case files: coarse, default, fine, very_fine");
    auto no_plots = std::make_shared<bool>(false);
    cmd->add_flag("--no-plots", *no_plots, "passed on to every case: no python3 pictures in their report.md");
    cmd->footer("Each case runs as `coremodal run CASE --output OUT/<case> --quiet`; a failing case does not stop "
                "the others. Exit code 1 if any case failed. See docs/how-to/batch.md.");
    auto run = [options, mesh_level, no_plots] {
        if (!mesh_level->empty()) options->mesh_level = *mesh_level;
        options->plots = !*no_plots;
        std::vector<BatchCase> cases = batch_cases(*options);
        // OUT is written in place: an earlier batch there moves to OUT.previous first.
        start_folder_in_place(options->output_dir, options->force, batch_folder_contents(cases));
        run_batch(cases, *options, std::cout);
        const std::filesystem::path out = options->output_dir;
        unless_interrupted([&] {  // no table of cases an interrupt stopped
            write_text_file(out / "batch.csv", batch_csv(cases));
            write_text_file(out / "batch.md", batch_markdown(cases));
        });
        print_batch_table(std::cout, cases);
        std::cout << "table: " << (out / "batch.csv").string() << ", " << (out / "batch.md").string() << std::endl;
        for (const auto& c : cases)
            if (!c.ok) return 1;
        return 0;
    };
    return {cmd, run, false};
}

}  // namespace coremodal
