"""`iesm build-map` / `iesm eval-map` on a tiny hand-made frame set (a table with a cup on it and
a chair, seen by a downward-looking camera), the `observations` round trip, and bad input."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest

from iesm_agent.cli import run
from iesm_agent.embeddings import text_vectors
from iesm_agent.frames import (Frame, Intrinsics, SceneMeta, Segmentation, write_frame,
                               write_frame_set)
from iesm_agent.sim.ground_truth import GroundTruth
from iesm_agent.store import load_map, save_map
from iesm_agent.store.model import GridSpec, InstanceGrid

CATEGORIES = ["table", "cup", "chair", "sofa", "bed", "lamp"]
# id, label, centre (x, y), size (dx, dy), bottom z, top z
BOXES = [(1, "table", (1.0, 1.0), (1.2, 0.8), 0.0, 0.75),
         (2, "cup", (1.2, 1.1), (0.15, 0.15), 0.75, 0.87),
         (3, "chair", (2.2, 1.0), (0.5, 0.5), 0.0, 0.9)]
CAM_Z = 3.0
# the simulator's camera (sim.camera.default_intrinsics): the cleaning defaults assume its resolution
INTR = Intrinsics(width=320, height=240, fx=160.0, fy=160.0, cx=159.5, cy=119.5)


def _render(cam_xy: tuple[float, float]) -> tuple[np.ndarray, np.ndarray]:
    """Depth (H, W) m and instance ids of a camera at CAM_Z looking straight down (top faces only)."""
    v, u = np.mgrid[0:INTR.height, 0:INTR.width].astype(float)
    depth = np.full(u.shape, CAM_Z, np.float32)
    ids = np.zeros(u.shape, np.int32)
    for iid, _label, (cx, cy), (dx, dy), _z0, top in sorted(BOXES, key=lambda b: b[5]):
        d = CAM_Z - top
        x = cam_xy[0] + (u - INTR.cx) * d / INTR.fx
        y = cam_xy[1] - (v - INTR.cy) * d / INTR.fy
        hit = (np.abs(x - cx) <= dx / 2) & (np.abs(y - cy) <= dy / 2)
        depth[hit], ids[hit] = d, iid
    return depth, ids


def _pose(cam_xy) -> np.ndarray:
    return np.array([[1, 0, 0, cam_xy[0]], [0, -1, 0, cam_xy[1]], [0, 0, -1, CAM_Z], [0, 0, 0, 1]], float)


def write_tiny_world(directory: Path, n_frames: int = 4) -> Path:
    """A frame directory with ground truth: masks from the instance ids, hash-space embeddings."""
    labels = {b[0]: b[1] for b in BOXES}
    emb, space = text_vectors([labels[i] for i in sorted(labels)], "hash-384")
    write_frame_set(directory, SceneMeta(scene_id="tiny", n_frames=n_frames, embedding_space=space,
                                         categories=CATEGORIES), INTR)
    for i in range(n_frames):
        cam = (0.9 + 0.4 * i, 1.0)
        depth, ids = _render(cam)
        present = [iid for iid in sorted(labels) if (ids == iid).sum() > 0]
        seg = Segmentation(masks=np.stack([ids == iid for iid in present]),
                           embeddings=emb[[iid - 1 for iid in present]], scores=np.full(len(present), 0.9, np.float32))
        write_frame(directory, Frame(index=i, rgb=np.zeros((240, 320, 3), np.uint8), depth=depth, pose=_pose(cam),
                                     segmentation=seg, instance_ids=ids))
    grid = GridSpec(cell_size=0.05, origin=(0.0, 0.0), height=50, width=70)
    ys, xs = (np.mgrid[0:grid.height, 0:grid.width] + 0.5) * 0.05
    flat, owner, top = [], [], []
    for iid, _label, (cx, cy), (dx, dy), _z0, z1 in BOXES:
        cells = np.flatnonzero(((np.abs(xs - cx) <= dx / 2) & (np.abs(ys - cy) <= dy / 2)).ravel())
        flat.append(cells), owner.append(np.full(len(cells), iid)), top.append(np.full(len(cells), z1))
    cells = InstanceGrid.from_entries(np.concatenate(flat), np.concatenate(owner), np.concatenate(top))
    objects = [{"id": iid, "label": lab, "center": [cx, cy, (z0 + z1) / 2], "size": [dx, dy, z1 - z0],
                "structural": False, "on": 1 if iid == 2 else None}
               for iid, lab, (cx, cy), (dx, dy), z0, z1 in BOXES]
    room = {"id": 1, "label": "living room", "polygon": [[0, 0], [3.5, 0], [3.5, 2.5], [0, 2.5]]}
    for o in objects:
        o["room"] = 1
    GroundTruth("tiny", objects, [room], grid, np.ones((50, 70), np.int32), np.zeros((50, 70), bool),
                cells).save(directory)
    return directory


@pytest.fixture(scope="module")
def tiny(tmp_path_factory) -> Path:
    return write_tiny_world(tmp_path_factory.mktemp("tiny"))


def test_build_map_keeps_the_cup_on_the_table_and_scores_perfectly(tiny, tmp_path, capsys):
    out = tmp_path / "tiny.iesm"
    assert run(["build-map", str(tiny), "-o", str(out)]) == 0
    scene = load_map(out)
    assert sorted(i.label for i in scene.instances) == ["chair", "cup", "table"]
    assert [i.id for i in scene.instances] == [1, 2, 3]
    cup = next(i for i in scene.instances if i.label == "cup")
    table = next(i for i in scene.instances if i.label == "table")
    assert cup.mean_height == pytest.approx(0.87, abs=0.01) and table.mean_height == pytest.approx(0.75, abs=0.01)
    # multi-occupancy: the table is kept under the cup
    assert scene.occupancy.multi_occupancy_cells > 0
    assert table.weight == 4 and sorted(table.frames) == [0, 1, 2, 3]
    obs = scene.observations
    assert obs.shape[1] == 5 and set(obs[:, 0].astype(int)) == {1, 2, 3}
    capsys.readouterr()
    assert run(["eval-map", str(out), "--gt", str(tiny), "--json"]) == 0
    r = json.loads(capsys.readouterr().out)
    assert (r["n_pred"], r["n_gt"], r["n_matched"], r["instance_diff"]) == (3, 3, 3, 0)
    assert r["auc_top"]["match"] == pytest.approx(1 - 0.5 / len(CATEGORIES))   # every rank 1: f = 1 from k = 1
    assert r["topdown"]["acc"] > 0.85 and r["stacked"]["n_gt"] == 1 and r["stacked"]["top1_gt"] == 1.0
    assert set(r["small"]) >= {"auc_top", "instance_diff", "n_pred", "n_gt"}
    assert run(["eval-map", str(out), "--gt", str(tiny)]) == 0
    assert "AUC^top" in capsys.readouterr().out


def test_no_second_pass_flag(tiny, tmp_path):
    out = tmp_path / "first.iesm"
    assert run(["build-map", str(tiny), "-o", str(out), "--no-second-pass"]) == 0
    assert load_map(out).meta["second_pass"] == "false"


def test_observations_round_trip_and_old_files_still_load(tiny, tmp_path, apartment_path):
    assert run(["build-map", str(tiny), "-o", str(tmp_path / "a.iesm")]) == 0
    scene = load_map(tmp_path / "a.iesm")
    save_map(scene, tmp_path / "b.iesm")
    again = load_map(tmp_path / "b.iesm")
    assert again == scene and np.array_equal(again.observations, scene.observations)
    assert load_map(apartment_path).observations is None
    with pytest.raises(ValueError, match="unknown instance ids"):
        scene.model_validate({**dict(scene), "observations": np.array([[99, 0, 0, 10, 0.5]])})


def _copy(src: Path, dst: Path) -> Path:
    import shutil

    shutil.copytree(src, dst)
    return dst


@pytest.mark.parametrize("damage, culprit", [
    (lambda d: (d / "frames" / "000002.depth.png").unlink(), "000002.depth.png"),
    (lambda d: (d / "frames" / "000001.pose.txt").write_text("1 0 0\n0 1 0\n0 0 1\n"), "000001.pose.txt"),
    (lambda d: (d / "intrinsics.json").write_text(json.dumps({**json.loads((d / "intrinsics.json").read_text()),
                                                              "fx": 0})), "intrinsics.json"),
    (lambda d: np.savez_compressed(d / "frames" / "000003.seg.npz", masks=np.zeros((1, 10, 10), bool),
                                   embeddings=np.zeros((1, 384), np.float32), scores=np.ones(1, np.float32)),
     "000003.seg.npz"),
])
def test_bad_frames_give_one_line_naming_the_file_and_no_map(tiny, tmp_path, capsys, damage, culprit):
    d = _copy(tiny, tmp_path / "frames")
    damage(d)
    out = tmp_path / "bad.iesm"
    capsys.readouterr()
    assert run(["build-map", str(d), "-o", str(out)]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("iesm: error:") and culprit in err[0]
    assert not out.exists() and not list(tmp_path.glob(".bad.iesm*"))


def test_queries_from_ground_truth_run_on_the_built_map(tiny, tmp_path, capsys):
    built = tmp_path / "tiny.iesm"
    assert run(["build-map", str(tiny), "-o", str(built)]) == 0
    suite = tmp_path / "suite.jsonl"
    assert run(["gen-queries", str(built), "--gt", str(tiny), "--types", "o", "-n", "3", "-o", str(suite)]) == 0
    assert "0 dropped" in capsys.readouterr().out
    lines = [json.loads(line) for line in suite.read_text().splitlines()]
    scene = load_map(built)
    by_id = {i.id: i.label for i in scene.instances}
    assert len(lines) == 3
    for q in lines:
        assert q["map"] == "tiny.iesm" and q["target"] in by_id
        assert by_id[q["target"]] in q["query"]                     # gt label == built label here
    assert run(["eval", str(suite), "-o", str(tmp_path / "run")]) == 0
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary["methods"]["mtefr"]["overall"]["osr"] == 1.0


def test_translate_drops_unmatched_targets():
    from iesm_agent.evals.suite import SuiteQuery
    from iesm_agent.evals.gt_queries import translate

    qs = [SuiteQuery(id="a", map="gt.json", query="find the cup", type="o", target=2, accept=[2, 5]),
          SuiteQuery(id="b", map="gt.json", query="find the bed", type="o", target=9, accept=[9])]
    kept, counts = translate(qs, {2: [11], 3: [12]}, "built.iesm")
    assert counts == (1, 0, 1) and len(kept) == 1
    assert (kept[0].target, kept[0].accept, kept[0].map) == (11, [11], "built.iesm")
    # a target held only by its own instances (no IoU pair): kept, every piece accepted, counted apart
    kept, counts = translate(qs, {2: [11], 5: [14, 13], 9: [20, 21]}, "built.iesm", matched={2, 5})
    assert counts == (1, 1, 0)
    assert [(q.target, q.accept) for q in kept] == [(11, [11, 13, 14]), (20, [20, 21])]


def test_a_segmenter_replaces_missing_seg_files(tiny, tmp_path):
    from iesm_agent.frames import FrameSet
    from iesm_agent.mapping.build import build_map
    from iesm_agent.sim import FaultConfig, SyntheticSegmenter

    d = _copy(tiny, tmp_path / "noseg")
    for seg in (d / "frames").glob("*.seg.npz"):
        seg.unlink()
    frames = FrameSet.open(d)
    no_faults = FaultConfig(min_area_px=20, miss_rate=0, split_rate=0, merge_rate=0, erode_rate=0,
                            embedding_noise=0, confusion_rate=0)
    segmenter = SyntheticSegmenter({b[0]: b[1] for b in BOXES}, no_faults, space=frames.meta.embedding_space)
    scene = build_map(frames, segmenter=segmenter)
    assert sorted(i.label for i in scene.instances) == ["chair", "cup", "table"]
    from iesm_agent.errors import IesmError

    with pytest.raises(IesmError, match="seg.npz"):
        build_map(frames)


def test_queries_target_only_objects_the_frames_show(tiny, tmp_path):
    import asyncio
    import shutil

    from iesm_agent.evals.gt_queries import generate_gt_suite
    from iesm_agent.evals.observed import observed_masks
    from iesm_agent.evals.matching import match_instances

    frames = tmp_path / "frames"
    shutil.copytree(tiny, frames)
    gt = GroundTruth.load(frames)
    # a sofa behind the camera's path: in the object list, never in a frame
    gt.objects.append({"id": 4, "label": "sofa", "center": [3.2, 2.2, 0.4], "size": [0.4, 0.4, 0.8],
                       "structural": False, "on": None, "room": 1})
    gt.save(frames)
    built = tmp_path / "tiny.iesm"
    assert run(["build-map", str(frames), "-o", str(built)]) == 0
    scene = load_map(built)
    by_label = {i.label: i.id for i in scene.instances}
    # paired on the observed footprints: the table's cells under the cup are not the table's
    assert match_instances(scene, gt, observed=observed_masks(frames, gt)) == {
        1: by_label["table"], 2: by_label["cup"], 3: by_label["chair"]}
    # a ground truth without frames has no observed footprints: matched on the box footprints
    assert observed_masks(tmp_path, gt) is None and observed_masks(None, gt) is None
    result, counts = asyncio.run(generate_gt_suite(str(built), frames, tmp_path / "s.jsonl", ["o"], per_type=10))
    assert counts.dropped == 0 and counts.own == 0 and result.queries
    assert {q.target for q in result.queries} <= set(by_label.values())
    assert not any("sofa" in q.query for q in result.queries)


def test_an_inflated_instance_still_holds_its_object(tiny, tmp_path):
    """A footprint spread too wide for IoU > 0.5 is still the object's instance for a query: its
    masks show that object; an object whose masks all went into another's instance is not."""
    import shutil

    from iesm_agent.evals.mapping_causes import built_instances
    from iesm_agent.evals.observed import observed_masks

    frames = tmp_path / "frames"
    shutil.copytree(tiny, frames)
    built = tmp_path / "tiny.iesm"
    assert run(["build-map", str(frames), "-o", str(built)]) == 0
    scene = load_map(built)
    gt = GroundTruth.load(frames)
    observed = observed_masks(frames, gt)
    by_label = {i.label: i.id for i in scene.instances}
    cup = by_label["cup"]
    flat, ids, top = scene.occupancy.entries()
    grid = scene.grid
    r, c = np.divmod(flat[ids == cup], grid.width)
    # the cup's footprint grown by 4 cells on every side: IoU with what the frames show falls under 0.5
    rows, cols = np.mgrid[r.min() - 4:r.max() + 5, c.min() - 4:c.max() + 5]
    grown = (rows * grid.width + cols).ravel()
    keep = ids != cup
    occupancy = InstanceGrid.from_entries(np.r_[flat[keep], grown], np.r_[ids[keep], np.full(len(grown), cup)],
                                          np.r_[top[keep], np.full(len(grown), 0.87)])
    inflated = scene.model_copy(update={"occupancy": occupancy})
    instances, matched = built_instances(inflated, gt, frames, observed)
    assert 2 not in matched and instances[2] == [cup]
    assert instances[1] == [by_label["table"]] and 1 in matched
    # a second piece of the cup, holding two of its views: both pieces are the cup, the paired one first
    piece = scene.instance(cup).model_copy(update={"id": 99})
    obs = scene.observations.copy()
    cup_rows = np.flatnonzero(obs[:, 0] == cup)
    obs[cup_rows[:2], 0] = 99
    split = scene.model_copy(update={
        "instances": [*scene.instances, piece], "observations": obs,
        "embeddings": np.vstack([scene.embeddings, scene.embeddings[[scene.instances.index(scene.instance(cup))]]]),
        "occupancy": InstanceGrid.from_entries(np.r_[flat, flat[ids == cup][:1]], np.r_[ids, [99]],
                                               np.r_[top, [0.87]])})
    instances, matched = built_instances(split, gt, frames, observed)
    assert 2 in matched and instances[2] == [cup, 99]
    # the cup's observations moved to the table's instance: the map holds no cup of its own
    obs = inflated.observations.copy()
    obs[obs[:, 0] == cup, 0] = by_label["table"]
    swallowed = inflated.model_copy(update={"observations": obs})
    instances, matched = built_instances(swallowed, gt, frames, observed)
    assert 2 not in instances
