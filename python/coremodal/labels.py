"""Pictures that cannot be misread: labels that do not print over each other,
legends beside the curves rather than on them, a unit on every axis.

The pictures place their labels with :func:`separate` (matplotlib's renderer
gives every text's box in pixels) and put their legends outside the axes
with :func:`legend_outside`; :func:`overlapping_texts`,
:func:`legends_over_data` and :func:`axes_without_units` say what is still
wrong, for the tests (python/tests/test_picture_labels.py).
"""

from __future__ import annotations

import re
from typing import Iterable

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure
from matplotlib.legend import Legend
from matplotlib.text import Annotation, Text
from matplotlib.transforms import Bbox

#: Boxes closer than this (pixels) count as touching: a gap a reader can see.
GAP_PX = 1.0
#: How far, in multiples of a label's height, separate() moves a label at most.
MAX_STEPS = 12
#: An axis label's unit: "[Hz]", "[m/s]", "[-]" for a ratio, or "(rpm)".
UNIT = re.compile(r"\[[^\]]+\]|\([^()]*(Hz|rpm|m|mm|s|m/s|m/min|N|kN|kg|%|-)\)")


def _renderer(figure: Figure):
    figure.canvas.draw()  # positions (and a layout engine's result) are final only after a draw
    return figure.canvas.get_renderer()


def _all_axes(figure: Figure) -> list[Axes]:
    """Every axes of the figure, the secondary axes (secondary_yaxis) included."""
    found: list[Axes] = []
    for ax in figure.axes:
        found.append(ax)
        found.extend(getattr(ax, "child_axes", []))
    return found


def _drawn_tick_labels(ax: Axes) -> list[Text]:
    """The tick labels matplotlib draws: those of ticks inside the view."""
    labels = []
    for axis in (ax.xaxis, ax.yaxis):
        low, high = sorted(axis.get_view_interval())
        span = high - low
        for tick in axis.get_major_ticks():
            if low - 1e-9 * span <= tick.get_loc() <= high + 1e-9 * span:
                labels.extend(t for t in (tick.label1, tick.label2) if t.get_visible() and t.get_text())
    return labels


def _boxes(figure: Figure) -> list[tuple[object, str, Bbox]]:
    """(artist, what it says, box in pixels) of every text a reader sees."""
    renderer = _renderer(figure)
    texts: list[Text] = list(figure.texts)
    boxes: list[tuple[object, str, Bbox]] = []
    legends = list(figure.legends)
    for ax in _all_axes(figure):
        texts += [ax.title, ax._left_title, ax._right_title, ax.xaxis.label, ax.yaxis.label]
        texts += _drawn_tick_labels(ax)
        texts += list(ax.texts)
        if ax.get_legend() is not None and ax.get_legend().get_visible():
            legends.append(ax.get_legend())
    for legend in legends:
        boxes.append((legend, "legend", legend.get_window_extent(renderer)))
    for t in texts:
        if t.get_visible() and t.get_text().strip():
            box = t.get_window_extent(renderer)
            if box.width > 0 and box.height > 0:
                boxes.append((t, t.get_text(), box))
    return boxes


def text_boxes(figure: Figure) -> list[tuple[str, Bbox]]:
    """Every text a reader sees, with its box in pixels: titles, axis labels,
    drawn tick labels, annotations and free texts, each legend as one box."""
    return [(text, box) for _, text, box in _boxes(figure)]


def _overlap(a: Bbox, b: Bbox, gap: float = GAP_PX) -> bool:
    return (a.x0 < b.x1 - gap and b.x0 < a.x1 - gap and a.y0 < b.y1 - gap and b.y0 < a.y1 - gap)


def overlapping_texts(figure: Figure) -> list[tuple[str, str]]:
    """Pairs of texts whose boxes overlap (each pair once)."""
    boxes = text_boxes(figure)
    return [(boxes[i][0], boxes[j][0]) for i in range(len(boxes)) for j in range(i + 1, len(boxes))
            if _overlap(boxes[i][1], boxes[j][1])]


def _densified(pixels: np.ndarray, step_px: float = 2.0) -> np.ndarray:
    """The points of a polyline every step_px pixels, so that a straight line
    under a legend is seen even when none of its vertices is."""
    pixels = pixels[np.isfinite(pixels).all(axis=1)]
    if len(pixels) < 2:
        return pixels
    parts = [pixels[:1]]
    for a, b in zip(pixels[:-1], pixels[1:]):
        n = max(1, int(np.ceil(np.hypot(*(b - a)) / step_px)))
        parts.append(a + np.outer(np.arange(1, n + 1) / n, b - a))
    return np.concatenate(parts)


def legends_over_data(figure: Figure) -> list[str]:
    """Legends with a drawn data point of any axes under them."""
    renderer = _renderer(figure)
    legends: list[Legend] = [ax.get_legend() for ax in _all_axes(figure) if ax.get_legend() is not None]
    legends += list(figure.legends)
    covered = []
    for legend in legends:
        box = legend.get_window_extent(renderer)
        for ax in figure.axes:
            window = ax.get_window_extent(renderer)
            for line in ax.lines:
                xy = line.get_xydata()
                if not len(xy):
                    continue
                pixels = _densified(line.get_transform().transform(np.asarray(xy, float)))
                inside = ((pixels[:, 0] >= window.x0) & (pixels[:, 0] <= window.x1) &
                          (pixels[:, 1] >= window.y0) & (pixels[:, 1] <= window.y1))
                under = ((pixels[:, 0] > box.x0) & (pixels[:, 0] < box.x1) &
                         (pixels[:, 1] > box.y0) & (pixels[:, 1] < box.y1))
                if (inside & under).any():
                    covered.append(f"legend over {line.get_label() or 'a curve'}")
                    break
    return covered


def axes_without_units(figure: Figure) -> list[str]:
    """Axis labels (of axes that show numbers) that name no unit."""
    missing = []
    for ax in _all_axes(figure):
        for axis, name in ((ax.xaxis, "x"), (ax.yaxis, "y")):
            if not axis.get_visible() or not _drawn_tick_labels_of(axis):
                continue
            label = axis.label.get_text()
            if not UNIT.search(label):
                missing.append(f"{name} axis '{label}'")
    return missing


def _drawn_tick_labels_of(axis) -> bool:
    return any(t.label1.get_visible() and t.label1.get_text() or t.label2.get_visible() and t.label2.get_text()
               for t in axis.get_major_ticks())


def legend_outside(ax: Axes, **options) -> Legend | None:
    """The legend to the right of the axes, never over the curves (the
    figure's layout engine makes room for it)."""
    handles, labels = ax.get_legend_handles_labels()
    if not handles:
        return None
    legend = ax.legend(loc="upper left", bbox_to_anchor=(1.02, 1.0), borderaxespad=0.0, **options)
    # Beyond a secondary axis on the right (m/min beside m/s): its tick labels
    # and label are in pixels, the anchor in axes widths, and the layout moves
    # the axes, so measure, place, and measure again.
    right = list(getattr(ax, "child_axes", []))
    for _ in range(3 if right else 0):
        renderer = _renderer(ax.figure)
        box = ax.get_window_extent(renderer)
        edge = max(child.get_tightbbox(renderer).x1 for child in right)
        legend.set_bbox_to_anchor((1.0 + (edge - box.x1 + 8) / box.width, 1.0), transform=ax.transAxes)
    return legend


def separate(figure: Figure, labels: Iterable[Annotation]) -> None:
    """Moves each annotation (text placed at an offset in points from its
    point) up or down, a little more each try, until its box overlaps no
    other text, legend or earlier label: crossings that lie close keep
    readable labels. A label that finds no free place within MAX_STEPS of its
    own height stays where it was put."""
    labels = [a for a in labels if a.get_visible() and a.get_text()]
    mine = set(id(a) for a in labels)
    fixed = [box for artist, _, box in _boxes(figure) if id(artist) not in mine]
    renderer = figure.canvas.get_renderer()
    placed: list[Bbox] = []
    points_per_pixel = 72.0 / figure.dpi
    for label in labels:
        start = tuple(label.xyann)
        box = label.get_window_extent(renderer)
        step = (box.height + 2 * GAP_PX) * points_per_pixel
        for k in range(2 * MAX_STEPS + 1):
            shift = (k + 1) // 2 * step * (1 if k % 2 else -1)  # 0, +1, -1, +2, -2, ...
            label.xyann = (start[0], start[1] + shift)
            box = label.get_window_extent(renderer)
            if not any(_overlap(box, other) for other in fixed + placed):
                break
        else:
            label.xyann = start
            box = label.get_window_extent(renderer)
        placed.append(box)


__all__ = ["axes_without_units", "legend_outside", "legends_over_data", "overlapping_texts", "separate",
           "text_boxes"]
