"""What a viewer needs beside a mode shape: its cylindrical components and
a suggested exaggeration. The program writes both into modes.h5 and
modes.xdmf (src/output/mode_display.cpp); this is the same rule in numpy,
for files that predate them and for shapes made in python.
"""

from __future__ import annotations

import numpy as np

#: The largest displacement is drawn as this fraction of the model's largest
#: extent (for a roll, its length)...
WARP_LENGTH_FRACTION = 0.10
#: ...but, for every mode other than bending and axial ones, at most this
#: fraction of its smallest extent (the diameter): a shell mode warped to 10 %
#: of the length would turn the tube inside out, a torsion mode turn by radians.
WARP_DIAMETER_FRACTION = 0.25
#: Mode types whose sections move as a whole and stay round at any scale.
SECTION_TYPES = ("bending", "axial")


def suggested_warp_scale(nodes: np.ndarray, shape: np.ndarray, mode_type: str) -> float:
    """Scale for Warp By Vector: the largest |u| becomes 10 % of the largest
    extent of ``nodes`` (capped at 25 % of the smallest extent unless
    ``mode_type`` is bending or axial); 0 for a zero shape."""
    largest = float(np.max(np.linalg.norm(shape, axis=1))) if len(shape) else 0.0
    if largest == 0.0:
        return 0.0
    extents = np.ptp(nodes, axis=0)
    extents = extents[extents > 0]  # a flat model has no extent across
    if not len(extents):
        return 0.0
    drawn = WARP_LENGTH_FRACTION * extents.max()
    if mode_type not in SECTION_TYPES:
        drawn = min(drawn, WARP_DIAMETER_FRACTION * extents.min())
    return float(drawn / largest)


def cylindrical(nodes: np.ndarray, shape: np.ndarray) -> np.ndarray:
    """(N, 3) u_r, u_theta, u_z about the z axis (x = y = 0); a node on the
    axis takes theta = 0 (u_r = u_x, u_theta = u_y)."""
    theta = np.arctan2(nodes[:, 1], nodes[:, 0])  # 0 on the axis
    cos, sin = np.cos(theta), np.sin(theta)
    return np.column_stack([shape[:, 0] * cos + shape[:, 1] * sin,
                            -shape[:, 0] * sin + shape[:, 1] * cos, shape[:, 2]])
