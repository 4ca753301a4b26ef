"""Command line, ``python3 -m coremodal`` or, installed (pip install ./python),
``coremodal-plot``: ``python3 -m coremodal table|plot RESULTS/modes.h5 ...``,
``python3 -m coremodal run-plot RESULTS_DIR --modes ...``,
``python3 -m coremodal converge-plot CONVERGE_DIR``,
``python3 -m coremodal study-plot STUDY_FOLDER``,
``python3 -m coremodal paraview RESULTS_DIR ...`` (ParaView's pvpython) and
``python3 -m coremodal winder-plot WINDER_FOLDER`` and
``python3 -m coremodal campbell-plot CAMPBELL_FOLDER`` and
``python3 -m coremodal response-plot RESPONSE_FOLDER`` and
``python3 -m coremodal traction-plot TRACTION_FOLDER``.
``python3 -m coremodal durability-plot DURABILITY_FOLDER`` and
``python3 -m coremodal selection-plot SELECT_FOLDER`` and
``python3 -m coremodal limits-plot LIMITS_FOLDER``.

    python3 -m coremodal table results/modes.h5
    python3 -m coremodal plot results/modes.h5 --mode 7 --out mode7.png
    python3 -m coremodal run-plot results/02-clamped-76x15 --modes 7,9   # the run report's PNGs
    python3 -m coremodal converge-plot results/CASE-converge     # error_vs_time.png from converge.json
    python3 -m coremodal study-plot results/06-study-safe-speed-study
    python3 -m coremodal paraview results/02-clamped-76x15 --mode 1 --out mode1.png   # needs pvpython
    python3 -m coremodal winder-plot results/11-two-drum-winder-winder  # crossing_diagram.png, response.png
    python3 -m coremodal campbell-plot results/12-rotation-tester-76x15-campbell  # campbell.png
    python3 -m coremodal response-plot results/13-rest-roll-response-response  # response.png
    python3 -m coremodal traction-plot results/19-grooved-idler-traction-traction  # traction.png
    python3 -m coremodal durability-plot results/18-core-B-durability  # durability.png
    python3 -m coremodal selection-plot results/18-core-selection-select  # selection_chart.png
    python3 -m coremodal limits-plot results/16-limits-rotogravure-150x15.8-4320-limits  # limits.png

The plot commands of a whole results folder (study-plot, winder-plot, ...)
are one table, FOLDER_PLOTS: a new one is a row there. ``--version`` prints
the package's version.

Exit status: 0 on success, 1 if the file cannot be read or the mode does not
exist, or the folder holds no study (with a one-line message on stderr), 2 for
a usage error.
"""

from __future__ import annotations

import argparse
import sys
from dataclasses import dataclass
from pathlib import Path

from .results import ResultsFormatError, load


@dataclass(frozen=True)
class FolderPlot:
    """A plot command that draws every picture of one command's results
    folder: ``module.function(folder)`` returns the path(s) it wrote and
    raises ``module.error`` on a folder it cannot read."""

    command: str  # the coremodal command that writes the folder
    pictures: str  # what it draws, for --help
    module: str
    function: str
    error: str
    when_empty: str = "nothing drawn"


FOLDER_PLOTS = {
    "study-plot": FolderPlot("study", "the PNG plots (of study.csv; calibrate's too)",
                             "study_plot", "draw_all", "StudyFormatError", "no successful point"),
    "winder-plot": FolderPlot("winder", "crossing_diagram.png and response.png", "winder_plot", "draw_all",
                              "WinderFormatError"),
    "campbell-plot": FolderPlot("campbell", "campbell.png", "campbell_plot", "draw", "CampbellFormatError"),
    "response-plot": FolderPlot("response", "response.png", "response_plot", "draw", "ResponseFormatError"),
    "traction-plot": FolderPlot("traction", "traction.png", "traction_plot", "draw", "TractionFormatError"),
    "durability-plot": FolderPlot("durability", "durability.png", "durability_plot", "draw_all",
                                  "DurabilityFormatError"),
    "selection-plot": FolderPlot("select", "selection_chart.png", "selection_plot", "draw_all",
                                 "SelectionFormatError"),
    "limits-plot": FolderPlot("limits", "limits.png", "limits_plot", "draw", "LimitsFormatError"),
}


def _size(text: str) -> tuple[int, int]:
    try:
        width, height = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT in pixels, got {text!r}")
    if width <= 0 or height <= 0:
        raise argparse.ArgumentTypeError(f"picture size must be positive, got {text!r}")
    return width, height


def _program_name() -> str:
    """How the user called us: the console script (coremodal-plot) or python3 -m coremodal."""
    called = Path(sys.argv[0]).name if sys.argv and sys.argv[0] else ""
    return "python3 -m coremodal" if called in ("", "__main__.py", "-c") else called


def _parser() -> argparse.ArgumentParser:
    from . import __version__

    parser = argparse.ArgumentParser(
        prog=_program_name(), description="Read and draw the results of coremodal (its results folders)."
    )
    parser.add_argument("--version", action="version", version=f"%(prog)s {__version__}")
    commands = parser.add_subparsers(dest="command", required=True)

    table = commands.add_parser("table", help="print every mode as a table")
    table.add_argument("results", type=Path, help="modes.h5 written by coremodal, or its results folder")

    plot = commands.add_parser("plot", help="draw one mode shape into a PNG")
    plot.add_argument("results", type=Path, help="modes.h5 written by coremodal, or its results folder")
    plot.add_argument("--mode", type=int, required=True, help="mode number, 1-based as in the table")
    plot.add_argument("--out", type=Path, help="PNG to write (default: mode_NN.png)")
    plot.add_argument("--scale", type=float, help="displacement scale of the side view "
                      "(default: the mode's warp scale: a bending or axial mode's largest "
                      "displacement = 10%% of the model's length, other modes' at most 25%% "
                      "of its diameter)")
    plot.add_argument("--size", type=_size, default=(1200, 900), metavar="WxH",
                      help="picture size in pixels (default 1200x900)")

    run = commands.add_parser(
        "run-plot", help="draw the PNGs of a run's report.md (mode_NN.png, spectrum.png) into its folder")
    run.add_argument("folder", type=Path, help="results folder of coremodal run (holding modes.h5)")
    run.add_argument("--modes", default="", help="modes to draw, e.g. 7,9,13 (default: only spectrum.png)")
    run.add_argument("--size", type=_size, default=(1000, 750), metavar="WxH",
                     help="size of each mode picture in pixels (default 1000x750)")
    run.add_argument("--frames", type=int, metavar="MODE",
                     help="also draw MODE swinging: mode_NN_frames.png (a strip) and mode_NN.gif (with PIL)")

    converge = commands.add_parser(
        "converge-plot", help="draw error against time (PNG) from a `coremodal converge` folder")
    converge.add_argument("results", type=Path, help="folder holding converge.json (or the file)")
    converge.add_argument("--out", type=Path,
                          help="PNG to write (default: error_vs_time.png beside converge.json)")
    converge.add_argument("--size", type=_size, default=(1000, 700), metavar="WxH",
                          help="picture size in pixels (default 1000x700)")
    converge.add_argument("--quiet", action="store_true", help="print nothing on success")
    paraview = commands.add_parser(
        "paraview", help="render a mode with ParaView (pvpython, under xvfb-run without a display)",
        description="Runs coremodal/paraview_mode.py in pvpython; its options: --list, --mode N, "
                    "--out PNG, --scale S, --size WxH, --frames [N], --gif GIF.")
    paraview.add_argument("script_args", nargs=argparse.REMAINDER,
                          help="RESULTS_DIR and the options of paraview_mode.py")
    for name, drawing in FOLDER_PLOTS.items():
        command = commands.add_parser(name, help=f"draw {drawing.pictures} of a `coremodal {drawing.command}` folder")
        command.add_argument("folder", type=Path, help=f"results folder of coremodal {drawing.command}")
    return parser


def _converge_plot(args: argparse.Namespace) -> int:
    from . import converge_plot  # matplotlib only when drawing

    try:
        study = converge_plot.load_study(args.results)
        folder = args.results if args.results.is_dir() else args.results.parent
        out = converge_plot.draw_error_vs_time(study, args.out or folder / "error_vs_time.png", args.size)
    except (converge_plot.ConvergeFormatError, KeyError, OSError) as error:
        print(f"coremodal: error: {error}", file=sys.stderr)
        return 1
    if not args.quiet:
        print(out)
    return 0


def _folder_plot(plot: "FolderPlot", folder: Path) -> int:
    """Draw a folder's pictures with its module's draw function; print the
    paths written, or the error (exit 1)."""
    import importlib

    module = importlib.import_module(f".{plot.module}", __package__)  # matplotlib only when drawing
    errors = (getattr(module, plot.error), KeyError, ValueError, OSError, StopIteration)
    try:
        drawn = getattr(module, plot.function)(folder)
    except errors as error:
        print(f"coremodal: error: {error}", file=sys.stderr)
        return 1
    paths = drawn if isinstance(drawn, list) else [drawn]
    _print("\n".join(str(p) for p in paths) if paths else f"{folder}: nothing to plot ({plot.when_empty})")
    return 0


def _run_plot(args: argparse.Namespace) -> int:
    from . import run_plot  # matplotlib only when drawing

    try:
        modes = run_plot.parse_modes(args.modes) if args.modes.strip() else []
        paths = run_plot.draw_run_plots(args.folder, modes, args.size, args.frames)
    except (ValueError, IndexError, OSError) as error:  # ResultsFormatError is a ValueError
        print(f"coremodal: error: {error}", file=sys.stderr)
        return 1
    _print("\n".join(str(p) for p in paths))
    return 0


def _paraview(args: argparse.Namespace) -> int:
    import subprocess

    from .pvrun import ParaViewMissing, pvpython_command

    try:
        command = pvpython_command(args.script_args)
    except ParaViewMissing as error:
        print(f"coremodal: error: {error}", file=sys.stderr)
        return 1
    return subprocess.run(command).returncode


def main(argv: list[str] | None = None) -> int:
    args = _parser().parse_args(argv)
    if args.command == "paraview":
        return _paraview(args)
    if args.command == "run-plot":
        return _run_plot(args)
    if args.command == "converge-plot":
        return _converge_plot(args)
    if args.command in FOLDER_PLOTS:
        return _folder_plot(FOLDER_PLOTS[args.command], args.folder)
    try:
        if args.results.is_dir():  # a results folder: its modes.h5
            if not (args.results / "modes.h5").is_file():
                raise ResultsFormatError(
                    f"{args.results}: a folder without modes.h5 (a beam-level run writes none; its modes are in "
                    "modes.csv and beam_shapes.csv)")
            args.results = args.results / "modes.h5"
        if not args.results.is_file():
            raise ResultsFormatError(f"{args.results}: no such file")
        results = load(args.results)
        if args.command == "table":
            output = results.table()
        else:
            from . import plot  # matplotlib only when drawing

            out = args.out or Path(f"mode_{args.mode:02d}.png")
            scale = plot.draw_mode(results, args.mode, out, args.scale, size_px=args.size)
            output = f"{out}: {results.label(args.mode)} (scale x{scale:.3g})"
    except (ResultsFormatError, IndexError, OSError) as error:
        print(f"coremodal: error: {error}", file=sys.stderr)
        return 1
    _print(output)
    return 0


def _print(output: str) -> None:
    try:
        print(output)
    except BrokenPipeError:  # e.g. piped into head: not an error
        sys.stderr.close()


if __name__ == "__main__":
    sys.exit(main())
