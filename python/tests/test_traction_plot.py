"""The traction picture (coremodal.traction_plot) on a small synthetic folder
laid out as ``coremodal traction`` writes it (traction.csv, summary.json)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from coremodal.traction_plot import TractionFormatError, draw, load


def png_size(path: Path) -> tuple[int, int]:
    header = path.read_bytes()[:24]
    assert header[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


def write_traction(folder: Path, grooved: bool = True) -> Path:
    """Four speeds; traction falling to zero at 3 m/s, the last point invalid."""
    folder.mkdir(parents=True, exist_ok=True)
    header = ("web_speed_m_s,tension_N_m,air_pressure_Pa,wrap_pressure_Pa,contact_pressure_Pa,air_share,p_star,"
              "h_star,traction_N_m,capstan_traction_N_m,effective_friction,theta_star,b_star,contact,valid")
    if grooved:
        header += ",plain_traction_N_m,plain_effective_friction"
    lines = [header + ",violations"]
    for v, t, f, valid in [(0, 30, 0.3, "true"), (1, 20, 0.2, "true"), (2, 10, 0.1, "true"), (3, 0, 0, "false")]:
        row = f"{v},100,0,2000,2000,0,0,0,{t},30,{f},,,true,{valid}"
        if grooved:
            row += f",{t / 10},{f / 10}"
        lines.append(row + ",")
    (folder / "traction.csv").write_text("\n".join(lines) + "\n")
    summary = {"case": {"name": "synthetic"}, "roller": {"grooves": {"shape": "circular" if grooved else "none"}},
               "clearance": {"effective_clearance_m": 25e-6},
               "traction_speeds": {"zero_traction_m_s": 3.0, "slip_m_s": 1.5}}
    (folder / "summary.json").write_text(json.dumps(summary))
    return folder


@pytest.mark.parametrize("grooved", [True, False])
def test_draws_traction_and_friction_against_speed(tmp_path: Path, grooved: bool) -> None:
    out = draw(write_traction(tmp_path / "t", grooved))
    assert out.name == "traction.png"
    assert png_size(out) == (1000, 800)


def test_refuses_a_folder_that_is_not_a_traction_result(tmp_path: Path) -> None:
    with pytest.raises(TractionFormatError, match="no such file"):
        load(tmp_path)
    folder = write_traction(tmp_path / "t")
    (folder / "summary.json").write_text("{}")
    with pytest.raises(TractionFormatError, match="not a coremodal traction summary"):
        load(folder)


def test_the_command_line_draws_it(tmp_path: Path) -> None:
    folder = write_traction(tmp_path / "t")
    done = subprocess.run([sys.executable, "-m", "coremodal", "traction-plot", str(folder)],
                          capture_output=True, text=True, cwd=Path(__file__).resolve().parents[1])
    assert done.returncode == 0, done.stderr
    assert (folder / "traction.png").is_file()
