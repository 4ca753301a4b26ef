"""The forced-response picture (coremodal.response_plot) on a small synthetic
folder laid out as ``coremodal response`` writes it (response.csv, peaks.csv,
summary.json)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from coremodal.response_plot import ResponseFormatError, draw


def write_response(folder: Path) -> Path:
    """A single-mode resonance (zeta 0.02) at 15 m/s crossing a 5 mm limit,
    with a second probe that the picture leaves out."""
    folder.mkdir(parents=True, exist_ok=True)
    rows = ["web_speed_m_s,speed_rpm,speed_hz,probe,position_m,amplitude_mm,order_1_mm"]
    for i in range(60):
        v = 5 + 15 * i / 59
        r = v / 15
        a = 0.5 * r * r / ((1 - r * r) ** 2 + (0.04 * r) ** 2) ** 0.5
        rpm = v / (3.14159 * 0.2) * 60
        rows += [f"{v},{rpm},{rpm / 60},mid-span,2.16,{a},{a}", f"{v},{rpm},{rpm / 60},z = 1 m,1,{a / 2},{a / 2}"]
    (folder / "response.csv").write_text("\n".join(rows) + "\n")
    (folder / "peaks.csv").write_text(
        "order,web_speed_m_s,speed_rpm,speed_hz,excitation_hz,amplitude_mm,mode,mode_frequency_hz\n"
        "1,15,1432,23.9,23.9,12.5,bending n=1 m=0,23.9\n")
    (folder / "summary.json").write_text(json.dumps({
        "case": {"name": "synthetic"},
        "inputs": {"probes": [{"name": "mid-span", "z_m": 2.16}, {"name": "z = 1 m", "z_m": 1}],
                   "roll_outer_diameter_m": 0.2},
        "speeds": {"limit_mm": 5, "from_amplitude_limit": {"reached": True, "web_speed_m_s": 13.6,
                                                                "implied_safe_factor": 0.91},
                       "safe_web_speed": [{"safe": 0.7, "v_safe_m_s": 10.5, "v_safe_m_min": 630.0},
                                             {"safe": 0.8, "v_safe_m_s": 12.0, "v_safe_m_min": 720.0}]}}))
    return folder


def test_the_picture_is_drawn_into_the_folder(tmp_path: Path) -> None:
    out = draw(write_response(tmp_path / "r"))
    assert out == tmp_path / "r" / "response.png"
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_limit_never_reached_draws_too(tmp_path: Path) -> None:
    folder = write_response(tmp_path / "r")
    summary = json.loads((folder / "summary.json").read_text())
    summary["speeds"]["from_amplitude_limit"] = {"reached": False}
    del summary["speeds"]["safe_web_speed"]
    (folder / "summary.json").write_text(json.dumps(summary))
    assert draw(folder).is_file()


def test_a_folder_without_the_tables_is_refused(tmp_path: Path) -> None:
    with pytest.raises(ResponseFormatError, match="no response.csv"):
        draw(tmp_path)


def test_the_command_line_draws_and_reports_a_wrong_folder(tmp_path: Path) -> None:
    folder = write_response(tmp_path / "r")
    done = subprocess.run([sys.executable, "-m", "coremodal", "response-plot", str(folder)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().endswith("response.png")
    bad = subprocess.run([sys.executable, "-m", "coremodal", "response-plot", str(tmp_path / "none")],
                         capture_output=True, text=True)
    assert bad.returncode == 1
    assert "coremodal: error:" in bad.stderr
