"""Pictures of mode shapes with matplotlib (Agg, no display needed).

One picture per mode, in three panels, so that it says what the mode is even
for a long slender roll, where a bending deflection is invisible at equal
scales and an ovalling section cannot be seen from outside:

1. "side view" (top left): the roll seen across its axis, at rest and
   deformed, the displacement exaggerated by the mode's suggested warp scale
   (the same as in ParaView and the frame strip: a bending or axial mode's
   largest displacement is 10 % of the model's length) and the height not to
   scale, so that a 4.5 m roll is a band, not a stick; see side_view_data;
2. "along the roll" (bottom): the mean displacement of each node plane
   versus z (section translation u_x, u_y, axial u_z and twist), see
   centreline_curves;
3. "cross-section" (top right): the outer ring of the plane that deforms
   most in its own plane, undeformed and deformed, exaggerated by the mode's
   dominant motion (so that a secondary motion stays small), see section_ring.

Clamp zones, chuck bodies, expanding elements and bearings (from the case in
modes.h5, coremodal.supports) are shaded in the side view and along the roll.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from pathlib import Path
from typing import Any

import matplotlib
import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator

from . import frames
from .results import Results
from .stations import Stations, stations
from .supports import clamp_spans, shade_supports, support_spans

#: The cross-section panel draws the mode's largest displacement (anywhere,
#: in any direction: its dominant motion) as this fraction of the ring's
#: radius; the ring's own in-plane motion is drawn at the same scale, so
#: that an axial mode's small breathing stays small.
SECTION_SCALE_FRACTION = 0.20
#: Nodes within this fraction of the largest radius are on the outer surface.
_OUTER_TOLERANCE = 1e-3
#: At most this many node planes are drawn as lines in the side view (every
#: k-th plane of a fine mesh), so that they stay lines and not a grey area.
SIDE_VIEW_MAX_PLANE_LINES = 45
#: Arrows from the section centres at rest to the deformed ones, at most.
SIDE_VIEW_ARROWS = 16
#: Major ticks at most along z and across in the side view: labels that
#: cannot overlap at the report's 1000 px width.
SIDE_VIEW_Z_TICKS = 8
SIDE_VIEW_ACROSS_TICKS = 4

__all__ = ["CentreLine", "SectionRing", "SideViewData", "centreline_curves",
           "clamp_spans", "draw_mode", "mode_figure", "section_ring", "side_view_data"]

@dataclass(frozen=True)
class CentreLine:
    """Mean displacement of each axial station (node plane, see
    coremodal.stations) of a shape; one entry per station, by ascending z."""

    z: np.ndarray  # mean z of the station's nodes, m
    ux: np.ndarray  # mean u_x: translation of the section
    uy: np.ndarray  # mean u_y
    uz: np.ndarray  # mean axial displacement
    twist: np.ndarray  # mean u_theta / r: rotation of the section about z, rad
    ring_shape: np.ndarray  # root mean square u_r of the outer ring, less the translation
    planes: bool  # True: the stations are node planes; False: bins of an unstructured mesh


@dataclass(frozen=True)
class SectionRing:
    """The outer ring of one axial station: its nodes sorted by angle."""

    z: float  # axial position of the ring, m
    station: int  # index of the station (as in CentreLine)
    radius: float  # undeformed radius, m
    centre: np.ndarray  # (2,) x, y of the core axis
    theta: np.ndarray  # (K,) angle of each node, ascending, rad
    xy: np.ndarray  # (K, 2) undeformed x, y
    displacement: np.ndarray  # (K, 2) u_x, u_y of the shape
    radial: np.ndarray  # (K,) radial displacement u_r
    scale: float  # draws the mode's largest displacement as SECTION_SCALE_FRACTION * radius
    in_plane_share: float  # the ring's largest in-plane displacement / the mode's largest

    @property
    def deformed(self) -> np.ndarray:
        """(K, 2) x, y of the ring deformed by ``scale`` times the shape."""
        return self.xy + self.scale * self.displacement


def axis_centre(nodes: np.ndarray) -> np.ndarray:
    """x, y of the core axis: the middle of the nodes' extent across."""
    return (nodes[:, :2].min(axis=0) + nodes[:, :2].max(axis=0)) / 2


def _cylindrical(nodes: np.ndarray, shape: np.ndarray, centre: np.ndarray):
    """Radius, angle, u_r and u_theta of every node about the axis."""
    dx, dy = nodes[:, 0] - centre[0], nodes[:, 1] - centre[1]
    radius = np.hypot(dx, dy)
    theta = np.arctan2(dy, dx)
    cos, sin = np.cos(theta), np.sin(theta)
    u_r = shape[:, 0] * cos + shape[:, 1] * sin
    u_theta = -shape[:, 0] * sin + shape[:, 1] * cos
    return radius, theta, u_r, u_theta


def centreline_curves(nodes: np.ndarray, shape: np.ndarray, where: Stations | None = None) -> CentreLine:
    """Mean u_x, u_y, u_z and twist (u_theta / r) of the nodes of each
    station (by default the mesh's node planes, coremodal.stations): how
    the roll's sections move along it, sampled where the mesh has nodes, so
    that no station is empty and the curves do not break.

    A bending mode shows as u_x or u_y curves, an axial mode as u_z, a
    torsion mode as the twist; shell modes (ovalling, breathing) leave all
    four near zero, and show in ``ring_shape``: the root mean square radial
    displacement of the outer nodes (within 0.1 % of the largest radius)
    less the part that the sections' mean translation (interpolated to each
    node's z) explains. Nodes on the axis (r = 0) are left out of the twist.
    """
    where = where or stations(nodes[:, 2])
    radius, theta, u_r, u_theta = _cylindrical(nodes, shape, axis_centre(nodes))
    off_axis = radius > 1e-9 * max(float(radius.max()), 1e-300)
    twist = np.zeros_like(radius)
    twist[off_axis] = u_theta[off_axis] / radius[off_axis]
    z, ux, uy = where.mean(nodes[:, 2]), where.mean(shape[:, 0]), where.mean(shape[:, 1])
    outer = radius >= (1 - _OUTER_TOLERANCE) * radius.max()
    # The translation at each outer node's own z (interpolated between the
    # stations), so that its change within a bin is not taken for shape.
    at_z = nodes[outer, 2]
    move_x = _interpolate(at_z, z, ux)
    move_y = _interpolate(at_z, z, uy)
    change = u_r[outer] - (move_x * np.cos(theta[outer]) + move_y * np.sin(theta[outer]))
    squared = np.zeros_like(radius)
    squared[outer] = change ** 2
    ring_shape = np.sqrt(where.mean(squared, outer))
    # A station without outer nodes (a chuck's shaft beyond the core) has no ring.
    return CentreLine(z=z, ux=ux, uy=uy, uz=where.mean(shape[:, 2]),
                      twist=np.nan_to_num(where.mean(twist, off_axis)),
                      ring_shape=np.nan_to_num(ring_shape), planes=where.planes)


def _interpolate(x: np.ndarray, xp: np.ndarray, fp: np.ndarray) -> np.ndarray:
    """Piecewise linear through (xp, fp), ascending xp, extended linearly
    beyond both ends (a bin's mean z lies inside the bin)."""
    if len(xp) < 2:
        return np.full_like(x, fp[0] if len(fp) else 0.0)
    values = np.interp(x, xp, fp)
    low, high = x < xp[0], x > xp[-1]
    values[low] = fp[0] + (x[low] - xp[0]) * (fp[1] - fp[0]) / (xp[1] - xp[0])
    values[high] = fp[-1] + (x[high] - xp[-1]) * (fp[-1] - fp[-2]) / (xp[-1] - xp[-2])
    return values


#: A ring needs this many nodes around to be drawn as a ring (a station of a
#: hex20 mesh holds 2 per cell around, a mid-edge plane 1 per cell).
_MIN_RING_NODES = 6


def section_ring(nodes: np.ndarray, shape: np.ndarray, fraction: float = SECTION_SCALE_FRACTION,
                 where: Stations | None = None) -> SectionRing:
    """The outer ring of the station (by default node plane) whose outer
    nodes move most in their plane (largest mean u_x^2 + u_y^2), sorted by
    angle; stations with at least 6 outer nodes are preferred.

    Outer nodes are those within 0.1 % of the largest radius. ``scale``
    makes the mode's largest displacement — its dominant motion, whatever
    its direction — ``fraction`` of the ring's radius, so that the ring's
    in-plane motion is drawn in proportion to it: a bending or ovalling
    ring moves by ``fraction`` of its radius, an axial mode's breathing by
    its share of the axial motion (1 for a shape that does not move).
    """
    where = where or stations(nodes[:, 2])
    centre = axis_centre(nodes)
    radius, theta, u_r, _ = _cylindrical(nodes, shape, centre)
    outer = np.flatnonzero(radius >= (1 - _OUTER_TOLERANCE) * radius.max())
    in_plane = shape[outer, 0] ** 2 + shape[outer, 1] ** 2
    count = np.bincount(where.index[outer], minlength=where.count)
    total = np.bincount(where.index[outer], weights=in_plane, minlength=where.count)
    mean_square = np.where(count > 0, total / np.maximum(count, 1), -1.0)
    if count.max() >= _MIN_RING_NODES:
        mean_square = np.where(count >= _MIN_RING_NODES, mean_square, -1.0)
    best = int(np.argmax(mean_square))
    ring = outer[where.index[outer] == best]
    ring = ring[np.argsort(theta[ring], kind="stable")]
    displacement = shape[ring, :2]
    largest = float(np.linalg.norm(shape, axis=1).max()) if len(shape) else 0.0
    in_plane_largest = float(np.sqrt((displacement ** 2).sum(axis=1)).max()) if len(ring) else 0.0
    ring_radius = float(radius[ring].mean()) if len(ring) else 0.0
    return SectionRing(
        z=float(nodes[ring, 2].mean()) if len(ring) else float(nodes[:, 2].mean()),
        station=best,
        radius=ring_radius,
        centre=centre,
        theta=theta[ring],
        xy=nodes[ring, :2],
        displacement=displacement,
        radial=u_r[ring],
        scale=fraction * ring_radius / largest if largest > 0 else 1.0,
        in_plane_share=in_plane_largest / largest if largest > 0 else 0.0,
    )


@dataclass(frozen=True)
class SideViewData:
    """The roll seen across its axis: per station, the mean z and the extent
    of its nodes in the direction ``across``, at rest and deformed."""

    rest: tuple[np.ndarray, np.ndarray, np.ndarray]  # z, low, high, m
    deformed: tuple[np.ndarray, np.ndarray, np.ndarray]
    across: int  # 0 (x) or 1 (y): the direction the mode moves in most, drawn upwards
    scale: float  # exaggeration of the shape
    drawn_fraction: float  # the largest displacement as drawn / the model's length


def side_view_data(results: Results, index: int, shape: np.ndarray | None = None,
                   scale: float | None = None) -> SideViewData:
    """Side view of mode ``index`` (1-based): its node planes at rest and
    deformed by ``scale`` (default: the mode's suggested warp scale,
    Results.warp_scales, which follows the mode's dominant motion: a bending
    or axial mode's largest displacement is 10 % of the length)."""
    shape = results.shape(index) if shape is None else shape
    view = frames.side_view(results, index, shape)
    if scale is not None:
        view = replace(view, scale=float(scale))
    length = float(np.ptp(results.nodes, axis=0).max()) or 1.0
    largest = float(np.linalg.norm(shape, axis=1).max()) if len(shape) else 0.0
    return SideViewData(rest=frames.outline(results, shape, view, 0.0),
                        deformed=frames.outline(results, shape, view, 1.0), across=view.across,
                        scale=view.scale, drawn_fraction=view.scale * largest / length)


def draw_mode(results: Results, index: int, png_path: str | Path, scale: float | None = None,
              **options: Any) -> float:
    """Draws mode ``index`` (1-based) of ``results`` into a PNG (mode_figure,
    whose keyword ``options`` it takes: size_px, dpi) and returns the
    displacement scale of the side view: ``scale``, by default the mode's
    suggested warp scale (Results.warp_scales)."""
    results._check_index(index)  # before warp_scales, so that a bad index says so
    if scale is None:
        scale = float(results.warp_scales[index - 1])
    mode_figure(results, index, scale, **options).savefig(Path(png_path), dpi=options.get("dpi", 100))
    return scale


def mode_figure(results: Results, index: int, scale: float | None = None, *,
                size_px: tuple[int, int] = (1200, 900), dpi: int = 100) -> Figure:
    """Mode ``index`` (1-based) of ``results`` as a matplotlib Figure of
    ``size_px`` pixels, in three panels: the side view of the deformed roll
    (top left, see side_view_data), the outer ring of the station that
    deforms most (top right; see section_ring) and the mean displacement of
    each node plane along the roll (bottom; see centreline_curves), with its
    legend beside it.

    ``scale`` multiplies the shape in the side view (default: the mode's
    suggested warp scale). The cross-section has its own exaggeration,
    written in its title. z runs left to right in both panels along the roll.
    """
    shape = results.shape(index)
    where = stations(results.nodes[:, 2])
    # Text shrinks with the picture, so that small pictures stay legible.
    font = float(np.clip(9.0 * min(size_px[0] / 1200, size_px[1] / 900) * 100 / dpi, 4.0, 12.0))
    with matplotlib.rc_context({"font.size": font, "axes.titlesize": font + 1,
                                "legend.fontsize": font - 1}):
        figure = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
        FigureCanvasAgg(figure)
        grid = figure.add_gridspec(2, 2, height_ratios=[1.0, 1.0], width_ratios=[2.3, 1.0],
                                   left=0.07, right=0.98, bottom=0.07, top=0.90,
                                   wspace=0.22, hspace=0.38)
        side = figure.add_subplot(grid[0, 0])
        along = figure.add_subplot(grid[1, 0], sharex=side)
        spans = support_spans(results.case)
        ring = section_ring(results.nodes, shape, where=where)
        _draw_side_view(side, side_view_data(results, index, shape, scale), spans)
        if results.types[index - 1] == "torsion":  # its turn does not show in the outline
            _draw_twist(side, results, index, shape)
        section = figure.add_subplot(grid[0, 1])
        _draw_section(section, ring)
        _draw_centreline(along, results, shape, centreline_curves(results.nodes, shape, where),
                         ring, spans)
        _draw_legend(figure.add_subplot(grid[1, 1]), [side, along, section])
        name = results.case_name or results.path.stem
        figure.suptitle(f"{name} — {results.label(index)}", fontsize=font + 3)
    return figure


def _draw_side_view(axes, view: SideViewData, spans) -> None:
    """The roll at rest (dashed outline) and deformed (blue), its node
    planes as lines and its section centres; across in mm, the height not
    to scale."""
    rest_z, rest_low, rest_high = view.rest
    z, low, high = view.deformed
    shade_supports(axes, spans)
    axes.fill_between(z, 1e3 * low, 1e3 * high, color="C0", alpha=0.75, lw=0, label="deformed")
    step = max(1, -(-len(z) // SIDE_VIEW_MAX_PLANE_LINES))
    axes.vlines(z[::step], 1e3 * low[::step], 1e3 * high[::step], color="white", lw=0.5, alpha=0.8)
    for edge in (rest_low, rest_high):
        axes.plot(rest_z, 1e3 * edge, "--", color="0.25", lw=0.9, label="at rest")
    axes.plot(z, 1e3 * (low + high) / 2, color="C3", lw=1.2, label="section centres")
    # How the section centres moved (every k-th): up for bending, along for
    # an axial mode, whose planes otherwise only crowd and spread.
    arrow = max(1, -(-len(z) // SIDE_VIEW_ARROWS))
    rest_mid, mid = 1e3 * (rest_low + rest_high) / 2, 1e3 * (low + high) / 2
    axes.quiver(rest_z[::arrow], rest_mid[::arrow], (z - rest_z)[::arrow], (mid - rest_mid)[::arrow],
                angles="xy", scale_units="xy", scale=1.0, color="k", width=0.004, zorder=4,
                label="centre displacement")
    z_all = np.concatenate([rest_z, z])
    across = 1e3 * np.concatenate([rest_low, rest_high, low, high])
    pad_z, pad_across = 0.02 * np.ptp(z_all), 0.08 * (np.ptp(across) or 1.0)
    axes.set_xlim(z_all.min() - pad_z, z_all.max() + pad_z)
    axes.set_ylim(across.min() - pad_across, across.max() + pad_across)
    axes.xaxis.set_major_locator(MaxNLocator(nbins=SIDE_VIEW_Z_TICKS))
    axes.yaxis.set_major_locator(MaxNLocator(nbins=SIDE_VIEW_ACROSS_TICKS))
    axes.set_xlabel("z (m)")
    axes.set_ylabel(f"{'xy'[view.across]} (mm), drawn")
    axes.set_title(f"side view: displacement ×{view.scale:.3g} (largest = {view.drawn_fraction:.0%} "
                   "of the length), height not to scale")
    axes.grid(True, lw=0.3, alpha=0.5)


def _draw_twist(axes, results: Results, index: int, shape: np.ndarray) -> None:
    """A torsion mode's surface lines on the side view (coremodal.frames):
    straight at rest, turned by the twist at a scale suited to rotations,
    coloured by the signed u_θ."""
    lines = frames.surface_lines(results, shape, frames.side_view(results, index, shape))
    frames.draw_surface_lines(axes, lines, 1.0, unit=1e3,
                              label=f"surface lines ×{lines.scale:.3g} (≤ {np.degrees(frames.TWIST_DRAWN_RAD):.0f}°), "
                                    "colour ±u_θ")


def _draw_centreline(axes, results: Results, shape: np.ndarray, curves: CentreLine,
                     ring: SectionRing, spans) -> None:
    """Section translation, axial displacement and twist versus z, divided by
    the largest nodal displacement (twist as the surface displacement R theta)."""
    largest = float(np.linalg.norm(shape, axis=1).max()) or 1.0
    outer = float(np.hypot(*(results.nodes[:, :2] - axis_centre(results.nodes)).T).max())
    shade_supports(axes, spans, label=False)  # the side view's entries say what they are
    axes.axhline(0.0, color="0.5", lw=0.6)
    axes.axvline(ring.z, color="0.3", lw=0.8, ls=":", label="cross-section")
    for values, label, style in [
        (curves.ux, "u_x (section)", "-"),
        (curves.uy, "u_y (section)", "-"),
        (curves.uz, "u_z (axial)", "--"),
        (curves.twist * outer, "twist × R_out", "-."),
        (curves.ring_shape, "ring shape (rms u_r)", ":"),
    ]:
        axes.plot(curves.z, values / largest, style, lw=1.4, label=label)
    drawn = np.abs([curves.ux, curves.uy, curves.uz, curves.twist * outer, curves.ring_shape])
    top = 1.05 * max(1.0, float(np.nanmax(drawn / largest, initial=0.0)))
    axes.set_ylim(-top, top)
    axes.xaxis.set_major_locator(MaxNLocator(nbins=SIDE_VIEW_Z_TICKS))
    axes.set_xlabel("z (m)")
    axes.set_ylabel("plane mean / max |u| [-]")
    axes.set_title("along the roll, at every node plane" if curves.planes else
                   "along the roll, in bins of z")
    axes.grid(True, lw=0.3, alpha=0.5)


def _draw_legend(axes, sources) -> None:
    """One legend for the side view, the curves and the cross-section, in
    the panel beside the curves, where it covers nothing."""
    handles, labels = [], []
    for source in sources:
        for handle, label in zip(*source.get_legend_handles_labels()):
            if label not in labels:
                handles.append(handle)
                labels.append(label)
    axes.set_axis_off()
    axes.legend(handles, labels, loc="center left", frameon=False)


def _draw_section(axes, ring: SectionRing) -> None:
    """Undeformed and deformed outer ring in mm, with arrows at some nodes."""
    if len(ring.theta) == 0:
        axes.set_axis_off()
        return
    mm = 1e3
    close = lambda a: mm * np.vstack([a, a[:1]])  # noqa: E731
    rest, moved = close(ring.xy - ring.centre), close(ring.deformed - ring.centre)
    axes.plot(rest[:, 0], rest[:, 1], "--", color="0.5", lw=1.0, label="section: outer ring at rest")
    axes.plot(moved[:, 0], moved[:, 1], "-", color="C3", lw=1.8, label="section: outer ring deformed")
    step = max(1, len(ring.theta) // 16)
    base = mm * (ring.xy[::step] - ring.centre)
    arrows = mm * ring.scale * ring.displacement[::step]
    axes.quiver(base[:, 0], base[:, 1], arrows[:, 0], arrows[:, 1], angles="xy", scale_units="xy",
                scale=1.0, color="C0", alpha=0.8, width=0.005, label="section: node displacement")
    # A spoke to the first node shows a rotation of the section (torsion).
    axes.plot([0, rest[0, 0]], [0, rest[0, 1]], "--", color="0.5", lw=0.8, label="section: spoke at rest")
    axes.plot([0, moved[0, 0]], [0, moved[0, 1]], "-", color="C3", lw=1.0,
              label="section: spoke moved (turns with torsion)")
    axes.plot([0], [0], "+", color="0.3")
    limit = 1.4 * mm * ring.radius
    axes.set_xlim(-limit, limit)
    axes.set_ylim(-limit, limit)
    axes.set_aspect("equal")
    axes.xaxis.set_major_locator(MaxNLocator(nbins=5))
    axes.yaxis.set_major_locator(MaxNLocator(nbins=5))
    axes.set_xlabel("x (mm)")
    axes.set_ylabel("y (mm)")
    # A ring that hardly moves in its plane (an axial mode's breathing) says so.
    share = "" if ring.in_plane_share > 0.5 else f"\nin-plane motion: {ring.in_plane_share:.0%} of the largest"
    axes.set_title(f"cross-section at z = {ring.z:.3g} m, ×{ring.scale:.3g}{share}")
    # Its entries are in the shared legend beside the curves (_draw_legend): none on the ring.
