"""The mode picture (coremodal.plot.mode_figure) as an engineer reads it: a
side view of the deformed roll in metres, curves sampled at the mesh's node
planes, supports shaded, and each mode exaggerated by its dominant motion."""

from __future__ import annotations

import dataclasses
import itertools
from types import SimpleNamespace

import numpy as np
import pytest

import coremodal
from coremodal import display
from coremodal.plot import (SECTION_SCALE_FRACTION, centreline_curves, mode_figure, section_ring,
                            side_view_data)
from coremodal.stations import N_BINS, node_planes, stations
from coremodal.supports import SupportSpan, support_spans

LENGTH, RADII, ANGLES = 2.2, (0.038, 0.053), 32


def graded_tube(n_planes: int = 41) -> np.ndarray:
    """Nodes of a tube whose planes crowd at z = 0 and spread towards
    z = LENGTH (spacing up to 2.5 % of the length): 60 equal bins in z
    would leave bins with no plane in them, as case 02's mesh did."""
    z = LENGTH * np.linspace(0.0, 1.0, n_planes) ** 2
    zz, theta, radius = np.meshgrid(z, np.linspace(-np.pi, np.pi, ANGLES, endpoint=False), RADII,
                                    indexing="ij")
    zz, theta, radius = zz.ravel(), theta.ravel(), radius.ravel()
    return np.column_stack([radius * np.cos(theta), radius * np.sin(theta), zz])


def test_the_centre_line_is_sampled_at_every_node_plane_without_a_gap() -> None:
    nodes = graded_tube()
    shape = np.zeros_like(nodes)
    shape[:, 0] = np.sin(np.pi * nodes[:, 2] / LENGTH)
    curves = centreline_curves(nodes, shape)
    planes = np.unique(nodes[:, 2])
    assert curves.planes
    np.testing.assert_allclose(curves.z, planes, rtol=0, atol=1e-12)
    assert np.all(np.isfinite([curves.ux, curves.uy, curves.uz, curves.twist, curves.ring_shape]))
    # At the planes the curve is the field itself, not a bin's average.
    np.testing.assert_allclose(curves.ux, np.sin(np.pi * planes / LENGTH), atol=1e-12)


def test_the_centre_line_of_a_real_mesh_holds_each_of_its_node_planes(
        results: coremodal.Results) -> None:
    curves = centreline_curves(results.nodes, results.shape(7))
    planes, count = node_planes(results.nodes[:, 2])
    assert curves.planes and len(curves.z) == count
    for z in np.unique(results.nodes[:, 2]):
        assert np.min(np.abs(curves.z - z)) < 1e-9
    assert np.all(np.isfinite(curves.ux)) and np.all(np.diff(curves.z) > 0)


def test_node_planes_join_rounding_errors_and_unstructured_nodes_are_binned() -> None:
    z = np.array([0.0, 1e-17, 0.5, 0.5 + 1e-16, 0.5 - 1e-16, 1.0])
    plane, count = node_planes(z)
    assert count == 3 and list(plane) == [0, 0, 1, 1, 1, 2]
    # A tet mesh: every node at its own z. Bins, none of them empty.
    scattered = np.random.default_rng(1).uniform(0.0, 1.0, 500) ** 3
    where = stations(scattered)
    assert not where.planes and where.count <= N_BINS
    assert set(where.index) == set(range(where.count))


def axial_mode_with_breathing(nodes: np.ndarray, breathing: float) -> np.ndarray:
    """u_z = sin(pi z / L) (the dominant, axial motion) and a Poisson
    breathing u_r = breathing * cos(pi z / L), as an axial mode of a tube."""
    z = nodes[:, 2]
    theta = np.arctan2(nodes[:, 1], nodes[:, 0])
    radial = breathing * np.cos(np.pi * z / LENGTH)
    return np.column_stack([radial * np.cos(theta), radial * np.sin(theta),
                            np.sin(np.pi * z / LENGTH)])


def test_an_axial_mode_is_exaggerated_by_its_axial_motion_not_its_breathing() -> None:
    nodes = graded_tube(81)
    breathing = 0.04
    shape = axial_mode_with_breathing(nodes, breathing)
    # The cross-section: the mode's largest displacement (axial, 1.0) is
    # drawn as 20 % of the radius, so the breathing ring moves by 4 % of that.
    ring = section_ring(nodes, shape)
    outer = max(RADII)
    assert ring.scale == pytest.approx(SECTION_SCALE_FRACTION * outer, rel=1e-3)
    drawn_change = np.hypot(*(ring.deformed - ring.centre).T) - outer
    assert np.abs(drawn_change).max() == pytest.approx(breathing * SECTION_SCALE_FRACTION * outer, rel=2e-2)
    assert ring.in_plane_share == pytest.approx(breathing, rel=2e-2)
    # The side view: the axial motion is drawn as 10 % of the length (the
    # warp scale of an axial mode), so the planes move along z by that much,
    # and the breathing by 4 % of it.
    scale = display.suggested_warp_scale(nodes, shape, "axial")
    fake = SimpleNamespace(nodes=nodes, warp_scales=np.array([scale]))
    view = side_view_data(fake, 1, shape)
    shift = view.deformed[0] - view.rest[0]
    assert np.abs(shift).max() == pytest.approx(0.10 * LENGTH, rel=1e-3)
    widening = (view.deformed[2] - view.rest[2])
    assert np.abs(widening).max() == pytest.approx(breathing * 0.10 * LENGTH, rel=2e-2)


def test_supports_of_a_chuck_scene_are_spans_from_each_core_end() -> None:
    chuck = {"inserted_length_m": 0.11, "shaft_length_m": 0.15,
             "expanding": [{"center_m": 0.07, "width_m": 0.06}]}
    case = {"core": {"length": 2.2}, "supports": {"type": "chucks", "clamps": [], "chucks": [
        {"name": "left", **chuck}, {"name": "right", **chuck}]}}
    spans = support_spans(case)
    by_kind = {kind: [(s.z_start, s.z_end) for s in spans if s.kind == kind]
               for kind in ("chuck body", "expanding element", "bearing")}
    np.testing.assert_allclose(by_kind["chuck body"], [(0.0, 0.11), (2.09, 2.2)], atol=1e-12)
    np.testing.assert_allclose(by_kind["expanding element"], [(0.04, 0.10), (2.10, 2.16)], atol=1e-12)
    bearings = [(a + b) / 2 for a, b in by_kind["bearing"]]
    np.testing.assert_allclose(bearings, [-0.15, 2.35], atol=1e-12)
    clamped = {"supports": {"clamps": [{"name": "left", "z_start": 0.3, "z_end": 0.2}]}}
    assert support_spans(clamped) == [SupportSpan("clamp", 0.2, 0.3)]
    assert support_spans({}) == []


def _side_view(figure):
    [axes] = [a for a in figure.axes if a.get_title().startswith("side view")]
    return axes


def _overlaps(boxes) -> list:
    return [(a, b) for a, b in itertools.combinations(boxes, 2) if a.overlaps(b)]


def test_the_mode_figure_is_a_side_view_in_metres_with_readable_ticks(
        results: coremodal.Results) -> None:
    figure = mode_figure(results, 7, size_px=(1000, 750))
    assert not [a for a in figure.axes if a.name == "3d"]  # no 3D stick any more
    side = _side_view(figure)
    assert side.get_xlabel() == "z (m)"
    low, high = side.get_xlim()
    z = results.nodes[:, 2]
    assert low <= z.min() and high >= z.max() and high - low < 1.5 * np.ptp(z)  # metres, not mm
    assert f"×{results.warp_scales[6]:.3g}" in side.get_title()
    renderer = figure.canvas.get_renderer()
    figure.canvas.draw()
    for axes in figure.axes:
        for axis in (axes.xaxis, axes.yaxis):
            boxes = [t.get_window_extent(renderer) for t in axis.get_ticklabels()
                     if t.get_visible() and t.get_text()]
            assert not _overlaps(boxes), f"tick labels overlap on {axes.get_title()!r}"


def test_the_mode_figure_shades_chucks_expanding_elements_and_bearings(
        results: coremodal.Results) -> None:
    chuck = {"inserted_length_m": 0.05, "shaft_length_m": 0.05,
             "expanding": [{"center_m": 0.03, "width_m": 0.02}]}
    with_chucks = dataclasses.replace(results, case={
        **results.case, "core": {"length": float(np.ptp(results.nodes[:, 2]))},
        "supports": {"type": "chucks", "clamps": [], "chucks": [
            {"name": "left", **chuck}, {"name": "right", **chuck}]}})
    figure = mode_figure(with_chucks, 7, size_px=(800, 600))
    labels = [t.get_text() for a in figure.axes if a.get_legend() for t in a.get_legend().get_texts()]
    for kind in ("chuck body", "expanding element", "bearing"):
        assert kind in labels


def twisted_tube() -> tuple[np.ndarray, np.ndarray]:
    """The graded tube in its first torsion mode: every section turns
    rigidly by phi(z) = sin(pi z / L) (per unit of the shape)."""
    nodes = graded_tube()
    phi = np.sin(np.pi * nodes[:, 2] / LENGTH)
    return nodes, np.column_stack([-nodes[:, 1] * phi, nodes[:, 0] * phi, np.zeros(len(nodes))])


def test_a_torsion_mode_is_drawn_as_surface_lines_that_turn_one_way_then_the_other() -> None:
    from matplotlib.collections import LineCollection
    from matplotlib.figure import Figure

    from coremodal import frames

    nodes, shape = twisted_tube()
    # A thin-walled torsion's warp scale would turn the lines by a sliver: the lines have their own scale.
    fake = SimpleNamespace(nodes=nodes, warp_scales=np.array([1e-3]), types=["torsion"])
    view = frames.side_view(fake, 1, shape)
    lines = frames.surface_lines(fake, shape, view)
    # u_theta / R of a section turned rigidly by phi is phi, at every line.
    np.testing.assert_allclose(lines.turn, np.sin(np.pi * lines.z / LENGTH)[:, None] * np.ones(frames.SURFACE_LINES),
                               atol=1e-12)
    assert lines.scale * np.abs(lines.turn).max() == pytest.approx(np.radians(20.0))
    rest, plus, minus = (frames.surface_line_heights(lines, a) for a in (0.0, 1.0, -1.0))
    assert np.ptp(rest, axis=0) == pytest.approx(np.zeros(frames.SURFACE_LINES), abs=1e-12)  # straight at rest
    middle = int(np.argmax(np.abs(lines.turn[:, 0])))
    # At the plane that turns most, each line has turned by +-20 degrees: the +1 and -1 frames differ.
    up = 0 if view.across == 0 else 1
    angle_plus = lines.angle + np.radians(20.0)
    expected = lines.centre[up] + lines.radius * (np.cos(angle_plus) if up == 0 else np.sin(angle_plus))
    np.testing.assert_allclose(plus[middle], expected, rtol=1e-9)
    assert np.abs(plus[middle] - minus[middle]).max() > 0.1 * lines.radius
    # The frames draw them, coloured by the signed turn; a bending mode's do not.
    for types, drawn in ((["torsion"], True), (["bending"], False)):
        axes = Figure().add_subplot()
        fake.types = types
        frames._draw_frame(axes, fake, shape, view, -1.0, frames._limits(fake, shape, view))
        collections = [c for c in axes.collections if isinstance(c, LineCollection)]
        assert bool(collections) == drawn
        if drawn:
            assert collections[0].get_array().max() <= 0 < -collections[0].get_array().min()


def test_the_mode_picture_of_a_torsion_mode_names_its_surface_lines(results: coremodal.Results) -> None:
    types = list(results.types)
    types[6] = "torsion"  # mode 7's picture drawn as a torsion mode's
    figure = mode_figure(dataclasses.replace(results, types=types), 7, size_px=(800, 600))
    labels = [t.get_text() for a in figure.axes if a.get_legend() for t in a.get_legend().get_texts()]
    assert any(label.startswith("surface lines ×") and "(≤ 20°), colour ±u_θ" in label for label in labels)
