"""Pictures that cannot be misread (coremodal.labels): in the Campbell
diagram, the winder's crossing diagram and response, and the study's
pictures, no text box overlaps another (matplotlib's renderer gives the
boxes in pixels), no legend lies on a curve, every axis that shows numbers
names its unit, and the resonance markers of the winder's response lie on
their curves. The checks themselves are shown to catch what they look for.
"""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import numpy as np
import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from coremodal import campbell_plot, study_plot, winder_plot
from coremodal.labels import axes_without_units, legend_outside, legends_over_data, overlapping_texts, separate

from test_campbell_plot import write_campbell
from test_study_plot import write_response_study, write_study
from test_winder_plot import write_winder

REPO = Path(__file__).resolve().parents[2]


@pytest.fixture
def drawn(monkeypatch: pytest.MonkeyPatch) -> list[Figure]:
    """Every figure the pictures save, kept for inspection."""
    figures: list[Figure] = []
    original = Figure.savefig

    def keeping(self, *args, **kwargs):
        figures.append(self)
        return original(self, *args, **kwargs)

    monkeypatch.setattr(Figure, "savefig", keeping)
    return figures


def assert_readable(figure: Figure) -> None:
    assert overlapping_texts(figure) == []
    assert legends_over_data(figure) == []
    assert axes_without_units(figure) == []


# ------------------------------------------------------------ the checks can fail


def test_the_checks_see_overlapping_labels_a_legend_on_a_curve_and_a_missing_unit() -> None:
    figure = Figure(figsize=(6, 4), dpi=100)
    FigureCanvasAgg(figure)
    ax = figure.add_subplot()
    ax.plot([0, 1], [0, 1], label="a curve")
    a = ax.annotate("crossing A", (0.5, 0.5), textcoords="offset points", xytext=(5, 0))
    b = ax.annotate("crossing B", (0.5, 0.5), textcoords="offset points", xytext=(8, 2))
    ax.legend(loc="center")  # on the diagonal
    ax.set_xlabel("speed")
    ax.set_ylabel("frequency (Hz)")
    assert ("crossing A", "crossing B") in overlapping_texts(figure)
    assert legends_over_data(figure) == ["legend over a curve"]
    assert axes_without_units(figure) == ["x axis 'speed'"]
    # What the pictures do about it.
    legend_outside(ax)
    separate(figure, [a, b])
    ax.set_xlabel("speed (rpm)")
    figure.set_layout_engine("constrained")
    assert_readable(figure)


# ------------------------------------------------------------ the pictures


def test_the_campbell_diagram_reads_cleanly(tmp_path: Path, drawn: list[Figure]) -> None:
    campbell_plot.draw(write_campbell(tmp_path / "c"))
    [figure] = drawn
    assert_readable(figure)
    legend = [t.get_text() for t in figure.axes[0].get_legend().get_texts()]
    # Only what is drawn: the torsion track at 120 Hz is inside the axes, so "no whirl" is listed.
    assert legend == ["backward whirl", "forward whirl", "no whirl", "excitation f = k f_rot (k x)", "critical speed"]


def test_the_legend_lists_no_track_that_lies_above_the_axes(tmp_path: Path, drawn: list[Figure]) -> None:
    folder = write_campbell(tmp_path / "c")
    rows = (folder / "campbell.csv").read_text().replace(",120,,torsion", ",5000,,torsion")
    (folder / "campbell.csv").write_text(rows)
    campbell_plot.draw(folder)
    legend = [t.get_text() for t in drawn[0].axes[0].get_legend().get_texts()]
    assert "no whirl" not in legend


def test_the_campbell_diagram_of_the_rotation_tester_reads_cleanly(tmp_path: Path, drawn: list[Figure]) -> None:
    # Case 12: two pairs of crossings a few rpm apart, whose labels would print over each other.
    binary = os.environ.get("COREMODAL_BIN")
    if not binary:
        pytest.skip("COREMODAL_BIN is not set: run through ctest (python_pytest)")
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1", OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    done = subprocess.run([binary, "campbell", str(REPO / "cases" / "12-rotation-tester-76x15.toml"), "--output",
                           str(tmp_path / "c"), "-q", "--no-plots"], capture_output=True, text=True, env=env,
                          timeout=600)
    assert done.returncode == 0, done.stderr
    campbell_plot.draw(tmp_path / "c")
    [figure] = drawn
    assert_readable(figure)
    assert figure.axes[0].child_axes[0].get_xlabel().startswith("web speed at Dp = 106 mm (m/s)")


def test_the_winder_pictures_read_cleanly_and_resonances_lie_on_their_curves(
        tmp_path: Path, drawn: list[Figure]) -> None:
    folder = write_winder(tmp_path / "w")
    winder_plot.draw_all(folder)
    crossing_diagram, response = drawn
    assert_readable(crossing_diagram)
    assert_readable(response)
    ax = response.axes[0]
    curves = {line.get_label(): line.get_xydata() for line in ax.lines if line.get_label().startswith("harmonic")}
    markers = [line.get_xydata()[0] for line in ax.lines if line.get_marker() == "v" and len(line.get_xydata())]
    assert markers, "no resonance marker drawn"
    for d_mm, x_over_f in markers:  # the crossing of harmonic 2 at 954.9 mm, 3e-7 m/N
        assert any(np.isclose(curve, [d_mm, x_over_f], rtol=1e-12).all(axis=1).any() for curve in curves.values())
    np.testing.assert_allclose(curves["harmonic 2"].max(axis=0)[1], 3e-7)  # the curve reaches the peak


def test_the_study_pictures_read_cleanly(tmp_path: Path, drawn: list[Figure]) -> None:
    for name, write in (("s", write_study), ("r", write_response_study)):
        (tmp_path / name).mkdir()
        study_plot.draw_all(write(tmp_path / name))
    assert len(drawn) >= 4
    for figure in drawn:
        assert_readable(figure)


def test_the_other_folder_pictures_read_cleanly(tmp_path: Path, drawn: list[Figure]) -> None:
    from coremodal import limits_plot, response_plot, traction_plot

    from test_limits_plot import write_limits
    from test_response_plot import write_response
    from test_traction_plot import write_traction

    limits_plot.draw(write_limits(tmp_path / "l"))
    response_plot.draw(write_response(tmp_path / "r"))
    traction_plot.draw(write_traction(tmp_path / "t"))
    assert len(drawn) == 3
    for figure in drawn:
        assert_readable(figure)


def test_the_run_pictures_read_cleanly(modes_h5: Path, tmp_path: Path, drawn: list[Figure]) -> None:
    import shutil

    from coremodal.run_plot import draw_run_plots

    shutil.copy(modes_h5, tmp_path / "modes.h5")
    draw_run_plots(tmp_path, [7, 9])
    assert len(drawn) == 3  # the spectrum and two modes
    for figure in drawn:
        assert_readable(figure)


def test_the_durability_and_selection_pictures_read_cleanly(tmp_path: Path, drawn: list[Figure]) -> None:
    from coremodal import durability_plot, selection_plot

    from test_durability_plot import run

    run(["durability", str(REPO / "cases" / "18-core-durability-76x15.csv"), "-o", str(tmp_path / "d"), "-p", "1e-5"])
    run(["select", str(REPO / "cases" / "18-core-selection.toml"), "-o", str(tmp_path / "s")])
    durability_plot.draw_all(tmp_path / "d")
    selection_plot.draw_all(tmp_path / "s")
    assert len(drawn) >= 2
    for figure in drawn:
        assert_readable(figure)
