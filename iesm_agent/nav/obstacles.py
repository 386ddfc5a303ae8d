"""The obstacle map (paper Sec. 3.4.1): which cells of the 2.5D map block a robot.

An instance is an obstacle if its mean height (m above the floor) is within [h_min, h_max] or its
label is in the obstacle-category list; its footprint cells (from the CSR occupancy) are blocked.
"""

from __future__ import annotations

import numpy as np
from pydantic import BaseModel, ConfigDict, Field

from ..rooms.config import LARGE_FIXED_LABELS, STRUCTURAL_LABELS
from ..store.model import SceneMap

OBSTACLE_LABELS = STRUCTURAL_LABELS + LARGE_FIXED_LABELS + ("bed", "sofa", "couch", "table", "bathtub", "toilet",
                                                            "sink", "stove", "oven", "washing machine", "piano")


class ObstacleConfig(BaseModel):
    """An instance blocks the robot if its mean height (m above the floor) lies in [h_min, h_max]
    or its label is in `labels`; planning inflates obstacles by `robot_radius`."""

    model_config = ConfigDict(extra="forbid")

    h_min: float = Field(0.05, ge=0)
    h_max: float = Field(1.5, gt=0)
    labels: tuple[str, ...] = OBSTACLE_LABELS
    robot_radius: float = Field(0.2, ge=0)


def obstacle_ids(scene: SceneMap, config: ObstacleConfig = ObstacleConfig()) -> list[int]:
    """Ids of the instances that block the robot."""
    labels = {label.lower() for label in config.labels}
    return [inst.id for inst in scene.instances
            if inst.label.lower() in labels
            or (inst.mean_height is not None and config.h_min <= inst.mean_height <= config.h_max)]


def obstacle_map(scene: SceneMap, config: ObstacleConfig = ObstacleConfig()) -> np.ndarray:
    """(H, W) bool, true where an obstacle instance occupies the cell."""
    return scene.cells_of(obstacle_ids(scene, config))


def inflate(obstacles: np.ndarray, radius_m: float, cell_size: float) -> np.ndarray:
    """(H, W) bool: `obstacles` grown by `radius_m` (cells whose centre lies within the radius of an
    obstacle cell's centre), via `cv2.distanceTransform`."""
    import cv2

    if radius_m <= 0 or not obstacles.any():
        return obstacles.copy()
    free = np.ascontiguousarray(~obstacles, dtype=np.uint8)
    distance = cv2.distanceTransform(free, cv2.DIST_L2, cv2.DIST_MASK_PRECISE)
    return distance * cell_size <= radius_m


def with_obstacles(scene: SceneMap, config: ObstacleConfig = ObstacleConfig()) -> SceneMap:
    """A copy of `scene` carrying its obstacle map (written into the map by `iesm rooms`)."""
    return scene.model_copy(update={"obstacles": obstacle_map(scene, config)})
