"""The chart of a ``coremodal select`` results folder (docs/how-to/durability.md,
"Choosing a core"):

    python3 -m coremodal selection-plot results/18-core-selection-select

reads ``selection.csv``, ``reels.csv`` and ``summary.json`` and draws
``selection_chart.png`` in the form of Figs. 18-19 of M. Ilomäki, "On the
durability of cores and rest roll dynamics": for each stand, each core
grade's maximum reel mass (its durability limit) against the reel width, up
to the widest rest roll that still meets the stand's speed (its corner), the
reel mass of the chart's roll diameter as a dotted line, and the reels asked
(filled where some core passes).
"""

from __future__ import annotations

import csv
import json
from pathlib import Path

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

#: Picture size in pixels at DPI, per stand.
PANEL_PX = (900, 650)
DPI = 100
FILES = ("selection.csv", "reels.csv", "summary.json")


class SelectionFormatError(Exception):
    """The folder holds no readable selection results."""


def _rows(path: Path) -> list[dict[str, str]]:
    with path.open(newline="") as f:
        return list(csv.DictReader(f))


def draw_chart(folder: Path) -> Path:
    folder = Path(folder)
    for name in FILES:
        if not (folder / name).is_file():
            raise SelectionFormatError(f"{folder / name}: no such file; expected a folder written by coremodal select")
    summary = json.loads((folder / "summary.json").read_text())
    if summary.get("command") != "select":
        raise SelectionFormatError(f"{folder / 'summary.json'}: not a coremodal select summary")
    table = _rows(folder / "selection.csv")
    reels = _rows(folder / "reels.csv")
    stands = [s["name"] for s in summary["stands"]]
    figure = Figure(figsize=(PANEL_PX[0] * len(stands) / DPI, PANEL_PX[1] / DPI), dpi=DPI)
    FigureCanvasAgg(figure)
    colours = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple", "tab:brown"]
    for k, stand in enumerate(summary["stands"]):
        ax = figure.add_subplot(1, len(stands), k + 1)
        rows = [r for r in table if r["stand"] == stand["name"]]
        widest = max(min(float(r["speed_width_m"]), 12.0) for r in rows)
        x_max = 1.15 * max(widest, max((float(r["width_m"]) for r in reels if r["stand"] == stand["name"]),
                                       default=0))
        for i, r in enumerate(rows):
            colour = colours[i % len(colours)]
            mass, width = float(r["max_roll_mass_kg"]), min(float(r["speed_width_m"]), x_max)
            ax.plot([0, width], [mass, mass], "-", color=colour, linewidth=2.2,
                    label=f"core {r['core']}: {mass:.0f} kg up to {float(r['speed_width_m']):.2f} m")
            ax.plot([width, width], [0, mass], "--", color=colour, linewidth=1.2)
            ax.plot([0, x_max], [0, x_max * float(r["reel_mass_kg_per_m"])], ":", color="grey", linewidth=1)
        ax.plot([], [], ":", color="grey",
                label=f"reel mass at {1e3 * stand['roll_diameter_m']:.0f} mm, {summary['paper_density_kg_m3']:.0f} kg/m^3")
        shown = set()
        for r in reels:
            if r["stand"] != stand["name"] or r["reel"] in shown:
                continue
            shown.add(r["reel"])
            passes = any(q["passes"] == "yes" for q in reels if q["reel"] == r["reel"])
            ax.plot(float(r["width_m"]), float(r["reel_mass_kg"]), "ko" if passes else "kx", markersize=8,
                    markerfacecolor="k" if passes else "none")
            ax.annotate(f"reel {r['reel']}", (float(r["width_m"]), float(r["reel_mass_kg"])),
                        textcoords="offset points", xytext=(6, 4), fontsize=8)
        ax.set_xlim(0, x_max)
        ax.set_ylim(0, 1.4 * max(float(r["max_roll_mass_kg"]) for r in rows))  # room for the legend
        ax.set_xlabel("reel width [m]")
        ax.set_ylabel("maximum reel mass [kg]")
        ax.set_title(f"{stand['name']}: {1e3 * stand['chuck_length_m']:.0f} mm chucks, {stand['winder']} winder, "
                     f"{stand['web_speed_m_s']:g} m/s, P = {summary['failure_probability']:g}", fontsize=9)
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7, loc="upper left")
    path = folder / "selection_chart.png"
    figure.savefig(path)
    return path


def draw_all(folder: Path) -> list[Path]:
    return [draw_chart(Path(folder))]


__all__ = ["SelectionFormatError", "draw_all", "draw_chart"]
