"""The forced response of a ``coremodal response`` results folder (docs/how-to/response.md):

    python3 -m coremodal response-plot results/13-rest-roll-response-response

reads ``response.csv``, ``peaks.csv`` and ``summary.json`` and draws
``response.png`` into that folder: the vibration amplitude at the first probe
(mid-span by default; the orbit's semi-major axis, mm) as a +- band against
web speed (m/s), the rotation speed (rpm) on a second axis above, the
+-limit lines, the resonance peaks labelled with their order and mode, and
the safe web speeds: from the amplitude limit, and I-5's at 0.7 and 0.8.
"""

from __future__ import annotations

import math
from pathlib import Path

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ._folder import read_folder

#: Picture size in pixels at DPI.
SIZE_PX = (1100, 700)
DPI = 100
TABLES = ("response.csv", "peaks.csv")


class ResponseFormatError(Exception):
    """The folder holds no readable response results."""


def load(folder: Path) -> tuple[dict, list[dict[str, str]], list[dict[str, str]]]:
    return read_folder(folder, TABLES, ResponseFormatError, "response")


def _speed_lines(ax, summary: dict) -> None:
    """The safe web speeds as vertical lines, labelled at staggered heights
    near the bottom (in axes fractions, so they never sit on the curve's
    peak): from the amplitude limit, and I-5's."""
    safe = summary["speeds"]
    where = ax.get_xaxis_transform()  # x in data, y in axes fraction
    amplitude = safe["from_amplitude_limit"]
    if amplitude.get("reached"):
        v = amplitude["web_speed_m_s"]
        ax.axvline(v, color="tab:red", lw=1.4)
        ax.text(v, 0.17, f" limit reached: {v:.2f} m/s\n (I-5 factor {amplitude['implied_safe_factor']:.2f})",
                transform=where, fontsize=8, color="tab:red")
    for i, item in enumerate(safe.get("safe_web_speed", [])):
        v = item["v_safe_m_s"]
        ax.axvline(v, color="tab:green", ls=":", lw=1.2)
        ax.text(v, 0.03 + 0.06 * i, f" I-5 x{item['safe']:.1f}: {v:.2f} m/s", transform=where, fontsize=8,
                color="tab:green")


def draw(folder: Path) -> Path:
    summary, rows, peaks = load(folder)
    probe = summary["inputs"]["probes"][0]["name"]
    points = sorted((float(r["web_speed_m_s"]), float(r["amplitude_mm"])) for r in rows if r["probe"] == probe)
    if not points:
        raise ResponseFormatError(f"{folder}: response.csv holds no amplitudes at {probe}")
    speeds, amplitudes = [p[0] for p in points], [p[1] for p in points]
    limit = summary["speeds"]["limit_mm"]
    fig = Figure(figsize=(SIZE_PX[0] / DPI, SIZE_PX[1] / DPI), dpi=DPI)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot(1, 1, 1)
    ax.fill_between(speeds, [-a for a in amplitudes], amplitudes, color="tab:blue", alpha=0.25, lw=0)
    ax.plot(speeds, amplitudes, color="tab:blue", lw=1.6, label=f"amplitude at {probe}")
    ax.plot(speeds, [-a for a in amplitudes], color="tab:blue", lw=1.6)
    for sign in (1, -1):
        ax.axhline(sign * limit, color="tab:red", ls="--", lw=1.2, label=f"limit ±{limit:g} mm" if sign > 0 else None)
    for i, p in enumerate(peaks):
        v, a = float(p["web_speed_m_s"]), float(p["amplitude_mm"])
        ax.plot([v], [a], "o", mfc="none", mec="k", ms=9)
        right = v > speeds[0] + 0.6 * (speeds[-1] - speeds[0])  # label towards the middle, inside the axes
        ax.annotate(f"{p['order']}x {p['mode']} ({float(p['mode_frequency_hz']):.1f} Hz): {a:.2f} mm", (v, a),
                    textcoords="offset points", xytext=(-6 if right else 6, 4 if i % 2 == 0 else -12),
                    ha="right" if right else "left", fontsize=8)
    _speed_lines(ax, summary)
    top = max(max(amplitudes), limit) * 1.15
    ax.set_ylim(-top, top)
    ax.set_xlim(speeds[0], speeds[-1] if speeds[-1] > speeds[0] else speeds[0] + 1)
    dp = summary["inputs"]["roll_outer_diameter_m"]
    rpm = ax.secondary_xaxis("top", functions=(lambda v: v / (math.pi * dp) * 60, lambda n: n / 60 * math.pi * dp))
    rpm.set_xlabel(f"rotation speed (rpm) at Dp = {dp * 1e3:.0f} mm")
    ax.set_xlabel("web speed (m/s)")
    ax.set_ylabel(f"vibration amplitude at {probe} (mm)")
    ax.set_title(f"Forced response: {summary['case']['name']}", pad=28)
    ax.grid(alpha=0.3)
    ax.legend(loc="upper left", fontsize=9)
    fig.tight_layout()
    out = folder / "response.png"
    fig.savefig(out)
    return out
