"""The obstacle map (paper Sec. 3.4.1): which cells of the 2.5D map block a robot.

An instance is an obstacle if its mean height (m above the floor) is within [h_min, h_max] or its
label is in the obstacle-category list; its footprint cells (from the CSR occupancy) are blocked.
"""

from __future__ import annotations

import numpy as np

from ..store.model import SceneMap
from .config import ObstacleConfig


def cells_of(scene: SceneMap, instance_ids) -> np.ndarray:
    """(H, W) bool: cells occupied by any of `instance_ids`."""
    flat, ids, _ = scene.occupancy.entries()
    mask = np.zeros(scene.grid.height * scene.grid.width, bool)
    mask[flat[np.isin(ids, np.asarray(list(instance_ids), np.int64))]] = True
    return mask.reshape(scene.grid.height, scene.grid.width)


def obstacle_ids(scene: SceneMap, config: ObstacleConfig = ObstacleConfig()) -> list[int]:
    """Ids of the instances that block the robot."""
    labels = {label.lower() for label in config.labels}
    return [inst.id for inst in scene.instances
            if inst.label.lower() in labels
            or (inst.mean_height is not None and config.h_min <= inst.mean_height <= config.h_max)]


def obstacle_map(scene: SceneMap, config: ObstacleConfig = ObstacleConfig()) -> np.ndarray:
    """(H, W) bool, true where an obstacle instance occupies the cell."""
    return cells_of(scene, obstacle_ids(scene, config))


def inflate(obstacles: np.ndarray, radius_m: float, cell_size: float) -> np.ndarray:
    """(H, W) bool: `obstacles` grown by `radius_m` (cells whose centre lies within the radius of an
    obstacle cell's centre), via `cv2.distanceTransform`."""
    import cv2

    if radius_m <= 0 or not obstacles.any():
        return obstacles.copy()
    free = np.ascontiguousarray(~obstacles, dtype=np.uint8)
    distance = cv2.distanceTransform(free, cv2.DIST_L2, cv2.DIST_MASK_PRECISE)
    return distance * cell_size <= radius_m
