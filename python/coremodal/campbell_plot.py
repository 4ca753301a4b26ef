"""The Campbell diagram of a ``coremodal campbell`` results folder (docs/how-to/campbell.md):

    python3 -m coremodal campbell-plot results/12-rotation-tester-76x15-campbell

reads ``campbell.csv``, ``critical_speeds.csv`` and ``summary.json`` and draws
``campbell.png`` into that folder: every tracked mode's frequency against the
rotation speed in rpm (forward whirl solid, backward whirl dashed, no whirl
grey), the excitation lines f = k f_rot dotted, and the critical speeds (the
crossings) ringed and numbered by order. The top axis gives the same speed as
web speed v = pi Dp f_rot at the roll's outer diameter Dp; the legend, beside
the axes, lists only what is drawn; no label prints over another
(coremodal.labels). The case's operating range ([rotation] operating_speeds),
when the summary has one, is a light band.
"""

from __future__ import annotations

import math
from collections import defaultdict
from pathlib import Path

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ._folder import read_folder
from .labels import legend_outside, separate

#: Picture size in pixels at DPI.
SIZE_PX = (1100, 750)
DPI = 100
TABLES = ("campbell.csv", "critical_speeds.csv")
#: Line style of each whirl ("" for none: axial, torsion, rigid, at rest).
STYLE = {"FW": ("tab:blue", "-"), "BW": ("tab:red", "--"), "": ("0.55", "-")}


class CampbellFormatError(Exception):
    """The folder holds no readable Campbell results."""


def load(folder: Path) -> tuple[dict, list[dict[str, str]], list[dict[str, str]]]:
    return read_folder(folder, TABLES, CampbellFormatError, "campbell")


def draw(folder: Path) -> Path:
    summary, modes, critical = load(folder)
    tracks: dict[int, list[tuple[float, float, str]]] = defaultdict(list)
    for row in modes:
        tracks[int(row["track"])].append((float(row["speed_rpm"]), float(row["frequency_hz"]), row["whirl"]))
    if not tracks:
        raise CampbellFormatError(f"{folder}: campbell.csv holds no modes")
    fig = Figure(figsize=(SIZE_PX[0] / DPI, SIZE_PX[1] / DPI), dpi=DPI, layout="constrained")
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1)
    speeds = sorted({s for points in tracks.values() for s, _, _ in points})
    # A crossing of the pencil (co-rotating coordinates) may lie beyond the
    # sweep's last speed, which stops below it: the axis reaches it.
    speeds.append(max([speeds[-1]] + [float(c["speed_rpm"]) for c in critical]))
    # Up to where the highest excitation line ends, and at least the first
    # elastic mode: the crossings, not every mode of the sweep.
    highest = max(f for points in tracks.values() for _, f, _ in points)
    first = min((f for points in tracks.values() for _, f, _ in points if f > 0), default=highest)
    reach = max(summary["rotation"]["excitation_orders"]) * speeds[-1] / 60
    top = min(highest, max(1.5 * reach, 1.3 * first)) * 1.05 or 1.0
    shown = set()
    for points in tracks.values():
        points.sort()
        whirl = next((w for _, _, w in points if w), "")
        colour, dash = STYLE.get(whirl, STYLE[""])
        xs, ys = [p[0] for p in points], [p[1] for p in points]
        # In the legend only what can be seen: a track wholly above the
        # frequency axis is not drawn in it.
        visible = any(0 <= y <= top for y in ys)
        label = None
        if visible and whirl not in shown:
            label = {"FW": "forward whirl", "BW": "backward whirl", "": "no whirl"}[whirl]
            shown.add(whirl)
        ax.plot(xs, ys, dash, color=colour, lw=1.6, label=label, marker="." if len(xs) == 1 else None)
    labels = []
    for i, order in enumerate(summary["rotation"]["excitation_orders"]):
        xs = [speeds[0], speeds[-1]]
        ax.plot(xs, [order * x / 60 for x in xs], ":", color="k", lw=1.0,
                label="excitation f = k f_rot (k x)" if i == 0 else None)
        # Named where the line leaves the axes: beside the right edge, or
        # under the top edge inside: never on a mode's curve.
        end = min(speeds[-1], top * 60 / order)
        right = end >= speeds[-1]
        labels.append(ax.annotate(f"{order}x", (end, order * end / 60), textcoords="offset points",
                                  xytext=(4, 0) if right else (-4, -4), ha="left" if right else "right",
                                  va="center" if right else "top", fontsize=9))
    for i, c in enumerate(critical):  # labels alternate below and above: crossings of a split pair lie close
        x, y = float(c["speed_rpm"]), float(c["frequency_hz"])
        ax.plot([x], [y], "o", mfc="none", mec="k", ms=10, label="critical speed" if i == 0 else None)
        labels.append(ax.annotate(f"{c['order']}x {c['whirl']}: {x:.0f} rpm", (x, y), textcoords="offset points",
                                  xytext=(6, -14 if i % 2 == 0 else 8), fontsize=8))
    operating = summary["rotation"].get("operating_speeds_rpm")
    if operating:  # [rotation] operating_speeds: the speeds the machine runs at
        ax.axvspan(operating[0], operating[1], color="tab:green", alpha=0.12, lw=0, label="operating range")
    ax.set_xlim(speeds[0], speeds[-1] if speeds[-1] > speeds[0] else speeds[0] + 1)
    ax.set_ylim(0, top)
    ax.set_xlabel("rotation speed (rpm)")
    ax.set_ylabel("natural frequency (Hz)")
    diameter = summary["rotation"].get("roll_outer_diameter_m")
    if diameter:  # web speed v = pi Dp n / 60 at the roll's outer diameter
        per_rpm = math.pi * diameter / 60
        web = ax.secondary_xaxis("top", functions=(lambda n: n * per_rpm, lambda v: v / per_rpm))
        web.set_xlabel(f"web speed at Dp = {diameter * 1e3:.4g} mm (m/s)")
    ax.set_title(f"Campbell diagram: {summary['case']['name']}")
    ax.grid(alpha=0.3)
    legend_outside(ax, fontsize=9)
    separate(fig, labels)
    out = folder / "campbell.png"
    fig.savefig(out)
    return out
