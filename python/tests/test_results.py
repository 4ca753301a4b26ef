"""The python reader and pictures, on a real modes.h5 of a free-free steel
tube (see conftest.py) — plus a copy of it edited to a future schema."""

from __future__ import annotations

import shutil
import struct
import subprocess
import sys
import xml.etree.ElementTree as ET
from pathlib import Path

import h5py
import numpy as np
import pytest

import coremodal
from coremodal.plot import (SECTION_SCALE_FRACTION, centreline_curves,
                            clamp_spans, draw_mode, section_ring)

N_MODES_ASKED = 10  # [analysis] modes in data/tiny.toml


def png_size(path: Path) -> tuple[int, int]:
    """(width, height) from a PNG's IHDR chunk."""
    header = path.read_bytes()[:24]
    assert header[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    return struct.unpack(">II", header[16:24])


def run_cli(env: dict[str, str], *args: str) -> subprocess.CompletedProcess[str]:
    return subprocess.run([sys.executable, "-m", "coremodal", *args], capture_output=True,
                          text=True, env=env, timeout=300)


# ------------------------------------------------------------------ loading


def test_counts_and_shapes_are_consistent(results: coremodal.Results) -> None:
    k = results.n_modes
    assert k == N_MODES_ASKED
    for per_mode in (results.frequencies_hz, results.eigenvalues, results.relative_residuals,
                     results.n, results.m, results.dominant_share):
        assert per_mode.shape == (k,)
    assert len(results.types) == k
    assert results.effective_mass.shape == (k, 4)

    assert results.schema_version == 1
    assert results.program.startswith("coremodal")
    assert isinstance(results.case, dict) and results.case
    assert results.cell_type in ("hex20", "hex27", "tet10")

    n_nodes, n_cells = results.n_nodes, results.n_cells
    assert results.nodes.shape == (n_nodes, 3) and n_nodes > 0
    assert results.cells.shape == (n_cells, coremodal.results.NODES_PER_CELL[results.cell_type])
    assert 0 <= results.cells.min() and results.cells.max() < n_nodes
    assert results.cell_part.shape == (n_cells,)
    assert 0 <= results.cell_part.min() and results.cell_part.max() < len(results.part_names)
    for name, group in results.node_groups.items():
        assert group.ndim == 1 and (group.size == 0 or group.max() < n_nodes), name

    for index in (1, k):
        shape = results.shape(index)
        assert shape.shape == (n_nodes, 3)
        assert np.all(np.isfinite(shape)) and np.any(shape != 0)
    for bad in (0, k + 1):
        with pytest.raises(IndexError, match=f"mode {bad} does not exist"):
            results.shape(bad)


def test_tube_dimensions_match_the_case(results: coremodal.Results) -> None:
    # Inner diameter 76 mm, wall 3 mm, length 0.5 m (data/tiny.toml).
    radius = np.hypot(results.nodes[:, 0], results.nodes[:, 1])
    assert radius.min() == pytest.approx(0.038, rel=1e-6)
    assert radius.max() == pytest.approx(0.041, rel=1e-6)
    assert np.ptp(results.nodes[:, 2]) == pytest.approx(0.5, rel=1e-9)


def test_frequencies_ascend_and_elastic_ones_are_positive(results: coremodal.Results) -> None:
    f = results.frequencies_hz
    tolerance = 1e-6 * float(np.abs(f).max())
    assert np.all(np.diff(f) >= -tolerance), f
    elastic = np.array([t != "rigid" for t in results.types])
    assert np.all(f[elastic] > 0), f


def test_free_free_tube_has_six_rigid_modes_first(results: coremodal.Results) -> None:
    assert results.types[:6] == ["rigid"] * 6
    assert "rigid" not in results.types[6:]
    # Rigid modes sit at (numerically) zero, far below the first elastic mode.
    first_elastic = results.frequencies_hz[6]
    assert np.all(np.abs(results.frequencies_hz[:6]) < 1e-2 * first_elastic)


def test_vtk_cells_hold_the_same_nodes_as_the_cells(results: coremodal.Results) -> None:
    vtk = results.vtk_cells
    corners = 4 if results.cell_type == "tet10" else 8
    assert vtk.shape == (results.n_cells, 10 if results.cell_type == "tet10" else 20)
    np.testing.assert_array_equal(vtk[:, :corners], results.cells[:, :corners])
    np.testing.assert_array_equal(np.sort(vtk, axis=1),
                                  np.sort(results.cells[:, : vtk.shape[1]], axis=1))


# ------------------------------------------------------------------ XDMF


def test_xdmf_is_a_temporal_collection_pointing_at_existing_datasets(
        modes_h5: Path, results: coremodal.Results) -> None:
    xdmf = modes_h5.with_name("modes.xdmf")
    assert xdmf.is_file(), f"no {xdmf} beside {modes_h5}"
    root = ET.parse(xdmf).getroot()
    collection = root.find("./Domain/Grid")
    assert collection.get("GridType") == "Collection"
    assert collection.get("CollectionType") == "Temporal"
    grids = collection.findall("Grid")
    assert len(grids) == results.n_modes
    # Time = mode number, in order.
    assert [float(g.find("Time").get("Value")) for g in grids] == list(range(1, results.n_modes + 1))

    expected_topology = "Tetrahedron_10" if results.cell_type == "tet10" else "Hexahedron_20"
    for index, grid in enumerate(grids, start=1):
        topology = grid.find("Topology")
        assert topology.get("TopologyType") == expected_topology
        assert int(topology.get("NumberOfElements")) == results.n_cells
        assert grid.get("Name").startswith(f"mode_{index:02d}_")
        point = {a.get("Name") for a in grid.findall("Attribute") if a.get("Center") == "Node"}
        assert point == {"displacement", "display_displacement", "u_r", "u_theta", "u_z"}
        fields = {a.get("Name"): a.find("DataItem").text.split()
                  for a in grid.findall("Attribute") if a.get("Center") == "Grid"}
        i = index - 1
        assert float(fields["frequency_hz"][0]) == results.frequencies_hz[i]  # all digits
        assert int(fields["n"][0]) == results.n[i] and int(fields["m"][0]) == results.m[i]
        assert int(fields["mode"][0]) == index
        assert "".join(chr(int(c)) for c in fields["type"]) == results.types[i]
        assert float(fields["warp_scale"][0]) == pytest.approx(results.warp_scales[i], rel=1e-15)

    # Play in ParaView at scale 1: the display array is the shape times its warp scale.
    with h5py.File(modes_h5, "r") as f:
        for index in range(1, results.n_modes + 1):
            np.testing.assert_allclose(f[f"modes/display/mode_{index:04d}"][()],
                                       results.warp_scales[index - 1] * results.shape(index), rtol=1e-6,
                                       atol=1e-6 * results.warp_scales[index - 1] * np.abs(results.shape(index)).max())
    with h5py.File(modes_h5, "r") as f:
        for item in root.iter("DataItem"):
            if item.get("Format") != "HDF":
                continue
            filename, dataset = item.text.strip().split(":", 1)
            assert filename == modes_h5.name
            assert dataset in f, dataset
            dims = tuple(int(d) for d in item.get("Dimensions").split())
            assert f[dataset].shape == dims, dataset


# ------------------------------------------------------------------ pictures


def test_draw_mode_writes_a_png_of_the_requested_size(results: coremodal.Results,
                                                      tmp_path: Path) -> None:
    default = tmp_path / "mode7.png"
    draw_mode(results, 7, default)
    assert default.stat().st_size > 10_000  # a picture, not an empty canvas
    assert png_size(default) == (1200, 900)

    small = tmp_path / "small.png"
    draw_mode(results, 7, small, size_px=(640, 480))
    assert png_size(small) == (640, 480)


def test_the_side_view_scale_is_the_modes_warp_scale(results: coremodal.Results,
                                                     tmp_path: Path) -> None:
    """The side view exaggerates as ParaView and the frame strip do, by the
    mode's suggested warp scale; --scale sets it instead."""
    scale = draw_mode(results, 7, tmp_path / "m.png", size_px=(320, 240))
    assert scale == pytest.approx(results.warp_scales[6])
    assert draw_mode(results, 7, tmp_path / "m2.png", scale=2.5, size_px=(320, 240)) == 2.5


# A synthetic tube: 121 planes of 48 nodes on each of 3 radii, for testing the
# curves and the ring on displacement fields known in closed form.
TUBE_LENGTH, TUBE_RADII, TUBE_PLANES, TUBE_ANGLES = 4.0, (0.075, 0.082, 0.09), 121, 48


def synthetic_tube() -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Nodes (N, 3) and each node's z, angle and radius."""
    z, theta, radius = np.meshgrid(np.linspace(0.0, TUBE_LENGTH, TUBE_PLANES),
                                   np.linspace(-np.pi, np.pi, TUBE_ANGLES, endpoint=False),
                                   TUBE_RADII, indexing="ij")
    z, theta, radius = z.ravel(), theta.ravel(), radius.ravel()
    nodes = np.column_stack([radius * np.cos(theta), radius * np.sin(theta), z])
    return nodes, z, theta, radius


def test_centreline_of_a_bending_sine_is_the_sine() -> None:
    nodes, z, _, _ = synthetic_tube()
    shape = np.zeros_like(nodes)
    shape[:, 0] = np.sin(np.pi * z / TUBE_LENGTH)
    curves = centreline_curves(nodes, shape)
    assert curves.planes and curves.z.shape == (TUBE_PLANES,)
    np.testing.assert_allclose(curves.ux, np.sin(np.pi * curves.z / TUBE_LENGTH), atol=1e-12)
    assert np.abs(curves.ux).max() == pytest.approx(1.0, abs=1e-12)
    for other in (curves.uy, curves.uz, curves.twist):
        np.testing.assert_allclose(other, 0.0, atol=1e-12)
    # The section moves but keeps its shape.
    assert np.abs(curves.ring_shape).max() < 1e-12


def test_centreline_shows_axial_displacement_and_twist() -> None:
    nodes, z, _, _ = synthetic_tube()
    shape = np.zeros_like(nodes)
    shape[:, 2] = np.cos(np.pi * z / TUBE_LENGTH)
    twist = 0.01 * z  # rad: the section turns as a rigid disc, u = twist * (-y, x)
    shape[:, 0], shape[:, 1] = -twist * nodes[:, 1], twist * nodes[:, 0]
    curves = centreline_curves(nodes, shape)
    np.testing.assert_allclose(curves.uz, np.cos(np.pi * curves.z / TUBE_LENGTH), atol=1e-12)
    np.testing.assert_allclose(curves.twist, 0.01 * curves.z, rtol=1e-9, atol=1e-12)
    for other in (curves.ux, curves.uy, curves.ring_shape):
        np.testing.assert_allclose(other, 0.0, atol=1e-12)


def test_section_ring_of_an_ovalling_field_is_an_n2_ring() -> None:
    nodes, z, theta, _ = synthetic_tube()
    # u_r = cos(2 theta), largest at mid-length: the ring is taken there.
    radial = 1e-3 * np.cos(2 * theta) * np.sin(np.pi * z / TUBE_LENGTH)
    shape = np.column_stack([radial * np.cos(theta), radial * np.sin(theta), np.zeros_like(z)])
    ring = section_ring(nodes, shape)
    outer = max(TUBE_RADII)
    assert ring.radius == pytest.approx(outer)
    assert ring.z == pytest.approx(TUBE_LENGTH / 2, abs=1e-9)  # the middle node plane
    assert len(ring.theta) == TUBE_ANGLES and np.all(np.diff(ring.theta) > 0)
    np.testing.assert_allclose(np.hypot(*ring.xy.T), outer)
    # The deformed ring's largest radial change is 20 % of the radius...
    deformed_radius = np.hypot(*(ring.deformed - ring.centre).T)
    change = deformed_radius - outer
    assert np.abs(change).max() == pytest.approx(SECTION_SCALE_FRACTION * outer, rel=1e-9)
    # ...and it is an n = 2 shape: two waves around, longest along x and y.
    spectrum = np.abs(np.fft.rfft(change))
    assert int(np.argmax(spectrum)) == 2
    assert spectrum[2] > 50 * np.delete(spectrum, 2).max()
    assert change[np.argmin(np.abs(ring.theta))] > 0  # theta = 0: wider
    assert change[np.argmin(np.abs(ring.theta - np.pi / 2))] < 0  # theta = 90 deg: narrower
    # The section does not move as a whole, but its shape changes.
    curves = centreline_curves(nodes, shape)
    np.testing.assert_allclose([curves.ux, curves.uy, curves.uz], 0.0, atol=1e-12)
    middle = np.argmin(np.abs(curves.z - TUBE_LENGTH / 2))
    assert curves.ring_shape[middle] == pytest.approx(1e-3 / np.sqrt(2), rel=1e-2)


def test_section_ring_of_a_bending_field_is_a_shifted_circle() -> None:
    nodes, z, _, _ = synthetic_tube()
    shape = np.zeros_like(nodes)
    shape[:, 1] = np.sin(np.pi * z / TUBE_LENGTH)
    ring = section_ring(nodes, shape)
    assert ring.z == pytest.approx(TUBE_LENGTH / 2, abs=1e-9)  # the middle node plane
    shift = ring.deformed - ring.xy
    np.testing.assert_allclose(shift[:, 0], 0.0, atol=1e-15)
    np.testing.assert_allclose(shift[:, 1], SECTION_SCALE_FRACTION * max(TUBE_RADII), rtol=1e-3)


def test_clamp_spans_read_the_case() -> None:
    case = {"supports": {"type": "clamped", "clamps": [
        {"name": "left", "z_start": 0.2, "z_end": 0.3},
        {"name": "right", "z_start": 4.02, "z_end": 4.12}]}}
    assert clamp_spans(case) == [(0.2, 0.3), (4.02, 4.12)]
    assert clamp_spans({"supports": {"type": "free", "clamps": []}}) == []
    assert clamp_spans({}) == []
    assert clamp_spans({"supports": {"clamps": [{"name": "no zone"}]}}) == []


def test_draw_mode_of_a_clamped_core_draws_three_panels(results: coremodal.Results,
                                                        tmp_path: Path) -> None:
    """The picture for a case with clamps (the tiny tube with two clamps
    added to its case): curves along the core and the cross-section."""
    import dataclasses

    clamped = dataclasses.replace(results, case={
        **results.case, "supports": {"type": "clamped", "clamps": [
            {"name": "left", "z_start": 0.0, "z_end": 0.05},
            {"name": "right", "z_start": 0.45, "z_end": 0.5}]}})
    out = tmp_path / "clamped.png"
    draw_mode(clamped, 7, out, size_px=(900, 700))
    assert png_size(out) == (900, 700)
    assert out.stat().st_size > 10_000


# ------------------------------------------------------------------ CLI


def test_cli_table_prints_every_mode(modes_h5: Path, results: coremodal.Results,
                                     cli_env: dict[str, str]) -> None:
    run = run_cli(cli_env, "table", str(modes_h5))
    assert run.returncode == 0, run.stderr
    rows = [line.split() for line in run.stdout.splitlines()]
    numbered = [row for row in rows if row and row[0].isdigit()]
    assert [int(row[0]) for row in numbered] == list(range(1, results.n_modes + 1))
    for row, frequency, kind in zip(numbered, results.frequencies_hz, results.types):
        assert float(row[1]) == pytest.approx(frequency, abs=1e-3)
        assert row[2] == kind


def test_cli_table_reads_a_results_folder_and_says_why_one_has_no_modes_h5(
        modes_h5: Path, cli_env: dict[str, str], tmp_path: Path) -> None:
    by_file = run_cli(cli_env, "table", str(modes_h5))
    by_folder = run_cli(cli_env, "table", str(modes_h5.parent))
    assert by_folder.returncode == 0, by_folder.stderr
    assert by_folder.stdout == by_file.stdout
    beam_run = tmp_path / "beam-run"
    beam_run.mkdir()
    (beam_run / "modes.csv").write_text("index,frequency_hz\n1,10\n")
    none = run_cli(cli_env, "table", str(beam_run))
    assert none.returncode == 1
    assert "a folder without modes.h5" in none.stderr and "modes.csv" in none.stderr


def test_the_table_prints_round_off_effective_masses_as_0_as_the_console_does(
        results: coremodal.Results) -> None:
    import dataclasses

    masses = np.array(results.effective_mass, copy=True)
    masses[0, :3] = [4.4e-23, 2.0, 0.0]  # round-off of an exact zero beside a real mass
    masses[1, :3] = [1e-3, 0.0, 0.0]  # small, but far above round-off: kept
    table = dataclasses.replace(results, effective_mass=masses).table().splitlines()
    first = table[2].split()
    assert float(first[6]) == 0.0 and float(first[7]) == 2.0
    assert float(table[3].split()[6]) == pytest.approx(1e-3)


def test_cli_plot_writes_the_png(modes_h5: Path, cli_env: dict[str, str],
                                 tmp_path: Path) -> None:
    out = tmp_path / "mode7.png"
    run = run_cli(cli_env, "plot", str(modes_h5), "--mode", "7", "--out", str(out),
                  "--size", "400x300")
    assert run.returncode == 0, run.stderr
    assert png_size(out) == (400, 300)

    run = run_cli(cli_env, "plot", str(modes_h5), "--mode", "999", "--out", str(out))
    assert run.returncode == 1
    assert "mode 999 does not exist" in run.stderr


# ------------------------------------------------------------------ schema


@pytest.fixture
def future_file(modes_h5: Path, tmp_path: Path) -> Path:
    """A copy of the real file claiming the next schema version."""
    copy = tmp_path / "future.h5"
    shutil.copyfile(modes_h5, copy)
    with h5py.File(copy, "r+") as f:
        f.attrs["schema_version"] = np.int32(coremodal.SUPPORTED_SCHEMA_VERSION + 1)
    return copy


def test_a_future_schema_version_is_rejected(future_file: Path,
                                             cli_env: dict[str, str]) -> None:
    newer = coremodal.SUPPORTED_SCHEMA_VERSION + 1
    with pytest.raises(coremodal.SchemaVersionError, match=f"schema_version {newer}"):
        coremodal.load(future_file)

    run = run_cli(cli_env, "table", str(future_file))
    assert run.returncode == 1
    assert f"schema_version {newer}" in run.stderr and "Traceback" not in run.stderr


def test_a_file_that_is_not_coremodal_results_is_rejected(tmp_path: Path) -> None:
    other = tmp_path / "other.h5"
    with h5py.File(other, "w") as f:
        f["x"] = np.zeros(3)
    with pytest.raises(coremodal.ResultsFormatError, match="not a coremodal results file"):
        coremodal.load(other)
