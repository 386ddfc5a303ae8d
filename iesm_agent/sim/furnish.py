"""Furnishing rooms: furniture against walls, in corners, in the middle, beside or flanking the
previous item, pictures and mirrors hung above it, and small items standing on supports (cups on
tables, books on shelf boards, lamps on nightstands, a dryer on the washing machine).

Free space is tracked on the fine ground-truth grid: an item fits when every cell of its
footprint belongs to its room and none is taken.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Optional

import numpy as np

from ..store.model import GridSpec
from .catalog import FURNITURE, FURNITURE_PASSES, SMALL, ItemSpec
from .shapes import SHAPES, place_boxes, place_surfaces
from .world import WALL_HEIGHT, WorldBuilder, footprint_slices

# wall / back direction (dx, dy) -> quarter turns that put an item's back (local -y) on that side
_TURNS = {(0, -1): 0, (1, 0): 1, (0, 1): 2, (-1, 0): 3}
_DIRS = list(_TURNS)
GAP = 0.06  # m between an item and the wall or its neighbour (> one grid cell, see _fits)


@dataclass
class Placed:
    """A placed item: footprint (x0, x1, y0, y1), quarter turns `k`, back direction `back`
    (the wall it stands against, None in the middle), top height, id, upward surfaces (m, 5)."""

    spec: ItemSpec
    id: int
    rect: tuple[float, float, float, float]
    k: int
    back: Optional[tuple[int, int]]
    top: float
    surfaces: np.ndarray


class Furnisher:
    """Places a room type's furniture list into one room at a time."""

    def __init__(self, builder: WorldBuilder, grid: GridSpec, rooms: np.ndarray, keep_out: list[np.ndarray],
                 rng: np.random.Generator):
        self.builder, self.grid, self.rooms, self.rng = builder, grid, rooms, rng
        self.taken = np.zeros(rooms.shape, bool)
        for ko in keep_out:
            self.taken[footprint_slices(grid, ko[0], ko[1])] = True

    # -- geometry helpers
    def _fits(self, room: int, rect, clearance: float = 0.0) -> bool:
        """Every cell within half a cell (plus `clearance`) of the footprint is in `room` and free.
        Items mark the cells within half a cell of their footprint as taken, so two footprints that
        overlap always share a checked cell, and two GAP apart never do."""
        x0, x1, y0, y1 = rect
        clearance += self.grid.cell_size / 2 + 1e-3
        rows, cols = footprint_slices(self.grid, (x0 - clearance, y0 - clearance), (x1 + clearance, y1 + clearance))
        want = ((x1 - x0 + 2 * clearance) / self.grid.cell_size) * ((y1 - y0 + 2 * clearance) / self.grid.cell_size)
        cells = self.rooms[rows, cols]
        return cells.size >= 0.8 * want and bool(np.all(cells == room)) and not self.taken[rows, cols].any()

    def _wall_distance(self, room: int, x: float, y: float, d: tuple[int, int]) -> float:
        """Coordinate (x for horizontal d, y for vertical d) of the first non-room cell edge from
        (x, y) in direction d, metres."""
        row, col = self.grid.cell_of(x, y)
        s, (ox, oy) = self.grid.cell_size, self.grid.origin
        if d[0]:
            line = self.rooms[row, col::d[0]] if d[0] > 0 else self.rooms[row, col::-1]
        else:
            line = self.rooms[row::d[1], col] if d[1] > 0 else self.rooms[row::-1, col]
        steps = int(np.argmax(line != room)) if np.any(line != room) else len(line)
        if d[0]:
            return ox + (col + (steps if d[0] > 0 else 1 - steps)) * s
        return oy + (row + (steps if d[1] > 0 else 1 - steps)) * s

    def _random_point(self, room: int) -> tuple[float, float]:
        cells = np.argwhere((self.rooms == room) & ~self.taken)
        r, c = cells[self.rng.integers(len(cells))]
        return self.grid.center_of(int(r), int(c))

    @staticmethod
    def _local(spec: ItemSpec):
        return SHAPES[spec.shape](*spec.size)

    def _commit(self, spec: ItemSpec, room: int, k: int, center, back, z0: float = 0.0,
                on: Optional[int] = None, mark: bool = True) -> Placed:
        boxes, surfaces = self._local(spec)
        world_boxes = place_boxes(boxes, k, center, z0)
        color = str(self.rng.choice(spec.colors))
        material = str(self.rng.choice(spec.materials))
        iid = self.builder.add(spec.label, color, material, room, world_boxes, on=on)
        lo, hi = world_boxes[:, 0].min(axis=0), world_boxes[:, 1].max(axis=0)
        rect = (lo[0], hi[0], lo[1], hi[1])
        if mark:
            self.taken[footprint_slices(self.grid, lo - self.grid.cell_size / 2, hi + self.grid.cell_size / 2)] = True
        return Placed(spec, iid, rect, k, back, float(hi[2]), place_surfaces(surfaces, k, center, z0))

    @staticmethod
    def _rect(spec: ItemSpec, k: int, center) -> tuple[float, float, float, float]:
        w, d, _ = spec.size
        half = np.array([w / 2, d / 2]) if k % 2 == 0 else np.array([d / 2, w / 2])
        return (center[0] - half[0], center[0] + half[0], center[1] - half[1], center[1] + half[1])

    def _against(self, spec: ItemSpec, room: int, x: float, y: float, d) -> tuple[float, float]:
        """Centre of `spec` with its back against the wall in direction d from (x, y)."""
        depth = spec.size[1]
        wall = self._wall_distance(room, x, y, d)
        if d[0]:
            return (wall - d[0] * (depth / 2 + GAP), y)
        return (x, wall - d[1] * (depth / 2 + GAP))

    # -- placement strategies: each returns (k, centre, back) candidates
    def _candidates(self, spec: ItemSpec, room: int):
        place = spec.place
        for _ in range(60):
            if place in ("wall", "corner"):
                x, y = self._random_point(room)
                d = _DIRS[self.rng.integers(4)]
                center = self._against(spec, room, x, y, d)
                if place == "corner":
                    side = (d[1], d[0]) if self.rng.random() < 0.5 else (-d[1], -d[0])
                    w = spec.size[0]
                    edge = self._wall_distance(room, *center, side)
                    center = (edge - side[0] * (w / 2 + GAP), center[1]) if side[0] else \
                        (center[0], edge - side[1] * (w / 2 + GAP))
                yield _TURNS[d], center, d
            elif place == "middle":
                yield int(self.rng.integers(4)), self._random_point(room), None
            else:
                return

    def _around(self, spec: ItemSpec, anchor: Placed):
        """Slots facing the anchor on each free side (beside), or next to it along its wall (flank)."""
        x0, x1, y0, y1 = anchor.rect
        w, d, _ = spec.size
        slots = []
        if spec.place == "flank" and anchor.back is not None:
            bx, by = anchor.back
            for s in (-1, 1):
                if bx:  # wall at +-x: flank along y
                    cx = (x1 - d / 2) if bx > 0 else (x0 + d / 2)
                    cy = (y1 + w / 2 + GAP) if s > 0 else (y0 - w / 2 - GAP)
                else:
                    cy = (y1 - d / 2) if by > 0 else (y0 + d / 2)
                    cx = (x1 + w / 2 + GAP) if s > 0 else (x0 - w / 2 - GAP)
                slots.append((anchor.k, (cx, cy), anchor.back))
            return slots
        for side in _DIRS:  # the side of the anchor the chair stands on = where its back points
            if anchor.back is not None and side == anchor.back:
                continue
            if anchor.back is not None and side != (-anchor.back[0], -anchor.back[1]):
                continue  # against a wall: only the front
            length = (x1 - x0) if side[1] else (y1 - y0)
            n = max(1, int(length // 0.6))
            for t in (np.arange(n) + 0.5) / n:
                if side[1]:
                    slots.append((_TURNS[side], (x0 + t * (x1 - x0), (y1 if side[1] > 0 else y0)
                                                 + side[1] * (d / 2 + GAP)), None))
                else:
                    slots.append((_TURNS[side], ((x1 if side[0] > 0 else x0) + side[0] * (d / 2 + GAP),
                                                 y0 + t * (y1 - y0)), None))
        order = self.rng.permutation(len(slots))
        return [slots[i] for i in order]

    def _hang(self, spec: ItemSpec, room: int, anchor: Placed) -> Optional[Placed]:
        """A picture or mirror on the wall above a wall-standing anchor."""
        if anchor.back is None:
            return None
        z0 = anchor.top + 0.25
        if z0 + spec.size[2] > WALL_HEIGHT - 0.1:
            return None
        x0, x1, y0, y1 = anchor.rect
        bx, by = anchor.back
        d = spec.size[1]
        if bx:
            center = ((x1 - d / 2) if bx > 0 else (x0 + d / 2), (y0 + y1) / 2)
        else:
            center = ((x0 + x1) / 2, (y1 - d / 2) if by > 0 else (y0 + d / 2))
        if bx:  # push flush with the wall behind the anchor
            center = (center[0] + bx * GAP, center[1])
        else:
            center = (center[0], center[1] + by * GAP)
        boxes = place_boxes(self._local(spec)[0], anchor.k, center, z0)
        existing = np.array(self.builder.boxes)
        lo = np.maximum(existing[:, None, 0], boxes[None, :, 0])
        hi = np.minimum(existing[:, None, 1], boxes[None, :, 1])
        if np.any(np.all(hi > lo, axis=-1)):  # e.g. a window in the way
            return None
        return self._commit(spec, room, anchor.k, center, anchor.back, z0=z0, mark=False)

    def place_furniture(self, spec: ItemSpec, room: int, anchor: Optional[Placed]) -> list[Placed]:
        if spec.place == "hang":
            hung = self._hang(spec, room, anchor) if anchor else None
            return [hung] if hung else []
        count = int(self.rng.integers(spec.count[0], spec.count[1] + 1))
        if spec.place in ("beside", "flank"):
            candidates = self._around(spec, anchor) if anchor else []
            clearance = 0.0
        else:
            candidates = self._candidates(spec, room)
            clearance = 0.5 if spec.place == "middle" else 0.0
        placed = []
        for k, center, back in candidates:
            if len(placed) == count:
                break
            if self._fits(room, self._rect(spec, k, center), clearance):
                placed.append(self._commit(spec, room, k, center, back))
        return placed

    def place_small(self, support: Placed, room: int) -> list[int]:
        """Small items from `support.spec.holds` standing on its surfaces; returns their ids."""
        surfaces = support.surfaces
        if not len(surfaces):
            return []
        zs = np.sort(surfaces[:, 4])
        headroom = {z: (zs[i + 1] - z - 0.03 if i + 1 < len(zs) else np.inf) for i, z in enumerate(zs)}
        used: list[tuple[int, tuple[float, float, float, float]]] = []
        ids = []
        for kind, prob in support.spec.holds:
            if self.rng.random() >= prob:
                continue
            spec = SMALL[kind]
            for _ in range(12):
                si = int(self.rng.integers(len(surfaces)))
                x0, x1, y0, y1, z = surfaces[si]
                if spec.size[2] > headroom[z]:
                    continue
                rect = self._rect(spec, support.k, (0.0, 0.0))
                hw, hd = rect[1], rect[3]
                if x1 - x0 < 2 * hw or y1 - y0 < 2 * hd:
                    continue
                cx, cy = self.rng.uniform(x0 + hw, x1 - hw), self.rng.uniform(y0 + hd, y1 - hd)
                mine = (cx - hw, cx + hw, cy - hd, cy + hd)
                if any(s == si and not (mine[1] <= r[0] or r[1] <= mine[0] or mine[3] <= r[2] or r[3] <= mine[2])
                       for s, r in used):
                    continue
                used.append((si, mine))
                ids.append(self._commit(spec, room, support.k, (cx, cy), None, z0=float(z), on=support.id,
                                        mark=False).id)
                break
        return ids

    def furnish(self, room: int, room_type: str, passes: int) -> None:
        for _ in range(passes):
            anchor: Optional[Placed] = None
            for spec in FURNITURE.get(room_type, ()):
                dependent = spec.place in ("beside", "flank", "hang")  # needs the previous item
                placed = self.place_furniture(spec, room, anchor) if self.rng.random() < spec.prob else []
                for item in placed:
                    self.place_small(item, room)
                if not dependent:
                    anchor = placed[0] if placed else None


def furnish_all(builder: WorldBuilder, grid: GridSpec, rooms: np.ndarray, labels: dict[int, str],
                keep_out: list[np.ndarray], size: str, rng: np.random.Generator) -> np.ndarray:
    """Furnish every room; returns the (H, W) bool grid of floor taken by furniture and keep-outs."""
    furnisher = Furnisher(builder, grid, rooms, keep_out, rng)
    for room, room_type in sorted(labels.items()):
        furnisher.furnish(room, room_type, FURNITURE_PASSES[size])
    return furnisher.taken
