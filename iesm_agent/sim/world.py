"""The simulated world: instances made of axis-aligned boxes, walls with door gaps, doors,
windows, and the ground-truth rasters (rooms, occupancy, 2.5D CSR map) at `FINE` resolution.

World coordinates in metres, z up, floor at z = 0; the apartment footprint starts at (0, 0).
"""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Optional

import numpy as np

from ..frames import Intrinsics
from ..store.model import GridSpec, InstanceGrid
from .catalog import COLORS, WALL_COLORS
from .floorplan import CELL, DOOR_WIDTH, FloorPlan, WallRun

WALL_HEIGHT = 2.6  # m, also the ceiling
WALL_T = 0.1  # wall thickness, m
FINE = 0.05  # ground-truth grid cell, m
MARGIN = 0.25  # m of grid around the footprint
OCCUPANCY_BAND = (0.05, 1.5)  # m: what blocks a robot


@dataclass
class SimInstance:
    """One ground-truth instance. `color` is a name from catalog.COLORS; `on` the id of the
    instance it stands on; `structural` for wall / door / window."""

    id: int
    label: str
    color: str
    material: str
    room: Optional[int]
    structural: bool = False
    on: Optional[int] = None

    @property
    def rgb(self) -> tuple[int, int, int]:
        return COLORS[self.color]


@dataclass
class World:
    """A generated scene. `boxes` (B, 2, 3) [lo, hi] corners in metres, `box_instance` (B,) the
    instance id of each box; `grid` the fine ground-truth grid; `room_raster` (H, W) int32 room id
    per fine cell (-1 outside rooms or inside walls); `poses` (N, 4, 4) camera-to-world (OpenCV
    camera axes)."""

    scene_id: str
    seed: int
    size: str
    open_plan: bool
    plan: FloorPlan
    instances: list[SimInstance]
    boxes: np.ndarray
    box_instance: np.ndarray
    grid: GridSpec
    room_raster: np.ndarray
    intrinsics: Intrinsics
    poses: np.ndarray = field(default_factory=lambda: np.zeros((0, 4, 4)))

    def instance_bounds(self) -> dict[int, tuple[np.ndarray, np.ndarray]]:
        """Instance id -> (lo (3,), hi (3,)) of the union of its boxes."""
        out = {}
        for inst in self.instances:
            boxes = self.boxes[self.box_instance == inst.id]
            out[inst.id] = (boxes[:, 0].min(axis=0), boxes[:, 1].max(axis=0))
        return out

    def box_rgb(self) -> np.ndarray:
        """(B, 3) float sRGB 0-255 of each box."""
        rgb = {inst.id: inst.rgb for inst in self.instances}
        return np.array([rgb[int(i)] for i in self.box_instance], np.float64).reshape(-1, 3)

    def occupancy(self) -> np.ndarray:
        """(H, W) bool: cells where some box overlaps the robot band OCCUPANCY_BAND."""
        lo, hi = OCCUPANCY_BAND
        blocking = (self.boxes[:, 0, 2] < hi) & (self.boxes[:, 1, 2] > lo)
        out = np.zeros((self.grid.height, self.grid.width), bool)
        for box in self.boxes[blocking]:
            out[footprint_slices(self.grid, box[0], box[1])] = True
        return out

    def instance_grid(self) -> InstanceGrid:
        """The ground-truth 2.5D map: every box footprint, per-cell top = highest box top."""
        cells, ids, tops = [], [], []
        for box, inst in zip(self.boxes, self.box_instance):
            rows, cols = footprint_slices(self.grid, box[0], box[1])
            rr, cc = np.mgrid[rows, cols]
            cells.append((rr * self.grid.width + cc).ravel())
            ids.append(np.full(rr.size, inst))
            tops.append(np.full(rr.size, box[1, 2]))
        return InstanceGrid.from_entries(np.concatenate(cells), np.concatenate(ids), np.concatenate(tops))


def footprint_slices(grid: GridSpec, lo, hi) -> tuple[slice, slice]:
    """Grid cells whose centre lies in the box footprint [lo, hi) (at least the cell holding the
    footprint centre), clipped to the grid."""
    s, (ox, oy) = grid.cell_size, grid.origin

    def span(a: float, b: float, origin: float, n: int) -> slice:
        first, last = int(np.ceil((a - origin) / s - 0.5)), int(np.ceil((b - origin) / s - 0.5))
        if last <= first:
            first = int(np.floor(((a + b) / 2 - origin) / s))
            last = first + 1
        return slice(min(max(first, 0), n), min(max(last, 0), n))

    return span(lo[1], hi[1], oy, grid.height), span(lo[0], hi[0], ox, grid.width)


class WorldBuilder:
    """Accumulates instances and their boxes."""

    def __init__(self) -> None:
        self.instances: list[SimInstance] = []
        self.boxes: list[np.ndarray] = []
        self.box_instance: list[int] = []

    def add(self, label: str, color: str, material: str, room: Optional[int], boxes: np.ndarray,
            structural: bool = False, on: Optional[int] = None) -> int:
        boxes = np.asarray(boxes, np.float64).reshape(-1, 2, 3)
        inst = SimInstance(len(self.instances) + 1, label, color, material, room, structural, on)
        self.instances.append(inst)
        self.boxes.extend(boxes)
        self.box_instance.extend([inst.id] * len(boxes))
        return inst.id


def _run_box(run: WallRun, a: float, b: float, z0: float, z1: float, thickness: float) -> np.ndarray:
    """Box of the piece [a, b] (metres along `run`) of a wall run, `thickness` across it."""
    lo_across, hi_across = run.coord - thickness / 2, run.coord + thickness / 2
    if run.along_x:
        return np.array([[a, lo_across, z0], [b, hi_across, z1]])
    return np.array([[lo_across, a, z0], [hi_across, b, z1]])


def _room_at(plan: FloorPlan, x: float, y: float) -> int:
    r, c = int(np.floor(y / CELL)), int(np.floor(x / CELL))
    if 0 <= r < plan.grid.shape[0] and 0 <= c < plan.grid.shape[1]:
        return int(plan.grid[r, c])
    return -1


def build_structure(plan: FloorPlan, builder: WorldBuilder, rng: np.random.Generator) -> list[np.ndarray]:
    """Walls (split at door gaps, none between open-plan pairs), open door panels and one window
    per room with an outside wall. Returns keep-out footprints (2, 2) [[x0, y0], [x1, y1]] in front
    of and behind each door, where furniture must not go."""
    wall_color = str(rng.choice(WALL_COLORS))
    doors = {door.run: door for door in plan.doors}
    open_pairs = set(plan.open_pairs)
    keep_out = []
    window_runs: dict[int, WallRun] = {}  # room -> its longest outside wall
    for run in plan.runs:
        if (run.a, run.b) in open_pairs:
            continue
        room = run.a if run.a > 0 else run.b
        pieces = [(run.lo - WALL_T / 2, run.hi + WALL_T / 2)]
        door = doors.get(run)
        if door is not None:
            g0, g1 = door.center - DOOR_WIDTH / 2, door.center + DOOR_WIDTH / 2
            pieces = [(pieces[0][0], g0), (g1, pieces[0][1])]
            # the room on the +y (+x) side of the line; the door swings open into it
            probe = (door.center, run.coord + CELL / 2) if run.along_x else (run.coord + CELL / 2, door.center)
            side = _room_at(plan, *probe)
            panel = np.array([[g0, run.coord + WALL_T / 2, 0.0], [g0 + 0.04, run.coord + WALL_T / 2 + 0.85, 2.05]])
            if not run.along_x:
                panel = panel[:, [1, 0, 2]]
            builder.add("door", str(rng.choice(("white", "brown", "light brown", "dark brown"))), "wood", side,
                        panel, structural=True)
            ko = np.array([[g0 - 0.1, run.coord - 1.0], [g1 + 0.1, run.coord + 1.0]])
            keep_out.append(ko if run.along_x else ko[:, ::-1])
        for a, b in pieces:
            if b - a > 0.05:
                builder.add("wall", wall_color, "plaster", room, _run_box(run, a, b, 0.0, WALL_HEIGHT, WALL_T),
                            structural=True)
        if run.a == -1 and plan.labels[run.b] not in ("hallway", "storage room") and run.length >= 1.6:
            if run.b not in window_runs or run.length > window_runs[run.b].length:
                window_runs[run.b] = run
    for room, run in sorted(window_runs.items()):
        width = min(1.4, run.length - 0.6)
        center = rng.uniform(run.lo + 0.3 + width / 2, run.hi - 0.3 - width / 2)
        builder.add("window", "light blue", "glass", room,
                    _run_box(run, center - width / 2, center + width / 2, 0.9, 2.1, WALL_T + 0.04), structural=True)
    return keep_out


def fine_grid(plan: FloorPlan) -> GridSpec:
    rows, cols = plan.grid.shape
    return GridSpec(cell_size=FINE, origin=(-MARGIN, -MARGIN),
                    height=int(round((rows * plan.cell + 2 * MARGIN) / FINE)),
                    width=int(round((cols * plan.cell + 2 * MARGIN) / FINE)))


def room_raster(plan: FloorPlan, grid: GridSpec, wall_boxes: np.ndarray) -> np.ndarray:
    """(H, W) int32 room id per fine cell by its centre; -1 outside the footprint or in a wall."""
    ys = grid.origin[1] + (np.arange(grid.height) + 0.5) * grid.cell_size
    xs = grid.origin[0] + (np.arange(grid.width) + 0.5) * grid.cell_size
    r, c = np.floor(ys / plan.cell).astype(int), np.floor(xs / plan.cell).astype(int)
    inside = (r[:, None] >= 0) & (r[:, None] < plan.grid.shape[0]) & (c[None] >= 0) & (c[None] < plan.grid.shape[1])
    out = np.where(inside, plan.grid[np.clip(r, 0, plan.grid.shape[0] - 1)[:, None],
                                     np.clip(c, 0, plan.grid.shape[1] - 1)[None]], -1).astype(np.int32)
    for box in wall_boxes:
        out[footprint_slices(grid, box[0], box[1])] = -1
    return out
