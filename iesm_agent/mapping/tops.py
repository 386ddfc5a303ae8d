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
    width = depth.shape[1]
    for m in masks:
        rows = np.flatnonzero(m.any(axis=1))
        if not len(rows):
            continue
        span = np.flatnonzero(m.any(axis=0))
        r0, c0 = int(rows[0]), int(span[0])
        box = (slice(r0, int(rows[-1]) + 1), slice(c0, int(span[-1]) + 1))
        mask, read = m[box], m[box] & valid[box]          # the mask's bounding box
        cols = np.flatnonzero(read.any(axis=0))
        first = np.argmax(read[:, cols], axis=0)          # row (in the box) of each column's highest reading
        local = np.arange(mask.shape[0])[:, None]
        holes = mask[:, cols] & (out[box][:, cols] == 0) & (local < first[None, :])
        if not holes.any():
            continue
        rr, cc = np.nonzero(read)
        if len(rr) < min_readings:
            continue
        h = float(np.percentile(world_points(depth, (rr + r0) * width + cc + c0, fx, fy, cx, cy, pose)[2],
                                TOP_PERCENTILE))
        if h >= cam_z:
            continue
        # the first reading above the mask in each column: what the camera sees beyond the object
        top = np.argmax(mask[:, cols], axis=0) + r0       # row of each column's highest mask pixel
        reach = max(int(top.max()), 1)
        above = valid[:reach, cols + c0] & (np.arange(reach)[:, None] < top[None, :])
        beyond = np.where(above.any(axis=0), reach - 1 - np.argmax(above[::-1], axis=0), -1)
        r, k = np.nonzero(holes & (beyond >= 0)[None, :])
        if not len(r):
            continue
        r, c = r + r0, cols[k] + c0
        a, b = (c - cx) / fx, (r - cy) / fy
        down = rot[2, 0] * a + rot[2, 1] * b + rot[2, 2]   # world z of the ray per unit of depth
        t = (h - cam_z) / np.where(down < 0, down, -1.0)
        front = depth[first[k] + r0, c]
        ok = ((down < 0) & (-down / np.sqrt(a * a + b * b + 1) < max_cos) & (t >= front) & (t <= max_ratio * front)
              & (t < depth[beyond[k], c]))
        out[r[ok], c[ok]] = t[ok]
    return out
