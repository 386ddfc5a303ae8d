"""Room segmentation (paper Sec. 3.2) and the contextual open-plan split.
`segment_rooms(scene, cell_labels) -> SceneMap` is the entry point."""

from .config import RoomConfig
from .labels import CellLabels, CellLabelSource
from .scene import segment_rooms, segment_scene

__all__ = ["CellLabelSource", "CellLabels", "RoomConfig", "segment_rooms", "segment_scene"]
