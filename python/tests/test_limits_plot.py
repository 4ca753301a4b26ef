"""The verdict picture (coremodal.limits_plot) on a small synthetic folder laid
out as ``coremodal limits`` writes it (limits.csv, summary.json)."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from coremodal.limits_plot import LimitsFormatError, draw

IDS = ["i5_0.7", "i5_0.8", "koenig", "order1_backward", "order1_forward", "order2", "amplitude_limit"]


def write_limits(folder: Path, target: bool = True) -> Path:
    """Three diameters; I-5 at 0.7 governs, the amplitude limit is not reached at the smallest."""
    folder.mkdir(parents=True, exist_ok=True)
    header = "diameter_mm,added,f1_hz,chuck_factor," + ",".join(
        f"{i}_m_s,{i}_low_m_s,{i}_high_m_s" for i in IDS) + ",governing,safe_m_s,safe_low_m_s,safe_high_m_s"
    rows = [header]
    for d, f1 in ((262.1, 22.0), (222.1, 24.0), (182.1, 28.0)):
        v1 = 3.14159 * d / 1e3 * f1
        values = [0.7 * v1, 0.8 * v1, 13.3, 0.99 * v1, 1.01 * v1, 0.5 * v1, 0.98 * v1 if d > 200 else None]
        cells = []
        for v in values:
            cells += ["", "", ""] if v is None else [f"{v}", f"{0.95 * v}", f"{1.05 * v}"]
        rows.append(f"{d},0,{f1},0.76," + ",".join(cells) + f",i5_0.7,{0.7 * v1},{0.665 * v1},{0.735 * v1}")
    (folder / "limits.csv").write_text("\n".join(rows) + "\n")
    verdict = {"line": "safe up to 11.5 m/s at roll change, D = 222.1 mm; governed by I-5 x0.7"}
    if target:
        verdict["target"] = {"web_speed_m_s": 12, "change_needed": True, "change_diameter_mm": 222.1}
    (folder / "summary.json").write_text(json.dumps({
        "case": {"name": "synthetic"}, "model": {"level": "beam"}, "verdict": verdict,
        "points": [{"criteria": [{"id": i, "name": i, "limiting": i != "i5_0.8"} for i in IDS]}]}))
    return folder


def test_the_picture_is_drawn_into_the_folder(tmp_path: Path) -> None:
    out = draw(write_limits(tmp_path / "l"))
    assert out == tmp_path / "l" / "limits.png"
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_without_a_target_it_draws_too(tmp_path: Path) -> None:
    assert draw(write_limits(tmp_path / "l", target=False)).is_file()


def test_a_folder_without_the_table_is_refused(tmp_path: Path) -> None:
    with pytest.raises(LimitsFormatError, match="no limits.csv"):
        draw(tmp_path)
