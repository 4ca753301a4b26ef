"""coremodal: read the results of a coremodal run (modes.h5) and draw its modes.

    import coremodal
    results = coremodal.load("results/modes.h5")
    print(results.frequencies_hz)
    coremodal.plot.draw_mode(results, 7, "mode7.png")

From the shell: ``python3 -m coremodal table results/modes.h5`` and
``python3 -m coremodal plot results/modes.h5 --mode 7 --out mode7.png``.
"""

from __future__ import annotations

import importlib
from types import ModuleType

from .results import (
    SUPPORTED_SCHEMA_VERSION,
    Results,
    ResultsFormatError,
    SchemaVersionError,
    load,
)

__all__ = [
    "SUPPORTED_SCHEMA_VERSION",
    "Results",
    "ResultsFormatError",
    "SchemaVersionError",
    "load",
    "plot",
]


def __getattr__(name: str) -> ModuleType:
    # matplotlib is slow to import; load coremodal.plot only when it is used.
    if name == "plot":
        return importlib.import_module(".plot", __name__)
    raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
