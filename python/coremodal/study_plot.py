"""Plots of a coremodal study: ``study.csv`` and ``study.json`` of a results
folder written by ``coremodal study`` (or ``coremodal calibrate``).

    python3 -m coremodal study-plot results/06-study-safe-speed-study

draws into that folder (docs/how-to/studies.md):

- ``modes_vs_<p>.png``: every tracked mode's frequency against the fastest
  parameter p, one line per track (the same physical mode, followed by MAC),
  ambiguous steps ringed in red; one panel per value of the other parameters;
- ``f1_vs_<p>.png`` and ``k_vs_<p>.png``: the first bending frequency and the
  chuck factor against each numeric parameter, one curve per value of the others;
- ``safe_speed.png``: König's chart, the safe web speed v_safe = safe pi D f1
  against the rest roll diameter D, one curve per roll width (or whatever
  else the study varies besides D), the web speed as a horizontal line and
  the diameter at which each roll must be changed marked on it;
- ``response_safe_speed.png`` (a study over a case with ``[response]``): the
  web speed at which the forced response first reaches the amplitude limit
  (±5 mm at mid-span by default) against the rest roll diameter (or the
  fastest numeric parameter), beside I-5 at 0.7 and 0.8 and König's v_krit
  from the same f1, the web speed as a horizontal line;
- ``calibration.png`` (a calibration folder): the fitted k against the FE k.
"""

from __future__ import annotations

import csv
import json
import math
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import matplotlib
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from .key_names import human_name, written_unit
from .labels import legend_outside, separate

#: Picture size in pixels at DPI.
SIZE_PX = (1100, 750)
DPI = 100
#: Panels of the tracked-modes picture at most (one per combination of the
#: slower parameters); further combinations are left out and said so.
MAX_PANELS = 6
#: Curves with a legend at most; more curves are drawn without one.
MAX_LEGEND = 14


class StudyFormatError(Exception):
    """The folder holds no readable study (missing or malformed files)."""


@dataclass
class Parameter:
    name: str  # "core.length"
    column: str  # "core.length_m" in study.csv
    numeric: bool
    unit: str  # SI unit, "" for plain numbers and text
    labels: list[str]  # the values as the case file wrote them: "10 mm"
    values: list[float]  # SI
    keys: list[str] = field(default_factory=list)  # every key set to the value

    @property
    def human_name(self) -> str:
        """"roll width" for core.length (coremodal.key_names)."""
        return human_name(self.keys[0] if self.keys else self.name)

    @property
    def shown_unit(self) -> tuple[str, float]:
        """The unit the study's values were written in and the factor from
        SI to it: ("mm", 1000) for values "10 mm", "30 mm"; else SI."""
        if not self.numeric:
            return "", 1.0
        return written_unit(self.labels, self.values, self.unit)

    def shown(self, si: float) -> float:
        """An SI value of this parameter in the unit it was written in."""
        return si * self.shown_unit[1]


@dataclass
class Study:
    folder: Path
    meta: dict[str, Any]
    parameters: list[Parameter]
    rows: list[dict[str, str]]  # study.csv, one row per point and tracked mode
    diameter_parameters: list[str] = field(default_factory=list)

    @property
    def case_name(self) -> str:
        """The case's name: study.json's case {name, file, ...} (schema 2),
        or the plain name older study.json files hold."""
        case = self.meta.get("case", "")
        return str(case.get("name", "")) if isinstance(case, dict) else str(case)

    @property
    def web_speed_m_s(self) -> float | None:
        return self.meta.get("options", {}).get("web_speed_m_s")

    @property
    def safe_factor(self) -> float:
        return float(self.meta.get("options", {}).get("safe_factor", 0.7))

    def ok_rows(self) -> list[dict[str, str]]:
        return [r for r in self.rows if r.get("status") == "ok"]

    def points(self) -> list[dict[str, str]]:
        """One row per successful point (its first tracked-mode row)."""
        seen: dict[str, dict[str, str]] = {}
        for r in self.ok_rows():
            seen.setdefault(r["point"], r)
        return list(seen.values())

    def value(self, row: dict[str, str], p: Parameter) -> float | str:
        text = row[p.column]
        return float(text) if p.numeric else text


def number(text: str | None) -> float:
    """A CSV cell as a float, NaN when empty."""
    if text is None or text == "":
        return math.nan
    return float(text)


def load_study(folder: Path) -> Study:
    folder = Path(folder)
    csv_path, json_path = folder / "study.csv", folder / "study.json"
    for path in (csv_path, json_path):
        if not path.is_file():
            raise StudyFormatError(f"{path}: no such file; expected a folder written by coremodal study")
    try:
        meta = json.loads(json_path.read_text())
        parameters = [
            Parameter(p["name"], p["column"], bool(p["numeric"]), p.get("unit", ""), list(p["labels"]),
                      [float(v) for v in p.get("values", [])], list(p.get("keys", [])))
            for p in meta["parameters"]
        ]
    except (ValueError, KeyError, TypeError) as error:
        raise StudyFormatError(f"{json_path}: not a coremodal study description ({error})") from error
    with csv_path.open(newline="") as f:
        rows = list(csv.DictReader(f))
    needed = {"point", "status", "track", "frequency_hz"} | {p.column for p in parameters}
    if rows and not needed <= set(rows[0]):
        raise StudyFormatError(f"{csv_path}: missing columns {sorted(needed - set(rows[0]))}")
    return Study(folder, meta, parameters, rows, list(meta.get("diameter_parameters", [])))


def file_stem(name: str) -> str:
    return "".join(c if c.isalnum() else "_" for c in name)


def axis_label(p: Parameter) -> str:
    """"roll width [m]": the parameter's human name and the unit its values
    were written in (coremodal.key_names)."""
    unit = p.shown_unit[0]
    if not p.numeric:
        return p.human_name  # names, not numbers
    return f"{p.human_name} [{unit or '-'}]"  # [-]: a ratio


def change_diameters(diameter: np.ndarray, v_safe: np.ndarray, web_speed: float) -> list[float]:
    """Diameters where v_safe(D) rises through the web speed as D grows: below
    them the roll runs faster than safe and must be changed. Same rule as the
    C++ report (analyses/study/study.cpp, safe_speed_crossings)."""
    order = np.argsort(diameter)
    d, v = np.asarray(diameter, float)[order], np.asarray(v_safe, float)[order]
    out = []
    for i in range(len(d) - 1):
        if v[i] < web_speed <= v[i + 1] and d[i + 1] > d[i]:
            out.append(float(d[i] + (web_speed - v[i]) * (d[i + 1] - d[i]) / (v[i + 1] - v[i])))
    return out


def _group_key(study: Study, row: dict[str, str], leave_out: set[str]) -> tuple:
    return tuple(row[p.column] for p in study.parameters if p.name not in leave_out)


def _group_label(study: Study, key: tuple, leave_out: set[str]) -> str:
    names = [p for p in study.parameters if p.name not in leave_out]
    parts = []
    for p, cell in zip(names, key):
        label = cell
        if p.numeric:
            for lab, val in zip(p.labels, p.values):
                if math.isclose(val, float(cell), rel_tol=1e-9, abs_tol=1e-300):
                    label = lab
        parts.append(f"{p.human_name} = {label}")
    return ", ".join(parts)


def _new_figure(rows: int = 1, cols: int = 1) -> tuple[Figure, Any]:
    # Constrained layout: the legends beside the axes get their room.
    figure = Figure(figsize=(SIZE_PX[0] / DPI, SIZE_PX[1] / DPI), dpi=DPI, layout="constrained")
    FigureCanvasAgg(figure)
    axes = figure.subplots(rows, cols, squeeze=False)
    return figure, axes


def _x_of(study: Study, p: Parameter, row: dict[str, str]) -> float:
    return p.shown(float(row[p.column])) if p.numeric else float(p.labels.index(row[p.column]))


def _categorical_ticks(ax: Any, p: Parameter) -> None:
    if not p.numeric:
        ax.set_xticks(range(len(p.labels)), p.labels)


def plot_tracked_modes(study: Study, out: Path) -> Path | None:
    """Frequency of every tracked mode against the fastest parameter."""
    if not study.parameters or not study.ok_rows():
        return None
    x_par = study.parameters[-1]
    slower = {p.name for p in study.parameters[:-1]}
    panels: dict[tuple, list[dict[str, str]]] = {}
    for r in study.ok_rows():
        panels.setdefault(_group_key(study, r, {x_par.name}), []).append(r)
    keys = list(panels)[:MAX_PANELS]
    # One colour per track in every panel: the same mode looks the same everywhere.
    track_ids = sorted({int(r["track"]) for r in study.ok_rows()})
    palette = matplotlib.colormaps["tab10"]
    colour = {str(t): palette(i % 10) for i, t in enumerate(track_ids)}
    cols = 1 if len(keys) == 1 else 2
    rows_n = math.ceil(len(keys) / cols)
    figure, axes = _new_figure(rows_n, cols)
    for i, key in enumerate(keys):
        ax = axes[i // cols][i % cols]
        tracks: dict[str, list[dict[str, str]]] = {}
        for r in panels[key]:
            tracks.setdefault(r["track"], []).append(r)
        elastic = {t: rs for t, rs in tracks.items() if rs[0]["type"] != "rigid"}
        for t, rs in sorted(elastic.items(), key=lambda kv: min(number(r["frequency_hz"]) for r in kv[1])):
            rs.sort(key=lambda r: _x_of(study, x_par, r))
            x = [_x_of(study, x_par, r) for r in rs]
            f = [number(r["frequency_hz"]) for r in rs]
            ax.plot(x, f, marker="o", markersize=3, color=colour[t], label=f"{t}: {rs[0]['label']}")
            amb = [(xi, fi) for xi, fi, r in zip(x, f, rs) if r.get("ambiguous") == "1"]
            if amb:
                ax.plot(*zip(*amb), linestyle="none", marker="o", markersize=9, markerfacecolor="none",
                        markeredgecolor="red")
        ax.set_xlabel(axis_label(x_par))
        ax.set_ylabel("frequency [Hz]")
        _categorical_ticks(ax, x_par)
        title = _group_label(study, key, {x_par.name}) if slower else ""
        ax.set_title(title or "tracked modes", fontsize=9)
        ax.grid(True, alpha=0.3)
        if len(elastic) <= MAX_LEGEND:
            legend_outside(ax, fontsize=6)
    for j in range(len(keys), rows_n * cols):
        axes[j // cols][j % cols].set_visible(False)
    note = "" if len(panels) <= MAX_PANELS else f" (first {MAX_PANELS} of {len(panels)} combinations)"
    figure.suptitle(f"{study.case_name}: modes tracked by MAC; red rings: ambiguous steps{note}",
                    fontsize=10)
    path = out / f"modes_vs_{file_stem(x_par.name)}.png"
    figure.savefig(path)
    return path


def plot_point_value(study: Study, out: Path, column: str, name: str, ylabel: str) -> list[Path]:
    """One picture per numeric parameter: a per-point value (f1_hz, k) against it,
    one curve per combination of the other parameters."""
    points = [r for r in study.points() if not math.isnan(number(r.get(column)))]
    if not points:
        return []
    paths = []
    for p in study.parameters:
        if not p.numeric or len(p.values) < 2:
            continue
        curves: dict[tuple, list[dict[str, str]]] = {}
        for r in points:
            curves.setdefault(_group_key(study, r, {p.name}), []).append(r)
        figure, axes = _new_figure()
        ax = axes[0][0]
        for key, rs in curves.items():
            rs.sort(key=lambda r: float(r[p.column]))
            ax.plot([p.shown(float(r[p.column])) for r in rs], [number(r[column]) for r in rs], marker="o",
                    markersize=4, label=_group_label(study, key, {p.name}) or name)
        ax.set_xlabel(axis_label(p))
        ax.set_ylabel(ylabel)
        ax.grid(True, alpha=0.3)
        if 1 < len(curves) <= MAX_LEGEND:
            legend_outside(ax, fontsize=7)
        ax.set_title(f"{study.case_name}: {ylabel} against {p.human_name}", fontsize=10)
        path = out / f"{name}_vs_{file_stem(p.name)}.png"
        figure.savefig(path)
        paths.append(path)
    return paths


def plot_safe_speed(study: Study, out: Path) -> Path | None:
    """König's chart: v_safe against the rest roll diameter, one curve per roll
    width (the non-diameter parameters), the web speed as a line."""
    points = [r for r in study.points() if not math.isnan(number(r.get("v_safe_m_s")))]
    diameter_names = set(study.diameter_parameters)
    if not points or not diameter_names:
        return None
    curves: dict[tuple, list[dict[str, str]]] = {}
    for r in points:
        curves.setdefault(_group_key(study, r, diameter_names), []).append(r)
    figure, axes = _new_figure()
    ax = axes[0][0]
    web = study.web_speed_m_s
    changes = []
    for key, rs in curves.items():
        d = np.array([number(r["diameter_m"]) for r in rs]) * 1e3
        v = np.array([number(r["v_safe_m_s"]) for r in rs])
        order = np.argsort(d)
        label = _group_label(study, key, diameter_names) or "v_safe"
        line, = ax.plot(d[order], v[order], marker="o", markersize=4, label=label)
        if web is not None:
            for dc in change_diameters(d, v, web):
                ax.plot([dc], [web], marker="v", markersize=10, color=line.get_color())
                # Level text, moved clear of the other labels (coremodal.labels.separate).
                changes.append(ax.annotate(f"change at {dc:.0f} mm", (dc, web), textcoords="offset points",
                                           xytext=(4, 8), fontsize=8, color=line.get_color()))
    if web is not None:
        ax.axhline(web, color="black", linestyle="--", linewidth=1)
        ax.annotate(f"web speed {web:g} m/s ({web * 60:.0f} m/min)", (0.01, web), xycoords=("axes fraction", "data"),
                    textcoords="offset points", xytext=(0, -12), fontsize=8)
    ax.set_xlabel("rest roll diameter D [mm]")
    ax.set_ylabel("safe web speed v_safe [m/s]")
    secondary = ax.secondary_yaxis("right", functions=(lambda v: v * 60, lambda v: v / 60))
    secondary.set_ylabel("web speed [m/min]")
    ax.grid(True, alpha=0.3)
    if len(curves) <= MAX_LEGEND:
        legend_outside(ax, fontsize=8)
    ax.set_title(f"{study.case_name}: safe web speed v_safe = {study.safe_factor:g} pi D f1 (I-5); "
                 "change the roll where its curve falls below the web speed", fontsize=9)
    separate(figure, changes)
    path = out / "safe_speed.png"
    figure.savefig(path)
    return path


def _response_axis(study: Study) -> tuple[set[str], str, Any] | None:
    """What the response picture draws against: the rest roll diameter in mm
    when the study changes it, else the fastest numeric parameter; the names
    left out of the curves' grouping, the axis label and x of a row."""
    if study.diameter_parameters:
        return set(study.diameter_parameters), "rest roll diameter D [mm]", lambda r: number(r["diameter_m"]) * 1e3
    numeric = [p for p in study.parameters if p.numeric]
    if not numeric:
        return None
    p = numeric[-1]
    return {p.name}, axis_label(p), lambda r: p.shown(float(r[p.column]))


def plot_response_safe_speed(study: Study, out: Path) -> Path | None:
    """The amplitude-based safe speed (forced response) against the rest
    roll diameter, beside I-5 at 0.7 and 0.8 and König, one colour per
    combination of the other parameters. A point whose amplitude stays within
    the limit over the response's speeds is an open triangle at the top of
    that range: safe at least up to there."""
    points = [r for r in study.points() if not math.isnan(number(r.get("amplitude_limit_m")))]
    axis = _response_axis(study)
    if not points or axis is None:
        return None
    leave_out, xlabel, x_of = axis
    curves: dict[tuple, list[dict[str, str]]] = {}
    for r in points:
        curves.setdefault(_group_key(study, r, leave_out), []).append(r)
    figure, axes = _new_figure()
    ax = axes[0][0]
    limit_mm = 1e3 * number(points[0]["amplitude_limit_m"])
    palette = matplotlib.colormaps["tab10"]
    for i, (key, rs) in enumerate(curves.items()):
        rs.sort(key=x_of)
        colour, group = palette(i % 10), _group_label(study, key, leave_out)
        prefix = f"{group}: " if group else ""
        x = np.array([x_of(r) for r in rs])
        reached = np.array([r.get("amplitude_limit_reached") == "1" for r in rs])
        v_limit = np.array([number(r["v_amplitude_limit_m_s"]) for r in rs])
        ax.plot(x[reached], v_limit[reached], marker="o", color=colour, linewidth=2,
                label=f"{prefix}±{limit_mm:g} mm reached (forced response)")
        if (~reached).any():
            top = np.array([number(r["response_max_web_speed_m_s"]) for r in rs])
            ax.plot(x[~reached], top[~reached], linestyle="none", marker="^", markersize=9, markerfacecolor="none",
                    color=colour, label=f"{prefix}±{limit_mm:g} mm not reached up to the last speed")
        for column, style, name in (("v_i5_07_m_s", "--", "I-5 × 0.7"), ("v_i5_08_m_s", "-.", "I-5 × 0.8"),
                                    ("v_koenig_m_s", ":", "König v_krit")):
            v = np.array([number(r.get(column)) for r in rs])
            if not np.isnan(v).all():
                ax.plot(x, v, linestyle=style, marker=".", color=colour, label=f"{prefix}{name}")
    web = study.web_speed_m_s
    if web is not None:
        ax.axhline(web, color="black", linestyle="--", linewidth=1)
        ax.annotate(f"web speed {web:g} m/s", (0.01, web), xycoords=("axes fraction", "data"),
                    textcoords="offset points", xytext=(0, -12), fontsize=8)
    ax.set_xlabel(xlabel)
    ax.set_ylabel("web speed [m/s]")
    secondary = ax.secondary_yaxis("right", functions=(lambda v: v * 60, lambda v: v / 60))
    secondary.set_ylabel("web speed [m/min]")
    ax.grid(True, alpha=0.3)
    if 4 * len(curves) <= MAX_LEGEND:
        legend_outside(ax, fontsize=7)
    ax.set_title(f"{study.case_name}: safe web speed from the forced response (±{limit_mm:g} mm) "
                 "beside I-5 and König", fontsize=9)
    path = out / "response_safe_speed.png"
    figure.savefig(path)
    return path


def plot_calibration(study: Study, out: Path) -> Path | None:
    """The fitted k against the FE k of a calibration folder, with the stated error."""
    table = study.folder / "calibration.csv"
    if not table.is_file():
        return None
    with table.open(newline="") as f:
        rows = [r for r in csv.DictReader(f) if r.get("status") == "ok"]
    if not rows:
        return None
    stated = None
    toml_path = study.folder / "calibration.toml"
    if toml_path.is_file():
        import tomllib  # python 3.11

        stated = tomllib.loads(toml_path.read_text())["fit"]["stated_error"]
    figure, axes = _new_figure()
    ax = axes[0][0]
    k_fe = np.array([number(r["k_fe"]) for r in rows])
    k_fit = np.array([number(r["k_fit"]) for r in rows])
    held = np.array([r["held_out"] == "1" for r in rows])
    lo, hi = float(min(k_fe.min(), k_fit.min())), float(max(k_fe.max(), k_fit.max()))
    pad = 0.05 * (hi - lo or 1)
    line = np.array([lo - pad, hi + pad])
    ax.plot(line, line, color="black", linewidth=1)
    if stated:
        ax.fill_between(line, line * (1 - stated), line * (1 + stated), color="grey", alpha=0.2,
                        label=f"stated error ±{100 * stated:g} %")
    ax.plot(k_fe[~held], k_fit[~held], "o", label="fitted points")
    ax.plot(k_fe[held], k_fit[held], "s", markerfacecolor="none", markersize=8, label="held-out points")
    ax.set_xlabel("k from the FE run, f1 / f_I-7(k = 1) [-]")
    ax.set_ylabel("k from the fitted law [-]")
    ax.grid(True, alpha=0.3)
    legend_outside(ax, fontsize=8)
    ax.set_title(f"{study.case_name}: calibrated chuck factor", fontsize=10)
    path = out / "calibration.png"
    figure.savefig(path)
    return path


def draw_all(folder: Path) -> list[Path]:
    """Every picture the study's data allow, into the folder; returns their paths."""
    study = load_study(Path(folder))
    out = study.folder
    paths: list[Path] = []

    tracked = plot_tracked_modes(study, out)
    paths += [tracked] if tracked else []
    paths += plot_point_value(study, out, "f1_hz", "f1", "first bending frequency f1 [Hz]")
    paths += plot_point_value(study, out, "k", "k", "chuck factor k = f1 / f_I-7(k = 1) [-]")
    for extra in (plot_safe_speed(study, out), plot_response_safe_speed(study, out), plot_calibration(study, out)):
        if extra:
            paths.append(extra)
    return paths


__all__ = ["Study", "StudyFormatError", "change_diameters", "draw_all", "load_study"]
