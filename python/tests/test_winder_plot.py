"""The winder pictures (coremodal.winder_plot) on a small synthetic folder laid
out as ``coremodal winder`` writes it (winder.csv, crossings.csv,
response.csv, summary.json)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from coremodal.winder_plot import WinderFormatError, draw_all, load_winder


def png_size(path: Path) -> tuple[int, int]:
    header = path.read_bytes()[:24]
    assert header[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


def write_winder(folder: Path) -> Path:
    """Three diameters; a drum mode at 20 Hz, a roll mode falling through it;
    one crossing of the 2nd harmonic."""
    folder.mkdir(parents=True, exist_ok=True)
    diameters = [0.5, 1.0, 1.5]
    modes = ["roll_diameter_m,mode,frequency_hz,type,track,share_drums,share_rolls,share_rider,damping_ratio,"
             "mac_previous,ambiguous"]
    response = ["roll_diameter_m,harmonic,frequency_hz,x_over_f_m_per_n"]
    for d in diameters:
        modes.append(f"{d},1,{30 / d},roll,1,0.1,0.9,0,0.05,,false")
        modes.append(f"{d},2,20,drum,2,0.9,0.1,0,0.01,,false")
        for k in (1, 2):
            response.append(f"{d},{k},{k * 30 / (3.14159 * d)},{1e-8 * k}")
    (folder / "winder.csv").write_text("\n".join(modes) + "\n")
    (folder / "response.csv").write_text("\n".join(response) + "\n")
    (folder / "crossings.csv").write_text(
        "roll_diameter_m,harmonic,harmonic_frequency_hz,track,mode_frequency_hz,type,damping_ratio,x_over_f_m_per_n\n"
        "0.9549,2,20,2,20,drum,0.01,3e-7\n")
    points = [{"roll_diameter_m": d,
               "estimate": {"symmetric": {"estimate_hz": 20.5}, "antisymmetric": {"estimate_hz": 20.2}}}
              for d in diameters]
    summary = {"case": {"name": "synthetic"}, "points": points,
               "scene": {"web_speed_m_s": 30.0,
                         "sweep": {"harmonics": 2, "max_frequency_hz": 80.0, "response_drum": "front",
                                   "response_direction": "vertical"}}}
    (folder / "summary.json").write_text(json.dumps(summary))
    return folder


def test_draws_the_crossing_diagram_and_the_response(tmp_path: Path) -> None:
    folder = write_winder(tmp_path / "w")
    paths = draw_all(folder)
    assert [p.name for p in paths] == ["crossing_diagram.png", "response.png"]
    for p in paths:
        assert png_size(p) == (1100, 750)


def test_reads_what_the_pictures_need(tmp_path: Path) -> None:
    results = load_winder(write_winder(tmp_path / "w"))
    assert results.web_speed == 30.0
    assert results.harmonics == 2
    assert len(results.crossings) == 1


def test_a_folder_without_winder_results_is_refused(tmp_path: Path) -> None:
    with pytest.raises(WinderFormatError, match="winder.csv: no such file"):
        load_winder(tmp_path)


def test_the_command_line_reports_a_missing_folder(tmp_path: Path) -> None:
    run = subprocess.run([sys.executable, "-m", "coremodal", "winder-plot", str(tmp_path / "none")],
                         capture_output=True, text=True, cwd=Path(__file__).resolve().parents[1])
    assert run.returncode == 1
    assert "no such file" in run.stderr
