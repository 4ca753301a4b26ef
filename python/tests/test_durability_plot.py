"""The durability and core-selection pictures (coremodal.durability_plot,
coremodal.selection_plot) on folders the program writes from the shipped
case 18 (``coremodal durability``, ``coremodal select`` with --no-plots), and
a folder that is not theirs refused.

Needs COREMODAL_BIN (the program); skipped without it."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

from coremodal.durability_plot import DurabilityFormatError, draw_durability
from coremodal.selection_plot import SelectionFormatError, draw_chart

REPO = Path(__file__).resolve().parents[2]


def png_size(path: Path) -> tuple[int, int]:
    header = path.read_bytes()[:24]
    assert header[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    return int.from_bytes(header[16:20], "big"), int.from_bytes(header[20:24], "big")


def run(args: list[str]) -> None:
    binary = os.environ.get("COREMODAL_BIN")
    if not binary:
        pytest.skip("COREMODAL_BIN is not set: run through ctest (python_pytest)")
    done = subprocess.run([binary, *args, "--no-plots", "-q"], capture_output=True, text=True, timeout=120)
    assert done.returncode == 0, done.stderr


def test_the_durability_plot_draws_the_fit_limits_and_reduced_curves(tmp_path: Path) -> None:
    out = tmp_path / "dur"
    run(["durability", str(REPO / "cases" / "18-core-durability-76x15.csv"), "-o", str(out), "-p", "1e-5"])
    assert not (out / "durability.png").exists()
    assert png_size(draw_durability(out)) == (1100, 750)


def test_the_selection_chart_has_one_panel_per_stand(tmp_path: Path) -> None:
    out = tmp_path / "sel"
    run(["select", str(REPO / "cases" / "18-core-selection.toml"), "-o", str(out)])
    assert png_size(draw_chart(out)) == (1800, 650)  # two stands, 900 px each


def test_a_folder_that_is_not_theirs_is_refused(tmp_path: Path) -> None:
    with pytest.raises(DurabilityFormatError, match="points.csv: no such file"):
        draw_durability(tmp_path)
    with pytest.raises(SelectionFormatError, match="selection.csv: no such file"):
        draw_chart(tmp_path)


def test_the_command_line_says_why_there_is_no_picture(tmp_path: Path) -> None:
    import sys

    for command in ("durability-plot", "selection-plot"):
        bad = subprocess.run([sys.executable, "-m", "coremodal", command, str(tmp_path / "none")],
                             capture_output=True, text=True, timeout=60)
        assert bad.returncode == 1
        assert "no such file" in bad.stderr
