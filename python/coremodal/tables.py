"""The CSV files of coremodal's results folders as small column tables:
modes.csv, study.csv, calibration.csv, batch.csv, converge.csv,
rigid_vs_elastic.csv, beam_shapes.csv — and any CSV a later analysis adds
(Campbell diagrams, responses), since every one of them is a header line
and rows of numbers and words.

    import coremodal
    modes = coremodal.read_table("results/02-clamped-76x15/modes.csv")
    modes["frequency_hz"]        # a numpy column
    modes[0]                     # the first row as a dict
    modes.to_pandas()            # a DataFrame, when pandas is installed

Only the standard library and numpy are needed; pandas is optional.
"""

from __future__ import annotations

import csv
import json
from pathlib import Path
from typing import Any, Iterator

import numpy as np

from ._optional import require

#: Rows shown by repr(table); the rest is summarised as "... N more rows".
REPR_ROWS = 12
#: Widest cell shown by repr(table), in characters.
REPR_CELL = 18


class Table:
    """Named columns of equal length: numbers as numpy arrays (int64 where
    every value is an integer, else float64 with NaN for an empty cell),
    words as lists of str."""

    def __init__(self, columns: dict[str, Any], name: str = "") -> None:
        lengths = {len(values) for values in columns.values()}
        if len(lengths) > 1:
            raise ValueError(f"{name or 'table'}: columns of different lengths {sorted(lengths)}")
        self._columns = dict(columns)
        self.name = name

    @property
    def columns(self) -> list[str]:
        return list(self._columns)

    def __len__(self) -> int:
        return len(next(iter(self._columns.values()))) if self._columns else 0

    def __contains__(self, column: str) -> bool:
        return column in self._columns

    def __getitem__(self, key: str | int) -> Any:
        """``table["frequency_hz"]``: a column; ``table[0]``: a row as a dict."""
        if isinstance(key, str):
            if key not in self._columns:
                raise KeyError(f"{self.name or 'table'} has no column {key!r}; columns: {', '.join(self.columns)}")
            return self._columns[key]
        if not -len(self) <= key < len(self):
            raise IndexError(f"{self.name or 'table'} has {len(self)} rows, not row {key}")
        return {name: _plain(values[key]) for name, values in self._columns.items()}

    def __iter__(self) -> Iterator[dict[str, Any]]:
        """The rows, each as a dict."""
        return (self[i] for i in range(len(self)))

    def to_pandas(self):
        """The table as a pandas DataFrame (pandas is not required otherwise)."""
        pandas = require("pandas", "to_pandas()", "apt install python3-pandas (or pip install pandas)")
        return pandas.DataFrame(self._columns)

    def __repr__(self) -> str:
        title = f"{self.name}: " if self.name else ""
        head = f"<{title}{len(self)} rows x {len(self._columns)} columns>"
        if not self._columns:
            return head
        shown = min(len(self), REPR_ROWS)
        cells = [[_cell(name) for name in self._columns]]
        cells += [[_cell(_format(values[i])) for values in self._columns.values()] for i in range(shown)]
        widths = [max(len(row[c]) for row in cells) for c in range(len(self._columns))]
        lines = [head] + ["  ".join(text.rjust(w) for text, w in zip(row, widths)) for row in cells]
        if len(self) > shown:
            lines.append(f"... {len(self) - shown} more rows")
        return "\n".join(lines)


def read_table(path: str | Path) -> Table:
    """Reads a CSV written by coremodal (a header line, then one row per
    line). Raises OSError if it cannot be read and ValueError if a row has
    the wrong number of cells."""
    path = Path(path)
    with open(path, newline="", encoding="utf-8") as f:
        rows = list(csv.reader(f))
    if not rows:
        raise ValueError(f"{path}: empty file (expected a header line)")
    header, body = rows[0], [r for r in rows[1:] if r]
    for line, row in enumerate(body, start=2):
        if len(row) != len(header):
            raise ValueError(f"{path}:{line}: {len(row)} cells, but the header names {len(header)} columns")
    columns = {name: _column([row[c] for row in body]) for c, name in enumerate(header)}
    return Table(columns, name=path.name)


def read_summary(path: str | Path) -> dict[str, Any]:
    """summary.json of a run (a folder or the file) as a dict; its keys are
    listed in docs/reference/results.md."""
    path = Path(path)
    if path.is_dir():
        path = path / "summary.json"
    with open(path, encoding="utf-8") as f:
        return json.load(f)


def _column(texts: list[str]) -> Any:
    """int64 if every cell is an integer, float64 if every non-empty cell is
    a number (empty -> NaN), else the words themselves."""
    try:
        return np.array([int(t) for t in texts], dtype=np.int64)
    except ValueError:
        pass
    try:
        return np.array([float(t) if t.strip() else np.nan for t in texts], dtype=np.float64)
    except ValueError:
        return list(texts)


def _plain(value: Any) -> Any:
    """numpy scalars as python numbers, for rows as dicts."""
    return value.item() if isinstance(value, np.generic) else value


def _format(value: Any) -> str:
    if isinstance(value, (float, np.floating)):
        return f"{value:.6g}"
    return str(value)


def _cell(text: str) -> str:
    return text if len(text) <= REPR_CELL else text[: REPR_CELL - 1] + "…"
