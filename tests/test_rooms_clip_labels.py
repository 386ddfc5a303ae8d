"""`iesm rooms --room-labels clip` (issue 21): per-cell room labels from CLIP frame features and room
text embeddings (paper Sec. 3.2). Synthetic frame directories with known room vectors: cameras
look straight down at the floor of a two-room layout, so the cells each frame sees are known;
plus the random-weight sam-clip output when its libraries are usable (else skipped)."""

from __future__ import annotations

import numpy as np
import pytest

from iesm_agent.cli import run
from iesm_agent.frames import Frame, Intrinsics, SceneMeta
from iesm_agent.frames.ours import write_frame, write_frame_features, write_frame_set, write_vocabulary
from iesm_agent.rooms.clip_labels import ClipFrameLabels
from iesm_agent.sim.layouts import grid_layout
from iesm_agent.store import load_map, save_map

ROOMS = ["bedroom", "kitchen", "bathroom"]
K = Intrinsics(width=64, height=48, fx=100.0, fy=100.0, cx=31.5, cy=23.5)
HEIGHT = 1.5  # m: the camera above the floor; each frame sees 0.96 m x 0.72 m of floor around it


def looking_down(x: float, y: float) -> np.ndarray:
    """Camera-to-world pose (OpenCV axes) of a camera at (x, y, HEIGHT) looking straight down."""
    pose = np.eye(4)
    pose[:3, :3] = np.array([[1, 0, 0], [0, -1, 0], [0, 0, -1]], float).T  # columns: camera x, y, z in the world
    pose[:3, 3] = (x, y, HEIGHT)
    return pose


def write_frames(directory, views, room_vectors, rooms=ROOMS):
    """One frame per (x, y, feature) in `views`; vocabulary with `rooms` and their vectors."""
    write_frame_set(directory, SceneMeta(scene_id="clip", n_frames=len(views), embedding_space="test-16",
                                         categories=[]), K)
    for i, (x, y, _) in enumerate(views):
        write_frame(directory, Frame(index=i, rgb=np.zeros((48, 64, 3), np.uint8),
                                     depth=np.full((48, 64), HEIGHT, np.float32), pose=looking_down(x, y)))
    write_frame_features(directory, np.stack([f for _, _, f in views]))
    write_vocabulary(directory, ["chair"], room_vectors[:1], rooms, room_vectors[:len(rooms)])


@pytest.fixture()
def room_vectors():
    rng = np.random.default_rng(0)
    q, _ = np.linalg.qr(rng.normal(size=(16, 16)))
    return q[:, :len(ROOMS)].T.astype(np.float32)  # (3, 16) orthonormal room vectors


def feature(vec, rng, noise=0.3):
    f = vec + noise * rng.normal(size=vec.shape) / np.sqrt(vec.size)
    return (f / np.linalg.norm(f)).astype(np.float32)


def test_cells_take_the_room_their_frames_score_best(tmp_path, room_vectors):
    layout = grid_layout(2, 1, labels=("bedroom", "kitchen"))  # rooms x 0-4 and 4-8 m, y 0-4 m
    rng = np.random.default_rng(1)
    bed, kit, bath = room_vectors
    views = [(2.0, 2.0, feature(bed, rng)), (2.1, 2.0, feature(bed, rng)), (1.9, 2.1, feature(bed, rng)),
             (2.0, 2.0, feature(kit, rng)),        # one frame misread as the kitchen: outvoted
             (6.0, 2.0, feature(kit, rng)), (6.0, 2.1, feature(kit, rng)),
             (6.0, 3.2, feature(bath, rng)),       # a corner of the kitchen read as a bathroom
             (2.0, 3.3, np.zeros(16, np.float32))]  # not embedded: no vote
    write_frames(tmp_path, views, room_vectors)
    source = ClipFrameLabels(tmp_path, stride=1)
    assert source.frame_rooms.tolist() == [0, 0, 0, 1, 1, 1, 2, -1]
    labels = source.cell_labels(layout.scene.grid)
    assert labels.names == ROOMS
    grid = layout.scene.grid

    def at(x, y):
        r, c = grid.cell_of(x, y)
        return labels.labels[r, c]

    assert at(2.0, 2.0) == 0 and at(2.3, 2.2) == 0    # bedroom under the bedroom frames
    assert at(6.0, 2.0) == 1 and at(5.7, 1.8) == 1    # kitchen
    assert at(6.0, 3.3) == 2                          # bathroom where only that frame looked
    assert at(2.0, 3.3) == -1 and at(3.5, 0.5) == -1  # the zero feature and unseen floor: no label
    observed = labels.labels >= 0
    # every observed cell lies under some frame's 0.96 x 0.72 m footprint
    rows, cols = np.nonzero(observed)
    xs, ys = grid.origin[0] + (cols + 0.5) * grid.cell_size, grid.origin[1] + (rows + 0.5) * grid.cell_size
    under = np.zeros(len(xs), bool)
    for x, y, f in views:
        if f.any():
            under |= (np.abs(xs - x) <= 0.5) & (np.abs(ys - y) <= 0.4)
    assert under.all()


def test_rooms_command_with_clip_labels(tmp_path, room_vectors, capsys):
    layout = grid_layout(2, 1, labels=("bedroom", "kitchen"))
    save_map(layout.scene, tmp_path / "grid.iesm")
    rng = np.random.default_rng(2)
    views = [(x, y, feature(room_vectors[0 if x < 4 else 1], rng)) for x in (1.0, 2.0, 3.0, 5.0, 6.0, 7.0)
             for y in (1.0, 2.0, 3.0)]
    frames = tmp_path / "frames"
    write_frames(frames, views, room_vectors)
    out = tmp_path / "rooms.iesm"
    assert run(["rooms", str(tmp_path / "grid.iesm"), "--frames", str(frames), "--room-labels", "clip",
                "-o", str(out)]) == 0
    assert "2 rooms" in capsys.readouterr().out
    scene = load_map(out)
    assert sorted(r.label for r in scene.rooms) == ["bedroom", "kitchen"]
    west = next(r for r in scene.rooms if r.label == "bedroom")
    assert scene.room_map[layout.scene.grid.cell_of(2.0, 2.0)] == west.id
    assert next(i for i in scene.instances if i.label == "refrigerator").room_label == "kitchen"


def one_error_line(capsys) -> str:
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("iesm: error: "), err
    return err[0]


def test_missing_or_bad_clip_files_are_one_line(tmp_path, room_vectors, capsys):
    layout = grid_layout(2, 1, labels=("bedroom", "kitchen"))
    save_map(layout.scene, tmp_path / "grid.iesm")
    frames, out = tmp_path / "frames", tmp_path / "out.iesm"
    write_frames(frames, [(2.0, 2.0, room_vectors[0])], room_vectors)
    args = ["rooms", str(tmp_path / "grid.iesm"), "--frames", str(frames), "--room-labels", "clip", "-o", str(out)]

    (frames / "frame_features.npz").unlink()
    assert run(args) == 2
    assert "needs frame_features.npz written by `iesm segment --segmenter sam-clip`" in one_error_line(capsys)
    write_frame_features(frames, room_vectors[:1])
    (frames / "vocabulary.npz").unlink()
    assert run(args) == 2
    assert "needs vocabulary.npz" in one_error_line(capsys)
    write_vocabulary(frames, ["chair"], room_vectors[:1])  # no rooms
    assert run(args) == 2
    assert "no room_names" in one_error_line(capsys)
    write_vocabulary(frames, ["chair"], room_vectors[:1], ROOMS, room_vectors[:, :8])  # another space
    assert run(args) == 2
    assert "room_embeddings have shape (3, 8)" in one_error_line(capsys)
    write_frame_features(frames, np.zeros((2, 16), np.float32))  # 2 features, 1 frame
    assert run(args) == 2
    assert "the set has 1 frames" in one_error_line(capsys)
    assert run(["rooms", str(tmp_path / "grid.iesm"), "--frames", str(tmp_path / "nowhere"), "--room-labels",
                "clip", "-o", str(out)]) == 2
    assert "not a frame directory" in one_error_line(capsys)
    assert run(args[:-4] + ["--room-labels", "vlm", "-o", str(out)]) == 2
    assert "expected sim or clip" in one_error_line(capsys)
    assert run(["rooms", str(tmp_path / "grid.iesm"), "--cell-labels", str(frames / "x.npz"), "--room-labels", "clip",
                "-o", str(out)]) == 2
    assert "give --frames DIR" in one_error_line(capsys)
    assert not out.exists()


@pytest.mark.slow
def test_random_weight_sam_clip_output_labels_cells(tmp_path):
    from test_segment_samclip import DATA, _libraries, _spec

    _libraries()
    if not (DATA / "7scenes").is_dir():
        pytest.skip("real frames missing")
    from iesm_agent.frames import FrameSet, open_recording
    from iesm_agent.frames.convert import import_recording
    from iesm_agent.mapping.build import build_map
    from iesm_agent.segment.run import segment_frame_set

    rec = open_recording(DATA / "7scenes")
    rec.refs = rec.refs[:2]
    directory = tmp_path / "f"
    import_recording(rec, directory, scene_id="t", embedding_space="none", categories=[])
    segment_frame_set(FrameSet.open(directory), directory / "frames", spec=_spec(tmp_path),
                      categories=["chair", "table"], rooms=["kitchen", "office"])
    source = ClipFrameLabels(directory)
    assert source.names == ["kitchen", "office"] and source.scores.shape == (2, 2)
    assert np.isin(source.frame_rooms, [0, 1]).all()
    grid = build_map(FrameSet.open(directory)).grid
    labels = source.cell_labels(grid)
    observed = labels.labels[labels.labels >= 0]
    assert observed.size > 100 and set(np.unique(observed)) <= set(source.frame_rooms.tolist())
