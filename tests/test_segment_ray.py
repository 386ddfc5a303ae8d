"""Ray Data (local) and the serial path write the same geometric masks and embeddings."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "real_rgbd"


@pytest.mark.slow
def test_geometric_serial_and_ray_write_the_same(tmp_path):
    pytest.importorskip("ray")
    pytest.importorskip("skimage")
    if not (DATA / "7scenes").is_dir():
        pytest.skip("real frames missing")
    from iesm_agent.frames import FrameSet, open_recording
    from iesm_agent.frames.convert import import_recording
    from iesm_agent.segment import SegmenterSpec
    from iesm_agent.segment.run import segment_frame_set

    rec = open_recording(DATA / "7scenes")
    rec.refs = rec.refs[:3]
    import_recording(rec, tmp_path / "a", scene_id="t", embedding_space="none", categories=[])
    shutil.copytree(tmp_path / "a", tmp_path / "b")
    spec = SegmenterSpec(name="geometric")
    segment_frame_set(FrameSet.open(tmp_path / "a"), tmp_path / "a" / "frames", spec=spec)
    segment_frame_set(FrameSet.open(tmp_path / "b"), tmp_path / "b" / "frames", spec=spec, backend="ray", workers=2)
    for i in range(3):
        a, b = FrameSet.open(tmp_path / "a").read(i).segmentation, FrameSet.open(tmp_path / "b").read(i).segmentation
        assert np.array_equal(a.masks, b.masks) and np.array_equal(a.embeddings, b.embeddings)
        assert np.array_equal(a.scores, b.scores)
