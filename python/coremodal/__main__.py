"""Command line: ``python3 -m coremodal table|plot RESULTS/modes.h5 ...``,
``python3 -m coremodal run-plot RESULTS_DIR --modes ...``,
``python3 -m coremodal converge-plot CONVERGE_DIR``,
``python3 -m coremodal study-plot STUDY_FOLDER``,
``python3 -m coremodal paraview RESULTS_DIR ...`` (ParaView's pvpython) and
``python3 -m coremodal winder-plot WINDER_FOLDER`` and
``python3 -m coremodal campbell-plot CAMPBELL_FOLDER`` and
``python3 -m coremodal response-plot RESPONSE_FOLDER`` and
``python3 -m coremodal traction-plot TRACTION_FOLDER``.
``python3 -m coremodal durability-plot DURABILITY_FOLDER`` and
``python3 -m coremodal selection-plot SELECT_FOLDER``.

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

Exit status: 0 on success, 1 if the file cannot be read or the mode does not
exist, or the folder holds no study (with a one-line message on stderr), 2 for
a usage error.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

from .results import ResultsFormatError, load


def _size(text: str) -> tuple[int, int]:
    try:
        width, height = (int(v) for v in text.lower().split("x"))
    except ValueError:
        raise argparse.ArgumentTypeError(f"expected WIDTHxHEIGHT in pixels, got {text!r}")
    if width <= 0 or height <= 0:
        raise argparse.ArgumentTypeError(f"picture size must be positive, got {text!r}")
    return width, height


def _parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="python3 -m coremodal", description="Read coremodal results (modes.h5)."
    )
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
    study = commands.add_parser(
        "study-plot", help="draw the PNG plots of a study or calibration folder (study.csv, study.json)")
    study.add_argument("folder", type=Path, help="results folder of coremodal study or coremodal calibrate")
    winder = commands.add_parser(
        "winder-plot", help="draw the crossing diagram and the response (PNG) of a `coremodal winder` folder")
    winder.add_argument("folder", type=Path, help="results folder of coremodal winder")
    campbell = commands.add_parser(
        "campbell-plot", help="draw campbell.png of a `coremodal campbell` folder")
    campbell.add_argument("folder", type=Path, help="results folder of coremodal campbell")
    traction = commands.add_parser(
        "traction-plot", help="draw traction.png of a `coremodal traction` folder")
    traction.add_argument("folder", type=Path, help="results folder of coremodal traction")
    response = commands.add_parser(
        "response-plot", help="draw response.png of a `coremodal response` folder")
    response.add_argument("folder", type=Path, help="results folder of coremodal response")
    durability = commands.add_parser(
        "durability-plot", help="draw durability.png of a `coremodal durability` folder")
    durability.add_argument("folder", type=Path, help="results folder of coremodal durability")
    selection = commands.add_parser(
        "selection-plot", help="draw selection_chart.png of a `coremodal select` folder")
    selection.add_argument("folder", type=Path, help="results folder of coremodal select")
    limits = commands.add_parser(
        "limits-plot", help="draw limits.png of a `coremodal limits` folder")
    limits.add_argument("folder", type=Path, help="results folder of coremodal limits")
    return parser


def _drawn(draw, errors: tuple) -> int:
    """Run a drawing function; print the paths it wrote, or its error (exit 1)."""
    try:
        paths = draw()
    except errors as error:
        print(f"coremodal: error: {error}", file=sys.stderr)
        return 1
    _print("\n".join(str(p) for p in paths))
    return 0


def _campbell_plot(folder: Path) -> int:
    from . import campbell_plot  # matplotlib only when drawing

    return _drawn(lambda: [campbell_plot.draw(folder)],
                  (campbell_plot.CampbellFormatError, KeyError, ValueError, OSError))


def _response_plot(folder: Path) -> int:
    from . import response_plot  # matplotlib only when drawing

    return _drawn(lambda: [response_plot.draw(folder)],
                  (response_plot.ResponseFormatError, KeyError, ValueError, OSError))


def _traction_plot(folder: Path) -> int:
    from . import traction_plot  # matplotlib only when drawing

    return _drawn(lambda: [traction_plot.draw(folder)],
                  (traction_plot.TractionFormatError, KeyError, ValueError, OSError))
def _limits_plot(folder: Path) -> int:
    from . import limits_plot  # matplotlib only when drawing

    return _drawn(lambda: [limits_plot.draw(folder)],
                  (limits_plot.LimitsFormatError, KeyError, ValueError, OSError))


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


def _study_plot(folder: Path) -> str:
    from . import study_plot  # matplotlib only when drawing

    paths = study_plot.draw_all(folder)
    return "\n".join(str(p) for p in paths) if paths else f"{folder}: nothing to plot (no successful point)"


def _winder_plot(folder: Path) -> int:
    from . import winder_plot  # matplotlib only when drawing

    return _drawn(lambda: winder_plot.draw_all(folder),
                  (winder_plot.WinderFormatError, KeyError, ValueError, OSError))


def _durability_plot(folder: Path) -> int:
    from . import durability_plot  # matplotlib only when drawing

    return _drawn(lambda: durability_plot.draw_all(folder),
                  (durability_plot.DurabilityFormatError, KeyError, ValueError, OSError, StopIteration))


def _selection_plot(folder: Path) -> int:
    from . import selection_plot  # matplotlib only when drawing

    return _drawn(lambda: selection_plot.draw_all(folder),
                  (selection_plot.SelectionFormatError, KeyError, ValueError, OSError))


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
    if args.command == "winder-plot":
        return _winder_plot(args.folder)
    if args.command == "campbell-plot":
        return _campbell_plot(args.folder)
    if args.command == "response-plot":
        return _response_plot(args.folder)
    if args.command == "traction-plot":
        return _traction_plot(args.folder)
    if args.command == "durability-plot":
        return _durability_plot(args.folder)
    if args.command == "selection-plot":
        return _selection_plot(args.folder)
    if args.command == "limits-plot":
        return _limits_plot(args.folder)
    if args.command == "study-plot":
        from .study_plot import StudyFormatError

        try:
            output = _study_plot(args.folder)
        except (StudyFormatError, OSError) as error:
            print(f"coremodal: error: {error}", file=sys.stderr)
            return 1
        _print(output)
        return 0
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
