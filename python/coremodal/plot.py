"""Pictures of mode shapes with matplotlib (Agg, no display needed).

One picture per mode, in three panels, so that it says what the mode is even
for a long slender core, where a bending deflection is invisible at equal
aspect and an ovalling section cannot be seen from outside:

1. a 3D view: the deformed boundary surface (every cell face that no other
   cell shares, with its mid-edge nodes so that the quadratic geometry of a
   coarse mesh still looks round), coloured by the displacement magnitude;
2. "along the core": the mean displacement of each axial station versus z
   (section translation u_x, u_y, axial u_z and twist), see centreline_curves;
3. "cross-section": the outer ring of the station that deforms most in its
   plane, undeformed and deformed (exaggerated), see section_ring.
"""

from __future__ import annotations

import weakref
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import matplotlib
import numpy as np
from matplotlib import cm, colors
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.ticker import MaxNLocator
from mpl_toolkits.mplot3d.art3d import Poly3DCollection

from .results import Results

#: The auto scale makes the largest displacement this fraction of the model's
#: largest extent (for a core, its length): clearly visible...
AUTO_SCALE_FRACTION = 0.10
#: ...but at most this fraction of its smallest extent (the outer diameter):
#: a shell mode (ovalling, breathing) drawn at 10 % of the length would move
#: the wall by more than the radius and turn the tube inside out.
AUTO_SCALE_CAP_FRACTION = 0.25
#: Axial stations (bins of nodes by z) of the "along the core" panel.
N_STATIONS = 60
#: The cross-section panel draws the ring's largest in-plane displacement
#: (for ovalling, breathing and bending: its largest radial change) as this
#: fraction of the ring's radius.
SECTION_SCALE_FRACTION = 0.20
#: Nodes within this fraction of the largest radius are on the outer surface.
_OUTER_TOLERANCE = 1e-3

# Faces of each cell type as corner cycles (gmsh local numbering) and the gmsh
# local node on each edge, so that a face can be drawn through its mid-edge
# nodes: corner, edge node, corner, edge node, ...
_HEX_FACES = [(0, 3, 2, 1), (4, 5, 6, 7), (0, 1, 5, 4), (1, 2, 6, 5), (2, 3, 7, 6), (3, 0, 4, 7)]
_HEX_EDGE_NODE = {
    (0, 1): 8, (0, 3): 9, (0, 4): 10, (1, 2): 11, (1, 5): 12, (2, 3): 13,
    (2, 6): 14, (3, 7): 15, (4, 5): 16, (4, 7): 17, (5, 6): 18, (6, 7): 19,
}  # fmt: skip
_TET_FACES = [(0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 2, 3)]
_TET_EDGE_NODE = {(0, 1): 4, (1, 2): 5, (0, 2): 6, (0, 3): 7, (2, 3): 8, (1, 3): 9}


def _face_tables(cell_type: str) -> tuple[np.ndarray, np.ndarray]:
    """(faces x corners) and (faces x polygon nodes) local index tables."""
    faces, edge_node = (_TET_FACES, _TET_EDGE_NODE) if cell_type == "tet10" else (
        _HEX_FACES, _HEX_EDGE_NODE)  # hex27 shares hex20's first 20 nodes
    polygons = []
    for face in faces:
        polygon = []
        for a, b in zip(face, face[1:] + face[:1]):
            polygon += [a, edge_node[(min(a, b), max(a, b))]]
        polygons.append(polygon)
    return np.array(faces), np.array(polygons)


def boundary_polygons(cells: np.ndarray, cell_type: str) -> np.ndarray:
    """Node indices of every boundary face as a polygon through its corner and
    mid-edge nodes: (F, 8) for hexahedra, (F, 6) for tetrahedra.

    A face is on the boundary when no other cell has the same corner nodes.
    """
    corners, polygons = _face_tables(cell_type)
    face_corners = cells[:, corners].reshape(-1, corners.shape[1])
    face_polygons = cells[:, polygons].reshape(-1, polygons.shape[1])
    _, inverse, counts = np.unique(
        np.sort(face_corners, axis=1), axis=0, return_inverse=True, return_counts=True
    )
    return face_polygons[counts[inverse.reshape(-1)] == 1]


#: Boundary faces per Results object: several pictures of one file (the run
#: report draws up to six) find them once.
_BOUNDARY_CACHE: "weakref.WeakKeyDictionary[Results, np.ndarray]" = weakref.WeakKeyDictionary()


def results_boundary(results: Results) -> np.ndarray:
    """boundary_polygons of the results' mesh, computed once per Results."""
    polygons = _BOUNDARY_CACHE.get(results)
    if polygons is None:
        polygons = boundary_polygons(results.cells, results.cell_type)
        _BOUNDARY_CACHE[results] = polygons
    return polygons


def auto_scale(nodes: np.ndarray, shape: np.ndarray) -> float:
    """Factor that makes the largest displacement AUTO_SCALE_FRACTION of the
    model's largest extent, capped at AUTO_SCALE_CAP_FRACTION of its smallest
    extent (0 for a zero shape)."""
    largest = float(np.max(np.linalg.norm(shape, axis=1))) if len(shape) else 0.0
    if largest == 0.0:
        return 0.0
    extents = np.ptp(nodes, axis=0)
    extents = extents[extents > 0]  # a flat model has no extent across
    drawn = min(AUTO_SCALE_FRACTION * extents.max(), AUTO_SCALE_CAP_FRACTION * extents.min())
    return float(drawn / largest)


@dataclass(frozen=True)
class CentreLine:
    """Mean displacement of each axial station (bin of nodes by z) of a shape.

    Arrays have one entry per station, NaN for a station without nodes.
    """

    z: np.ndarray  # mean z of the station's nodes, m
    ux: np.ndarray  # mean u_x: translation of the section
    uy: np.ndarray  # mean u_y
    uz: np.ndarray  # mean axial displacement
    twist: np.ndarray  # mean u_theta / r: rotation of the section about z, rad
    ring_shape: np.ndarray  # root mean square u_r of the outer ring, less the translation
    edges: np.ndarray  # (stations + 1,) station bounds in z


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
    scale: float  # draws the largest in-plane displacement as SECTION_SCALE_FRACTION * radius

    @property
    def deformed(self) -> np.ndarray:
        """(K, 2) x, y of the ring deformed by ``scale`` times the shape."""
        return self.xy + self.scale * self.displacement


def axis_centre(nodes: np.ndarray) -> np.ndarray:
    """x, y of the core axis: the middle of the nodes' extent across."""
    return (nodes[:, :2].min(axis=0) + nodes[:, :2].max(axis=0)) / 2


def _stations(z: np.ndarray, n_stations: int) -> tuple[np.ndarray, np.ndarray]:
    """Station index of every node and the station edges: n_stations equal
    bins between the smallest and largest z."""
    low, high = float(z.min()), float(z.max())
    edges = np.linspace(low, high, n_stations + 1)
    if high <= low:
        return np.zeros(len(z), dtype=np.int64), edges
    index = np.floor((z - low) / (high - low) * n_stations).astype(np.int64)
    return np.clip(index, 0, n_stations - 1), edges


def _cylindrical(nodes: np.ndarray, shape: np.ndarray, centre: np.ndarray):
    """Radius, angle, u_r and u_theta of every node about the axis."""
    dx, dy = nodes[:, 0] - centre[0], nodes[:, 1] - centre[1]
    radius = np.hypot(dx, dy)
    theta = np.arctan2(dy, dx)
    cos, sin = np.cos(theta), np.sin(theta)
    u_r = shape[:, 0] * cos + shape[:, 1] * sin
    u_theta = -shape[:, 0] * sin + shape[:, 1] * cos
    return radius, theta, u_r, u_theta


def centreline_curves(nodes: np.ndarray, shape: np.ndarray,
                      n_stations: int = N_STATIONS) -> CentreLine:
    """Mean u_x, u_y, u_z and twist (u_theta / r) of the nodes of each of
    ``n_stations`` equal bins in z: how the core's sections move along it.

    A bending mode shows as u_x or u_y curves, an axial mode as u_z, a
    torsion mode as the twist; shell modes (ovalling, breathing) leave all
    four near zero, and show in ``ring_shape``: the root mean square radial
    displacement of the outer nodes (within 0.1 % of the largest radius)
    less the part that the sections' mean translation (interpolated to each
    node's z) explains. Nodes on the
    axis (r = 0) are left out of the twist.
    """
    station, edges = _stations(nodes[:, 2], n_stations)
    radius, theta, u_r, u_theta = _cylindrical(nodes, shape, axis_centre(nodes))

    def mean(values: np.ndarray, use: np.ndarray | None = None) -> np.ndarray:
        where = station if use is None else station[use]
        values = values if use is None else values[use]
        count = np.bincount(where, minlength=n_stations).astype(np.float64)
        total = np.bincount(where, weights=values, minlength=n_stations)
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(count > 0, total / count, np.nan)

    off_axis = radius > 1e-9 * max(float(radius.max()), 1e-300)
    twist = np.zeros_like(radius)
    twist[off_axis] = u_theta[off_axis] / radius[off_axis]
    z, ux, uy = mean(nodes[:, 2]), mean(shape[:, 0]), mean(shape[:, 1])
    outer = radius >= (1 - _OUTER_TOLERANCE) * radius.max()
    # The translation at each outer node's own z (interpolated between the
    # stations), so that its change within a station is not taken for shape.
    filled = np.isfinite(z)
    at_z = nodes[outer, 2]
    move_x = _interpolate(at_z, z[filled], ux[filled])
    move_y = _interpolate(at_z, z[filled], uy[filled])
    change = u_r[outer] - (move_x * np.cos(theta[outer]) + move_y * np.sin(theta[outer]))
    squared = np.zeros_like(radius)
    squared[outer] = change ** 2
    return CentreLine(
        z=z, ux=ux, uy=uy, uz=mean(shape[:, 2]), twist=mean(twist, off_axis),
        ring_shape=np.sqrt(mean(squared, outer)), edges=edges,
    )


def _interpolate(x: np.ndarray, xp: np.ndarray, fp: np.ndarray) -> np.ndarray:
    """Piecewise linear through (xp, fp), ascending xp, extended linearly
    beyond both ends (the stations' mean z lie inside the end stations)."""
    if len(xp) < 2:
        return np.full_like(x, fp[0] if len(fp) else 0.0)
    values = np.interp(x, xp, fp)
    low, high = x < xp[0], x > xp[-1]
    values[low] = fp[0] + (x[low] - xp[0]) * (fp[1] - fp[0]) / (xp[1] - xp[0])
    values[high] = fp[-1] + (x[high] - xp[-1]) * (fp[-1] - fp[-2]) / (xp[-1] - xp[-2])
    return values


def section_ring(nodes: np.ndarray, shape: np.ndarray, n_stations: int = N_STATIONS,
                 fraction: float = SECTION_SCALE_FRACTION) -> SectionRing:
    """The outer ring of the station whose outer nodes move most in their
    plane (largest root mean square of u_x, u_y), sorted by angle.

    Outer nodes are those within 0.1 % of the largest radius. In the chosen
    station the ring is the plane of nodes (same z) that moves most, when it
    has at least 6 nodes (structured meshes), else all the station's outer
    nodes. ``scale`` makes the ring's largest in-plane displacement
    ``fraction`` of its radius (1 for a ring that does not move).
    """
    centre = axis_centre(nodes)
    radius, theta, u_r, _ = _cylindrical(nodes, shape, centre)
    outer = np.flatnonzero(radius >= (1 - _OUTER_TOLERANCE) * radius.max())
    station, _ = _stations(nodes[:, 2], n_stations)
    in_plane = shape[outer, 0] ** 2 + shape[outer, 1] ** 2
    count = np.bincount(station[outer], minlength=n_stations)
    total = np.bincount(station[outer], weights=in_plane, minlength=n_stations)
    mean_square = np.where(count > 0, total / np.maximum(count, 1), -1.0)
    best = int(np.argmax(mean_square))
    ring = outer[station[outer] == best]

    # The plane of nodes in the station that moves most, if there are planes.
    z = nodes[ring, 2]
    length = float(np.ptp(nodes[:, 2])) or 1.0
    layer_z, layer = np.unique(np.round(z / (1e-9 * length)), return_inverse=True)
    layer_count = np.bincount(layer)
    if layer_count.max() >= 6:
        layer_square = np.bincount(layer, weights=in_plane[station[outer] == best])
        layer_square = np.where(layer_count >= 6, layer_square / layer_count, -1.0)
        ring = ring[layer == int(np.argmax(layer_square))]

    ring = ring[np.argsort(theta[ring], kind="stable")]
    displacement = shape[ring, :2]
    largest = float(np.sqrt((displacement ** 2).sum(axis=1)).max()) if len(ring) else 0.0
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
    )


def clamp_spans(case: dict[str, Any]) -> list[tuple[float, float]]:
    """(z_start, z_end) of every clamp in the case's ``supports.clamps``."""
    supports = case.get("supports") if isinstance(case, dict) else None
    clamps = supports.get("clamps") if isinstance(supports, dict) else None
    spans = []
    for clamp in clamps or []:
        try:
            spans.append((float(clamp["z_start"]), float(clamp["z_end"])))
        except (KeyError, TypeError, ValueError):
            continue  # not a zone along z: nothing to shade
    return spans


def draw_mode(results: Results, index: int, png_path: str | Path, scale: float | None = None,
              **options: Any) -> float:
    """Draws mode ``index`` (1-based) of ``results`` into a PNG (mode_figure,
    whose keyword ``options`` it takes: size_px, dpi, elevation, azimuth) and
    returns the displacement scale of the 3D view.

    ``scale`` multiplies the (mass-normalised) shape in the 3D view; by
    default it is chosen so that the largest displacement is 10 % of the
    model's largest extent, but at most 25 % of its smallest extent (see
    auto_scale).
    """
    if scale is None:
        scale = auto_scale(results.nodes, results.shape(index))
    mode_figure(results, index, scale, **options).savefig(Path(png_path), dpi=options.get("dpi", 100))
    return scale


def mode_figure(
    results: Results,
    index: int,
    scale: float | None = None,
    *,
    size_px: tuple[int, int] = (1200, 900),
    dpi: int = 100,
    elevation: float = 25.0,
    azimuth: float = -60.0,
) -> Figure:
    """Mode ``index`` (1-based) of ``results`` as a matplotlib Figure of
    ``size_px`` pixels, in three panels: the deformed core in 3D (top left),
    the outer ring of the station that deforms most (top right; see
    section_ring) and the mean displacement of each axial station along the
    core (bottom; see centreline_curves).

    ``scale`` multiplies the shape in the 3D view (default: auto_scale). The
    cross-section has its own exaggeration, written in its title. The core
    axis (z) runs left to right in the 3D view and the along-the-core panel.
    """
    shape = results.shape(index)
    if scale is None:
        scale = auto_scale(results.nodes, shape)
    # Text shrinks with the picture, so that small pictures stay legible.
    font = float(np.clip(9.0 * min(size_px[0] / 1200, size_px[1] / 900) * 100 / dpi, 4.0, 12.0))
    with matplotlib.rc_context({"font.size": font, "axes.titlesize": font + 1,
                                "legend.fontsize": font - 1}):
        figure = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
        FigureCanvasAgg(figure)
        # 3D view and cross-section side by side (3D axes are always square),
        # the curves along the core below them at full width, like the core.
        grid = figure.add_gridspec(2, 2, height_ratios=[1.2, 1.0], width_ratios=[1.45, 1.0],
                                   left=0.07, right=0.97, bottom=0.07, top=0.90,
                                   wspace=0.15, hspace=0.3)
        _draw_3d(figure, figure.add_subplot(grid[0, 0], projection="3d"), results, shape,
                 scale, elevation, azimuth)
        centreline = centreline_curves(results.nodes, shape)
        ring = section_ring(results.nodes, shape)
        _draw_section(figure.add_subplot(grid[0, 1]), ring)
        _draw_centreline(figure.add_subplot(grid[1, :]), results, shape, centreline, ring)
        name = results.case_name or results.path.stem
        figure.suptitle(f"{name} — {results.label(index)}", fontsize=font + 3)
    return figure


def _draw_3d(figure: Figure, axes, results: Results, shape: np.ndarray, scale: float,
             elevation: float, azimuth: float) -> None:
    """The deformed boundary surface, coloured by |u|."""
    deformed = results.nodes + scale * shape
    magnitude = np.linalg.norm(shape, axis=1)
    polygons = results_boundary(results)
    # Plot axes (z, x, y): the core lies horizontally, as on a machine.
    vertices = deformed[polygons][:, :, [2, 0, 1]]
    face_values = magnitude[polygons].mean(axis=1)
    norm = colors.Normalize(vmin=0.0, vmax=float(magnitude.max()) or 1.0)
    colormap = matplotlib.colormaps["viridis"]
    surface = Poly3DCollection(
        vertices,
        facecolors=colormap(norm(face_values)),
        edgecolors=(0.1, 0.1, 0.1, 0.25),
        linewidths=0.2,
    )
    axes.add_collection3d(surface)
    # A long core is a thin diagonal box: zoom in a little to use the panel.
    _fit_axes(axes, vertices.reshape(-1, 3), zoom=1.15)
    axes.view_init(elev=elevation, azim=azimuth)
    axes.set_xlabel("z (m)")
    axes.set_ylabel("x (m)")
    axes.set_zlabel("y (m)")
    mappable = cm.ScalarMappable(norm=norm, cmap=colormap)
    # Horizontal, in the empty lower left corner of the square 3D panel.
    figure.colorbar(mappable, cax=axes.inset_axes([0.08, 0.14, 0.38, 0.025]),
                    orientation="horizontal", label="|u| (mass-normalised)")
    axes.set_title(f"3D view, displacement scale x{scale:.3g}")


def _draw_centreline(axes, results: Results, shape: np.ndarray, curves: CentreLine,
                     ring: SectionRing) -> None:
    """Section translation, axial displacement and twist versus z, divided by
    the largest nodal displacement (twist as the surface displacement R theta)."""
    largest = float(np.linalg.norm(shape, axis=1).max()) or 1.0
    outer = float(np.hypot(*(results.nodes[:, :2] - axis_centre(results.nodes)).T).max())
    for (start, end), label in zip(clamp_spans(results.case), ["clamp"] + [None] * 1000):
        axes.axvspan(min(start, end), max(start, end), color="0.6", alpha=0.3, lw=0,
                     label=label)
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
    axes.set_xlim(curves.edges[0], curves.edges[-1])
    drawn = np.abs([curves.ux, curves.uy, curves.uz, curves.twist * outer, curves.ring_shape])
    top = 1.05 * max(1.0, float(np.nanmax(drawn / largest, initial=0.0)))
    axes.set_ylim(-top, top)
    axes.set_xlabel("z (m)")
    axes.set_ylabel("station mean / max |u|")
    axes.set_title("along the core")
    axes.legend(loc="best", ncol=3, framealpha=0.8)
    axes.grid(True, lw=0.3, alpha=0.5)


def _draw_section(axes, ring: SectionRing) -> None:
    """Undeformed and deformed outer ring, with arrows at some nodes."""
    if len(ring.theta) == 0:
        axes.set_axis_off()
        return
    close = lambda a: np.vstack([a, a[:1]])  # noqa: E731
    rest, moved = close(ring.xy - ring.centre), close(ring.deformed - ring.centre)
    axes.plot(rest[:, 0], rest[:, 1], "--", color="0.5", lw=1.0, label="undeformed")
    axes.plot(moved[:, 0], moved[:, 1], "-", color="C3", lw=1.8, label="deformed")
    step = max(1, len(ring.theta) // 16)
    base = ring.xy[::step] - ring.centre
    axes.quiver(base[:, 0], base[:, 1], ring.scale * ring.displacement[::step, 0],
                ring.scale * ring.displacement[::step, 1], angles="xy", scale_units="xy",
                scale=1.0, color="C0", alpha=0.8, width=0.005, label="node displacement")
    # A spoke to the first node shows a rotation of the section (torsion).
    axes.plot([0, rest[0, 0]], [0, rest[0, 1]], "--", color="0.5", lw=0.8)
    axes.plot([0, moved[0, 0]], [0, moved[0, 1]], "-", color="C3", lw=1.0)
    axes.plot([0], [0], "+", color="0.3")
    limit = 1.4 * ring.radius
    axes.set_xlim(-limit, limit)
    axes.set_ylim(-limit, limit)
    axes.set_aspect("equal")
    axes.set_xlabel("x (m)")
    axes.set_ylabel("y (m)")
    axes.set_title(f"cross-section at z = {ring.z:.3g} m, ×{ring.scale:.3g}")
    axes.legend(loc="best", framealpha=0.8)


def _fit_axes(axes, points: np.ndarray, zoom: float = 1.0) -> None:
    """Equal scale on all three axes: a tube must look round."""
    low, high = points.min(axis=0), points.max(axis=0)
    span = np.maximum(high - low, 1e-3 * max(float((high - low).max()), 1e-12))
    centre = (low + high) / 2
    axes.set_xlim(centre[0] - span[0] / 2, centre[0] + span[0] / 2)
    axes.set_ylim(centre[1] - span[1] / 2, centre[1] + span[1] / 2)
    axes.set_zlim(centre[2] - span[2] / 2, centre[2] + span[2] / 2)
    axes.set_box_aspect(tuple(span), zoom=zoom)
    # Fewer ticks on the short axes, whose labels would otherwise overlap.
    for axis, length in zip((axes.xaxis, axes.yaxis, axes.zaxis), span):
        axis.set_major_locator(MaxNLocator(nbins=max(2, round(6 * length / span.max()))))
