"""Camera intrinsics and a trajectory through every room: waypoints spread over each room's free
floor, a full turn in place at each, plus one view through every door.

Poses are camera-to-world 4x4 with OpenCV camera axes (x right, y down, z forward), metres.
"""

from __future__ import annotations

import numpy as np

from ..frames import Intrinsics
from ..store.model import GridSpec
from .floorplan import FloorPlan

CAMERA_HEIGHT = 1.35  # m
PITCH_DEG = 15.0  # downward
ROBOT_RADIUS = 0.3  # m of clearance around a waypoint
HEADINGS = 8  # views per waypoint (45 degrees apart)
AREA_PER_WAYPOINT = {"small": 8.0, "hm3d": 20.0}  # m^2 of room per waypoint


def default_intrinsics(width: int = 320, height: int = 240, hfov_deg: float = 90.0) -> Intrinsics:
    """Square pixels, principal point at the image centre (pixel centres at integer coordinates)."""
    f = (width / 2) / np.tan(np.radians(hfov_deg) / 2)
    return Intrinsics(width=width, height=height, fx=f, fy=f, cx=(width - 1) / 2, cy=(height - 1) / 2)


def look_pose(position, yaw: float, pitch_deg: float = PITCH_DEG) -> np.ndarray:
    """Camera-to-world pose at `position` (3,) looking along heading `yaw` (radians from +x,
    counter-clockwise) tilted down by `pitch_deg`."""
    p = np.radians(pitch_deg)
    forward = np.array([np.cos(yaw) * np.cos(p), np.sin(yaw) * np.cos(p), -np.sin(p)])
    right = np.array([np.sin(yaw), -np.cos(yaw), 0.0])
    down = np.cross(forward, right)
    pose = np.eye(4)
    pose[:3, :3] = np.column_stack([right, down, forward])
    pose[:3, 3] = position
    return pose


def _free_space(blocked: np.ndarray, rooms: np.ndarray, cell: float) -> np.ndarray:
    """(H, W) float32 distance in metres from each room cell to the nearest blocked or wall cell."""
    import cv2

    free = ((rooms >= 0) & ~blocked).astype(np.uint8)
    return cv2.distanceTransform(free, cv2.DIST_L2, 5).astype(np.float32) * cell


def trajectory(plan: FloorPlan, grid: GridSpec, rooms: np.ndarray, blocked: np.ndarray, size: str,
               rng: np.random.Generator) -> np.ndarray:
    """(N, 4, 4) camera poses visiting every room and looking through every door."""
    clearance = _free_space(blocked, rooms, grid.cell_size)
    poses = []
    for room in sorted(plan.labels):
        ok = (rooms == room) & (clearance >= ROBOT_RADIUS)
        if not ok.any():
            ok = (rooms == room) & (clearance >= clearance[rooms == room].max() - 1e-6)
        cells = np.argwhere(ok)
        area = (rooms == room).sum() * grid.cell_size ** 2
        n = max(1, int(round(area / AREA_PER_WAYPOINT[size])))
        # farthest-point sampling, starting from the roomiest spot
        chosen = [cells[int(np.argmax(clearance[ok]))]]
        dist = np.linalg.norm(cells - chosen[0], axis=1)
        for _ in range(1, min(n, len(cells))):
            chosen.append(cells[int(np.argmax(dist))])
            dist = np.minimum(dist, np.linalg.norm(cells - chosen[-1], axis=1))
        for r, c in chosen:
            x, y = grid.center_of(int(r), int(c))
            start = rng.uniform(0, 2 * np.pi)
            poses += [look_pose((x, y, CAMERA_HEIGHT), start + 2 * np.pi * h / HEADINGS) for h in range(HEADINGS)]
    for door in plan.doors:  # from 1.2 m in front of the gap, looking through it
        run = door.run
        for side in (-1, 1):
            offset = side * 1.2
            x, y = (door.center, run.coord + offset) if run.along_x else (run.coord + offset, door.center)
            r, c = grid.cell_of(x, y)
            if grid.contains(r, c) and clearance[r, c] >= ROBOT_RADIUS * 0.7:
                yaw = np.arctan2(-offset, 0.0) if run.along_x else np.arctan2(0.0, -offset)
                poses.append(look_pose((x, y, CAMERA_HEIGHT), yaw, pitch_deg=5.0))
                break
    return np.array(poses)
