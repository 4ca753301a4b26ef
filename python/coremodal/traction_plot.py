"""The picture of a ``coremodal traction`` results folder (docs/how-to/traction.md):

    python3 -m coremodal traction-plot results/19-grooved-idler-traction-traction

reads ``traction.csv`` and ``summary.json`` and draws ``traction.png``: the
traction Delta T [N/m] (top) and the effective friction f_e (bottom) against
the web speed [m/s], the capstan equation without air dashed, the plain
roller beside a grooved one, the zero-traction (and slip) speed as vertical
lines and the points outside the paper's validity limits crossed.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Any

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from .labels import legend_outside

#: Picture size in pixels at DPI.
SIZE_PX = (1000, 800)
DPI = 100
COLUMNS = {"web_speed_m_s", "traction_N_m", "capstan_traction_N_m", "effective_friction", "valid"}


class TractionFormatError(Exception):
    """The folder holds no readable traction results."""


def load(folder: Path) -> tuple[dict[str, Any], list[dict[str, str]]]:
    folder = Path(folder)
    for name in ("traction.csv", "summary.json"):
        if not (folder / name).is_file():
            raise TractionFormatError(f"{folder / name}: no such file; expected a folder written by coremodal traction")
    try:
        summary = json.loads((folder / "summary.json").read_text())
        float(summary["traction_speeds"]["zero_traction_m_s"])
    except (ValueError, KeyError, TypeError) as error:
        raise TractionFormatError(f"{folder / 'summary.json'}: not a coremodal traction summary ({error})") from error
    with (folder / "traction.csv").open(newline="") as f:
        reader = csv.DictReader(f)
        rows = list(reader)
        fields = set(reader.fieldnames or [])
    if not COLUMNS <= fields:
        raise TractionFormatError(f"{folder / 'traction.csv'}: missing columns {sorted(COLUMNS - fields)}")
    if not rows:
        raise TractionFormatError(f"{folder / 'traction.csv'}: no rows")
    return summary, rows


def column(rows: list[dict[str, str]], name: str) -> list[float]:
    return [float(r[name]) for r in rows]


def draw(folder: Path) -> Path:
    folder = Path(folder)
    summary, rows = load(folder)
    v = column(rows, "web_speed_m_s")
    figure = Figure(figsize=(SIZE_PX[0] / DPI, SIZE_PX[1] / DPI), dpi=DPI, layout="constrained")
    FigureCanvasAgg(figure)
    top = figure.add_subplot(2, 1, 1)
    bottom = figure.add_subplot(2, 1, 2, sharex=top)
    shape = summary["roller"]["grooves"]["shape"]
    label = "plain roller" if shape == "none" else f"{shape} grooves"
    top.plot(v, column(rows, "capstan_traction_N_m"), "k--", linewidth=1, label="capstan equation, no air (eq. 1)")
    top.plot(v, column(rows, "traction_N_m"), color="tab:blue", linewidth=2, label=f"{label} (eq. 13)")
    bottom.plot(v, column(rows, "effective_friction"), color="tab:blue", linewidth=2, label=f"{label} (eq. 15)")
    if "plain_traction_N_m" in rows[0]:
        top.plot(v, column(rows, "plain_traction_N_m"), color="tab:orange", linewidth=1.2,
                 label="the same roller without grooves")
        bottom.plot(v, column(rows, "plain_effective_friction"), color="tab:orange", linewidth=1.2,
                    label="the same roller without grooves")
    bad = [i for i, r in enumerate(rows) if r["valid"] != "true"]
    if bad:
        top.plot([v[i] for i in bad], [float(rows[i]["traction_N_m"]) for i in bad], "rx",
                 label="outside the paper's validity limits")
    zero = float(summary["traction_speeds"]["zero_traction_m_s"])
    for ax in (top, bottom):
        if v[0] <= zero <= v[-1]:
            ax.axvline(zero, color="tab:red", linewidth=1, linestyle=":")
        ax.grid(True, alpha=0.3)
        ax.set_ylim(bottom=0)
    if v[0] <= zero <= v[-1]:
        top.annotate(f"zero traction {zero:.3g} m/s", (zero, 0), textcoords="offset points", xytext=(4, 8),
                     fontsize=9, color="tab:red")
    slip = summary["traction_speeds"].get("slip_m_s")
    if slip is not None and v[0] <= slip <= v[-1]:
        top.axvline(slip, color="tab:purple", linewidth=1, linestyle="-.", label=f"slip speed {slip:.3g} m/s")
    top.set_ylabel("traction ΔT [N/m]")
    bottom.set_ylabel("effective friction f_e [-]")
    bottom.set_xlabel("web speed V_w [m/s]")
    top.tick_params(labelbottom=False)  # the shared speed axis is read on the lower panel
    top.set_title(f"{summary['case']['name']}: web-to-roller traction (Rice & Gans), "
                  f"h_eff = {1e6 * summary['clearance']['effective_clearance_m']:.4g} µm")
    legend_outside(top, fontsize=8)  # beside the curves, not on them (coremodal.labels)
    legend_outside(bottom, fontsize=8)
    out = folder / "traction.png"
    figure.savefig(out)
    return out
