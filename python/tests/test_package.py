"""The package's user-facing objects on a real run folder (conftest.py's
tiny free-free tube): coremodal.load of a folder, the Table reader, the mode
table, pandas/meshio/pyvista conversions, warp scales and cylindrical
components as the program wrote them."""

from __future__ import annotations

import sys
from pathlib import Path

import h5py
import numpy as np
import pytest

import coremodal
from coremodal import display
from coremodal.tables import Table, read_table


@pytest.fixture(scope="session")
def run_folder(modes_h5: Path) -> Path:
    return modes_h5.parent


@pytest.fixture(scope="session")
def run(run_folder: Path) -> coremodal.Run:
    return coremodal.load(run_folder)


# ------------------------------------------------------------------ opening


def test_a_run_folder_opens_as_a_run_with_a_short_repr(run: coremodal.Run,
                                                       results: coremodal.Results) -> None:
    assert isinstance(run, coremodal.Run)
    text = repr(run)
    first = next(i for i, t in enumerate(results.types) if t != "rigid")
    assert text == (f"<coremodal run {results.case_name}: solid, {results.n_modes} modes, "
                    f"f1 = {results.frequencies_hz[first]:.2f} Hz ({results.types[first]})>")
    assert "\n" not in repr(results) and len(repr(results)) < 300
    assert repr(results).startswith(f"<coremodal.Results {results.case_name}")


def test_load_gives_modes_h5_results_as_before(modes_h5: Path) -> None:
    assert isinstance(coremodal.load(modes_h5), coremodal.Results)
    assert isinstance(coremodal.load_h5(modes_h5), coremodal.Results)


def test_load_refuses_what_is_not_there(tmp_path: Path) -> None:
    with pytest.raises(coremodal.ResultsFormatError, match="no such file or folder"):
        coremodal.load(tmp_path / "nothing")
    folder = coremodal.load(tmp_path)  # an empty folder is a Folder without tables
    assert isinstance(folder, coremodal.Folder)
    with pytest.raises(coremodal.ResultsFormatError, match="holds none of study.csv"):
        folder.table


def test_the_mode_table_of_modes_csv_equals_modes_h5(run: coremodal.Run,
                                                     results: coremodal.Results) -> None:
    modes = run.modes
    assert len(modes) == results.n_modes
    np.testing.assert_allclose(modes["frequency_hz"], results.frequencies_hz, rtol=1e-9)
    assert list(modes["type"]) == results.types
    assert modes.columns == results.modes.columns
    np.testing.assert_array_equal(results.modes["n"], results.n)
    assert modes[0]["index"] == 1 and isinstance(modes[0]["index"], int)
    assert run.summary["modes"][0]["frequency_hz"] == pytest.approx(results.frequencies_hz[0], rel=1e-12)
    assert run.results.n_modes == results.n_modes and run.shape(1).shape == (results.n_nodes, 3)


# ------------------------------------------------------------------ tables


def test_read_table_types_its_columns(tmp_path: Path) -> None:
    csv = tmp_path / "study.csv"
    csv.write_text("point,core.length,status,f1_hz\n1,1.5,ok,48.5\n2,2,failed,\n")
    table = read_table(csv)
    assert table.columns == ["point", "core.length", "status", "f1_hz"]
    assert table["point"].dtype == np.int64 and table["core.length"].dtype == np.float64
    assert table["status"] == ["ok", "failed"]
    assert np.isnan(table["f1_hz"][1])
    assert [row["point"] for row in table] == [1, 2]
    assert repr(table).splitlines()[0] == "<study.csv: 2 rows x 4 columns>"
    with pytest.raises(KeyError, match="no column 'f2_hz'"):
        table["f2_hz"]
    with pytest.raises(IndexError):
        table[2]
    folder = coremodal.load(tmp_path)
    assert folder.table["f1_hz"][0] == 48.5  # a study folder's main table


def test_read_table_names_the_line_of_a_broken_row(tmp_path: Path) -> None:
    csv = tmp_path / "bad.csv"
    csv.write_text("a,b\n1,2\n3\n")
    with pytest.raises(ValueError, match=r"bad.csv:3: 1 cells, but the header names 2 columns"):
        read_table(csv)


def test_table_repr_shortens_long_tables() -> None:
    table = Table({"x": np.arange(30)}, name="long")
    assert repr(table).splitlines()[-1] == "... 18 more rows"


def test_to_pandas_gives_the_mode_table(run: coremodal.Run, results: coremodal.Results) -> None:
    pandas = pytest.importorskip("pandas", reason="pandas is not installed (apt install python3-pandas)")
    frame = run.to_pandas()
    assert isinstance(frame, pandas.DataFrame)
    assert list(frame.columns) == run.modes.columns and len(frame) == results.n_modes
    np.testing.assert_allclose(results.to_pandas()["frequency_hz"], results.frequencies_hz)


def test_without_pandas_the_error_says_what_to_install(monkeypatch, results: coremodal.Results) -> None:
    monkeypatch.setitem(sys.modules, "pandas", None)  # import pandas now fails
    with pytest.raises(ImportError, match=r"to_pandas\(\) needs pandas: apt install python3-pandas"):
        results.to_pandas()


# ------------------------------------------------------------------ meshes


def test_to_meshio_holds_the_mesh_and_the_chosen_shapes(results: coremodal.Results) -> None:
    pytest.importorskip("meshio", reason="meshio is not installed (apt install python3-meshio)")
    mesh = results.to_meshio([1, 7])
    np.testing.assert_array_equal(mesh.points, results.nodes)
    assert mesh.cells[0].type == "hexahedron20"
    np.testing.assert_array_equal(mesh.cells[0].data, results.vtk_cells)
    assert sorted(mesh.point_data) == ["mode_01", "mode_07"]
    np.testing.assert_array_equal(mesh.point_data["mode_07"], results.shape(7))
    np.testing.assert_array_equal(mesh.cell_data["part"][0], results.cell_part)
    with pytest.raises(IndexError, match="mode 99 does not exist"):
        results.to_meshio([99])


def test_to_pyvista_or_a_clear_import_error(monkeypatch, results: coremodal.Results) -> None:
    try:
        import pyvista  # noqa: F401
    except ImportError:
        with pytest.raises(ImportError, match="needs pyvista"):
            results.to_pyvista()
        return
    grid = results.to_pyvista([2])
    assert grid.n_points == results.n_nodes and grid.n_cells == results.n_cells
    np.testing.assert_array_equal(grid.point_data["mode_02"], results.shape(2))
    monkeypatch.setitem(sys.modules, "pyvista", None)
    with pytest.raises(ImportError, match="needs pyvista"):
        results.to_pyvista()


# ------------------------------------------------------------------ display data


def test_warp_scales_follow_the_rule_for_each_mode_type(modes_h5: Path, results: coremodal.Results) -> None:
    with h5py.File(modes_h5, "r") as f:
        stored = f["modes/warp_scale"][()]
    length = float(np.ptp(results.nodes, axis=0).max())
    diameter = float(np.ptp(results.nodes, axis=0).min())
    for i in range(1, results.n_modes + 1):
        largest = float(np.linalg.norm(results.shape(i), axis=1).max())
        drawn = stored[i - 1] * largest  # the largest displacement as warped
        if results.types[i - 1] in ("bending", "axial"):
            assert drawn == pytest.approx(0.10 * length, rel=1e-12)
        else:
            assert drawn == pytest.approx(min(0.10 * length, 0.25 * diameter), rel=1e-12)
        assert stored[i - 1] == pytest.approx(
            display.suggested_warp_scale(results.nodes, results.shape(i), results.types[i - 1]), rel=1e-12)
    np.testing.assert_array_equal(results.warp_scales, stored)


def test_the_cylindrical_components_in_the_file_are_the_shape_turned(modes_h5: Path,
                                                                     results: coremodal.Results) -> None:
    theta = np.arctan2(results.nodes[:, 1], results.nodes[:, 0])
    with h5py.File(modes_h5, "r") as f:
        for index in (1, results.n_modes):
            u = results.shape(index)
            u_r = f[f"modes/u_r/mode_{index:04d}"][()]
            assert u_r.dtype == np.float32
            scale = float(np.abs(u).max())
            # Independent check: u_r e_r + u_theta e_theta + u_z e_z == u.
            u_theta, u_z = f[f"modes/u_theta/mode_{index:04d}"][()], f[f"modes/u_z/mode_{index:04d}"][()]
            back = np.column_stack([u_r * np.cos(theta) - u_theta * np.sin(theta),
                                    u_r * np.sin(theta) + u_theta * np.cos(theta), u_z])
            np.testing.assert_allclose(back, u, atol=1e-6 * scale)  # float32: 6e-8 relative
            np.testing.assert_allclose(results.cylindrical(index)[:, 0], u_r, atol=1e-6 * scale)


def test_large_datasets_are_gzip_compressed(modes_h5: Path) -> None:
    with h5py.File(modes_h5, "r") as f:
        sizes = []

        def visit(name: str, item) -> None:
            if isinstance(item, h5py.Dataset) and item.dtype.kind in "fi":
                sizes.append((name, item.size, item.compression))

        f.visititems(visit)
    for name, size, compression in sizes:
        assert compression == ("gzip" if size >= 4096 else None), name
