"""Box builders for furniture shapes, in an item's local frame: width along x, depth along y with
the back at y = -depth/2 (the side that goes against a wall), floor at z = 0, metres.

Each builder returns (boxes, surfaces): boxes (n, 2, 3) [lo, hi] corners, surfaces (m, 5) rows
[x0, x1, y0, y1, z] of upward faces small items can stand on.
"""

from __future__ import annotations

import numpy as np


def _box(x0, x1, y0, y1, z0, z1) -> list[list[float]]:
    return [[x0, y0, z0], [x1, y1, z1]]


def block(w, d, h):
    return [_box(-w / 2, w / 2, -d / 2, d / 2, 0, h)], [[-w / 2, w / 2, -d / 2, d / 2, h]]


def table(w, d, h):
    leg, top = 0.05, 0.04
    xs, ys = (-w / 2 + 0.03, w / 2 - 0.03 - leg), (-d / 2 + 0.03, d / 2 - 0.03 - leg)
    boxes = [_box(-w / 2, w / 2, -d / 2, d / 2, h - top, h)]
    boxes += [_box(x, x + leg, y, y + leg, 0, h - top) for x in xs for y in ys]
    return boxes, [[-w / 2, w / 2, -d / 2, d / 2, h]]


def chair(w, d, h):
    seat = min(0.47, h * 0.5)
    return ([_box(-w / 2, w / 2, -d / 2, d / 2, 0, seat), _box(-w / 2, w / 2, -d / 2, -d / 2 + 0.06, seat, h)],
            [[-w / 2, w / 2, -d / 2 + 0.06, d / 2, seat]])


def sofa(w, d, h):
    seat, arm, back = 0.42, 0.18, 0.2
    boxes = [_box(-w / 2 + arm, w / 2 - arm, -d / 2 + back, d / 2, 0, seat),
             _box(-w / 2, w / 2, -d / 2, -d / 2 + back, 0, h),
             _box(-w / 2, -w / 2 + arm, -d / 2 + back, d / 2, 0, seat + 0.2),
             _box(w / 2 - arm, w / 2, -d / 2 + back, d / 2, 0, seat + 0.2)]
    return boxes, [[-w / 2 + arm, w / 2 - arm, -d / 2 + back, d / 2, seat]]


def bed(w, d, h):
    head = 0.08
    return ([_box(-w / 2, w / 2, -d / 2 + head, d / 2, 0, h), _box(-w / 2, w / 2, -d / 2, -d / 2 + head, 0, h + 0.45)],
            [[-w / 2, w / 2, -d / 2 + head, d / 2, h]])


def shelf(w, d, h):
    t = 0.025
    n_boards = max(2, int(h // 0.42))
    levels = np.linspace(0.05, h - t, n_boards + 1)
    boxes = [_box(-w / 2, w / 2, -d / 2, -d / 2 + t, 0, h),
             _box(-w / 2, -w / 2 + t, -d / 2, d / 2, 0, h), _box(w / 2 - t, w / 2, -d / 2, d / 2, 0, h)]
    boxes += [_box(-w / 2 + t, w / 2 - t, -d / 2 + t, d / 2, z, z + t) for z in levels]
    surfaces = [[-w / 2 + t, w / 2 - t, -d / 2 + t, d / 2, z + t] for z in levels]
    return boxes, surfaces


def lamp(w, d, h):
    stem = 0.05
    return ([_box(-stem / 2, stem / 2, -stem / 2, stem / 2, 0, 0.7 * h), _box(-w / 2, w / 2, -d / 2, d / 2, 0.65 * h, h),
             _box(-w / 3, w / 3, -d / 3, d / 3, 0, 0.04)], [])


def panel(w, d, h):
    return [_box(-w / 2, w / 2, -d / 2, d / 2, 0, h)], []


SHAPES = {"block": block, "table": table, "chair": chair, "sofa": sofa, "bed": bed, "shelf": shelf,
          "lamp": lamp, "panel": panel}


def rotate_quarter(points_xy: np.ndarray, k: int) -> np.ndarray:
    """Rotate (..., 2) points by k * 90 degrees counter-clockwise about the origin."""
    x, y = points_xy[..., 0], points_xy[..., 1]
    for _ in range(k % 4):
        x, y = -y, x
    return np.stack([x, y], axis=-1)


def place_boxes(boxes: np.ndarray, k: int, center_xy: tuple[float, float], z0: float = 0.0) -> np.ndarray:
    """Local boxes (n, 2, 3) rotated by k quarter turns, moved to `center_xy` and lifted by `z0`,
    re-sorted so each box is [lo, hi]."""
    boxes = np.asarray(boxes, np.float64).copy()
    boxes[..., :2] = rotate_quarter(boxes[..., :2], k) + np.asarray(center_xy)
    boxes[..., 2] += z0
    return np.stack([boxes.min(axis=1), boxes.max(axis=1)], axis=1)


def place_surfaces(surfaces: np.ndarray, k: int, center_xy: tuple[float, float], z0: float = 0.0) -> np.ndarray:
    """Surfaces (m, 5) [x0, x1, y0, y1, z] transformed like `place_boxes`."""
    surfaces = np.asarray(surfaces, np.float64).reshape(-1, 5)
    if not len(surfaces):
        return surfaces
    corners = np.stack([surfaces[:, [0, 2]], surfaces[:, [1, 3]]], axis=1)
    corners = rotate_quarter(corners, k) + np.asarray(center_xy)
    lo, hi = corners.min(axis=1), corners.max(axis=1)
    return np.column_stack([lo[:, 0], hi[:, 0], lo[:, 1], hi[:, 1], surfaces[:, 4] + z0])
