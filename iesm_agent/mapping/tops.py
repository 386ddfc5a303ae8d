"""Tops of objects seen from above at grazing incidence (not in the paper; `MappingConfig.paper()`
and `uncleaned()` turn it off).

A camera at 1.35 m sees the top of a kettle, a toaster or a microwave on a counter (0.9-1.2 m)
from a few metres away at a grazing angle, where a structured-light sensor returns nothing: the
mask holds the top face, the depth image holds only the front face. Projected, such an object
keeps one or two rows of cells of a footprint it should hold whole (on tuning seeds 0-4, 13 of 31
unmatched stacked objects, and most of the cells they miss had no reading at all). `fill_tops`
gives those pixels the depth at which their ray meets the horizontal plane at the height of the
mask's top: where a top face must be if the pixel shows one, and never behind what the camera
sees beyond the object (a top cannot reach past the wall seen above it: a towel hanging on a rail
would otherwise be filled through the wall behind it).
"""

from __future__ import annotations

import numpy as np

from .project import world_points

#: a mask's top height is this percentile of the world heights of its readings (tuning seeds 0-4:
#: {95, 98, 99, 100}, see `MappingConfig.top_fill_max_cos`)
TOP_PERCENTILE = 98.0


def fill_tops(depth: np.ndarray, masks: np.ndarray, fx: float, fy: float, cx: float, cy: float, pose: np.ndarray,
              *, max_cos: float, max_ratio: float, min_readings: int) -> np.ndarray:
    """Copy of `depth` (H, W) metres (0 = no reading) with the tops of `masks` (K, H, W) bool
    filled in; intrinsics in pixels, `pose` (4, 4) camera-to-world, world z up (frames.md).

    For each mask with at least `min_readings` readings: h = the `TOP_PERCENTILE` of its readings'
    world heights. A mask pixel without a reading that lies above the highest reading of its image
    column (a smaller row; the camera is upright) gets the depth t at which its ray meets the plane
    z = h, when h is below the camera and the ray descends to it, the plane would be seen there at
    grazing incidence (|cos| of the ray with the vertical under `max_cos`, the reason a sensor reads
    nothing), and t lies between the depth of the column's highest reading (behind the front edge)
    and `max_ratio` times it, and before the first reading above the mask in that column (what is
    seen beyond the object; a column with none above the mask is not filled). A pixel filled for
    one mask keeps that depth (masks in order).
    """
    out = depth.copy()
    valid = depth > 0
    rot, cam_z = pose[:3, :3], float(pose[2, 3])
    row_index = np.arange(depth.shape[0])[:, None]
    # per pixel: the row of the nearest reading at or above it in its column (-1: none)
    above = np.maximum.accumulate(np.where(valid, row_index, -1), axis=0)
    for m in masks:
        read = m & valid
        pix = np.flatnonzero(read)
        if len(pix) < min_readings:
            continue
        h = float(np.percentile(world_points(depth, pix, fx, fy, cx, cy, pose)[2], TOP_PERCENTILE))
        if h >= cam_z:
            continue
        cols = np.flatnonzero(read.any(axis=0))
        first = np.argmax(read[:, cols], axis=0)          # row of each column's highest reading
        top = np.argmax(m[:, cols], axis=0)               # row of each column's highest mask pixel
        beyond = above[np.maximum(top - 1, 0), cols]      # row of the first reading above the mask
        seen = (top > 0) & (beyond >= 0)
        cols, first, beyond = cols[seen], first[seen], beyond[seen]
        r, k = np.nonzero(m[:, cols] & (out[:, cols] == 0) & (row_index < first[None, :]))
        if not len(r):
            continue
        c = cols[k]
        a, b = (c - cx) / fx, (r - cy) / fy
        down = rot[2, 0] * a + rot[2, 1] * b + rot[2, 2]   # world z of the ray per unit of depth
        t = (h - cam_z) / np.where(down < 0, down, -1.0)
        front = depth[first[k], c]
        ok = ((down < 0) & (-down / np.sqrt(a * a + b * b + 1) < max_cos) & (t >= front) & (t <= max_ratio * front)
              & (t < depth[beyond[k], c]))
        out[r[ok], c[ok]] = t[ok]
    return out
