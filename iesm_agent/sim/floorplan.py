"""Floor plans grown room by room on a coarse grid (the constrained-growth idea ProcTHOR uses).

Each room of the program gets a seed cell and grows as a rectangle towards its target area; each
leftover free region then joins, whole, the neighbouring room furthest below its target (unless
that would wrap it around another room), giving L- and T-shaped rooms that tile the footprint
without overlap and walls without staircases. Doors join rooms along a spanning tree of the adjacency graph (public
rooms first); an open-plan variant removes the whole wall between one public pair. Coarse cell
(row, col) covers x in [col * cell, ...), y in [row * cell, ...) metres.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import IesmError
from ..rooms.outline import cells_polygon
from .catalog import FOOTPRINTS, OPEN_PLAN_PAIRS, PROGRAMS, PUBLIC

CELL = 0.5  # coarse plan cell, metres
DOOR_WIDTH = 0.9  # m
MIN_DOOR_RUN = 1.5  # m of shared wall needed for a door or an open-plan join
OUTSIDE = -1
_STEPS = ((-1, 0), (1, 0), (0, -1), (0, 1))  # (drow, dcol)


@dataclass(frozen=True)
class WallRun:
    """A straight piece of boundary between rooms `a` < `b` (OUTSIDE = -1 for the exterior).
    `along_x`: the run lies on the line y = `coord` from x = `lo` to `hi`; else on x = `coord`
    from y = `lo` to `hi` (metres)."""

    a: int
    b: int
    along_x: bool
    coord: float
    lo: float
    hi: float

    @property
    def length(self) -> float:
        return self.hi - self.lo


@dataclass(frozen=True)
class RunDoor:
    """A door gap of DOOR_WIDTH centred at `center` (metres along the run) in `run`."""

    run: WallRun
    center: float


@dataclass
class FloorPlan:
    """`grid` (R, C) int32 room id per coarse cell (ids 1..N, OUTSIDE never occurs inside the
    footprint); `labels[id]` the room type; `runs` every boundary run; `doors`; `open_pairs`
    (a, b) joined with no wall."""

    grid: np.ndarray
    labels: dict[int, str]
    runs: list[WallRun]
    doors: list[RunDoor]
    open_pairs: list[tuple[int, int]]
    cell: float = CELL

    def polygon(self, room_id: int) -> list[tuple[float, float]]:
        return cells_polygon(self.grid == room_id, self.cell)

    def connected(self) -> bool:
        """Every room reachable from room 1 through doors and open-plan joins."""
        edges = [(d.run.a, d.run.b) for d in self.doors] + list(self.open_pairs)
        return len(_components(list(self.labels), edges)) == 1


def _components(nodes: list[int], edges: list[tuple[int, int]]) -> list[set[int]]:
    parent = {n: n for n in nodes}

    def find(n: int) -> int:
        while parent[n] != n:
            parent[n] = parent[parent[n]]
            n = parent[n]
        return n

    for a, b in edges:
        parent[find(a)] = find(b)
    groups: dict[int, set[int]] = {}
    for n in nodes:
        groups.setdefault(find(n), set()).add(n)
    return list(groups.values())


def _shift(mask: np.ndarray, dr: int, dc: int) -> np.ndarray:
    """mask moved by (dr, dc) cells, zero-filled: out[r, c] = mask[r - dr, c - dc]."""
    out = np.zeros_like(mask)
    rs, rd = (slice(0, mask.shape[0] - dr), slice(dr, None)) if dr >= 0 else (slice(-dr, None), slice(0, dr))
    cs, cd = (slice(0, mask.shape[1] - dc), slice(dc, None)) if dc >= 0 else (slice(-dc, None), slice(0, dc))
    out[rd, cd] = mask[rs, cs]
    return out


def _grow(grid: np.ndarray, targets: dict[int, int], rng: np.random.Generator) -> None:
    """Grow seeded rooms in place: rectangles first, then every free region (0) joins a neighbour."""
    seeds = {i: np.argwhere(grid == i)[0] for i in targets}
    rects = {i: [r, r + 1, c, c + 1] for i, (r, c) in seeds.items()}  # [r0, r1) x [c0, c1)
    area = {i: 1 for i in targets}
    active = set(targets)
    while active:  # rectangular growth, the room furthest below its target first
        i = max(sorted(active), key=lambda k: (targets[k] - area[k]) / targets[k])
        r0, r1, c0, c1 = rects[i]
        if area[i] >= targets[i]:
            active.discard(i)
            continue
        # grow the shorter side first so rooms stay compact
        order = [0, 1, 2, 3] if (r1 - r0) <= (c1 - c0) else [2, 3, 0, 1]
        order = order[:2][::rng.choice([1, -1])] + order[2:][::rng.choice([1, -1])]
        for d in order:
            box = [[r0 - 1, r0, c0, c1], [r1, r1 + 1, c0, c1], [r0, r1, c0 - 1, c0], [r0, r1, c1, c1 + 1]][d]
            if box[0] < 0 or box[2] < 0 or box[1] > grid.shape[0] or box[3] > grid.shape[1]:
                continue
            strip = grid[box[0]:box[1], box[2]:box[3]]
            if np.all(strip == 0):
                strip[...] = i
                rects[i] = [min(r0, box[0]), max(r1, box[1]), min(c0, box[2]), max(c1, box[3])]
                area[i] += strip.size
                break
        else:
            active.discard(i)
    # leftovers: each connected free region joins, whole, the neighbouring room furthest below
    # its target, so boundaries stay on rectangle edges (L- and T-shaped rooms, no staircases)
    import cv2

    n, regions = cv2.connectedComponents((grid == 0).astype(np.uint8), connectivity=4)
    for region in range(1, n):
        cells = regions == region
        around = np.zeros_like(cells)
        for dr, dc in _STEPS:
            around |= _shift(cells, dr, dc)
        neighbours = np.unique(grid[around & (grid > 0)]).tolist()
        ranked = sorted(neighbours, key=lambda k: ((area[k] - targets[k]) / targets[k], k))
        for k in ranked:  # the first that does not wrap around another room (no holes)
            if not _has_hole((grid == k) | cells):
                break
        else:
            k = ranked[0]
        grid[cells] = k
        area[k] += int(cells.sum())


def _has_hole(mask: np.ndarray) -> bool:
    """True when the region's complement (outside the grid included) is not one 8-connected piece."""
    import cv2

    n, _ = cv2.connectedComponents(np.pad(~mask, 1, constant_values=True).astype(np.uint8), connectivity=8)
    return n - 1 > 1


def _runs(codes: np.ndarray) -> list[tuple[int, int, int, int]]:
    """Maximal runs of equal non-negative codes along each row of `codes` (L, M):
    (line, start, end_exclusive, code)."""
    padded = np.pad(codes, ((0, 0), (1, 1)), constant_values=-1)
    change = padded[:, 1:] != padded[:, :-1]  # (L, M + 1): boundary before position j
    lines, starts = np.nonzero(change[:, :-1] & (codes >= 0))
    out = []
    for line, start in zip(lines.tolist(), starts.tolist()):
        end = start + 1 + int(np.argmax(change[line, start + 1:]))
        out.append((line, start, end, int(codes[line, start])))
    return out


def boundary_runs(grid: np.ndarray, cell: float) -> list[WallRun]:
    """Every straight boundary run between different rooms (or a room and the outside)."""
    n = int(grid.max()) + 2
    padded = np.pad(grid, 1, constant_values=OUTSIDE)
    runs = []
    for along_x, (below, above) in ((True, (padded[:-1, 1:-1], padded[1:, 1:-1])),
                                    (False, (padded[1:-1, :-1].T, padded[1:-1, 1:].T))):
        lo_id, hi_id = np.minimum(below, above), np.maximum(below, above)
        codes = np.where(below != above, (lo_id + 1) * n + (hi_id + 1), -1)
        for line, start, end, code in _runs(codes):
            runs.append(WallRun(code // n - 1, code % n - 1, along_x, line * cell, start * cell, end * cell))
    return runs


def _choose_doors(labels: dict[int, str], runs: list[WallRun], open_pair: tuple[int, int] | None,
                  rng: np.random.Generator) -> list[RunDoor] | None:
    """Doors along a spanning tree (public-public, then public-private, then private-private
    edges), plus a few extra public-public doors; None when some room cannot be reached."""
    longest: dict[tuple[int, int], WallRun] = {}  # the longest shared run of each pair of rooms
    for run in sorted(runs, key=lambda r: r.length):
        if run.a > 0 and run.length >= MIN_DOOR_RUN:
            longest[(run.a, run.b)] = run

    def rank(pair: tuple[int, int]) -> int:
        return 2 - sum(labels[k] in PUBLIC for k in pair)

    pairs = sorted(longest, key=lambda p: (rank(p), rng.random()))
    chosen: list[tuple[int, int]] = []
    joined = [open_pair] if open_pair else []
    for pair in pairs:
        if pair == open_pair:
            continue
        groups = _components(list(labels), joined + chosen)
        together = any(pair[0] in g and pair[1] in g for g in groups)
        if not together or (rank(pair) == 0 and rng.random() < 0.3):
            chosen.append(pair)
    if len(_components(list(labels), joined + chosen)) != 1:
        return None
    doors = []
    for pair in chosen:
        run = longest[pair]
        margin = 0.15 + DOOR_WIDTH / 2
        doors.append(RunDoor(run, float(rng.uniform(run.lo + margin, run.hi - margin))))
    return doors


def grow_floor_plan(size: str, open_plan: bool, rng: np.random.Generator, attempts: int = 50) -> FloorPlan:
    """A connected floor plan for program `size` ("small" or "hm3d"); with `open_plan`, one
    public pair (kitchen-living room, hallway-living room, ...) shares no wall."""
    if size not in PROGRAMS:
        raise IesmError(f"unknown scene size {size!r} (choose from {', '.join(PROGRAMS)})")
    program, (fx, fy) = PROGRAMS[size], FOOTPRINTS[size]
    shape = (int(round(fy / CELL)), int(round(fx / CELL)))
    labels = {i + 1: label for i, (label, _) in enumerate(program)}
    targets = {i + 1: max(2, int(round(area / CELL ** 2))) for i, (_, area) in enumerate(program)}
    for _ in range(attempts):
        grid = np.zeros(shape, np.int32)
        seeds: list[tuple[int, int]] = []
        for i in labels:
            cand = np.argwhere(grid == 0)[rng.choice(int(np.sum(grid == 0)), size=24)]
            dist = np.min(np.abs(cand[:, None, :] - np.array(seeds)[None]).sum(-1), axis=1) if seeds else \
                -np.abs(cand - np.array(shape) / 2).sum(1)
            r, c = cand[int(np.argmax(dist))]
            grid[r, c] = i
            seeds.append((int(r), int(c)))
        _grow(grid, targets, rng)
        runs = boundary_runs(grid, CELL)
        open_pair = None
        if open_plan:
            shared = {(r.a, r.b) for r in runs if r.a > 0 and r.length >= MIN_DOOR_RUN}
            open_pair = next((p for want in OPEN_PLAN_PAIRS for p in sorted(shared)
                              if {labels[p[0]], labels[p[1]]} == set(want)), None)
            if open_pair is None:
                continue
        doors = _choose_doors(labels, runs, open_pair, rng)
        if doors is not None:
            return FloorPlan(grid, labels, runs, doors, [open_pair] if open_pair else [])
    raise IesmError(f"could not grow a connected {size} floor plan in {attempts} attempts")
