"""Axial stations of a mesh: where the pictures sample a shape along the roll.

A coremodal mesh of a tube (gmsh's extrusion, the harmonic level's section
turned about the axis) has its nodes in planes of equal z, and those planes
are the only places where the shape is known: a picture that samples at
other stations (fixed bins in z) gets bins with no node in them, and its
curves break there. So the stations are the node planes. An unstructured
mesh (a user's tet10 mesh) has almost every node at its own z; there the
stations are equal bins in z, and bins without nodes are left out, so that
the curves stay continuous.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

#: Nodes whose z differ by less than this fraction of the model's length are
#: in one plane (gmsh writes a plane's nodes with rounding errors of ~1e-16).
PLANE_TOLERANCE = 1e-9
#: A mesh whose planes hold fewer nodes than this on average has no planes
#: (every tube mesh holds at least one ring of nodes around, 8 or more).
MIN_NODES_PER_PLANE = 4
#: Bins in z of an unstructured mesh.
N_BINS = 60


@dataclass(frozen=True)
class Stations:
    """Which station every node is in; stations are numbered by ascending z."""

    index: np.ndarray  # (N,) station of every node, 0 .. count - 1
    count: int
    planes: bool  # True: node planes; False: bins of an unstructured mesh

    def mean(self, values: np.ndarray, use: np.ndarray | None = None) -> np.ndarray:
        """Mean of ``values`` (one per node) over each station's nodes (those
        where ``use`` is true, if given); NaN for a station without them."""
        where = self.index if use is None else self.index[use]
        values = values if use is None else values[use]
        count = np.bincount(where, minlength=self.count).astype(np.float64)
        total = np.bincount(where, weights=values, minlength=self.count)
        with np.errstate(invalid="ignore", divide="ignore"):
            return np.where(count > 0, total / count, np.nan)


def node_planes(z: np.ndarray, tolerance: float = PLANE_TOLERANCE) -> tuple[np.ndarray, int]:
    """Plane of every node (nodes closer in z than ``tolerance`` times the
    length are one plane; a sorted sweep, so that no rounding boundary can
    split a plane) and the number of planes."""
    if len(z) == 0:
        return np.zeros(0, dtype=np.int64), 0
    order = np.argsort(z, kind="stable")
    gap = tolerance * (float(np.ptp(z)) or 1.0)
    sorted_plane = np.concatenate([[0], np.cumsum(np.diff(z[order]) > gap)]).astype(np.int64)
    plane = np.empty(len(z), dtype=np.int64)
    plane[order] = sorted_plane
    return plane, int(sorted_plane[-1]) + 1


def stations(z: np.ndarray, n_bins: int = N_BINS) -> Stations:
    """The node planes of ``z`` if the mesh has planes, else ``n_bins`` equal
    bins in z with the empty ones left out."""
    plane, count = node_planes(z)
    if count * MIN_NODES_PER_PLANE <= len(z):
        return Stations(plane, count, True)
    low, high = float(z.min()), float(z.max())
    if high <= low:
        return Stations(np.zeros(len(z), dtype=np.int64), 1, False)
    bins = np.clip(np.floor((z - low) / (high - low) * n_bins).astype(np.int64), 0, n_bins - 1)
    used, index = np.unique(bins, return_inverse=True)
    return Stations(index.reshape(-1).astype(np.int64), len(used), False)
