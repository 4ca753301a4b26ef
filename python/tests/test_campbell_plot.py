"""The Campbell diagram (coremodal.campbell_plot) on a small synthetic folder
laid out as ``coremodal campbell`` writes it (campbell.csv,
critical_speeds.csv, summary.json)."""

from __future__ import annotations

import json
import subprocess
import sys
from pathlib import Path

import pytest

from coremodal.campbell_plot import CampbellFormatError, draw


def write_campbell(folder: Path) -> Path:
    """A pair at 50 Hz splitting into FW and BW, a torsion mode at 120 Hz, and
    the order-1 and order-2 crossings of the pair."""
    folder.mkdir(parents=True, exist_ok=True)
    rows = ["speed_rpm,speed_hz,track,frequency_hz,whirl,label,relative_residual"]
    for rpm in (0, 1500, 3000, 4500):
        split = 0.01 * rpm / 60
        rows += [f"{rpm},{rpm / 60},1,{50 - split},BW,bending n=1 m=0,1e-15",
                 f"{rpm},{rpm / 60},2,{50 + split},FW,bending n=1 m=0,1e-15",
                 f"{rpm},{rpm / 60},3,120,,torsion n=0 m=0,1e-15"]
    (folder / "campbell.csv").write_text("\n".join(rows) + "\n")
    (folder / "critical_speeds.csv").write_text(
        "order,speed_rpm,speed_hz,frequency_hz,web_speed_m_s,track,whirl,label\n"
        "2,1500,25,50,8.3,1,BW,bending n=1 m=0\n1,3000,50,50,16.6,2,FW,bending n=1 m=0\n")
    (folder / "summary.json").write_text(json.dumps(
        {"case": {"name": "synthetic"}, "rotation": {"excitation_orders": [1, 2]}}))
    return folder


def test_the_diagram_is_drawn_into_the_folder(tmp_path: Path) -> None:
    out = draw(write_campbell(tmp_path / "c"))
    assert out == tmp_path / "c" / "campbell.png"
    assert out.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def test_a_folder_without_the_tables_is_refused(tmp_path: Path) -> None:
    with pytest.raises(CampbellFormatError, match="no campbell.csv"):
        draw(tmp_path)


def test_the_command_line_draws_and_reports_a_wrong_folder(tmp_path: Path) -> None:
    folder = write_campbell(tmp_path / "c")
    done = subprocess.run([sys.executable, "-m", "coremodal", "campbell-plot", str(folder)],
                          capture_output=True, text=True)
    assert done.returncode == 0, done.stderr
    assert done.stdout.strip().endswith("campbell.png")
    bad = subprocess.run([sys.executable, "-m", "coremodal", "campbell-plot", str(tmp_path / "none")],
                         capture_output=True, text=True)
    assert bad.returncode == 1
    assert "coremodal: error:" in bad.stderr


def test_a_pencil_crossing_beyond_the_sweep_is_drawn(tmp_path: Path) -> None:
    """Co-rotating coordinates: the sweep stops below the first forward
    critical speed, which the pencil reports beyond the sweep's last speed
    (critical_speeds.csv with its source column)."""
    folder = write_campbell(tmp_path / "c")
    (folder / "critical_speeds.csv").write_text(
        "order,speed_rpm,speed_hz,frequency_hz,web_speed_m_s,track,whirl,label,refined,interpolated_speed_rpm,source\n"
        "2,1500,25,50,8.3,1,BW,bending n=1 m=0,true,1500,sweep\n"
        "1,5200,86.7,86.7,28.9,0,FW,bending n=1 m=0,true,5200,pencil\n")
    assert draw(folder).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"


def drawn_axes(folder: Path, monkeypatch: pytest.MonkeyPatch):
    """The axes of campbell.png as drawn (the figure caught at savefig)."""
    from matplotlib.figure import Figure
    caught = []
    save = Figure.savefig
    monkeypatch.setattr(Figure, "savefig", lambda fig, *a, **k: (caught.append(fig), save(fig, *a, **k))[1])
    draw(folder)
    return caught[0].axes[0]


def test_the_operating_range_is_shaded_when_the_summary_has_it(tmp_path: Path, monkeypatch) -> None:
    folder = write_campbell(tmp_path / "c")
    summary = json.loads((folder / "summary.json").read_text())
    summary["rotation"]["operating_speeds_rpm"] = [1000.0, 4000.0]
    (folder / "summary.json").write_text(json.dumps(summary))
    ax = drawn_axes(folder, monkeypatch)
    bands = [p for p in ax.patches if p.get_label() == "operating range"]
    assert len(bands) == 1
    xs = [x for x, _ in bands[0].get_xy()]  # axvspan: x in data coordinates
    assert min(xs) == pytest.approx(1000.0) and max(xs) == pytest.approx(4000.0)
    legend = fig_legend_texts(ax)
    assert "operating range" in legend


def test_no_band_without_an_operating_range(tmp_path: Path, monkeypatch) -> None:
    ax = drawn_axes(write_campbell(tmp_path / "c"), monkeypatch)
    assert not [p for p in ax.patches if p.get_label() == "operating range"]
    assert "operating range" not in fig_legend_texts(ax)


def fig_legend_texts(ax) -> list[str]:
    legends = [ax.get_legend()] + list(ax.figure.legends)
    return [t.get_text() for lg in legends if lg is not None for t in lg.get_texts()]
