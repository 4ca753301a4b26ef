"""The Pareto front of a convergence study: relative error against run time.

Reads ``converge.json`` written by ``coremodal converge`` and draws
``error_vs_time.png``: log-log, one colour per model level (solid, beam,
harmonic),
one line style per tracked mode (solid line: f1, the first bending mode;
dashed: the first ovalling mode). Each point is one level of the refinement
ladder, labelled with its DOFs; the finest level's point (open marker) is the
error estimate of the extrapolation, not a measured error. Every model level's
error is against its own extrapolated frequency; a model level other than the
solid (the beam) also gets a dotted curve of its error against the solid's
extrapolated frequency of the same role, which levels off at the model error
(a beam never converges to the 3D answer). For the harmonic level, exact in
theta on the solid's own r-z section, that difference is not a model error
but what the solid's extrapolation leaves of its circumferential
discretization (``MODEL_ERROR_MEANING``). Named mesh levels checked with
``--check-levels`` appear as black stars. Horizontal lines mark the 1 %, 0.1 %
and 0.01 % targets.

    python3 -m coremodal converge-plot results/03-rest-roll-150x15.8-4320-converge
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any

# Modes drawn, by the role converge gives them, and their line styles.
ROLE_STYLES = {"f1": ("-", "o", "f1 (first bending)"), "ovalling": ("--", "s", "first ovalling")}
TARGETS = (1e-2, 1e-3, 1e-4)
MODEL_COLOURS = ("tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple")
# What a model level's difference from the solid's extrapolated frequency is;
# a level not listed here: "model error".
MODEL_ERROR_MEANING = {"harmonic": "the solid's discretization around"}


def error_meaning(model: str) -> str:
    """What the difference between ``model``'s and the solid's extrapolated frequencies means."""
    return MODEL_ERROR_MEANING.get(model, "model error")


class ConvergeFormatError(ValueError):
    """converge.json is missing or lacks what the plot needs."""


def load_study(folder_or_file: Path | str) -> dict[str, Any]:
    """The study from converge.json (a folder holding it, or the file)."""
    path = Path(folder_or_file)
    if path.is_dir():
        path = path / "converge.json"
    try:
        study = json.loads(path.read_text())
    except (OSError, json.JSONDecodeError) as error:
        raise ConvergeFormatError(f"{path}: cannot read a convergence study ({error})") from error
    if not isinstance(study, dict) or "models" not in study:
        raise ConvergeFormatError(f"{path}: no 'models' list; expected converge.json written by coremodal converge")
    return study


def error_curves(study: dict[str, Any]) -> list[dict[str, Any]]:
    """One curve per model level and role: times [s], relative errors, DOFs,
    and whether the last point is the finest level (an estimate). ``against``
    says which extrapolated frequency the errors are measured from: "own" (the
    model level's own), or "solid" for the extra curve of a model level other
    than the solid (its ``error_vs_solid`` values: the model error shows as the
    level the curve flattens to)."""
    curves = []
    for model in study["models"]:
        levels = model["levels"]
        for mode in model["modes"]:
            role = mode.get("role", "")
            if role not in ROLE_STYLES:
                continue
            richardson = mode.get("richardson", {})
            for against, key in (("own", "relative_error"), ("solid", "error_vs_solid")):
                points = [(levels[v["level"]]["timing_s"]["total"], v[key], levels[v["level"]]["n_dofs"],
                           v["level"] == len(levels) - 1)
                          for v in mode["values"] if key in v]
                if not points:
                    continue
                curves.append({
                    "model": model["model"], "role": role, "id": mode["id"], "against": against,
                    "time_s": [p[0] for p in points], "error": [p[1] for p in points],
                    "dofs": [p[2] for p in points],
                    "finest": [p[3] and against == "own" for p in points],
                    "asymptotic": bool(richardson.get("asymptotic", False)),
                    "order": richardson.get("order"),
                })
    return curves


def model_errors(study: dict[str, Any]) -> list[dict[str, Any]]:
    """The study's model errors (a model level's extrapolated frequency against
    the solid's, per role); empty for a study of one model level."""
    return list(study.get("model_errors", []))


def check_points(study: dict[str, Any]) -> list[dict[str, Any]]:
    """Named mesh levels (--check-levels): name, time and error per role."""
    points = []
    for check in study.get("checks", []):
        for mode in check.get("modes", []):
            if mode.get("role") in ROLE_STYLES and "relative_error" in mode:
                points.append({"name": check["name"], "role": mode["role"],
                               "time_s": check["timing_s"]["total"], "error": mode["relative_error"]})
    return points


def draw_error_vs_time(study: dict[str, Any], out: Path | str, size_px: tuple[int, int] = (1000, 700)) -> Path:
    """Draws the study's error-vs-time picture into ``out`` (PNG) and returns its path."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    curves = error_curves(study)
    dpi = 100
    fig, ax = plt.subplots(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
    floor = 1e-9  # an error of exactly 0 cannot sit on a log axis
    colours = {m["model"]: MODEL_COLOURS[i % len(MODEL_COLOURS)] for i, m in enumerate(study["models"])}
    for c in curves:
        style, marker, title = ROLE_STYLES[c["role"]]
        errors = [max(e, floor) for e in c["error"]]
        if c["against"] == "solid":
            ax.plot(c["time_s"], errors, ":", color=colours[c["model"]], marker="x",
                    label=f"{c['model']}: {title} against the solid's f0 ({error_meaning(c['model'])})")
            continue
        note = "" if c["asymptotic"] else ", not asymptotic"
        order = f", p = {c['order']:.2f}" if c.get("order") else ""
        ax.plot(c["time_s"], errors, style, color=colours[c["model"]], marker=marker,
                label=f"{c['model']}: {title} ({c['id']}{order}{note})")
        for t, e, dofs, finest in zip(c["time_s"], errors, c["dofs"], c["finest"]):
            if finest:  # the finest level's error is the extrapolation's estimate
                ax.plot([t], [e], marker, color="white", markeredgecolor=colours[c["model"]], zorder=3)
            ax.annotate(f"{dofs:,}", (t, e), textcoords="offset points", xytext=(4, 4), fontsize=7, color="0.3")
    for i, p in enumerate(check_points(study)):
        ax.plot([p["time_s"]], [max(p["error"], floor)], "*", color="black", markersize=10, zorder=4,
                label="named mesh levels (--check-levels)" if i == 0 else None)
        ax.annotate(f"{p['name']} ({p['role']})", (p["time_s"], max(p["error"], floor)),
                    textcoords="offset points", xytext=(5, -10), fontsize=8)
    for target in TARGETS:
        ax.axhline(target, color="0.6", linewidth=0.8, linestyle=":")
        ax.annotate(f"{target * 100:g} %", (1, target), xycoords=("axes fraction", "data"), xytext=(-30, 2),
                    textcoords="offset points", fontsize=8, color="0.4")
    lines = [f"{e['model']} {e['role']}: {100 * e['model_error']:+.3g} % against the solid"
             + ("" if error_meaning(e["model"]) == "model error" else f" ({error_meaning(e['model'])})")
             for e in model_errors(study) if e.get("role") in ROLE_STYLES or e.get("role") in ("torsion", "axial")]
    if lines:
        ax.text(0.99, 0.99, "against the solid (extrapolated values)\n" + "\n".join(lines), transform=ax.transAxes,
                ha="right", va="top", fontsize=8, bbox={"boxstyle": "round", "facecolor": "white", "alpha": 0.8})
    ax.set_xscale("log")
    ax.set_yscale("log")
    ax.set_xlabel("run time per level [s] (median; mesh + assembly + factor and solve + classification)")
    ax.set_ylabel("relative error against the extrapolated frequency\n(own model level; dotted: against the solid's)")
    case = study.get("case", "")  # {name, file, description} since schema_version 2; a name before
    ax.set_title(f"{case.get('name', '') if isinstance(case, dict) else case}: accuracy against cost (labels: DOFs; open marker: finest level, "
                 "estimate)", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    if curves:
        ax.legend(fontsize=8, loc="best")  # two model levels fill the lower left
    else:
        ax.text(0.5, 0.5, "no tracked mode could be extrapolated", transform=ax.transAxes, ha="center")
    fig.tight_layout()
    out = Path(out)
    fig.savefig(out)
    plt.close(fig)
    return out
