"""Real RGB-D recordings (../shared/data/real_rgbd): layout readers, checks, gravity alignment,
`iesm segment` + `iesm build-map` with the geometric segmenter, and bad input refused with one
line and exit 2 (nothing written). Skipped when the data folder is missing."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest

from iesm_agent.cli import run
from iesm_agent.frames import FrameSet, detect_layout, open_recording
from iesm_agent.frames.layouts import quaternion_pose

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "real_rgbd"
pytestmark = pytest.mark.skipif(not (DATA / "7scenes").is_dir(), reason="real RGB-D frames not in ../shared")
pytest.importorskip("skimage")


def seven_subset(tmp_path: Path, frames=(0, 300, 600)) -> Path:
    """A 7-Scenes folder with a few of the real frames."""
    out = tmp_path / "seven"
    out.mkdir()
    shutil.copy(DATA / "7scenes" / "camera-intrinsics.txt", out)
    for i in frames:
        for kind in ("color.jpg", "depth.png", "pose.txt"):
            shutil.copy(DATA / "7scenes" / f"frame-{i:06d}.{kind}", out)
    return out


def test_layouts_are_detected():
    assert detect_layout(DATA / "7scenes") == "7scenes"
    assert detect_layout(DATA / "3dmatch") == "7scenes"
    assert detect_layout(DATA / "replica" / "office0") == "replica"


def test_replica_reader_uses_its_scale_intrinsics_and_poses():
    rec = open_recording(DATA / "replica" / "office0")
    assert (rec.intrinsics.width, rec.intrinsics.fx, rec.depth_scale) == (1200, 600.0, 6553.5)
    frame = rec.read(0)
    valid = frame.depth[frame.depth > 0]
    assert 0.5 < np.median(valid) < 5.0                      # metres, not raw units
    traj = np.loadtxt(DATA / "replica" / "office0" / "traj.txt")
    assert np.allclose(frame.pose, traj[0].reshape(4, 4), atol=1e-6)


def test_segment_and_build_map_on_real_frames(tmp_path, capsys):
    src = seven_subset(tmp_path)
    out = tmp_path / "frames"
    assert run(["segment", str(src), "-o", str(out), "--segmenter", "geometric"]) == 0
    said = capsys.readouterr().out
    assert "gravity: up from" in said and "floor plane from depth" in said
    frames = FrameSet.open(out)
    assert len(frames) == 3 and frames.meta.embedding_space == "lab-hist-64"
    assert frames.meta.source["layout"] == "7scenes"
    seg = frames.read(0).segmentation
    assert seg is not None and len(seg.scores) >= 5 and seg.masks.shape[1:] == (480, 640)
    assert np.allclose(np.linalg.norm(seg.embeddings, axis=1), 1, atol=1e-5)
    # gravity: cameras stand upright (camera y axis points down) about 1.4 m above the floor
    for i in range(3):
        pose = frames.read(i).pose
        assert pose[2, 1] < -0.7 and 0.9 < pose[2, 3] < 2.0
    assert run(["build-map", str(out), "-o", str(tmp_path / "m.iesm")]) == 0
    from iesm_agent.store import load_map

    scene = load_map(tmp_path / "m.iesm")
    assert len(scene.instances) >= 5 and {i.label for i in scene.instances} == {"object"}
    tops = scene.occupancy.top[np.isfinite(scene.occupancy.top)]
    assert np.percentile(tops, 1) > -0.3 and tops.max() < 3.0  # floor at 0, nothing at 3.3 m


def _fails(argv, capsys, needle: str) -> None:
    assert run(argv) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("iesm: error:") and needle in err[0], err


def test_missing_depth_file(tmp_path, capsys):
    src = seven_subset(tmp_path)
    (src / "frame-000300.depth.png").unlink()
    out = tmp_path / "out"
    _fails(["segment", str(src), "-o", str(out)], capsys, "frame-000300.depth.png: file is missing")
    assert not out.exists() and not list(tmp_path.glob(".out.iesm-tmp*"))
    assert run(["segment", str(src), "-o", str(out), "--skip-bad-frames"]) == 0
    assert len(FrameSet.open(out)) == 2
    assert "1 frames skipped (1 missing file)" in capsys.readouterr().out


def test_depth_in_the_wrong_unit(tmp_path, capsys):
    import cv2

    src = seven_subset(tmp_path)
    for p in src.glob("*.depth.png"):  # metres written as integers: 0..4
        d = cv2.imread(str(p), cv2.IMREAD_UNCHANGED)
        cv2.imwrite(str(p), np.rint(d / 1000.0).astype(np.uint16))
    _fails(["segment", str(src), "-o", str(tmp_path / "out")], capsys, "wrong unit")
    assert not (tmp_path / "out").exists()


def test_nan_pose(tmp_path, capsys):
    src = seven_subset(tmp_path)
    (src / "frame-000600.pose.txt").write_text("nan 0 0 0\n0 1 0 0\n0 0 1 0\n0 0 0 1\n")
    _fails(["segment", str(src), "-o", str(tmp_path / "out")], capsys, "NaN")
    assert not (tmp_path / "out").exists()


def test_empty_directory(tmp_path, capsys):
    (tmp_path / "empty").mkdir()
    _fails(["segment", str(tmp_path / "empty"), "-o", str(tmp_path / "out")], capsys, "no frames found")
    _fails(["build-map", str(tmp_path / "empty"), "-o", str(tmp_path / "m.iesm")], capsys, "")
    assert not (tmp_path / "m.iesm").exists()


def test_scannet_inf_poses_are_skipped_and_counted(tmp_path, capsys):
    src = tmp_path / "scan"
    for d in ("color", "depth", "pose", "intrinsic"):
        (src / d).mkdir(parents=True)
    k = np.eye(4)
    k[0, 0] = k[1, 1] = 585.0
    k[0, 2], k[1, 2] = 320.0, 240.0
    np.savetxt(src / "intrinsic" / "intrinsic_depth.txt", k)
    for n, i in enumerate((0, 300, 600)):
        shutil.copy(DATA / "7scenes" / f"frame-{i:06d}.color.jpg", src / "color" / f"{n}.jpg")
        shutil.copy(DATA / "7scenes" / f"frame-{i:06d}.depth.png", src / "depth" / f"{n}.png")
        pose = np.loadtxt(DATA / "7scenes" / f"frame-{i:06d}.pose.txt")
        np.savetxt(src / "pose" / f"{n}.txt", np.full((4, 4), -np.inf) if n == 1 else pose)
    assert detect_layout(src) == "scannet"
    assert run(["segment", str(src), "-o", str(tmp_path / "out")]) == 0
    assert "1 frames skipped (1 invalid pose (-inf: tracking lost))" in capsys.readouterr().out
    assert len(FrameSet.open(tmp_path / "out")) == 2


def test_tum_association_and_quaternions(tmp_path):
    import cv2

    src = tmp_path / "rgbd_dataset_freiburg1_desk"
    (src / "rgb").mkdir(parents=True)
    (src / "depth").mkdir()
    rgb_lines, depth_lines, gt_lines = [], [], []
    for n, i in enumerate((0, 300, 600)):
        t = 100.0 + n
        shutil.copy(DATA / "7scenes" / f"frame-{i:06d}.color.jpg", src / "rgb" / f"{t:.6f}.png")
        d = cv2.imread(str(DATA / "7scenes" / f"frame-{i:06d}.depth.png"), cv2.IMREAD_UNCHANGED)
        cv2.imwrite(str(src / "depth" / f"{t + 0.01:.6f}.png"), (d.astype(np.uint32) * 5).clip(0, 65535).astype(np.uint16))
        rgb_lines.append(f"{t:.6f} rgb/{t:.6f}.png")
        depth_lines.append(f"{t + 0.01:.6f} depth/{t + 0.01:.6f}.png")
        gt_lines.append(f"{t + 0.005:.4f} 1 2 3 0 0 {np.sin(0.25):.8f} {np.cos(0.25):.8f}")
    (src / "rgb.txt").write_text("# comment\n" + "\n".join(rgb_lines) + "\n")
    (src / "depth.txt").write_text("\n".join(depth_lines) + "\n")
    (src / "groundtruth.txt").write_text("\n".join(gt_lines) + "\n")
    rec = open_recording(src)
    assert rec.layout == "tum" and len(rec) == 3 and rec.intrinsics.fx == 517.3 and rec.depth_scale == 5000.0
    frame = rec.read(1)
    assert np.allclose(frame.pose[:3, 3], [1, 2, 3])
    assert np.allclose(frame.pose[:3, :3], quaternion_pose(["0"] * 3 + ["0", "0", str(np.sin(0.25)),
                                                                        str(np.cos(0.25))])[:3, :3])
    assert np.isclose(frame.pose[0, 0], np.cos(0.5))          # a 0.5 rad turn about z
    assert 0.5 < np.median(frame.depth[frame.depth > 0]) < 5
