"""Pictures of a ``coremodal winder`` results folder (docs/how-to/winder.md):

    python3 -m coremodal winder-plot results/11-two-drum-winder-winder

reads ``winder.csv``, ``crossings.csv``, ``response.csv`` and ``summary.json``
and draws into that folder:

- ``crossing_diagram.png``: every tracked mode's frequency against the roll
  diameter (drum-dominated modes bold), the roll rotation harmonics
  f_k = k v / (pi d) dashed, the crossings ringed and numbered by harmonic,
  and the drum-frequency estimate (symmetric, antisymmetric) dotted;
- ``response.png``: |X/F| at the drum's centre at each harmonic against the
  roll diameter (log scale), the crossings' resonance values marked on
  their curves (each curve passes through the resonances solved at their own
  diameters).

Legends stand beside the axes and no label prints over another
(coremodal.labels).
"""

from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from .labels import legend_outside, separate

#: Picture size in pixels at DPI.
SIZE_PX = (1100, 750)
DPI = 100
#: Line colour and width of each mode type.
STYLE = {"drum": ("tab:blue", 2.2), "roll": ("tab:orange", 0.9), "rider": ("tab:green", 0.9)}
FILES = ("winder.csv", "crossings.csv", "response.csv", "summary.json")


class WinderFormatError(Exception):
    """The folder holds no readable winder results."""


@dataclass
class WinderResults:
    folder: Path
    summary: dict[str, Any]
    modes: list[dict[str, str]]
    crossings: list[dict[str, str]]
    response: list[dict[str, str]]

    @property
    def web_speed(self) -> float:
        return float(self.summary["scene"]["web_speed_m_s"])

    @property
    def harmonics(self) -> int:
        return int(self.summary["scene"]["sweep"]["harmonics"])

    @property
    def max_frequency(self) -> float:
        return float(self.summary["scene"]["sweep"]["max_frequency_hz"])


def _rows(path: Path, needed: set[str]) -> list[dict[str, str]]:
    with path.open(newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        fields = set(reader.fieldnames or [])
    if not needed <= fields:
        raise WinderFormatError(f"{path}: missing columns {sorted(needed - fields)}")
    return rows


def load_winder(folder: Path) -> WinderResults:
    folder = Path(folder)
    for name in FILES:
        if not (folder / name).is_file():
            raise WinderFormatError(f"{folder / name}: no such file; expected a folder written by coremodal winder")
    try:
        summary = json.loads((folder / "summary.json").read_text())
        float(summary["scene"]["web_speed_m_s"])  # what every picture needs
        int(summary["scene"]["sweep"]["harmonics"])
    except (ValueError, KeyError, TypeError) as error:
        raise WinderFormatError(f"{folder / 'summary.json'}: not a coremodal winder summary ({error})") from error
    modes = _rows(folder / "winder.csv", {"roll_diameter_m", "frequency_hz", "type", "track"})
    crossings = _rows(folder / "crossings.csv", {"roll_diameter_m", "harmonic", "mode_frequency_hz", "x_over_f_m_per_n"})
    response = _rows(folder / "response.csv", {"roll_diameter_m", "harmonic", "x_over_f_m_per_n"})
    return WinderResults(folder, summary, modes, crossings, response)


def _figure() -> tuple[Figure, Any]:
    figure = Figure(figsize=(SIZE_PX[0] / DPI, SIZE_PX[1] / DPI), dpi=DPI, layout="constrained")
    FigureCanvasAgg(figure)
    return figure, figure.add_subplot(1, 1, 1)


def _tracks(results: WinderResults) -> dict[int, list[tuple[float, float, str]]]:
    """Per track: (d in mm, f, type), one entry per diameter (degenerate partners once)."""
    tracks: dict[int, dict[float, tuple[float, float, str]]] = {}
    for r in results.modes:
        d = 1e3 * float(r["roll_diameter_m"])
        tracks.setdefault(int(r["track"]), {}).setdefault(d, (d, float(r["frequency_hz"]), r["type"]))
    return {t: sorted(points.values()) for t, points in tracks.items()}


def draw_crossing_diagram(results: WinderResults, out: Path) -> Path:
    figure, ax = _figure()
    for points in _tracks(results).values():
        for (d0, f0, kind), (d1, f1, _) in zip(points, points[1:]):
            colour, width = STYLE.get(kind, ("grey", 0.8))
            ax.plot([d0, d1], [f0, f1], color=colour, linewidth=width, zorder=2 if kind == "drum" else 1)
    diameters = sorted({float(r["roll_diameter_m"]) for r in results.modes})
    harmonic_labels = []
    d = np.linspace(diameters[0], diameters[-1], 200)
    for k in range(1, results.harmonics + 1):
        f = k * results.web_speed / (math.pi * d)
        ax.plot(1e3 * d, f, "k--", linewidth=0.9)
        inside = np.nonzero(f <= results.max_frequency)[0]
        if inside.size:
            i = inside[0]
            harmonic_labels.append(ax.annotate(f"{k}x", (1e3 * d[i], f[i]), textcoords="offset points",
                                               xytext=(4, 2), fontsize=9))
    points = results.summary.get("points", [])
    # Dots, not lines: the estimate's drum root jumps where it veers with the rolls' bounce.
    for family, colour in (("symmetric", "navy"), ("antisymmetric", "c")):
        xs = [1e3 * p["roll_diameter_m"] for p in points]
        ys = [p["estimate"][family]["estimate_hz"] for p in points]
        ax.plot(xs, ys, ".", color=colour, markersize=3, label=f"drum estimate, {family}")
    labels = []
    for c in results.crossings:
        x, y = 1e3 * float(c["roll_diameter_m"]), float(c["mode_frequency_hz"])
        ax.plot(x, y, "o", markersize=10, markerfacecolor="none", markeredgecolor="red", zorder=3)
        labels.append(ax.annotate(f"{c['harmonic']}x", (x, y), textcoords="offset points", xytext=(6, -12),
                                  color="red", fontsize=9))
    ax.plot([], [], "o", markersize=10, markerfacecolor="none", markeredgecolor="red",
            label="crossing (k x: the harmonic)")
    for kind, (colour, width) in STYLE.items():
        ax.plot([], [], color=colour, linewidth=width, label=f"{kind}-dominated mode")
    ax.plot([], [], "k--", linewidth=0.9, label="roll rotation harmonics k v / (pi d)")
    ax.set_ylim(0, results.max_frequency)
    ax.set_xlim(1e3 * diameters[0], 1e3 * diameters[-1])
    ax.set_xlabel("roll diameter d [mm]")
    ax.set_ylabel("frequency [Hz]")
    ax.set_title(f"{results.summary['case']['name']}: crossing diagram at {results.web_speed * 60:.0f} m/min")
    ax.grid(True, alpha=0.3)
    legend_outside(ax, fontsize=8)
    separate(figure, harmonic_labels + labels)
    path = out / "crossing_diagram.png"
    figure.savefig(path)
    return path


def draw_response(results: WinderResults, out: Path) -> Path:
    figure, ax = _figure()
    for k in range(1, results.harmonics + 1):
        # The sweep's diameters and each resonance of this harmonic at its own
        # diameter (crossings.csv, solved there): the curve reaches its peaks,
        # and the resonance markers lie on it.
        points = [(float(r["roll_diameter_m"]), float(r["x_over_f_m_per_n"])) for r in results.response
                  if int(r["harmonic"]) == k]
        points += [(float(c["roll_diameter_m"]), float(c["x_over_f_m_per_n"])) for c in results.crossings
                   if int(c["harmonic"]) == k]
        points.sort()
        ax.semilogy([1e3 * d for d, _ in points], [x for _, x in points], label=f"harmonic {k}")
    for c in results.crossings:
        ax.semilogy(1e3 * float(c["roll_diameter_m"]), float(c["x_over_f_m_per_n"]), "rv", markersize=7)
    ax.semilogy([], [], "rv", label="resonance at a crossing")
    sweep = results.summary["scene"]["sweep"]
    ax.set_xlabel("roll diameter d [mm]")
    ax.set_ylabel(f"|X/F| at the {sweep['response_drum']} drum's centre, {sweep['response_direction']} [m/N]")
    ax.set_title("response to each roll rotation harmonic as the rolls grow")
    ax.grid(True, which="both", alpha=0.3)
    legend_outside(ax, fontsize=8)
    path = out / "response.png"
    figure.savefig(path)
    return path


def draw_all(folder: Path) -> list[Path]:
    results = load_winder(Path(folder))
    return [draw_crossing_diagram(results, results.folder), draw_response(results, results.folder)]


__all__ = ["WinderFormatError", "WinderResults", "draw_all", "load_winder"]
