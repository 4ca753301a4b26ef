"""The study plots (coremodal.study_plot) on a small synthetic study folder
laid out as ``coremodal study`` writes it (study.csv, study.json), so that the
pictures and König's change diameters can be checked against known numbers."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from coremodal import study_plot
from coremodal.key_names import human_name, written_unit
from coremodal.study_plot import (StudyFormatError, axis_label, change_diameters, draw_all, load_study,
                                  plot_point_value)

WEB_SPEED = 14.0
HEADER = ("point,rest_paper.thickness_m,core.length_m,status,predecessor,track,label,type,n,m,multiplicity,"
          "frequency_hz,mac_previous,ambiguous,new_track,f1_hz,k,li_m,span_m,f_i7_hz,diameter_m,v_safe_m_s,"
          "n_dofs,time_s,error")


def png_size(path: Path) -> tuple[int, int]:
    header = path.read_bytes()[:24]
    assert header[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


def v_safe(d: float, length: float) -> float:
    """A made-up safe speed rising with the diameter and falling with the width."""
    return 40.0 * d / 0.2 * (2.0 / length) ** 2


def write_study(folder: Path, *, failed_point: bool = False) -> Path:
    """A 3 x 2 grid over rest paper thickness x core length: two tracked
    groups per point (a bending pair and a torsion mode that cross)."""
    thicknesses, lengths = [0.01, 0.03, 0.05], [2.0, 3.0]
    rows, point = [HEADER], 0
    for t in thicknesses:
        for length in lengths:
            point += 1
            d = 0.106 + 2 * t
            f1 = v_safe(d, length) / (0.7 * np.pi * d)
            common = f"{f1},0.8,0.1,{length - 0.2},{f1 / 0.8},{d},{v_safe(d, length)},5000,1.0"
            prefix = f"{point},{t},{length}"
            if failed_point and point == 6:
                rows.append(f"{prefix},failed,,,,,,,,,,,,{',' * 9}solve failed")
                continue
            pred = "" if point == 1 else str(point - 1)
            torsion = 30.0 + 10 * point  # crosses the bending frequency
            amb = "1" if point == 4 else "0"
            rows.append(f"{prefix},ok,{pred},1,bending n=1 m=0,bending,1,0,2,{f1},0.99,{amb},0,{common},")
            rows.append(f"{prefix},ok,{pred},2,torsion n=0 m=1,torsion,0,1,1,{torsion},0.98,0,0,{common},")
    (folder / "study.csv").write_text("\n".join(rows) + "\n")
    meta = {
        "kind": "study", "case": "synthetic", "case_file": "x.toml", "n_points": 6, "n_failed": int(failed_point),
        "parameters": [
            {"name": "rest_paper.thickness", "column": "rest_paper.thickness_m", "keys": ["rest_paper.thickness"],
             "numeric": True, "unit": "m", "labels": ["10 mm", "30 mm", "50 mm"], "values": thicknesses},
            {"name": "core.length", "column": "core.length_m", "keys": ["core.length"], "numeric": True,
             "unit": "m", "labels": ["2 m", "3 m"], "values": lengths},
        ],
        "diameter_parameters": ["rest_paper.thickness"],
        "options": {"mesh": "coarse", "modes": 12, "safe_factor": 0.7, "web_speed_m_s": WEB_SPEED},
    }
    (folder / "study.json").write_text(json.dumps(meta))
    return folder


def test_change_diameter_is_where_v_safe_rises_through_the_web_speed() -> None:
    d = np.array([0.3, 0.1, 0.2])  # any order
    v = np.array([30.0, 10.0, 20.0])
    assert change_diameters(d, v, 14.0) == pytest.approx([0.14])
    assert change_diameters(d, v, 5.0) == []  # safe everywhere
    assert change_diameters(d, v, 40.0) == []  # never safe in range
    assert change_diameters(d, v, 20.0) == pytest.approx([0.2])  # exactly on a point


def test_every_plot_is_drawn_from_a_study_folder(tmp_path: Path) -> None:
    paths = draw_all(write_study(tmp_path))
    names = sorted(p.name for p in paths)
    assert names == sorted([
        "modes_vs_core_length.png", "f1_vs_rest_paper_thickness.png", "f1_vs_core_length.png",
        "k_vs_rest_paper_thickness.png", "k_vs_core_length.png", "safe_speed.png"])
    for p in paths:
        width, height = png_size(p)
        assert (width, height) == (1100, 750)


def test_the_study_is_read_with_its_diameter_parameters_and_web_speed(tmp_path: Path) -> None:
    study = load_study(write_study(tmp_path, failed_point=True))
    assert [p.name for p in study.parameters] == ["rest_paper.thickness", "core.length"]
    assert study.diameter_parameters == ["rest_paper.thickness"]
    assert study.web_speed_m_s == WEB_SPEED
    assert len(study.points()) == 5  # the failed point is left out
    # The König chart: one curve per length; the 3 m curve crosses 14 m/s.
    d = np.array([0.106 + 2 * t for t in (0.01, 0.03, 0.05)])
    v3 = np.array([v_safe(x, 3.0) for x in d])
    crossing = change_diameters(d, v3, WEB_SPEED)
    assert len(crossing) == 1 and d[0] < crossing[0] < d[-1]
    draw_all(tmp_path)
    assert (tmp_path / "safe_speed.png").is_file()


def test_a_folder_without_a_study_is_an_error(tmp_path: Path) -> None:
    with pytest.raises(StudyFormatError, match="study.csv"):
        load_study(tmp_path)
    (tmp_path / "study.csv").write_text("x\n")
    (tmp_path / "study.json").write_text("{not json")
    with pytest.raises(StudyFormatError, match="study.json"):
        load_study(tmp_path)


def test_the_command_line_draws_and_reports(tmp_path: Path, cli_env: dict[str, str]) -> None:
    write_study(tmp_path)
    run = subprocess.run([sys.executable, "-m", "coremodal", "study-plot", str(tmp_path)], capture_output=True,
                         text=True, env=cli_env, timeout=300)
    assert run.returncode == 0, run.stderr
    assert "safe_speed.png" in run.stdout
    missing = subprocess.run([sys.executable, "-m", "coremodal", "study-plot", str(tmp_path / "none")],
                             capture_output=True, text=True, env=cli_env, timeout=300)
    assert missing.returncode == 1
    assert missing.stderr.startswith("coremodal: error:")


def test_axes_are_in_human_words_and_in_the_units_the_values_were_written_in(
        tmp_path: Path, monkeypatch: pytest.MonkeyPatch) -> None:
    study = load_study(write_study(tmp_path))
    thickness, length = study.parameters
    assert axis_label(thickness) == "rest paper thickness [mm]"  # written "10 mm", not core.length [m]
    assert axis_label(length) == "roll width [m]"
    # The pictures: f1 against the thickness has its x axis in mm.
    figures = []
    original = study_plot._new_figure

    def recording(*args, **kwargs):
        figure, axes = original(*args, **kwargs)
        figures.append(figure)
        return figure, axes

    monkeypatch.setattr(study_plot, "_new_figure", recording)
    [path] = [p for p in plot_point_value(study, tmp_path, "f1_hz", "f1", "f1 [Hz]")
              if p.name == "f1_vs_rest_paper_thickness.png"]
    [axes] = [f.axes[0] for f in figures if f.axes[0].get_xlabel() == "rest paper thickness [mm]"]
    x = np.concatenate([line.get_xdata() for line in axes.get_lines()])
    np.testing.assert_allclose(sorted(set(x)), [10.0, 30.0, 50.0])
    legend = [t.get_text() for t in axes.get_legend().get_texts()]
    assert legend == ["roll width = 2 m", "roll width = 3 m"]


def test_human_names_have_a_table_and_a_fallback() -> None:
    assert human_name("core.length") == "roll width"
    assert human_name("supports.left.center") == "clamp zone centre"
    assert human_name("supports.right.expanding.1.width") == "expanding element width"
    assert human_name("supports.left.bearing.radial_stiffness") == "bearing radial stiffness"
    assert human_name("core.material.E_z") == "core axial modulus E_z"
    assert human_name("rest_paper.material.density") == "rest paper density"
    assert human_name("analysis.tolerance") == "tolerance (analysis)"  # not in the table
    assert human_name("model") == "model"


def test_the_written_unit_is_read_back_from_the_labels() -> None:
    assert written_unit(["10 mm", "30 mm"], [0.01, 0.03], "m") == ("mm", 1000.0)
    assert written_unit(["6 bar", "8 bar"], [6e5, 8e5], "Pa") == ("bar", pytest.approx(1e-5))
    # A range's labels have 4 significant digits: 13.34 mm of 0.0133352 m.
    unit, factor = written_unit(["10 mm", "13.34 mm"], [0.01, 0.0133352], "m")
    assert (unit, factor) == ("mm", 1000.0)
    assert written_unit(["2", "3"], [2.0, 3.0], "") == ("", 1.0)  # plain numbers
    assert written_unit(["10 mm", "0.03 m"], [0.01, 0.03], "m") == ("m", 1.0)  # mixed: SI
    assert written_unit(["steel", "aluminium"], [0.0, 1.0], "") == ("", 1.0)


RESPONSE_COLUMNS = ("amplitude_limit_m,amplitude_limit_reached,v_amplitude_limit_m_s,amplitude_implied_factor,"
                    "response_max_web_speed_m_s,max_amplitude_m,max_amplitude_web_speed_m_s,v_i5_07_m_s,v_i5_08_m_s,"
                    "v_koenig_m_s")


def write_response_study(folder: Path, *, response: bool = True) -> Path:
    """A study over rest paper thickness of a case with [response], laid out
    as coremodal study writes it: the thinnest roll never reaches the limit."""
    thicknesses = [0.005, 0.01, 0.04]
    header = HEADER.replace("point,rest_paper.thickness_m,core.length_m,", "point,rest_paper.thickness_m,")
    header = header.replace(",error", "," + RESPONSE_COLUMNS + ",error")
    rows = [header]
    for i, t in enumerate(thicknesses):
        d = 0.182 + 2 * t
        f1 = 26.0 - 100 * t
        common = f"{f1},0.7,0.25,3.82,{f1 / 0.7},{d},{0.7 * np.pi * d * f1},846,2.5"
        if not response:
            cells = "," * 9
        elif i == 0:
            cells = f"0.005,0,,,30,0.0048,17.0,{0.7 * np.pi * d * f1},{0.8 * np.pi * d * f1},15.9"
        else:
            cells = f"0.005,1,{np.pi * d * f1 * 0.99},0.99,30,0.006,17.5,{0.7 * np.pi * d * f1},{0.8 * np.pi * d * f1},17.9"
        rows.append(f"{i + 1},{t},ok,{i or ''},1,bending n=1 m=0,bending,1,0,2,{f1},0.99,0,0,{common},{cells},")
    (folder / "study.csv").write_text("\n".join(rows) + "\n")
    meta = {
        "kind": "study", "case": "synthetic response", "case_file": "x.toml", "n_points": 3, "n_failed": 0,
        "parameters": [
            {"name": "rest_paper.thickness", "column": "rest_paper.thickness_m", "keys": ["rest_paper.thickness"],
             "numeric": True, "unit": "m", "labels": ["5 mm", "10 mm", "40 mm"], "values": thicknesses},
        ],
        "diameter_parameters": ["rest_paper.thickness"],
        "options": {"mesh": "coarse", "modes": 12, "safe_factor": 0.7, "web_speed_m_s": WEB_SPEED},
        "response": response,
    }
    (folder / "study.json").write_text(json.dumps(meta))
    return folder


def test_a_response_study_draws_the_amplitude_based_safe_speed(tmp_path: Path) -> None:
    names = {p.name for p in draw_all(write_response_study(tmp_path))}
    assert {"response_safe_speed.png", "safe_speed.png"} <= names
    assert png_size(tmp_path / "response_safe_speed.png") == (1100, 750)
    plain = tmp_path / "plain"
    plain.mkdir()
    assert "response_safe_speed.png" not in {p.name for p in draw_all(write_response_study(plain, response=False))}
    # Without a diameter parameter the picture is drawn against the fastest numeric parameter.
    study = load_study(tmp_path)
    study.diameter_parameters = []
    assert study_plot.plot_response_safe_speed(study, plain) == plain / "response_safe_speed.png"
