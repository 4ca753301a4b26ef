"""The mesh and mode shapes of a modes.h5 as pyvista or meshio objects,
for users of those packages (neither is needed by coremodal itself).

Cells are the quadratic cells as ParaView gets them (/mesh/vtk_cells: VTK
node order; a hex27 is given as its 20-node hexahedron). Each requested
mode becomes point data ``mode_NN`` (the displacement vector); ``part`` is
cell data, the index into ``Results.part_names``.
"""

from __future__ import annotations

from typing import TYPE_CHECKING, Iterable

import numpy as np

from ._optional import require

if TYPE_CHECKING:
    from .results import Results

#: VTK cell type numbers (vtkCellType.h) of the quadratic cells.
VTK_QUADRATIC_TETRA = 24
VTK_QUADRATIC_HEXAHEDRON = 25
#: meshio's names of the same cells (meshio uses VTK's node order).
MESHIO_CELL = {10: "tetra10", 20: "hexahedron20"}


def _mode_list(results: "Results", modes: Iterable[int] | None) -> list[int]:
    chosen = list(range(1, results.n_modes + 1)) if modes is None else [int(m) for m in modes]
    for index in chosen:
        results._check_index(index)
    return chosen


def _point_data(results: "Results", modes: list[int]) -> dict[str, np.ndarray]:
    width = max(2, len(str(results.n_modes)))
    return {f"mode_{index:0{width}d}": results.shape(index) for index in modes}


def to_pyvista(results: "Results", modes: Iterable[int] | None = None):
    """A pyvista.UnstructuredGrid of the mesh with the shapes of ``modes``
    (1-based; default: all) as point data ``mode_NN`` and the cell data
    ``part``. Raises ImportError (saying how to install it) without pyvista."""
    pyvista = require("pyvista", "Results.to_pyvista()", "pip install pyvista (Results.to_meshio() needs "
                      "only meshio: apt install python3-meshio)")
    chosen = _mode_list(results, modes)
    cells = results.vtk_cells
    per_cell = cells.shape[1]
    kind = VTK_QUADRATIC_TETRA if per_cell == 10 else VTK_QUADRATIC_HEXAHEDRON
    flat = np.hstack([np.full((len(cells), 1), per_cell, dtype=np.int64), cells]).ravel()
    grid = pyvista.UnstructuredGrid(flat, np.full(len(cells), kind, dtype=np.uint8), results.nodes)
    for name, values in _point_data(results, chosen).items():
        grid.point_data[name] = values
    grid.cell_data["part"] = results.cell_part
    return grid


def to_meshio(results: "Results", modes: Iterable[int] | None = None):
    """A meshio.Mesh of the mesh with the shapes of ``modes`` (1-based;
    default: all) as point data ``mode_NN`` and the cell data ``part``
    (``mesh.write("roll.vtu")`` writes it for any VTK reader). Raises
    ImportError (saying how to install it) without meshio."""
    meshio = require("meshio", "Results.to_meshio()", "apt install python3-meshio (or pip install meshio)")
    chosen = _mode_list(results, modes)
    cells = results.vtk_cells
    return meshio.Mesh(
        points=results.nodes,
        cells=[(MESHIO_CELL[cells.shape[1]], cells)],
        point_data=_point_data(results, chosen),
        cell_data={"part": [results.cell_part]},
    )
