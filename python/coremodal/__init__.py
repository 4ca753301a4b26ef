"""coremodal: read the results of coremodal runs and draw their modes.

    import coremodal
    run = coremodal.load("results/02-clamped-76x15")   # a run's folder
    run                                  # <coremodal run 02-clamped-76x15: solid, 20 modes, f1 = ... Hz (bending)>
    run.modes.to_pandas()                # the mode table (pandas optional)
    r = run.results                      # modes.h5: coremodal.load("results/.../modes.h5") also works
    r.frequencies_hz, r.shape(7), r.cylindrical(7), r.warp_scales
    fig = run.plot_mode(7)               # matplotlib Figures: plot_mode, plot_spectrum, plot_frames

From the shell: ``python3 -m coremodal table results/modes.h5``,
``python3 -m coremodal plot results/modes.h5 --mode 7 --out mode7.png`` and
``python3 -m coremodal paraview RESULTS_DIR --mode 1`` (pvpython); see
docs/reference/results.md.
"""

from __future__ import annotations

import importlib
from types import ModuleType

from .results import (
    SUPPORTED_SCHEMA_VERSION,
    Results,
    ResultsFormatError,
    SchemaVersionError,
    load_h5,
)
from .run import Folder, Run, load
from .tables import Table, read_summary, read_table

__version__ = "0.1.0"

__all__ = [
    "SUPPORTED_SCHEMA_VERSION",
    "Folder",
    "Results",
    "ResultsFormatError",
    "Run",
    "SchemaVersionError",
    "Table",
    "frames",
    "load",
    "load_h5",
    "plot",
    "read_summary",
    "read_table",
]

#: Modules that import matplotlib, which is slow to import: loaded when used.
_LAZY = ("plot", "frames", "run_plot")


def __getattr__(name: str) -> ModuleType:
    if name in _LAZY:
        return importlib.import_module(f".{name}", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
