"""The pictures of a run's report.md (coremodal.run_plot): drawn from a real
modes.h5 (the tiny free-free tube of conftest.py) into its folder."""

from __future__ import annotations

import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from coremodal.run_plot import draw_run_plots, mode_png_name, parse_modes


def png_size(path: Path) -> tuple[int, int]:
    header = path.read_bytes()[:24]
    assert header[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


@pytest.fixture()
def folder(modes_h5: Path, tmp_path: Path) -> Path:
    """A results folder of its own holding a copy of modes.h5."""
    shutil.copy(modes_h5, tmp_path / "modes.h5")
    return tmp_path


def test_mode_numbers_are_read_from_a_comma_list():
    assert parse_modes("7,9, 13") == [7, 9, 13]
    assert mode_png_name(7) == "mode_07.png"
    assert mode_png_name(123) == "mode_123.png"
    with pytest.raises(ValueError):
        parse_modes("seven")
    with pytest.raises(ValueError):
        parse_modes(",")


def test_the_listed_modes_and_the_spectrum_are_drawn_into_the_folder(folder: Path):
    written = draw_run_plots(folder, [7, 9], size_px=(500, 375))
    assert [p.name for p in written] == ["spectrum.png", "mode_07.png", "mode_09.png"]
    assert png_size(folder / "mode_07.png") == (500, 375)
    assert png_size(folder / "spectrum.png")[0] > 0


def test_a_mode_the_file_does_not_hold_is_an_error_before_anything_is_drawn(folder: Path):
    with pytest.raises(IndexError, match="mode 999 does not exist"):
        draw_run_plots(folder, [7, 999])
    assert not list(folder.glob("*.png"))


def test_the_command_line_draws_and_reports_errors_with_status_1(folder: Path, cli_env: dict):
    ok = subprocess.run([sys.executable, "-m", "coremodal", "run-plot", str(folder), "--modes", "8",
                         "--size", "400x300"], capture_output=True, text=True, env=cli_env)
    assert ok.returncode == 0, ok.stderr
    assert (folder / "mode_08.png").is_file() and (folder / "spectrum.png").is_file()
    assert "mode_08.png" in ok.stdout
    empty = folder / "empty"
    empty.mkdir()
    bad = subprocess.run([sys.executable, "-m", "coremodal", "run-plot", str(empty)],
                         capture_output=True, text=True, env=cli_env)
    assert bad.returncode == 1
    assert bad.stderr.startswith("coremodal: error:")
