"""A mode that moves, in matplotlib (no ParaView needed): side views of the
deformed roll at several phases of its swing, as one strip of frames (PNG)
or as an animated GIF (with PIL).

    fig = coremodal.frames.frame_strip_figure(results, 1)      # a Figure
    coremodal.frames.draw_frame_strip(results, 1, "mode_01_frames.png")
    coremodal.frames.draw_animation(results, 1, "mode_01.gif")

The side view looks across the roll's axis (z, left to right) at the plane
the mode moves in most (x or y, up): at every plane of mesh nodes (the
stations the mesh really has) it draws the extent of the deformed nodes, so
that a bending mode shows as the roll's outline bending and an axial mode
as its stations moving along z. The shape is exaggerated by the mode's
suggested warp scale (Results.warp_scales: for a bending mode, the largest
displacement is 10 % of the model's length), the same as in ParaView.
"""

from __future__ import annotations

import io
from dataclasses import dataclass
from pathlib import Path

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from ._optional import require
from .results import Results
from .stations import stations

#: The strip's frames: the swing at +1, +1/2, 0, -1/2, -1 of its amplitude
#: (sin of the phase), top to bottom — a standing mode's whole motion.
STRIP_AMPLITUDES = (1.0, 0.5, 0.0, -0.5, -1.0)
#: Frames per period of the GIF, and milliseconds per frame (1.2 s a period).
GIF_FRAMES = 12
GIF_FRAME_MS = 100
#: Width of the strip; its height follows from the roll's shape (equal
#: scales along and across, so that the drawn deflection is true), capped.
STRIP_WIDTH_PX = 1000
STRIP_MAX_HEIGHT_PX = 1400
GIF_WIDTH_PX = 800
DPI = 100


def _is_torsion(results: Results, view: SideView) -> bool:
    return view.index > 0 and list(getattr(results, "types", []))[view.index - 1:view.index] == ["torsion"]


@dataclass(frozen=True)
class SideView:
    """What the side view draws of one shape: node planes and directions."""

    plane: np.ndarray  # (N,) node plane of every node, 0 .. P-1, in order of z
    n_planes: int
    across: int  # 0 (x) or 1 (y): the direction drawn upwards
    scale: float  # exaggeration of the shape
    index: int = 0  # the mode (1-based), 0 if not known


def side_view(results: Results, index: int, shape: np.ndarray) -> SideView:
    """Node planes (nodes of equal z; bins of z for an unstructured mesh,
    coremodal.stations), the transverse direction the mode moves in most
    and its suggested warp scale."""
    where = stations(results.nodes[:, 2])
    across = 0 if float(np.sum(shape[:, 0] ** 2)) >= float(np.sum(shape[:, 1] ** 2)) else 1
    return SideView(plane=where.index, n_planes=where.count, across=across,
                    scale=float(results.warp_scales[index - 1]), index=index)


#: A torsion mode's surface lines turn by at most this angle (20 degrees) in
#: the pictures: a rotation drawn as a rotation, whatever the warp scale of
#: its displacements (which, for a thin wall's torsion, would turn the lines
#: by a few degrees or by several turns).
TWIST_DRAWN_RAD = np.radians(20.0)
#: Surface lines (generators of the outer surface) on the half of the roll
#: that faces the viewer, from -75 to +75 degrees about the line of sight.
SURFACE_LINES = 9
SURFACE_LINE_SPREAD_RAD = np.radians(75.0)


@dataclass(frozen=True)
class SurfaceLines:
    """Straight lines along the outer surface at rest, as a torsion mode
    turns them: at each node plane, the angle each line has turned through
    per unit of the shape (u_theta / R of the outer nodes there)."""

    z: np.ndarray  # (P,) mean z of each node plane, m
    angle: np.ndarray  # (L,) angle of each line at rest about the axis, rad (atan2(y, x))
    turn: np.ndarray  # (P, L) u_theta / R at each plane and line, rad per unit of the shape
    radius: float  # outer radius, m
    centre: np.ndarray  # (2,) x, y of the axis
    across: int  # the direction drawn upwards (SideView.across)
    scale: float  # the largest turn drawn is TWIST_DRAWN_RAD


def surface_lines(results: Results, shape: np.ndarray, view: SideView) -> SurfaceLines:
    """The surface lines of ``shape`` on the side facing the viewer, who
    looks along the transverse axis that is not ``view.across``."""
    nodes = results.nodes
    centre = (nodes[:, :2].min(axis=0) + nodes[:, :2].max(axis=0)) / 2
    x, y = (nodes[:, :2] - centre).T
    radius, theta = np.hypot(x, y), np.arctan2(y, x)
    outer = radius >= (1 - 1e-3) * radius.max()
    u_theta = -np.sin(theta) * shape[:, 0] + np.cos(theta) * shape[:, 1]
    facing = 0.0 if view.across == 1 else np.pi / 2  # the line of sight's angle: x or y towards the viewer
    angle = facing + np.linspace(-SURFACE_LINE_SPREAD_RAD, SURFACE_LINE_SPREAD_RAD, SURFACE_LINES)
    r_out = float(radius[outer].mean())
    z, turn = [], []
    for plane in range(view.n_planes):
        ring = np.flatnonzero(outer & (view.plane == plane))
        if len(ring) < 3:
            continue
        z.append(float(nodes[ring, 2].mean()))
        turn.append(np.interp(angle, theta[ring], u_theta[ring] / r_out, period=2 * np.pi))
    turn = np.array(turn)
    largest = float(np.abs(turn).max()) if turn.size else 0.0
    return SurfaceLines(z=np.array(z), angle=angle, turn=turn, radius=r_out, centre=centre,
                        across=view.across, scale=TWIST_DRAWN_RAD / largest if largest > 0 else 0.0)


def surface_line_heights(lines: SurfaceLines, amplitude: float) -> np.ndarray:
    """(P, L) the height of each line at each plane, in the side view's
    upward direction (m), turned by amplitude * scale * turn."""
    turned = lines.angle[None, :] + amplitude * lines.scale * lines.turn
    along = np.cos(turned) if lines.across == 0 else np.sin(turned)
    return lines.centre[lines.across] + lines.radius * along


def draw_surface_lines(axes, lines: SurfaceLines, amplitude: float, unit: float = 1.0, label: str | None = None):
    """The surface lines at ``amplitude`` of the swing, coloured by the
    signed turn (red one way, blue the other; grey at rest): the lines twist
    one way at +1 and the other way at -1. Heights in metres times ``unit``."""
    from matplotlib.collections import LineCollection

    heights = unit * surface_line_heights(lines, amplitude)
    segments, turns = [], []
    for k in range(len(lines.angle)):
        points = np.column_stack([lines.z, heights[:, k]])
        segments += [points[i:i + 2] for i in range(len(points) - 1)]
        turns += list(amplitude * (lines.turn[:-1, k] + lines.turn[1:, k]) / 2)
    largest = float(np.abs(lines.turn).max()) or 1.0
    collection = LineCollection(segments, cmap="coolwarm", norm=_symmetric_norm(largest), linewidths=1.3,
                                label=label, zorder=3)
    collection.set_array(np.array(turns))
    axes.add_collection(collection)
    return collection


def _symmetric_norm(largest: float):
    from matplotlib.colors import Normalize

    return Normalize(vmin=-largest, vmax=largest)


def outline(results: Results, shape: np.ndarray, view: SideView, amplitude: float):
    """(z, low, high) of each node plane, deformed by amplitude * scale * shape:
    the plane's mean axial position and the extent of its nodes across."""
    moved = results.nodes + amplitude * view.scale * shape
    count = np.bincount(view.plane, minlength=view.n_planes)
    z = np.bincount(view.plane, weights=moved[:, 2], minlength=view.n_planes) / np.maximum(count, 1)
    across = moved[:, view.across]
    high = np.full(view.n_planes, -np.inf)
    low = np.full(view.n_planes, np.inf)
    np.maximum.at(high, view.plane, across)
    np.minimum.at(low, view.plane, across)
    return z, low, high


def _draw_frame(axes, results: Results, shape: np.ndarray, view: SideView, amplitude: float,
                limits: tuple[float, float, float, float]) -> None:
    rest_z, rest_low, rest_high = outline(results, shape, view, 0.0)
    z, low, high = outline(results, shape, view, amplitude)
    axes.fill_between(rest_z, rest_low, rest_high, color="0.85", lw=0)
    axes.fill_between(z, low, high, color="C0", alpha=0.85, lw=0)
    axes.plot(z, (low + high) / 2, color="C3", lw=1.0)  # the section centres
    if _is_torsion(results, view):  # a turn does not show in the outline: the surface lines do
        draw_surface_lines(axes, surface_lines(results, shape, view), amplitude)
    axes.set_xlim(limits[0], limits[1])
    axes.set_ylim(limits[2], limits[3])
    axes.set_aspect("equal")
    axes.set_yticks([])
    axes.text(0.005, 0.95, f"{amplitude:+.1f} x amplitude", transform=axes.transAxes, va="top", fontsize=8)


def _limits(results: Results, shape: np.ndarray, view: SideView) -> tuple[float, float, float, float]:
    """One frame for every phase: the roll at both extremes of its swing."""
    spans = [outline(results, shape, view, a) for a in (-1.0, 1.0)]
    z_low = min(float(s[0].min()) for s in spans)
    z_high = max(float(s[0].max()) for s in spans)
    low = min(float(s[1].min()) for s in spans)
    high = max(float(s[2].max()) for s in spans)
    along, across = 0.02 * (z_high - z_low), 0.08 * (high - low)
    return z_low - along, z_high + along, low - across, high + across


def _panel_height_px(limits: tuple[float, float, float, float], width_px: float) -> float:
    """Height of a panel ``width_px`` wide that shows ``limits`` at equal scales."""
    return width_px * (limits[3] - limits[2]) / max(limits[1] - limits[0], 1e-300)


def frame_strip_figure(results: Results, index: int, amplitudes: tuple[float, ...] = STRIP_AMPLITUDES,
                       size_px: tuple[int, int] | None = None, dpi: int = DPI) -> Figure:
    """Mode ``index`` (1-based) at each of ``amplitudes`` (fractions of its
    swing), one side view per row, sharing the axes; a matplotlib Figure.
    Its height fits the rows at equal scales unless ``size_px`` is given."""
    shape = results.shape(index)
    view = side_view(results, index, shape)
    limits = _limits(results, shape, view)
    if size_px is None:
        rows_px = len(amplitudes) * (_panel_height_px(limits, 0.9 * STRIP_WIDTH_PX) + 12) + 125
        size_px = (STRIP_WIDTH_PX, int(min(rows_px, STRIP_MAX_HEIGHT_PX)))
    figure = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
    FigureCanvasAgg(figure)
    rows = figure.subplots(len(amplitudes), 1, squeeze=False, gridspec_kw={"hspace": 0.08})[:, 0]
    for axes, amplitude in zip(rows, amplitudes):
        _draw_frame(axes, results, shape, view, amplitude, limits)
        axes.tick_params(labelbottom=axes is rows[-1])
    rows[-1].set_xlabel("z (m)")
    name = results.case_name or results.path.parent.name
    turned = ""
    if _is_torsion(results, view):
        turned = (f"\nsurface lines turned x{surface_lines(results, shape, view).scale:.3g} (largest "
                  f"{np.degrees(TWIST_DRAWN_RAD):.0f}°), red and blue: u_θ one way and the other")
    figure.suptitle(f"{name} — {results.label(index)}\nside view, {'xy'[view.across]} up, "
                    f"displacement x{view.scale:.3g} (largest = {_drawn_fraction(results, shape, view):.0%} "
                    f"of the model's length){turned}", fontsize=10)
    title_px = 70 + (18 if turned else 0)  # a third line for a torsion mode's surface lines
    figure.subplots_adjust(left=0.05, right=0.95, top=1 - title_px / size_px[1], bottom=45 / size_px[1])
    return figure


def _drawn_fraction(results: Results, shape: np.ndarray, view: SideView) -> float:
    largest = float(np.linalg.norm(shape, axis=1).max())
    return view.scale * largest / (float(np.ptp(results.nodes, axis=0).max()) or 1.0)


def strip_file(index: int) -> str:
    """File name of the frame strip of mode ``index``, as report.md links it."""
    return f"mode_{index:02d}_frames.png"


def animation_file(index: int) -> str:
    """File name of the animated GIF of mode ``index``."""
    return f"mode_{index:02d}.gif"


def draw_frame_strip(results: Results, index: int, png_path: str | Path, **options) -> Path:
    """Writes frame_strip_figure into a PNG; returns its path."""
    path = Path(png_path)
    frame_strip_figure(results, index, **options).savefig(path, dpi=options.get("dpi", DPI))
    return path


def animation_frames(results: Results, index: int, n_frames: int = GIF_FRAMES,
                     size_px: tuple[int, int] | None = None, dpi: int = DPI) -> list[bytes]:
    """PNG bytes of ``n_frames`` side views over one period (sin of the phase)."""
    shape = results.shape(index)
    view = side_view(results, index, shape)
    limits = _limits(results, shape, view)
    if size_px is None:
        size_px = (GIF_WIDTH_PX, int(min(_panel_height_px(limits, 0.9 * GIF_WIDTH_PX) + 90, GIF_WIDTH_PX)))
    frames = []
    for k in range(n_frames):
        figure = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
        FigureCanvasAgg(figure)
        axes = figure.add_subplot(1, 1, 1)
        _draw_frame(axes, results, shape, view, float(np.sin(2 * np.pi * k / n_frames)), limits)
        axes.set_title(results.label(index), fontsize=9)
        axes.set_xlabel("z (m)")
        figure.tight_layout()
        buffer = io.BytesIO()
        figure.savefig(buffer, format="png", dpi=dpi)
        frames.append(buffer.getvalue())
    return frames


def draw_animation(results: Results, index: int, gif_path: str | Path, **options) -> Path:
    """Writes mode ``index`` swinging as a looping GIF. Raises ImportError
    (saying how to install it) without PIL."""
    Image = require("PIL.Image", "an animated GIF", "apt install python3-pil (or pip install pillow)")
    images = [Image.open(io.BytesIO(png)).convert("RGB") for png in animation_frames(results, index, **options)]
    path = Path(gif_path)
    images[0].save(path, save_all=True, append_images=images[1:], duration=GIF_FRAME_MS, loop=0)
    return path
