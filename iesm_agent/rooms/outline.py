"""One tracer of cell regions: the exact outline of a boolean cell mask through cell corners.

Used by the room segmentation (`rooms.scene.room_polygon`, simplified there) and by the
simulator's floor plans (exact, the ground truth's room polygons). OpenCV's contours run through
cell centres, half a cell inside the region, so they cannot give the exact outline the ground
truth needs.
"""

from __future__ import annotations

import numpy as np


def cells_polygon(mask: np.ndarray, cell: float) -> list[tuple[float, float]]:
    """Outer boundary of a cell region of `mask` (H, W) bool as a counter-clockwise rectilinear
    polygon through cell corners, (x = column, y = row) times `cell` (metres from the grid's
    corner), collinear vertices removed. A region of several blobs: the boundary that encloses
    the largest area (the largest blob's outline, never a hole's); [] for an empty mask."""
    rows, cols = mask.shape
    padded = np.pad(mask, 1)
    edges: dict[tuple[int, int], list[tuple[int, int]]] = {}
    # (neighbour offset, edge start, edge end) with corners as (x, y) in cell units of cell (r, c)
    sides = (((-1, 0), lambda r, c: (c, r), lambda r, c: (c + 1, r)),
             ((0, 1), lambda r, c: (c + 1, r), lambda r, c: (c + 1, r + 1)),
             ((1, 0), lambda r, c: (c + 1, r + 1), lambda r, c: (c, r + 1)),
             ((0, -1), lambda r, c: (c, r + 1), lambda r, c: (c, r)))
    for (dr, dc), start, end in sides:
        open_side = mask & ~padded[1 + dr:1 + dr + rows, 1 + dc:1 + dc + cols]
        r, c = np.nonzero(open_side)
        for a, b in zip(zip(*start(r, c)), zip(*end(r, c))):
            edges.setdefault((int(a[0]), int(a[1])), []).append((int(b[0]), int(b[1])))
    loops = []
    while edges:
        loop, point = [], next(iter(edges))
        while point in edges:
            loop.append(point)
            nxt = edges[point].pop()
            if not edges[point]:
                del edges[point]
            point = nxt
        loops.append(loop)
    if not loops:
        return []
    loop = max(loops, key=_enclosed_area)
    keep = [p for k, p in enumerate(loop) if not _collinear(loop[k - 1], p, loop[(k + 1) % len(loop)])]
    return [(x * cell, y * cell) for x, y in keep]


def _collinear(a, b, c) -> bool:
    return (b[0] - a[0]) * (c[1] - b[1]) - (b[1] - a[1]) * (c[0] - b[0]) == 0


def _enclosed_area(loop: list[tuple[int, int]]) -> float:
    """Absolute shoelace area of a closed loop of (x, y) points."""
    xy = np.asarray(loop, np.float64)
    return abs(float(np.dot(xy[:, 0], np.roll(xy[:, 1], -1)) - np.dot(xy[:, 1], np.roll(xy[:, 0], -1)))) / 2
