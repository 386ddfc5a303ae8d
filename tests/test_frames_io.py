"""Frame directories: writer/reader round trip, text_vectors spaces, and one clear IesmError
naming the file for each kind of bad input."""

from __future__ import annotations

import json

import numpy as np
import pytest

from iesm_agent.embeddings import HASH_SPACE, text_vectors
from iesm_agent.errors import IesmError
from iesm_agent.frames import (Frame, FrameSet, Intrinsics, SceneMeta, Segmentation,
                               write_frame, write_frame_set)
from iesm_agent.sim.ground_truth import GroundTruth
from iesm_agent.store.model import GridSpec, InstanceGrid

H, W = 12, 16


def _frame(index: int, rng: np.random.Generator) -> Frame:
    masks = np.zeros((2, H, W), bool)
    masks[0, 2:6, 3:9] = True
    masks[1, 7:, :5] = True
    emb = rng.standard_normal((2, 8)).astype(np.float32)
    emb /= np.linalg.norm(emb, axis=1, keepdims=True)
    pose = np.eye(4)
    pose[:3, 3] = [1.5, -2.25, 1.3]
    return Frame(index=index, rgb=rng.integers(0, 256, (H, W, 3), dtype=np.uint8),
                 depth=np.round(rng.uniform(0, 9, (H, W)), 3).astype(np.float32), pose=pose,
                 segmentation=Segmentation(masks, emb, np.array([0.9, 0.4], np.float32)),
                 instance_ids=rng.integers(0, 300, (H, W)).astype(np.int32))


@pytest.fixture()
def frame_dir(tmp_path):
    rng = np.random.default_rng(0)
    meta = SceneMeta(scene_id="t", n_frames=2, embedding_space=HASH_SPACE, categories=["chair", "table"])
    write_frame_set(tmp_path, meta, Intrinsics(width=W, height=H, fx=8.0, fy=8.0, cx=7.5, cy=5.5))
    frames = [_frame(i, rng) for i in range(2)]
    for f in frames:
        write_frame(tmp_path, f)
    return tmp_path, frames


def test_round_trip(frame_dir):
    directory, written = frame_dir
    fs = FrameSet.open(directory)
    assert len(fs) == 2 and fs.meta.categories == ["chair", "table"] and fs.intrinsics.fx == 8.0
    for orig, back in zip(written, fs):
        assert np.array_equal(orig.rgb, back.rgb)
        assert np.abs(orig.depth - back.depth).max() <= 0.0005 + 1e-6  # millimetre quantisation
        assert back.depth.dtype == np.float32
        assert np.allclose(orig.pose, back.pose)
        assert np.array_equal(orig.instance_ids, back.instance_ids)
        assert np.array_equal(orig.segmentation.masks, back.segmentation.masks)
        assert np.allclose(orig.segmentation.embeddings, back.segmentation.embeddings)
    assert not list(directory.rglob(".*"))  # no temp files left behind


def test_ground_truth_round_trip(tmp_path):
    grid = GridSpec(cell_size=0.05, origin=(-1.0, 2.0), height=4, width=5)
    cells = InstanceGrid.from_entries(np.array([0, 0, 7]), np.array([3, 4, 3]), np.array([0.8, 1.2, 0.8]))
    gt = GroundTruth("s", [{"id": 3, "label": "table"}], [{"id": 1, "label": "kitchen"}], grid,
                     np.full((4, 5), 1, np.int32), np.eye(4, 5, dtype=bool), cells)
    gt.save(tmp_path)
    back = GroundTruth.load(tmp_path)
    assert back.grid == grid and back.cells == cells and back.objects == gt.objects
    assert np.array_equal(back.rooms, gt.rooms) and np.array_equal(back.occupancy, gt.occupancy)
    with pytest.raises(IesmError, match="gt"):
        GroundTruth.load(tmp_path / "nowhere")


def _expect_error(directory, name):
    with pytest.raises(IesmError) as info:
        FrameSet.open(directory).read(0)
    assert name in str(info.value)


def test_missing_depth_names_the_file(frame_dir):
    directory, _ = frame_dir
    (directory / "frames" / "000000.depth.png").unlink()
    _expect_error(directory, "000000.depth.png")


@pytest.mark.parametrize("text", ["1 0 0\n0 1 0\n0 0 1\n", "1 0 0 0\n0 1 0 0\n0 0 1 0\n", "a b c d\n" * 4])
def test_bad_pose_names_the_file(frame_dir, text):
    directory, _ = frame_dir
    (directory / "frames" / "000000.pose.txt").write_text(text)
    _expect_error(directory, "000000.pose.txt")


def test_zero_focal_length_names_the_file(frame_dir):
    directory, _ = frame_dir
    path = directory / "intrinsics.json"
    data = json.loads(path.read_text())
    data["fx"] = 0
    path.write_text(json.dumps(data))
    with pytest.raises(IesmError) as info:
        FrameSet.open(directory)
    assert "intrinsics.json" in str(info.value) and "fx" in str(info.value)


def test_mask_shape_mismatch_names_the_file(frame_dir):
    directory, _ = frame_dir
    np.savez_compressed(directory / "frames" / "000000.seg.npz", masks=np.zeros((1, H + 1, W), bool),
                        embeddings=np.zeros((1, 8), np.float32), scores=np.ones(1, np.float32))
    _expect_error(directory, "000000.seg.npz")


def test_bad_scene_json_names_the_file(frame_dir):
    directory, _ = frame_dir
    (directory / "scene.json").write_text('{"format": "iesm-frames"')
    with pytest.raises(IesmError, match="scene.json"):
        FrameSet.open(directory)


def test_text_vectors_hash_space_is_deterministic_and_compositional():
    a, space = text_vectors(["chair", "dark brown chair", "refrigerator"], space=HASH_SPACE)
    b, _ = text_vectors(["chair", "dark brown chair", "refrigerator"], space=HASH_SPACE)
    assert space == HASH_SPACE and a.shape == (3, 384) and a.dtype == np.float32
    assert np.array_equal(a, b) and np.allclose(np.linalg.norm(a, axis=1), 1.0, atol=1e-5)
    assert a[0] @ a[1] > a[0] @ a[2] + 0.2
    with pytest.raises(IesmError, match="unknown embedding space"):
        text_vectors(["chair"], space="clip-b32")


def test_text_vectors_named_encoder_space_without_encoder_is_an_error(monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    with pytest.raises(IesmError, match="all-MiniLM-L6-v2"):
        text_vectors(["chair"], space="all-MiniLM-L6-v2")
    assert text_vectors(["chair"])[1] == HASH_SPACE
