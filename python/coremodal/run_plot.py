"""Pictures for the report of one ``coremodal run``: the modes.h5 of a results
folder.

    python3 -m coremodal run-plot results/02-clamped-76x15 --modes 7,9,13

draws into that folder (docs/reference/results.md, "report.md"):

- ``mode_NN.png`` for each listed mode: the three-panel picture of
  coremodal.plot.draw_mode (side view, cross-section, curves along the
  roll), a little smaller than the ``plot`` default;
- ``spectrum.png``: every mode's frequency against its number, coloured by
  its type, so that the order of bending, torsion, axial and shell modes is
  seen at a glance;
- with ``--frames N``: ``mode_NN_frames.png``, mode N swinging as a strip of
  side views (coremodal.frames), and ``mode_NN.gif``, the same animated
  (only where PIL is installed).

The program chooses the modes (one of each type, lowest first) and calls this
after writing modes.h5.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from . import frames, plot
from .results import Results, load

#: Mode pictures in the report: big enough to read, small enough to draw fast.
MODE_SIZE_PX = (1000, 750)
SPECTRUM_SIZE_PX = (900, 450)
DPI = 100
#: One colour per mode type (the classifier's words), the same in every report.
TYPE_COLOURS = {
    "rigid": "0.6",
    "bending": "C0",
    "torsion": "C1",
    "axial": "C2",
    "ovalling": "C3",
    "breathing": "C4",
    "mixed": "C7",
}


def parse_modes(text: str) -> list[int]:
    """``"7,9,13"`` -> [7, 9, 13]; raises ValueError for anything else."""
    modes = [int(part) for part in text.split(",") if part.strip()]
    if not modes:
        raise ValueError(f"expected mode numbers separated by commas, got {text!r}")
    return modes


def mode_png_name(index: int) -> str:
    """File name of the picture of mode ``index``, as the report links it."""
    return f"mode_{index:02d}.png"


def draw_spectrum(results: Results, png_path: str | Path,
                  size_px: tuple[int, int] = SPECTRUM_SIZE_PX, dpi: int = DPI) -> Path:
    """Writes spectrum_figure into a PNG; returns its path."""
    path = Path(png_path)
    spectrum_figure(results, size_px, dpi).savefig(path, dpi=dpi)
    return path


def spectrum_figure(results: Results, size_px: tuple[int, int] = SPECTRUM_SIZE_PX,
                    dpi: int = DPI) -> Figure:
    """Frequency of every mode against its number, a stem per mode coloured
    by type, one legend entry per type present; a matplotlib Figure."""
    figure = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
    FigureCanvasAgg(figure)
    axes = figure.add_subplot(1, 1, 1)
    index = np.arange(1, results.n_modes + 1)
    for kind in dict.fromkeys(results.types):  # in order of first appearance
        take = np.array([t == kind for t in results.types])
        colour = TYPE_COLOURS.get(kind, "k")
        axes.vlines(index[take], 0.0, results.frequencies_hz[take], colors=colour, lw=1.2)
        axes.plot(index[take], results.frequencies_hz[take], "o", color=colour, label=kind)
    axes.set_xlabel("mode number [-]")
    axes.set_ylabel("frequency (Hz)")
    axes.set_xlim(0.3, results.n_modes + 0.7)
    axes.set_ylim(bottom=0.0)
    axes.grid(True, lw=0.3, alpha=0.5)
    axes.legend(loc="upper left", framealpha=0.8)
    axes.set_title(f"{results.case_name or results.path.parent.name}: {results.n_modes} modes by type")
    figure.tight_layout()
    return figure


def draw_run_plots(folder: str | Path, modes: list[int],
                   size_px: tuple[int, int] = MODE_SIZE_PX, frames_mode: int | None = None) -> list[Path]:
    """Draws mode_NN.png for each of ``modes`` and spectrum.png into
    ``folder`` (which holds modes.h5), and for ``frames_mode`` its frame
    strip and, where PIL is installed, its GIF; returns the paths written.

    Raises ResultsFormatError or OSError for an unreadable folder and
    IndexError for a mode the file does not hold (before drawing anything).
    """
    folder = Path(folder)
    results = load(folder / "modes.h5")
    for index in modes + ([frames_mode] if frames_mode is not None else []):
        results._check_index(index)
    written = [draw_spectrum(results, folder / "spectrum.png")]
    for index in modes:
        path = folder / mode_png_name(index)
        plot.draw_mode(results, index, path, size_px=size_px)
        written.append(path)
    if frames_mode is not None:
        written.append(frames.draw_frame_strip(results, frames_mode, folder / frames.strip_file(frames_mode)))
        try:
            written.append(frames.draw_animation(results, frames_mode, folder / frames.animation_file(frames_mode)))
        except ImportError:
            pass  # no PIL: the strip shows the motion in the report all the same
    return written
