"""Reading modes.h5, the results file written by the coremodal program.

The layout (schema version 1) is described in docs/reference/results.md, section
"modes.h5 and modes.xdmf". Everything but the mode shapes is read at once;
each shape is read from the file when asked for, so that large meshes with
many modes do not fill memory.
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import Any, Iterable

import h5py
import numpy as np

from . import display, meshes
from .tables import Table

# The console's mode table (src/output/summary.cpp, kNegligibleMassShare)
# prints effective masses below this share of the model mass as 0.
NEGLIGIBLE_MASS_SHARE = 1e-9

#: Newest layout of modes.h5 that this package understands.
SUPPORTED_SCHEMA_VERSION = 1

#: Nodes per cell for each cell type, in gmsh order.
NODES_PER_CELL = {"hex20": 20, "hex27": 27, "tet10": 10}


class ResultsFormatError(ValueError):
    """The file is not a coremodal modes.h5, or is damaged."""


class SchemaVersionError(ResultsFormatError):
    """The file was written by a newer coremodal than this package can read."""


@dataclass(frozen=True, eq=False)
class Results:
    """The contents of one modes.h5.

    Per-mode arrays have one row per mode in frequency order; row ``i - 1``
    belongs to mode ``i`` as numbered in the table and in ParaView.
    """

    path: Path
    schema_version: int
    program: str  # "coremodal 0.1.0"
    case_name: str
    case: dict[str, Any]  # the resolved case, as the program understood it
    # Modes, K of them.
    frequencies_hz: np.ndarray  # (K,) float64
    eigenvalues: np.ndarray  # (K,) float64, omega^2 in rad^2/s^2
    relative_residuals: np.ndarray  # (K,) float64
    types: list[str]  # rigid, bending, torsion, axial, breathing, ovalling, mixed
    n: np.ndarray  # (K,) int32, circumferential wave number
    m: np.ndarray  # (K,) int32, axial nodes
    dominant_share: np.ndarray  # (K,) float64
    effective_mass: np.ndarray  # (K, 4) float64: x, y, z in kg; rz in kg m^2
    # Mesh: N nodes, C cells.
    nodes: np.ndarray  # (N, 3) float64, metres
    cells: np.ndarray  # (C, nodes_per_cell) int64, gmsh node order
    vtk_cells: np.ndarray  # (C, 20 or 10) int64, VTK node order
    cell_type: str  # hex20 | hex27 | tet10
    cell_part: np.ndarray  # (C,) int32, index into part_names
    part_names: list[str]
    node_groups: dict[str, np.ndarray] = field(default_factory=dict)

    @property
    def n_modes(self) -> int:
        return len(self.frequencies_hz)

    @property
    def n_nodes(self) -> int:
        return len(self.nodes)

    @property
    def n_cells(self) -> int:
        return len(self.cells)

    def shape(self, index: int) -> np.ndarray:
        """Displacement of every node in mode ``index`` (1-based), shape (N, 3).

        Shapes are mass-normalised; they are zero at clamped nodes.
        """
        self._check_index(index)
        with h5py.File(self.path, "r") as f:
            return np.asarray(f[f"modes/shapes/mode_{index:04d}"][()], dtype=np.float64)

    def cylindrical(self, index: int) -> np.ndarray:
        """Mode ``index`` (1-based) in cylindrical components about the z
        axis, shape (N, 3): u_r, u_theta, u_z (float64, from the shape)."""
        return display.cylindrical(self.nodes, self.shape(index))

    @cached_property
    def warp_scales(self) -> np.ndarray:
        """(K,) the suggested Warp By Vector scale of each mode, as written
        into modes.xdmf (computed with coremodal.display for older files)."""
        with h5py.File(self.path, "r") as f:
            if "modes/warp_scale" in f:
                return np.asarray(f["modes/warp_scale"][()], dtype=np.float64)
        return np.array([display.suggested_warp_scale(self.nodes, self.shape(i), self.types[i - 1])
                         for i in range(1, self.n_modes + 1)])

    @property
    def model(self) -> str:
        """The model level the case asked for: solid, harmonic ("" if unknown)."""
        return str(self.case.get("model", "")) if isinstance(self.case, dict) else ""

    @property
    def modes(self) -> Table:
        """The mode table (the columns of modes.csv) as a coremodal Table."""
        return Table({
            "index": np.arange(1, self.n_modes + 1),
            "frequency_hz": self.frequencies_hz,
            "type": list(self.types),
            "n": self.n.astype(np.int64),
            "m": self.m.astype(np.int64),
            "dominant_share": self.dominant_share,
            "relative_residual": self.relative_residuals,
            "eff_mass_x_kg": self.effective_mass[:, 0],
            "eff_mass_y_kg": self.effective_mass[:, 1],
            "eff_mass_z_kg": self.effective_mass[:, 2],
            "eff_mass_rz_kgm2": self.effective_mass[:, 3],
        }, name=f"{self.case_name or self.path.name} modes")

    def to_pandas(self):
        """The mode table as a pandas DataFrame (needs pandas)."""
        return self.modes.to_pandas()

    def to_pyvista(self, modes: Iterable[int] | None = None):
        """The mesh with the shapes of ``modes`` (default all) as a
        pyvista.UnstructuredGrid; see coremodal.meshes.to_pyvista."""
        return meshes.to_pyvista(self, modes)

    def to_meshio(self, modes: Iterable[int] | None = None):
        """The mesh with the shapes of ``modes`` (default all) as a
        meshio.Mesh; see coremodal.meshes.to_meshio."""
        return meshes.to_meshio(self, modes)

    def __repr__(self) -> str:
        first = first_elastic(self.frequencies_hz, self.types)
        lowest = f", f1 = {self.frequencies_hz[first]:.2f} Hz ({self.types[first]})" if first is not None else ""
        model = f", {self.model}" if self.model else ""
        return (f"<coremodal.Results {self.case_name or '?'}{model}: {self.n_modes} modes{lowest}; "
                f"{self.cell_type} mesh of {self.n_nodes} nodes; {self.path}>")

    def label(self, index: int) -> str:
        """One-line description of mode ``index`` (1-based), e.g.
        ``"mode 7: 48.80 Hz, bending, n=1, m=0"``."""
        self._check_index(index)
        i = index - 1
        return (
            f"mode {index}: {self.frequencies_hz[i]:.2f} Hz, {self.types[i]}, "
            f"n={self.n[i]}, m={self.m[i]}"
        )

    def table(self) -> str:
        """All modes as a fixed-width text table, one line per mode."""
        header = (
            f"{'mode':>4}  {'freq [Hz]':>11}  {'type':<10} {'n':>3} {'m':>3}  {'share':>5}"
            f"  {'meff_x [kg]':>11} {'meff_y [kg]':>11} {'meff_z [kg]':>11}"
            f" {'meff_rz [kg m^2]':>16}"
        )
        lines = [
            f"{self.case_name or self.path.name}: {self.n_modes} modes "
            f"({self.program}, {self.cell_type} mesh of {self.n_nodes} nodes, "
            f"{self.n_cells} cells)",
            header,
        ]
        # Effective masses below NEGLIGIBLE_MASS_SHARE of the largest (of the
        # masses; of the rotary inertias) are round-off of an exact zero
        # (symmetry): 0, as the run's console shows them.
        shown = np.array(self.effective_mass, dtype=np.float64, copy=True)
        for columns in (slice(0, 3), slice(3, 4)):
            part = shown[:, columns]
            if part.size:
                part[np.abs(part) < NEGLIGIBLE_MASS_SHARE * np.max(np.abs(part))] = 0.0
        for i in range(self.n_modes):
            mx, my, mz, mrz = shown[i]
            lines.append(
                f"{i + 1:>4}  {self.frequencies_hz[i]:>11.3f}  {self.types[i]:<10}"
                f" {self.n[i]:>3} {self.m[i]:>3}  {self.dominant_share[i]:>5.2f}"
                f"  {mx:>11.4g} {my:>11.4g} {mz:>11.4g} {mrz:>16.4g}"
            )
        return "\n".join(lines)

    def _check_index(self, index: int) -> None:
        if not 1 <= index <= self.n_modes:
            raise IndexError(
                f"mode {index} does not exist: {self.path} holds modes 1 to {self.n_modes}"
            )


def first_elastic(frequencies_hz: Any, types: list[str]) -> int | None:
    """Row of the lowest mode that is not rigid (None if there is none)."""
    for i, kind in enumerate(types):
        if kind != "rigid":
            return i
    return None


def load_h5(path: str | Path) -> Results:
    """Reads a modes.h5 written by coremodal.

    Raises SchemaVersionError if the file is newer than this package
    understands, ResultsFormatError if it is not a coremodal results file,
    and OSError if it cannot be opened.
    """
    path = Path(path)
    with h5py.File(path, "r") as f:
        version = _schema_version(f, path)
        try:
            return _read(f, path, version)
        except KeyError as error:
            raise ResultsFormatError(f"{path}: incomplete coremodal results file: {error}") from None


def _schema_version(f: h5py.File, path: Path) -> int:
    if "schema_version" not in f.attrs:
        raise ResultsFormatError(
            f"{path} is not a coremodal results file (no schema_version attribute)"
        )
    version = int(f.attrs["schema_version"])
    if version > SUPPORTED_SCHEMA_VERSION:
        raise SchemaVersionError(
            f"{path} has schema_version {version}, but this coremodal python package reads "
            f"schema_version {SUPPORTED_SCHEMA_VERSION} at most: use the python package of "
            f"the coremodal version that wrote the file ({_text(f.attrs.get('program', '?'))})"
        )
    if version < 1:
        raise ResultsFormatError(f"{path}: invalid schema_version {version}")
    return version


def _read(f: h5py.File, path: Path, version: int) -> Results:
    mesh, modes = f["mesh"], f["modes"]
    cells = np.asarray(mesh["cells"][()], dtype=np.int64)
    cell_type = _text(mesh["cells"].attrs["cell_type"])
    if cell_type not in NODES_PER_CELL:
        raise ResultsFormatError(f"{path}: unknown cell_type {cell_type!r}")
    case_text = _text(f["case/json"][()])
    try:
        case = json.loads(case_text) if case_text else {}
    except json.JSONDecodeError as error:
        raise ResultsFormatError(f"{path}: /case/json is not valid JSON: {error}") from None
    return Results(
        path=path,
        schema_version=version,
        program=_text(f.attrs.get("program", "")),
        case_name=_text(f.attrs.get("case_name", "")),
        case=case,
        frequencies_hz=np.asarray(modes["frequency_hz"][()], dtype=np.float64),
        eigenvalues=np.asarray(modes["eigenvalue"][()], dtype=np.float64),
        relative_residuals=np.asarray(modes["relative_residual"][()], dtype=np.float64),
        types=_texts(modes["type"]),
        n=np.asarray(modes["n"][()], dtype=np.int32),
        m=np.asarray(modes["m"][()], dtype=np.int32),
        dominant_share=np.asarray(modes["dominant_share"][()], dtype=np.float64),
        effective_mass=np.asarray(modes["effective_mass"][()], dtype=np.float64).reshape(-1, 4),
        nodes=np.asarray(mesh["nodes"][()], dtype=np.float64).reshape(-1, 3),
        cells=cells.reshape(-1, NODES_PER_CELL[cell_type]),
        vtk_cells=np.asarray(mesh["vtk_cells"][()], dtype=np.int64),
        cell_type=cell_type,
        cell_part=np.asarray(mesh["cell_part"][()], dtype=np.int32),
        part_names=_texts(mesh["part_names"]),
        node_groups={
            name: np.asarray(group[()], dtype=np.int64)
            for name, group in mesh.get("node_groups", {}).items()
        },
    )


def _text(value: Any) -> str:
    """A string attribute or scalar dataset value as str (h5py gives bytes
    for some string types)."""
    if isinstance(value, bytes):
        return value.decode("utf-8")
    if isinstance(value, np.ndarray) and value.shape == ():
        return _text(value[()])
    return str(value)


def _texts(dataset: h5py.Dataset) -> list[str]:
    return [_text(v) for v in dataset[()]]


#: The name this module always had for load_h5 (coremodal.load also opens folders).
load = load_h5
