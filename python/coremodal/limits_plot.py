"""The verdict of a ``coremodal limits`` results folder (docs/how-to/limits.md):

    python3 -m coremodal limits-plot results/16-limits-rotogravure-150x15.8-4320-limits

reads ``limits.csv`` and ``summary.json`` and draws ``limits.png`` into that
folder, in the form of Ilomaki's Fig. 10 and Koenig's Abb. 8: web speed (m/s)
against rest-roll diameter (mm), every criterion a curve (dashed where it is
reported but does not limit), the governing envelope shaded below, the band of
the safe speed, the target speed and the roll-change diameter marked.
"""

from __future__ import annotations

from pathlib import Path

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ._folder import read_folder

#: Picture size in pixels at DPI.
SIZE_PX = (1100, 700)
DPI = 100
TABLES = ("limits.csv",)


class LimitsFormatError(Exception):
    """The folder holds no readable limits results."""


def _value(row: dict[str, str], key: str) -> float | None:
    text = row.get(key, "")
    return float(text) if text else None


def draw(folder: Path) -> Path:
    summary, rows = read_folder(folder, TABLES, LimitsFormatError, "limits")
    if not rows:
        raise LimitsFormatError(f"{folder}: limits.csv holds no diameters")
    rows = sorted(rows, key=lambda r: float(r["diameter_mm"]))
    d = [float(r["diameter_mm"]) for r in rows]
    criteria = summary["points"][0]["criteria"]
    fig = Figure(figsize=(SIZE_PX[0] / DPI, SIZE_PX[1] / DPI), dpi=DPI)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1)
    safe = [float(r["safe_m_s"]) for r in rows]
    low = [float(r["safe_low_m_s"]) for r in rows]
    high = [float(r["safe_high_m_s"]) for r in rows]
    ax.fill_between(d, 0, low, color="tab:green", alpha=0.15, lw=0, label="safe (conservative end)")
    ax.fill_between(d, low, high, color="tab:orange", alpha=0.25, lw=0, label="band of the safe speed")
    ax.plot(d, safe, color="k", lw=2.2, label="governing (point value)")
    plotted = list(high) + list(safe)
    for c in criteria:
        key = c["id"] + "_m_s"
        pts = [(x, _value(r, key)) for x, r in zip(d, rows)]
        pts = [(x, v) for x, v in pts if v is not None]
        if not pts:
            continue
        plotted += [p[1] for p in pts]
        ax.plot([p[0] for p in pts], [p[1] for p in pts], lw=1.2, marker=".", ls="-" if c["limiting"] else "--",
                label=c["name"])
    verdict = summary["verdict"]
    target = verdict.get("target")
    if target:
        ax.axhline(target["web_speed_m_s"], color="tab:red", lw=1.2, ls=":",
                   label=f"target {target['web_speed_m_s']:.2f} m/s")
        if target["change_needed"]:
            ax.axvline(target["change_diameter_mm"], color="tab:red", lw=1.2,
                       label=f"roll change at {target['change_diameter_mm']:.1f} mm")
    if target:
        plotted.append(target["web_speed_m_s"])
    top = max(plotted) * 1.3  # room for the legend above the curves
    ax.set_ylim(0, top)
    ax.set_xlim(min(d), max(d) if max(d) > min(d) else min(d) + 1)
    ax.invert_xaxis()  # the roll unwinds from left to right
    ax.set_xlabel("rest-roll diameter Dp (mm), unwinding →")
    ax.set_ylabel("web speed (m/s)")
    ax.set_title(f"How fast: {summary['case']['name']} ({summary['model']['level']} level)\n{verdict['line']}",
                 fontsize=9)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper right", fontsize=8, ncol=2)
    fig.tight_layout()
    out = folder / "limits.png"
    fig.savefig(out)
    return out
