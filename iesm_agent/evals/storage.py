"""Storage comparison of the paper's Table 5: our `.iesm` file against the bytes a VLMaps-style dense
per-cell feature grid and a HOV-SG-style per-point 3D map would take for the same frames.

The two baselines are not run; their sizes are computed from what the same frames would make them
store, with the feature sizes and layouts those systems use (stated in `ASSUMPTIONS`):

- VLMaps (Huang et al. 2023): an LSeg feature (512 float32) per top-down cell, averaged over every
  depth point that falls into the cell, plus the per-cell colour (3 uint8), height (float32) and
  point weight (float32). Counted over the observed cells only (the released code keeps a dense
  gs x gs grid, which is larger still: reported as `vlmaps_dense_bytes`).
- HOV-SG (Werby et al. 2024): the scene point cloud voxel-downsampled at 2 cm, stored as binary PLY
  (xyz float64 + rgb uint8 = 27 B/point), every object's own point cloud again (each observed point
  belongs to one object or the background), a CLIP ViT-H-14 feature (1024 float32) per object, per
  room and per floor.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
from pydantic import BaseModel

from ..frames import FrameSet
from ..mapping.cells import keys_of
from ..mapping.project import world_points

LSEG_DIM = 512
CLIP_DIM = 1024
VLMAPS_CELL_BYTES = LSEG_DIM * 4 + 3 + 4 + 4
HOVSG_VOXEL_M = 0.02
PLY_POINT_BYTES = 3 * 8 + 3
ASSUMPTIONS = (
    f"VLMaps: {LSEG_DIM}-d float32 LSeg feature + RGB + height + weight per observed cell "
    f"({VLMAPS_CELL_BYTES} B/cell); HOV-SG: scene and per-object point clouds at {HOVSG_VOXEL_M * 100:.0f} cm "
    f"voxels as binary PLY ({PLY_POINT_BYTES} B/point), {CLIP_DIM}-d float32 CLIP feature per object, room and floor"
)


class StorageReport(BaseModel):
    """Bytes per representation for one scene, and our saving against each baseline (0..1)."""

    scene_id: str
    ours_bytes: int
    vlmaps_bytes: int
    vlmaps_dense_bytes: int
    hovsg_bytes: int
    observed_cells: int
    voxels: int
    object_voxels: int

    @property
    def saving_vs_vlmaps(self) -> float:
        return 1.0 - self.ours_bytes / self.vlmaps_bytes

    @property
    def saving_vs_hovsg(self) -> float:
        return 1.0 - self.ours_bytes / self.hovsg_bytes


def _voxel_keys(points: np.ndarray, voxel: float) -> np.ndarray:
    """Unique int64 keys of the `voxel`-metre voxels holding world `points` (3, n)."""
    ijk = np.floor(points / voxel).astype(np.int64) + (1 << 20)
    return np.unique((ijk[0] << 42) | (ijk[1] << 21) | ijk[2])


def storage_comparison(frames_dir: str | Path, map_path: str | Path, n_rooms: int = 0) -> StorageReport:
    """Measure our map file at `map_path` and size both baselines from the frames in `frames_dir`."""
    frames = FrameSet.open(frames_dir)
    k, cell = frames.intrinsics, frames.meta.cell_size
    cells, voxels, object_voxels = [], [], []
    for frame in frames:
        pixels = np.flatnonzero(frame.depth > 0)
        points = world_points(frame.depth, pixels, k.fx, k.fy, k.cx, k.cy, frame.pose)
        cells.append(np.unique(keys_of(np.floor(points[1] / cell), np.floor(points[0] / cell))))
        voxels.append(_voxel_keys(points, HOVSG_VOXEL_M))
        if frame.instance_ids is not None:  # points on objects, stored again in each object's cloud
            on_object = frame.instance_ids.ravel()[pixels] > 0
            object_voxels.append(_voxel_keys(points[:, on_object], HOVSG_VOXEL_M))
    n_cells = len(np.unique(np.concatenate(cells))) if cells else 0
    n_voxels = len(np.unique(np.concatenate(voxels))) if voxels else 0
    n_object_voxels = len(np.unique(np.concatenate(object_voxels))) if object_voxels else n_voxels

    from ..store import load_map

    scene = load_map(map_path)
    grid = scene.grid
    features = (len(scene.instances) + max(n_rooms, len(scene.rooms)) + 1) * CLIP_DIM * 4
    return StorageReport(
        scene_id=scene.scene_id,
        ours_bytes=Path(map_path).stat().st_size,
        vlmaps_bytes=n_cells * VLMAPS_CELL_BYTES,
        vlmaps_dense_bytes=grid.height * grid.width * VLMAPS_CELL_BYTES,
        hovsg_bytes=(n_voxels + n_object_voxels) * PLY_POINT_BYTES + features,
        observed_cells=n_cells, voxels=n_voxels, object_voxels=n_object_voxels,
    )
