"""Axis-aligned box geometry of instances and the spatial relations people use between them.

Shared by `MapStore` (candidate geometry fields, `relate`), the offline model's spatial expert
(which rebuilds boxes from the geometry in the prompt) and the spatial query generator. World
frame: x, y on the floor, z up, metres. A box is (lo, hi) corners; arrays are (N, 3) float64.
Pairwise functions return (Na, Nb) arrays, vectorised over both sets.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any, Iterable

import numpy as np

#: vertical slack (m) when one box rests on another (mapped heights are noisy)
REST_TOLERANCE = 0.12
#: how far above a surface (m) something still counts as resting on it
REST_GAP = 0.35
#: footprint share of the upper box over the lower one for "on" / "under"
OVERLAP_MIN = 0.3
#: horizontal gap (m) within which "above" / "below" hold without overlapping footprints
ABOVE_REACH = 0.6
#: footprint gap (m) within which two objects are "next to" / "near" each other
NEAR_GAP = 0.6
_COMPASS = ("east", "north-east", "north", "north-west", "west", "south-west", "south", "south-east")


@dataclass(frozen=True)
class Boxes:
    """`ids` (N,) int64; `lo`, `hi` (N, 3) float64 box corners in metres."""

    ids: np.ndarray
    lo: np.ndarray
    hi: np.ndarray

    @property
    def center(self) -> np.ndarray:
        """(N, 3) box centres (m)."""
        return (self.lo + self.hi) / 2

    @property
    def size(self) -> np.ndarray:
        """(N, 3) extents dx, dy, dz (m)."""
        return self.hi - self.lo

    def __len__(self) -> int:
        return len(self.ids)

    def take(self, rows: Any) -> "Boxes":
        """The boxes at `rows` (index array or bool mask)."""
        return Boxes(self.ids[rows], self.lo[rows], self.hi[rows])

    @classmethod
    def from_views(cls, views: Iterable[dict]) -> "Boxes":
        """Boxes from candidate views with `center` [x, y, z], `size` [dx, dy, dz] and optional
        `z_range` [z0, z1]; views without usable geometry are skipped."""
        ids, lo, hi = [], [], []
        for v in views:
            try:
                c = np.asarray(v["center"], np.float64).reshape(3)
                s = np.abs(np.asarray(v.get("size", (0, 0, 0)), np.float64).reshape(3))
                ident = int(v["id"])
            except (KeyError, TypeError, ValueError):
                continue
            if not (np.isfinite(c).all() and np.isfinite(s).all()):
                continue
            low, high = c - s / 2, c + s / 2
            z = v.get("z_range")
            if isinstance(z, (list, tuple)) and len(z) == 2 and all(isinstance(t, (int, float)) for t in z):
                low[2], high[2] = min(z), max(z)
            ids.append(ident)
            lo.append(low)
            hi.append(high)
        return cls(np.array(ids, np.int64), np.array(lo, np.float64).reshape(-1, 3),
                   np.array(hi, np.float64).reshape(-1, 3))


def xy_gap(a: Boxes, b: Boxes) -> np.ndarray:
    """(Na, Nb) distance between footprints (m); 0 where they overlap or touch."""
    dx = np.maximum(0.0, np.maximum(a.lo[:, None, 0] - b.hi[None, :, 0], b.lo[None, :, 0] - a.hi[:, None, 0]))
    dy = np.maximum(0.0, np.maximum(a.lo[:, None, 1] - b.hi[None, :, 1], b.lo[None, :, 1] - a.hi[:, None, 1]))
    return np.hypot(dx, dy)


def center_distance(a: Boxes, b: Boxes) -> np.ndarray:
    """(Na, Nb) horizontal distance between box centres (m)."""
    d = a.center[:, None, :2] - b.center[None, :, :2]
    return np.hypot(d[..., 0], d[..., 1])


def xy_overlap(a: Boxes, b: Boxes) -> np.ndarray:
    """(Na, Nb) footprint intersection area over the smaller footprint, in [0, 1]."""
    w = np.clip(np.minimum(a.hi[:, None, 0], b.hi[None, :, 0]) - np.maximum(a.lo[:, None, 0], b.lo[None, :, 0]), 0, None)
    h = np.clip(np.minimum(a.hi[:, None, 1], b.hi[None, :, 1]) - np.maximum(a.lo[:, None, 1], b.lo[None, :, 1]), 0, None)
    area_a = np.prod(np.maximum(a.size[:, :2], 0.02), axis=1)
    area_b = np.prod(np.maximum(b.size[:, :2], 0.02), axis=1)
    return np.clip(w * h / np.minimum(area_a[:, None], area_b[None, :]), 0.0, 1.0)


def rests_on(a: Boxes, b: Boxes) -> np.ndarray:
    """(Na, Nb) bool: a stands on b (footprints overlap, a's base near b's top, a not below)."""
    base_gap = a.lo[:, None, 2] - b.hi[None, :, 2]
    lifted = a.center[:, None, 2] > b.center[None, :, 2]
    return ((xy_overlap(a, b) >= OVERLAP_MIN) & (base_gap >= -REST_TOLERANCE) & (base_gap <= REST_GAP)
            & lifted & (a.ids[:, None] != b.ids[None, :]))


def is_within(a: Boxes, b: Boxes) -> np.ndarray:
    """(Na, Nb) bool: a's centre lies within b's height and their footprints overlap (on one of b's
    shelves, in one of its compartments)."""
    return ((xy_overlap(a, b) >= OVERLAP_MIN) & (a.center[:, None, 2] >= b.lo[None, :, 2])
            & (a.center[:, None, 2] <= b.hi[None, :, 2]) & (a.ids[:, None] != b.ids[None, :]))


def is_under(a: Boxes, b: Boxes) -> np.ndarray:
    """(Na, Nb) bool: a is under b (footprints overlap, a's centre below b's, a's top not above b's)."""
    return ((xy_overlap(a, b) >= OVERLAP_MIN) & (a.hi[:, None, 2] <= b.hi[None, :, 2] + REST_TOLERANCE)
            & (a.center[:, None, 2] < b.center[None, :, 2]) & (a.ids[:, None] != b.ids[None, :]))


def is_above(a: Boxes, b: Boxes) -> np.ndarray:
    """(Na, Nb) bool: a is above b (a's base at or over b's top, footprints within `ABOVE_REACH`)."""
    return ((a.lo[:, None, 2] >= b.hi[None, :, 2] - REST_TOLERANCE) & (xy_gap(a, b) <= ABOVE_REACH)
            & (a.ids[:, None] != b.ids[None, :]))


def segment_distance(a: Boxes, r1: Boxes, r2: Boxes) -> np.ndarray:
    """(Na,) the smallest distance (m) from a's centre to a segment joining an r1 and an r2 centre,
    plus how far a's projection falls outside the segment; pairs of one object with itself, and
    segments ending at a itself, are skipped."""
    p = a.center[:, None, None, :2]
    s, e = r1.center[None, :, None, :2], r2.center[None, None, :, :2]
    d = e - s
    length2 = np.maximum((d ** 2).sum(-1), 1e-9)
    t = ((p - s) * d).sum(-1) / length2
    closest = s + np.clip(t, 0, 1)[..., None] * d
    off = np.hypot(*(p - closest).transpose(3, 0, 1, 2))
    outside = np.maximum(0, np.maximum(-t, t - 1)) * np.sqrt(length2)
    cost = off + outside
    same = (r1.ids[:, None] == r2.ids[None, :])[None]
    own = (a.ids[:, None, None] == r1.ids[None, :, None]) | (a.ids[:, None, None] == r2.ids[None, None, :])
    cost = np.where(same | own, np.inf, cost)
    return cost.reshape(len(a), -1).min(axis=1, initial=np.inf)


def compass(dx: float, dy: float) -> str:
    """Compass direction of the vector (dx, dy) (x east, y north)."""
    return _COMPASS[int(np.round(np.arctan2(dy, dx) / (np.pi / 4))) % 8]


def describe_pair(a: Boxes, b: Boxes, shared_cells: int = 0) -> dict[str, Any]:
    """Relations of the single box `a` to the single box `b`: distances (m), the vertical relation,
    whether they are near, a's compass direction from b and the number of grid cells they share."""
    gap = float(xy_gap(a, b)[0, 0])
    if rests_on(a, b)[0, 0]:
        vertical = "on"
    elif rests_on(b, a)[0, 0]:
        vertical = "supports"
    elif is_under(a, b)[0, 0]:
        vertical = "under"
    elif is_above(a, b)[0, 0]:
        vertical = "above"
    elif is_above(b, a)[0, 0]:
        vertical = "below"
    else:
        vertical = "level"
    d = a.center[0, :2] - b.center[0, :2]
    return {"a": int(a.ids[0]), "b": int(b.ids[0]), "vertical": vertical,
            "center_distance": round(float(np.hypot(*d)), 3), "gap": round(gap, 3),
            "near": bool(gap <= NEAR_GAP), "direction": compass(float(d[0]), float(d[1])),
            "height_diff": round(float(a.center[0, 2] - b.center[0, 2]), 3),
            "overlap": round(float(xy_overlap(a, b)[0, 0]), 3), "shared_cells": int(shared_cells)}
