"""ParaView opens a run's modes.xdmf with the modes as time steps and
renders a mode (python/coremodal/paraview_mode.py under pvpython, behind
xvfb-run when there is no display). Skipped, saying why, where ParaView is
not installed: it is an optional group of scripts/setup.sh
(COREMODAL_PARAVIEW=1)."""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

import coremodal
from coremodal.pvrun import ParaViewMissing, pvpython_command

#: pvpython starts in 5-20 s; a render of the tiny tube takes a few more.
PVPYTHON_TIMEOUT_S = 300


def pvpython_or_skip() -> None:
    try:
        pvpython_command([])
    except ParaViewMissing as why:
        pytest.skip(f"ParaView tests skipped: {why}")


def run_script(*args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run(pvpython_command(list(args)), capture_output=True, text=True,
                          timeout=PVPYTHON_TIMEOUT_S)


@pytest.fixture(scope="session")
def rendered(modes_h5: Path, tmp_path_factory: pytest.TempPathFactory) -> tuple[Path, str]:
    """Mode 7 rendered with 4 frames and a GIF: (folder, stdout)."""
    pvpython_or_skip()
    out = tmp_path_factory.mktemp("paraview")
    done = run_script(str(modes_h5.parent), "--mode", "7", "--out", str(out / "mode_07.png"),
                      "--size", "800x400", "--frames", "4", "--gif", str(out / "mode_07.gif"))
    assert done.returncode == 0, f"stdout:\n{done.stdout}\nstderr:\n{done.stderr}"
    return out, done.stdout


def test_paraview_lists_every_mode_as_a_time_step(modes_h5: Path, results: coremodal.Results) -> None:
    pvpython_or_skip()
    done = run_script(str(modes_h5.parent), "--list")
    assert done.returncode == 0, done.stderr
    lines = done.stdout.strip().splitlines()
    assert lines[0] == f"time steps: {results.n_modes}"
    steps = lines[1:]
    assert len(steps) == results.n_modes
    for index, line in enumerate(steps, start=1):
        # "7: mode 7: 1476.61 Hz, ovalling, n=2, m=0; frequency_hz 1476.61, warp_scale ..."
        assert line.startswith(f"{index}: {results.label(index)}; frequency_hz "), line
        frequency = float(line.split("frequency_hz ")[1].split(",")[0])
        assert frequency == pytest.approx(results.frequencies_hz[index - 1], rel=1e-5)
        warp = float(line.split("warp_scale ")[1])
        assert warp == pytest.approx(results.warp_scales[index - 1], rel=1e-3)


def test_the_rendered_mode_is_a_picture_not_a_blank(rendered: tuple[Path, str]) -> None:
    import matplotlib.image

    out, stdout = rendered
    image = matplotlib.image.imread(out / "mode_07.png")[:, :, :3]
    assert image.shape[:2] == (400, 800)
    pixels = (image.reshape(-1, 3) * 255).round().astype(np.uint8)
    colours = np.unique(pixels, axis=0)
    drawn = np.any(pixels < 250, axis=1).mean()  # not the white background
    # The warped tube coloured by |u| (viridis), the scalar bar and the text:
    # hundreds of colours over a tenth of the picture; a blank render has 1.
    assert len(colours) > 100, f"only {len(colours)} colours"
    assert drawn > 0.05, f"only {drawn:.1%} of the pixels are drawn"


def test_the_orientation_axes_are_labelled_dark_on_white(rendered: tuple[Path, str]) -> None:
    import matplotlib.image

    out, _ = rendered
    image = (matplotlib.image.imread(out / "mode_07.png")[:, :, :3] * 255).round().astype(int)
    corner = image[-100:, :100]  # the orientation axes, lower left
    # Their X, Y, Z: grey to black pixels (the axes themselves are red, yellow, green).
    # ParaView's default labels are white on the white background: 3 such pixels there, 25 drawn dark.
    grey = (np.ptp(corner, axis=2) < 40) & (corner.max(axis=2) < 170)
    assert grey.sum() > 12, f"{grey.sum()} dark pixels in the orientation axes' corner"


def test_the_animation_frames_differ_and_join_into_a_gif(rendered: tuple[Path, str]) -> None:
    import matplotlib.image

    out, stdout = rendered
    frames = sorted(out.glob("mode_07_frame_*.png"))
    assert [f.name for f in frames] == [f"mode_07_frame_{k:03d}.png" for k in range(4)]
    # Phases 0 and 90 degrees: undeformed and fully warped, not the same picture.
    first, quarter = (matplotlib.image.imread(frames[k]) for k in (0, 1))
    assert np.abs(first - quarter).max() > 0.1
    gif = out / "mode_07.gif"
    assert gif.is_file() and gif.read_bytes()[:6] in (b"GIF87a", b"GIF89a"), stdout


def test_without_pvpython_the_command_says_what_to_install(tmp_path: Path, cli_env: dict) -> None:
    env = dict(cli_env, PATH=str(tmp_path))  # a PATH with no pvpython on it
    done = subprocess.run([sys.executable, "-m", "coremodal", "paraview", str(tmp_path), "--list"],
                          capture_output=True, text=True, env=env)
    assert done.returncode == 1
    assert "pvpython is not installed: apt install paraview python3-paraview xvfb" in done.stderr


def test_without_a_display_the_script_runs_under_xvfb_run(tmp_path: Path) -> None:
    fake = tmp_path / "pvpython"
    fake.write_text("#!/bin/sh\n")
    fake.chmod(0o755)
    xvfb = tmp_path / "xvfb-run"
    shutil.copy(fake, xvfb)
    with_display = pvpython_command(["R"], {"PATH": str(tmp_path), "DISPLAY": ":0"})
    assert with_display[0] == str(fake) and with_display[-1] == "R"
    headless = pvpython_command(["R"], {"PATH": str(tmp_path)})
    assert headless[:4] == [str(xvfb), "-a", "-s", "-screen 0 1920x1080x24 -noreset"]
    os.remove(xvfb)
    with pytest.raises(ParaViewMissing, match="no xvfb-run"):
        pvpython_command(["R"], {"PATH": str(tmp_path)})
