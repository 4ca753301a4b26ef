"""Optional packages (pandas, meshio, pyvista, PIL): imported when a feature
needs them, with an error that says how to install them."""

from __future__ import annotations

import importlib
from types import ModuleType


def require(module: str, feature: str, install: str) -> ModuleType:
    """``module`` imported, or ImportError "FEATURE needs MODULE: INSTALL"."""
    try:
        return importlib.import_module(module)
    except ImportError:
        raise ImportError(f"{feature} needs {module.split('.')[0]}: {install}") from None
