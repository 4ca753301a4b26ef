"""A results folder of coremodal, opened as one object.

    import coremodal
    run = coremodal.load("results/07-rotogravure-chucks-150x15.8-4320")
    run                      # <coremodal run 07-rotogravure-chucks-150x15.8-4320: harmonic, 12 modes, f1 = 25.79 Hz (bending)>
    run.modes                # the mode table (modes.csv) as a coremodal Table
    run.to_pandas()          # ... as a pandas DataFrame
    run.summary["beam"]      # summary.json as a dict
    run.results.shape(7)     # modes.h5: mesh and shapes (coremodal.Results)
    run.to_meshio([1, 2])    # the mesh and two shapes for meshio (or to_pyvista)
    fig = run.plot_mode(1)   # a matplotlib Figure

Every other folder a command writes opens as a Folder: its ``summary``
(summary.json of campbell, response, winder, limits, select, traction and
durability, study.json, converge.json: one scheme, docs/reference/results.md), its
``command`` and its main ``table`` (campbell.csv, response.csv, winder.csv,
limits.csv, selection.csv, traction.csv, points.csv of durability,
study.csv, calibration.csv, batch.csv, converge.csv, sensitivity.csv), with
``to_pandas()``.

    spin = coremodal.load("results/12-rotation-tester-76x15-campbell")
    spin.command             # "campbell"
    spin.to_pandas()         # campbell.csv
    spin.read("critical_speeds.csv")
"""

from __future__ import annotations

from functools import cached_property
from pathlib import Path
from typing import Any, Iterable

from .results import Results, ResultsFormatError, first_elastic, load_h5
from .tables import Table, read_summary, read_table

#: The main table of each kind of folder, in the order they are looked for
#: when the folder's JSON does not name its command.
FOLDER_TABLES = ("study.csv", "calibration.csv", "batch.csv", "converge.csv", "campbell.csv", "winder.csv",
                 "response.csv", "sensitivity.csv", "limits.csv", "selection.csv", "traction.csv", "points.csv")
#: The main table of the folder each command writes.
COMMAND_TABLES = {"campbell": "campbell.csv", "response": "response.csv", "winder": "winder.csv",
                  "study": "study.csv", "calibrate": "calibration.csv", "converge": "converge.csv", "run": "modes.csv",
                  "limits": "limits.csv", "select": "selection.csv", "traction": "traction.csv",
                  "durability": "points.csv"}
#: Where each command's JSON is (the same scheme in each).
SUMMARY_FILES = ("summary.json", "study.json", "converge.json")


class Folder:
    """Any coremodal results folder: its CSV files as tables."""

    def __init__(self, path: str | Path) -> None:
        self.path = Path(path)
        if not self.path.is_dir():
            raise ResultsFormatError(f"{self.path}: no such folder")

    @property
    def files(self) -> list[str]:
        return sorted(p.name for p in self.path.iterdir() if p.is_file())

    def read(self, name: str) -> Table:
        """The CSV ``name`` of this folder ("study.csv", "rigid_vs_elastic.csv", ...)."""
        return read_table(self.path / name)

    @cached_property
    def summary(self) -> dict[str, Any]:
        """The folder's JSON as a dict (summary.json, study.json or
        converge.json); {} for a folder without one (batch, sensitivity, fit)."""
        for name in SUMMARY_FILES:
            if (self.path / name).is_file():
                return read_summary(self.path / name)
        return {}

    @property
    def command(self) -> str:
        """The coremodal command that wrote the folder ("" when its JSON does
        not say: a batch, a sensitivity or a fit, or an older folder)."""
        return str(self.summary.get("command", ""))

    @cached_property
    def table(self) -> Table:
        """The folder's main table: the CSV of its command (campbell.csv,
        response.csv, winder.csv, limits.csv, selection.csv, traction.csv,
        points.csv, study.csv, converge.csv), else the first of
        FOLDER_TABLES it holds."""
        if self.command in COMMAND_TABLES and (self.path / COMMAND_TABLES[self.command]).is_file():
            return self.read(COMMAND_TABLES[self.command])
        for name in FOLDER_TABLES:
            if (self.path / name).is_file():
                return self.read(name)
        raise ResultsFormatError(f"{self.path} holds none of {', '.join(FOLDER_TABLES)}")

    def to_pandas(self):
        """The main table as a pandas DataFrame (needs pandas)."""
        return self.table.to_pandas()

    def __repr__(self) -> str:
        what = f"{self.command} " if self.command else ""
        return f"<coremodal {what}folder {self.path.name}: {', '.join(self.files)}>"


class Run(Folder):
    """The folder of one ``coremodal run``: summary.json, modes.csv and,
    except for the beam model level, modes.h5."""

    def __init__(self, path: str | Path) -> None:
        super().__init__(path)
        if not (self.path / "summary.json").is_file():
            raise ResultsFormatError(f"{self.path} is not the folder of a coremodal run (no summary.json)")
        if self.command not in ("", "run"):
            raise ResultsFormatError(f"{self.path} was written by coremodal {self.command}, not run: "
                                     "open it with coremodal.load()")

    @property
    def name(self) -> str:
        return str(self.summary.get("case", {}).get("name", self.path.name))

    @property
    def level(self) -> str:
        """solid, harmonic, coupled or beam (the case's [analysis] model names)."""
        return str(self.summary.get("model", {}).get("level", ""))

    @cached_property
    def modes(self) -> Table:
        """The mode table, from modes.csv."""
        return self.read("modes.csv")

    @property
    def table(self) -> Table:
        return self.modes

    @property
    def frequencies_hz(self):
        return self.modes["frequency_hz"]

    @cached_property
    def results(self) -> Results:
        """modes.h5: mesh, mode shapes, the resolved case. Raises
        ResultsFormatError for a run without it (the beam model level)."""
        path = self.path / "modes.h5"
        if not path.is_file():
            raise ResultsFormatError(f"{self.path} has no modes.h5 (a {self.level or 'beam'}-level run writes "
                                     "beam_shapes.csv instead)")
        return load_h5(path)

    def shape(self, index: int):
        """Displacement of every node in mode ``index`` (1-based), (N, 3)."""
        return self.results.shape(index)

    def to_pyvista(self, modes: Iterable[int] | None = None):
        return self.results.to_pyvista(modes)

    def to_meshio(self, modes: Iterable[int] | None = None):
        return self.results.to_meshio(modes)

    def plot_mode(self, index: int, **options):
        """Mode ``index`` in the three panels of the report; a matplotlib Figure."""
        from . import plot

        return plot.mode_figure(self.results, index, **options)

    def plot_spectrum(self, **options):
        """Every mode's frequency against its number, by type; a Figure."""
        from . import run_plot

        return run_plot.spectrum_figure(self.results, **options)

    def plot_frames(self, index: int, **options):
        """Mode ``index`` swinging: a strip of side views; a Figure."""
        from . import frames

        return frames.frame_strip_figure(self.results, index, **options)

    def __repr__(self) -> str:
        types = list(self.modes["type"]) if "type" in self.modes else []
        first = first_elastic(None, types)
        lowest = (f", f1 = {self.modes['frequency_hz'][first]:.2f} Hz ({types[first]})"
                  if first is not None else "")
        return f"<coremodal run {self.name}: {self.level}, {len(self.modes)} modes{lowest}>"


def load(path: str | Path) -> Run | Folder | Results:
    """Opens coremodal results: a run's folder gives a Run, every other
    results folder (campbell, response, winder, study, calibration, batch,
    converge, sensitivity, fit) a Folder, and a modes.h5 file its Results."""
    path = Path(path)
    if path.is_dir():
        folder = Folder(path)
        is_run = (path / "summary.json").is_file() and folder.command in ("", "run")
        return Run(path) if is_run else folder
    if not path.is_file():
        raise ResultsFormatError(f"{path}: no such file or folder")
    return load_h5(path)
