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

from coremodal.study_plot import StudyFormatError, change_diameters, draw_all, load_study

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
