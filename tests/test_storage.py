"""Storage comparison (paper Table 5) on a hand-made frame directory: the byte counts follow from
the layouts stated in iesm_agent/evals/storage.py."""

import numpy as np

from iesm_agent.evals.storage import CLIP_DIM, PLY_POINT_BYTES, VLMAPS_CELL_BYTES, storage_comparison
from iesm_agent.frames import Frame, Intrinsics, SceneMeta, write_frame, write_frame_set
from iesm_agent.store import GridSpec, Instance, SceneMap, save_map


def test_sizes_follow_the_stated_layouts(tmp_path):
    # a 2 x 2 camera at the origin looking along +z, every pixel 1 m away: four points at
    # x, y = +-0.5 m, z = 1 m, so four top-down cells and four 2 cm voxels; one pixel is an object
    write_frame_set(tmp_path / "f", SceneMeta(scene_id="t", n_frames=1, embedding_space="hash-384"),
                    Intrinsics(width=2, height=2, fx=1, fy=1, cx=0.5, cy=0.5))
    ids = np.array([[1, 0], [0, 0]], np.int32)
    write_frame(tmp_path / "f", Frame(index=0, rgb=np.zeros((2, 2, 3), np.uint8), depth=np.ones((2, 2), np.float32),
                                      pose=np.eye(4), instance_ids=ids))
    scene = SceneMap(scene_id="t", grid=GridSpec(cell_size=0.05, height=10, width=20),
                     instances=[Instance(id=1, label="cup")])
    save_map(scene, tmp_path / "t.iesm")

    report = storage_comparison(tmp_path / "f", tmp_path / "t.iesm")

    assert (report.observed_cells, report.voxels, report.object_voxels) == (4, 4, 1)
    assert report.ours_bytes == (tmp_path / "t.iesm").stat().st_size
    assert report.vlmaps_bytes == 4 * VLMAPS_CELL_BYTES
    assert report.vlmaps_dense_bytes == 10 * 20 * VLMAPS_CELL_BYTES
    # scene cloud (4 points) + the cup's own cloud (1 point); features for 1 object, 0 rooms, 1 floor
    assert report.hovsg_bytes == (4 + 1) * PLY_POINT_BYTES + (1 + 0 + 1) * CLIP_DIM * 4
    assert report.saving_vs_hovsg == 1 - report.ours_bytes / report.hovsg_bytes
