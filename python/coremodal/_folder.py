"""A results folder's summary.json and CSV tables, for the drawing modules
(campbell_plot, response_plot): every file checked first, so that a wrong
folder is refused with the file it lacks."""

from __future__ import annotations

import csv
import json
from pathlib import Path


def _rows(path: Path) -> list[dict[str, str]]:
    with path.open(newline="") as f:
        return list(csv.DictReader(f))


def read_folder(folder: Path, tables: tuple[str, ...], error: type[Exception], command: str) -> tuple:
    """(summary, rows of tables[0], rows of tables[1], ...); `error` names the
    first missing file and the command whose folder this is not."""
    for name in tables + ("summary.json",):
        if not (folder / name).is_file():
            raise error(f"{folder}: no {name} (not a coremodal {command} folder)")
    return (json.loads((folder / "summary.json").read_text()),) + tuple(_rows(folder / t) for t in tables)
