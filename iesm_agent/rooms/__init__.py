"""Room segmentation (paper Sec. 3.2), the contextual open-plan split, the obstacle map and room
metrics. `segment_rooms(scene, cell_labels) -> SceneMap` is the entry point."""

from .config import ObstacleConfig, RoomConfig
from .labels import CellLabels, CellLabelSource
from .obstacles import inflate, obstacle_map
from .scene import segment_rooms, segment_scene

__all__ = ["CellLabelSource", "CellLabels", "ObstacleConfig", "RoomConfig", "inflate", "obstacle_map",
           "segment_rooms", "segment_scene"]
