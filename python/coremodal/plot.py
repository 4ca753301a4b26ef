"""Pictures of mode shapes with matplotlib (Agg, no display needed).

The deformed core is drawn as its boundary surface: every cell face that no
other cell shares, with its mid-edge nodes so that the quadratic geometry of a
coarse mesh still looks round, coloured by the displacement magnitude.
"""

from __future__ import annotations

from pathlib import Path

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


def draw_mode(
    results: Results,
    index: int,
    png_path: str | Path,
    scale: float | None = None,
    *,
    size_px: tuple[int, int] = (1200, 900),
    dpi: int = 100,
    elevation: float = 25.0,
    azimuth: float = -60.0,
) -> float:
    """Draws mode ``index`` (1-based) of ``results`` deformed, into a PNG of
    ``size_px`` pixels, and returns the displacement scale used.

    ``scale`` multiplies the (mass-normalised) shape; by default it is chosen
    so that the largest displacement is 10 % of the model's largest extent,
    but at most 25 % of its smallest extent (see auto_scale).
    The core axis (z) runs left to right in the picture.
    """
    shape = results.shape(index)
    if scale is None:
        scale = auto_scale(results.nodes, shape)
    deformed = results.nodes + scale * shape
    magnitude = np.linalg.norm(shape, axis=1)

    polygons = boundary_polygons(results.cells, results.cell_type)
    # Plot axes (z, x, y): the core lies horizontally, as on a machine.
    vertices = deformed[polygons][:, :, [2, 0, 1]]
    face_values = magnitude[polygons].mean(axis=1)
    norm = colors.Normalize(vmin=0.0, vmax=float(magnitude.max()) or 1.0)
    colormap = matplotlib.colormaps["viridis"]

    figure = Figure(figsize=(size_px[0] / dpi, size_px[1] / dpi), dpi=dpi)
    FigureCanvasAgg(figure)
    axes = figure.add_subplot(projection="3d")
    surface = Poly3DCollection(
        vertices,
        facecolors=colormap(norm(face_values)),
        edgecolors=(0.1, 0.1, 0.1, 0.25),
        linewidths=0.2,
    )
    axes.add_collection3d(surface)
    _fit_axes(axes, vertices.reshape(-1, 3))
    axes.view_init(elev=elevation, azim=azimuth)
    axes.set_xlabel("z (m)")
    axes.set_ylabel("x (m)")
    axes.set_zlabel("y (m)")

    mappable = cm.ScalarMappable(norm=norm, cmap=colormap)
    figure.colorbar(mappable, ax=axes, shrink=0.6, pad=0.1,
                    label="|u|, mass-normalised shape")
    name = results.case_name or results.path.stem
    axes.set_title(
        f"{name} — {results.label(index)}\ndisplacement scale x{scale:.3g}", fontsize=11
    )
    png_path = Path(png_path)
    figure.savefig(png_path, dpi=dpi)
    return scale


def _fit_axes(axes, points: np.ndarray) -> None:
    """Equal scale on all three axes: a tube must look round."""
    low, high = points.min(axis=0), points.max(axis=0)
    span = np.maximum(high - low, 1e-3 * max(float((high - low).max()), 1e-12))
    centre = (low + high) / 2
    axes.set_xlim(centre[0] - span[0] / 2, centre[0] + span[0] / 2)
    axes.set_ylim(centre[1] - span[1] / 2, centre[1] + span[1] / 2)
    axes.set_zlim(centre[2] - span[2] / 2, centre[2] + span[2] / 2)
    axes.set_box_aspect(tuple(span))
    # Fewer ticks on the short axes, whose labels would otherwise overlap.
    for axis, length in zip((axes.xaxis, axes.yaxis, axes.zaxis), span):
        axis.set_major_locator(MaxNLocator(nbins=max(2, round(6 * length / span.max()))))
