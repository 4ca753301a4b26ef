"""Picture of a ``coremodal durability`` results folder (docs/how-to/durability.md):

    python3 -m coremodal durability-plot results/18-core-B-durability

reads ``points.csv``, ``curves.csv`` and ``summary.json`` and draws
``durability.png`` in the form of Figs. 16-17 of M. Ilomäki, "On the
durability of cores and rest roll dynamics": the simulator points, the
power-law fit, its confidence and prediction limits and the reduced curve of
each failure probability, on log-log axes with units.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Any

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.ticker import ScalarFormatter

#: Picture size in pixels at DPI.
SIZE_PX = (1100, 750)
DPI = 100
FILES = ("points.csv", "curves.csv", "summary.json")


class DurabilityFormatError(Exception):
    """The folder holds no readable durability results."""


def _columns(path: Path) -> dict[str, list[float]]:
    with path.open(newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        names = list(reader.fieldnames or [])
    return {n: [float(r[n]) for r in rows] for n in names}


def load_durability(folder: Path) -> tuple[dict[str, Any], dict[str, list[float]], dict[str, list[float]]]:
    folder = Path(folder)
    for name in FILES:
        if not (folder / name).is_file():
            raise DurabilityFormatError(f"{folder / name}: no such file; expected a folder written by "
                                        "coremodal durability")
    summary = json.loads((folder / "summary.json").read_text())
    if summary.get("command") != "durability":
        raise DurabilityFormatError(f"{folder / 'summary.json'}: not a coremodal durability summary")
    return summary, _columns(folder / "points.csv"), _columns(folder / "curves.csv")


def draw_durability(folder: Path) -> Path:
    summary, points, curves = load_durability(folder)
    data = summary["data"]
    unit = data["weight_unit"]
    weight = data["weight"]
    level = 100 * summary["confidence"]["level"]
    figure = Figure(figsize=(SIZE_PX[0] / DPI, SIZE_PX[1] / DPI), dpi=DPI)
    FigureCanvasAgg(figure)
    ax = figure.add_subplot(1, 1, 1)
    x = curves["cycles"]
    ax.loglog(points["cycles"], points[f"{weight}_{unit}"], "ko", markersize=4, label="simulator results")
    ax.loglog(x, curves[f"fit_{unit}"], "k-", linewidth=2,
              label=f"fit y = {summary['fit']['b0']:.4g} x^{summary['fit']['b1']:.4g} ({{16}}-{{20}})")
    ax.loglog(x, curves[f"confidence_lower_{unit}"], "b--", linewidth=1, label=f"{level:g} % confidence limits")
    ax.loglog(x, curves[f"confidence_upper_{unit}"], "b--", linewidth=1)
    ax.loglog(x, curves[f"prediction_lower_{unit}"], "g:", linewidth=1.2, label=f"{level:g} % prediction limits")
    ax.loglog(x, curves[f"prediction_upper_{unit}"], "g:", linewidth=1.2)
    colours = ["tab:orange", "tab:red", "tab:purple", "tab:brown", "tab:pink", "tab:olive", "tab:cyan"]
    for i, limit in enumerate(summary["limits"]):
        name = next(n for n in curves if n.startswith(f"P_") and
                    abs(float(n[2:].rsplit("_", 1)[0]) - limit["failure_probability"])
                    <= 1e-6 * limit["failure_probability"])
        ax.loglog(x, curves[name], "-", color=colours[i % len(colours)], linewidth=1.3,
                  label=f"P = {limit['failure_probability']:g} (lambda = {limit['lambda']:.3f})"
                  + (": the mean at C" if limit["lambda"] == 0 else ""))
    ax.set_xlabel("winding-unwinding cycles x [cycles]")
    ax.set_ylabel(f"{weight.replace('_', ' ')} y [{unit}]")
    ax.set_title(f"durability on a {1e3 * data['chuck_length_m']:g} mm {data['chuck_type']} test chuck: "
                 f"n = {data['points']}, S_log = {summary['fit']['s_log']:.4g}, C = {level:g} %")
    for axis in (ax.xaxis, ax.yaxis):
        axis.set_major_formatter(ScalarFormatter())  # 20, not 2x10^1
    ax.yaxis.set_minor_formatter(ScalarFormatter())
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8, loc="lower left")
    path = Path(folder) / "durability.png"
    figure.savefig(path)
    return path


def draw_all(folder: Path) -> list[Path]:
    return [draw_durability(Path(folder))]


__all__ = ["DurabilityFormatError", "draw_all", "draw_durability", "load_durability"]
