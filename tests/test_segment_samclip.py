"""`sam-clip` with randomly initialised models built by the same code (a small SAM image encoder,
a small open_clip config with pretrained=None): loading, batching, shapes, the written layout,
the vocabulary in the masks' space, and serial vs Ray (local) writing the same masks and
embeddings. Needs segment-anything, open_clip and a torchvision matching torch (else skipped)."""

from __future__ import annotations

import json
import shutil
from pathlib import Path

import numpy as np
import pytest

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "real_rgbd"

TINY_CLIP = {"embed_dim": 32,
             "vision_cfg": {"image_size": 64, "layers": 1, "width": 64, "patch_size": 16},
             "text_cfg": {"context_length": 77, "vocab_size": 49408, "width": 64, "heads": 2, "layers": 1}}


def _libraries():
    try:
        import open_clip  # noqa: F401
        import segment_anything  # noqa: F401
    except Exception as exc:  # a torchvision built for another torch fails with RuntimeError
        pytest.skip(f"sam-clip libraries unusable here: {exc}")


@pytest.fixture
def frames_dir(tmp_path):
    _libraries()
    if not (DATA / "7scenes").is_dir():
        pytest.skip("real frames missing")
    from iesm_agent.frames import open_recording
    from iesm_agent.frames.convert import import_recording

    rec = open_recording(DATA / "7scenes")
    rec.refs = rec.refs[:2]
    import_recording(rec, tmp_path / "f", scene_id="t", embedding_space="none", categories=[])
    return tmp_path / "f"


def _spec(tmp_path):
    from iesm_agent.segment import SegmenterSpec

    cfg = tmp_path / "iesm-tiny-clip.json"
    cfg.write_text(json.dumps(TINY_CLIP))
    return SegmenterSpec(name="sam-clip", sam_model="tiny", clip_model="iesm-tiny-clip", clip_config=str(cfg),
                         random_weights=True, points_per_side=4, pred_iou_thresh=0.0, stability_score_thresh=0.0,
                         min_mask_area=0, device="cpu", threads=1)


def _read_all(directory: Path) -> list:
    out = []
    for p in sorted((directory / "frames").glob("*.seg.npz")):
        with np.load(p, allow_pickle=False) as d:
            out.append((d["masks"].copy(), d["embeddings"].copy(), d["scores"].copy()))
    return out


@pytest.mark.slow
def test_random_weight_sam_clip_writes_masks_vocabulary_and_builds(frames_dir, tmp_path):
    from iesm_agent.frames import FrameSet
    from iesm_agent.mapping.build import build_map
    from iesm_agent.segment.run import segment_frame_set

    frames = FrameSet.open(frames_dir)
    report = segment_frame_set(frames, frames_dir / "frames", spec=_spec(tmp_path), categories=["chair", "table"],
                               rooms=["kitchen", "office"])
    assert report.space == "open_clip:iesm-tiny-clip:random-seed0"
    frames = FrameSet.open(frames_dir)
    seg = frames.read(0).segmentation
    assert seg.masks.shape[1:] == (480, 640) and seg.embeddings.shape[1] == 32
    assert np.allclose(np.linalg.norm(seg.embeddings, axis=1), 1, atol=1e-5)
    vocab = frames.vocabulary()
    assert list(vocab["names"]) == ["chair", "table"] and vocab["embeddings"].shape == (2, 32)
    assert frames.frame_features().shape == (2, 32)
    scene = build_map(frames)
    assert {i.label for i in scene.instances} <= {"chair", "table"}


@pytest.mark.slow
def test_sam_clip_serial_and_ray_write_the_same(frames_dir, tmp_path):
    pytest.importorskip("ray")
    from iesm_agent.frames import FrameSet
    from iesm_agent.segment.run import segment_frame_set

    other = tmp_path / "g"
    shutil.copytree(frames_dir, other)
    spec = _spec(tmp_path)
    segment_frame_set(FrameSet.open(frames_dir), frames_dir / "frames", spec=spec, backend="serial")
    segment_frame_set(FrameSet.open(other), other / "frames", spec=spec, backend="ray", workers=1)
    serial, ray_out = _read_all(frames_dir), _read_all(other)
    assert len(serial) == len(ray_out) == 2
    for (m1, e1, s1), (m2, e2, s2) in zip(serial, ray_out):
        assert np.array_equal(m1, m2)
        assert np.allclose(e1, e2, atol=1e-5) and np.allclose(s1, s2, atol=1e-6)
    assert np.allclose(FrameSet.open(frames_dir).frame_features(), FrameSet.open(other).frame_features(), atol=1e-5)
