"""Walls of maps that have room polygons but no wall instances (maps imported from an object list).

Every room polygon's boundary is drawn into the grid as a 4-connected line of blocked cells (one
cell thick, cells holding the boundary by the grid's floor convention). Doors are gaps in those
lines: where the map declares doors (`meta["doors"]`, JSON `[{"position": [x, y], "width": w}]`
in metres, from the object list's `doors`), the wall cells within w / 2 of each position; otherwise
one gap of `door_width` (0.9 m) on every edge segment two rooms share, placed where the fewest
obstacle cells lie within `clearance` m of the wall on either side across the gap plus the robot
radius (ties: nearest the segment's middle), so a door does not open onto a wardrobe. Shared
segments shorter than `min_shared` get no door. Cells of obstacle instances stay blocked (the gap
removes wall cells only).

`map_walls(scene, obstacles, robot_radius)` decides where a map's walls come from and says so in
`Walls.description`, which `PathResult.walls` carries: the map's own wall instances, the room
polygons, or none ("the path ignores walls").
"""

from __future__ import annotations

import json
from dataclasses import dataclass, field

import numpy as np

from ..errors import IesmError
from ..store.model import GridSpec, Room, SceneMap

#: labels of instances that are walls (a map with any of them keeps its own walls)
WALL_LABELS = ("wall", "walls", "partition", "partition wall")
DOOR_WIDTH = 0.9  # m, the simulator's and a common interior door's clear width
NO_WALLS = "none: the map has no walls or room polygons; the path ignores walls"


@dataclass
class Door:
    """A gap in the polygon walls: centre (x, y) and width in metres, and the two rooms it joins
    (room ids; None for a declared door)."""

    x: float
    y: float
    width: float
    rooms: tuple[int, int] | None = None


@dataclass
class Walls:
    """`cells` (H, W) bool wall cells after the door gaps (all False when the map has its own
    walls or none); `source` "instances", "room polygons" or "none"; `description` one line for
    `PathResult.walls`; `doors` the gaps made."""

    cells: np.ndarray
    source: str
    description: str
    doors: list[Door] = field(default_factory=list)


def declared_doors(scene: SceneMap) -> list[Door] | None:
    """Doors the map declares in `meta["doors"]` (written by the object-list importer), else None."""
    text = scene.meta.get("doors")
    if text is None:
        return None
    try:
        return [Door(float(d["position"][0]), float(d["position"][1]), float(d["width"])) for d in json.loads(text)]
    except (ValueError, KeyError, TypeError, IndexError) as exc:
        raise IesmError(f"meta 'doors' is not a list of {{position: [x, y], width}}: {exc}", scene.scene_id,
                        "meta.doors") from None


def _continuous(grid: GridSpec, xy: np.ndarray) -> np.ndarray:
    """(N, 2) world points (m) -> (N, 2) integer (col, row) of the cells holding them."""
    return np.floor((xy - np.asarray(grid.origin)) / grid.cell_size + 1e-9).astype(np.int64)


def shared_segments(rooms: list[Room], tol: float = 1e-6) -> list[tuple[int, int, np.ndarray, np.ndarray]]:
    """(room a, room b, p0, p1) for every stretch (m) of boundary two rooms' polygons share:
    collinear edges whose projections overlap by more than `tol`."""
    edges = []
    for room in rooms:
        if room.polygon:
            poly = np.asarray(room.polygon, np.float64)
            edges += [(room.id, a, b) for a, b in zip(poly, np.roll(poly, -1, axis=0)) if np.hypot(*(b - a)) > tol]
    out = []
    for i, (ra, a0, a1) in enumerate(edges):
        direction = (a1 - a0) / np.hypot(*(a1 - a0))
        normal = np.array([-direction[1], direction[0]])
        for rb, b0, b1 in edges[i + 1:]:
            if rb == ra or abs((b0 - a0) @ normal) > tol or abs((b1 - a0) @ normal) > tol:
                continue
            lo = max(0.0, min((b0 - a0) @ direction, (b1 - a0) @ direction))
            hi = min(np.hypot(*(a1 - a0)), max((b0 - a0) @ direction, (b1 - a0) @ direction))
            if hi - lo > tol:
                out.append((ra, rb, a0 + lo * direction, a0 + hi * direction))
    return out


def _cell_centres(grid: GridSpec, cells: np.ndarray) -> np.ndarray:
    """(N, 2) world (x, y) centres (m) of (N, 2) (row, col) cells."""
    return np.asarray(grid.origin) + (cells[:, ::-1] + 0.5) * grid.cell_size


def _gap_centre(p0: np.ndarray, p1: np.ndarray, width: float, obstacles: np.ndarray, grid: GridSpec,
                robot_radius: float, clearance: float) -> float | None:
    """Distance (m) from p0 along p0 -> p1 of the clearest door centre, None when the segment is
    too short for a door."""
    length = float(np.hypot(*(p1 - p0)))
    margin = grid.cell_size  # keep the gap off the corner walls
    half = min(width, length - 2 * margin) / 2
    if half <= 0:
        return None
    direction = (p1 - p0) / length
    normal = np.array([-direction[1], direction[0]])
    centres = np.arange(margin + half, length - margin - half + 1e-9, grid.cell_size)
    if len(centres) == 0:
        centres = np.array([length / 2])
    points = _cell_centres(grid, np.argwhere(obstacles))
    rel = points - p0
    along, across = rel @ direction, rel @ normal
    along = np.sort(along[np.abs(across) <= clearance])
    reach = half + robot_radius
    clutter = np.searchsorted(along, centres + reach, "right") - np.searchsorted(along, centres - reach, "left")
    best = np.flatnonzero(clutter == clutter.min())
    return float(centres[best[np.argmin(np.abs(centres[best] - length / 2))]])


def _clear(walls: np.ndarray, grid: GridSpec, where) -> None:
    """Unset, in place, the wall cells for whose centres `where(centres (N, 2) m) -> (N,) bool` is true."""
    cells = np.argwhere(walls)
    if len(cells):
        gone = cells[where(_cell_centres(grid, cells))]
        walls[gone[:, 0], gone[:, 1]] = False


def polygon_walls(scene: SceneMap, obstacles: np.ndarray, robot_radius: float = 0.2, door_width: float = DOOR_WIDTH,
                  clearance: float = 0.6, min_shared: float = 0.5) -> tuple[np.ndarray, list[Door]]:
    """(H, W) bool wall cells of the room polygons with door gaps (module docstring), and the doors."""
    import cv2

    grid = scene.grid
    canvas = np.zeros((grid.height, grid.width), np.uint8)
    for room in scene.rooms:
        if room.polygon:
            pts = _continuous(grid, np.asarray(room.polygon, np.float64))
            # cv2 takes int32 (col, row) points; clip far-away vertices so the cast cannot wrap
            pts = np.clip(pts, -(1 << 20), 1 << 20).astype(np.int32)
            cv2.polylines(canvas, [pts.reshape(-1, 1, 2)], True, 1, thickness=1, lineType=cv2.LINE_4)
    walls = canvas.astype(bool)
    doors = declared_doors(scene)
    if doors is not None:
        for door in doors:
            _clear(walls, grid, lambda c, d=door: np.hypot(c[:, 0] - d.x, c[:, 1] - d.y) <= d.width / 2)
        return walls, doors
    doors = []
    tolerance = 1.5 * grid.cell_size  # drawn cells sit up to one cell off the true line
    for ra, rb, p0, p1 in shared_segments(scene.rooms):
        if np.hypot(*(p1 - p0)) < min_shared:
            continue
        t = _gap_centre(p0, p1, door_width, obstacles, grid, robot_radius, clearance)
        if t is None:
            continue
        length = float(np.hypot(*(p1 - p0)))
        direction = (p1 - p0) / length
        normal = np.array([-direction[1], direction[0]])
        half = min(door_width, length - 2 * grid.cell_size) / 2

        def in_gap(c, p0=p0, d=direction, n=normal, t=t, half=half):
            rel = c - p0
            return (np.abs(rel @ d - t) <= half) & (np.abs(rel @ n) <= tolerance)

        _clear(walls, grid, in_gap)
        centre = p0 + t * direction
        doors.append(Door(round(float(centre[0]), 3), round(float(centre[1]), 3), round(2 * half, 3), (ra, rb)))
    return walls, doors


def wall_instance_ids(scene: SceneMap) -> list[int]:
    """Ids of the map's wall instances (labels in `WALL_LABELS`)."""
    return [inst.id for inst in scene.instances if inst.label.lower() in WALL_LABELS]


def map_walls(scene: SceneMap, obstacles: np.ndarray, robot_radius: float = 0.2) -> Walls:
    """Where `scene`'s walls come from: its wall instances (already in `obstacles`), else the room
    polygons of an imported map (not rooms segmented by `iesm rooms`, whose outlines are no walls),
    else none."""
    empty = np.zeros_like(obstacles, dtype=bool)
    n_walls = len(wall_instance_ids(scene))
    if n_walls:
        return Walls(empty, "instances", f"instances: the map's {n_walls} wall instances")
    polygons = [room for room in scene.rooms if room.polygon]
    if polygons and "room_segmentation" not in scene.meta:
        cells, doors = polygon_walls(scene, obstacles, robot_radius)
        kind = "declared" if declared_doors(scene) is not None else "one per shared edge"
        return Walls(cells, "room polygons",
                     f"room polygons: walls drawn from {len(polygons)} room outlines with {len(doors)} door gaps "
                     f"({kind})", doors)
    if polygons:
        return Walls(empty, "none", "none: the map has no wall instances and its room outlines were segmented, "
                                    "not given; the path ignores walls")
    return Walls(empty, "none", NO_WALLS)
