"""`iesm sim` end to end: the frame directory and ground truth it writes, its summary, refusing a
non-empty directory, --force, and bad options as one-line errors."""

from __future__ import annotations

import json

import numpy as np
import pytest

from iesm_agent.cli import run
from iesm_agent.frames import FrameSet
from iesm_agent.sim.ground_truth import GroundTruth
from iesm_agent.sim.catalog import COLORS


@pytest.fixture(scope="module")
def sim_dir(tmp_path_factory):
    with pytest.MonkeyPatch.context() as mp:
        mp.setenv("IESM_EMBEDDINGS", "0")  # the hash space: no model load in this test
        parent = tmp_path_factory.mktemp("sim")
        out = parent / "flat"
        assert run(["sim", "--seed", "1", "--out", str(out), "--open-plan", "--realism", "easy"]) == 0
        return out


@pytest.mark.slow
def test_sim_writes_a_readable_frame_directory(sim_dir, capsys):
    fs = FrameSet.open(sim_dir)
    assert fs.meta.scene_id == "sim-small-1-open" and fs.meta.embedding_space == "hash-384"
    assert 50 <= len(fs) <= 120 and (fs.intrinsics.width, fs.intrinsics.height) == (320, 240)
    assert {"chair", "wall", "door", "window", "sofa"} <= set(fs.meta.categories)
    frame = fs.read(5)
    assert frame.segmentation is not None and frame.instance_ids is not None
    assert frame.segmentation.embeddings.shape[1] == 384 and len(frame.segmentation.masks) >= 1
    assert 0 < frame.depth.max() <= 10.0
    gt = GroundTruth.load(sim_dir)
    ids = {o["id"] for o in gt.objects}
    assert set(np.unique(gt.cells.ids).tolist()) == ids
    assert set(np.unique(gt.rooms).tolist()) - {-1} == {r["id"] for r in gt.rooms_list}
    assert gt.occupancy.any() and gt.rooms.shape == gt.occupancy.shape == (gt.grid.height, gt.grid.width)
    for obj in gt.objects:
        assert tuple(obj["color_rgb"]) == COLORS[obj["tags"]["color"]]
        assert obj["structural"] == (obj["label"] in ("wall", "door", "window"))
    assert any(o["on"] is not None for o in gt.objects) and gt.cells.multi_occupancy_cells > 0
    seen = set()
    for f in fs:
        seen |= set(np.unique(f.instance_ids).tolist())
    non_structural = {o["id"] for o in gt.objects if not o["structural"]}
    assert len(seen & non_structural) >= 0.8 * len(non_structural)  # the trajectory sees most things
    assert not [p for p in sim_dir.parent.iterdir() if p.name.startswith(".")]  # no temp dir left


@pytest.mark.slow
def test_sim_refuses_a_non_empty_directory_and_force_replaces(sim_dir, capsys, monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    before = json.loads((sim_dir / "scene.json").read_text())
    assert run(["sim", "--seed", "2", "--out", str(sim_dir)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.startswith("iesm: error:") and "not empty" in err and str(sim_dir) in err and "\n" not in err
    assert json.loads((sim_dir / "scene.json").read_text()) == before
    assert run(["sim", "--seed", "2", "--out", str(sim_dir), "--force", "--realism", "easy"]) == 0
    out = capsys.readouterr().out
    assert "sim-small-2" in out and "rooms" in out and "frames" in out and "stacked" in out and str(sim_dir) in out
    assert json.loads((sim_dir / "scene.json").read_text())["scene_id"] == "sim-small-2"


def test_bad_options_are_one_line_errors(tmp_path, capsys):
    assert run(["sim", "--out", str(tmp_path / "x"), "--size", "mansion"]) == 2
    assert "mansion" in capsys.readouterr().err
    assert run(["sim", "--out", str(tmp_path / "missing" / "x")]) == 2
    assert "parent directory" in capsys.readouterr().err
    faults = tmp_path / "faults.json"
    faults.write_text('{"miss_rate": 2}')
    assert run(["sim", "--out", str(tmp_path / "y"), "--faults", str(faults)]) == 2
    err = capsys.readouterr().err
    assert "faults.json" in err and "miss_rate" in err
    assert not (tmp_path / "x").exists() and not (tmp_path / "y").exists()
