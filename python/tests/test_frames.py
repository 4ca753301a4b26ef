"""coremodal.frames: the first bending mode swinging, as side views."""

from __future__ import annotations

import dataclasses

from pathlib import Path

import numpy as np
import pytest
from matplotlib.figure import Figure

import coremodal
from coremodal import frames


def bending_shape(results: coremodal.Results, amplitude: float = 1e-3) -> np.ndarray:
    """A synthetic first bending shape of the 0.5 m tube: u_y = a sin(pi z / L)."""
    shape = np.zeros_like(results.nodes)
    shape[:, 1] = amplitude * np.sin(np.pi * results.nodes[:, 2] / 0.5)
    return shape


def test_the_side_view_at_zero_amplitude_is_the_undeformed_roll(results: coremodal.Results) -> None:
    shape = bending_shape(results)
    view = frames.side_view(results, 7, shape)
    assert view.across == 1  # the shape moves in y: y is drawn up
    z, low, high = frames.outline(results, shape, view, 0.0)
    # data/tiny.toml: 8 cells along a 0.5 m tube, quadratic: 17 node planes.
    assert view.n_planes == 17
    np.testing.assert_allclose(z, np.linspace(0.0, 0.5, 17), atol=1e-12)
    np.testing.assert_allclose(high, 0.041, rtol=1e-6)
    np.testing.assert_allclose(low, -0.041, rtol=1e-6)


def test_at_full_amplitude_each_plane_moves_by_scale_times_its_displacement(
        results: coremodal.Results) -> None:
    shape = bending_shape(results)
    view = dataclasses.replace(frames.side_view(results, 7, shape), scale=20.0)
    z0, low0, high0 = frames.outline(results, shape, view, 0.0)
    z1, low1, high1 = frames.outline(results, shape, view, -1.0)
    expected = -20.0 * 1e-3 * np.sin(np.pi * z0 / 0.5)  # a rigid shift of each section
    np.testing.assert_allclose(low1 - low0, expected, atol=1e-12)
    np.testing.assert_allclose(high1 - high0, expected, atol=1e-12)
    np.testing.assert_allclose(z1, z0, atol=1e-15)  # no axial motion


def test_the_scale_is_the_modes_warp_scale(results: coremodal.Results) -> None:
    view = frames.side_view(results, 7, results.shape(7))
    assert view.scale == results.warp_scales[6]


def test_the_strip_is_a_figure_of_five_frames_and_a_png(results: coremodal.Results, tmp_path: Path) -> None:
    index = 7
    figure = frames.frame_strip_figure(results, index)
    assert isinstance(figure, Figure) and len(figure.axes) == len(frames.STRIP_AMPLITUDES)
    path = frames.draw_frame_strip(results, index, tmp_path / frames.strip_file(index))
    assert path.name == f"mode_{index:02d}_frames.png" and path.stat().st_size > 10_000


def test_the_animation_is_a_looping_gif_of_one_period(results: coremodal.Results, tmp_path: Path) -> None:
    Image = pytest.importorskip("PIL.Image", reason="PIL is not installed (apt install python3-pil)")
    index = 7
    # Phases 0, 90, 180, 270 degrees: amplitudes 0, 1, 0, -1, no two alike in
    # a row (PIL merges equal neighbours, e.g. sin 60 and sin 120 degrees).
    path = frames.draw_animation(results, index, tmp_path / "mode.gif", n_frames=4)
    with Image.open(path) as gif:
        assert gif.format == "GIF" and gif.n_frames == 4
        assert gif.info.get("loop") == 0


def test_figures_come_back_from_the_run_object(modes_h5: Path) -> None:
    run = coremodal.load(modes_h5.parent)
    for figure in (run.plot_mode(7, size_px=(400, 300)), run.plot_spectrum(), run.plot_frames(7)):
        assert isinstance(figure, Figure)
