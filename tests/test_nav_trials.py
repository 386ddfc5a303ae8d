"""N-SR trials: the simulated agent against ground truth that differs from the built map, and
`iesm eval` on a suite with start positions over a map whose frame directory holds ground truth."""

from __future__ import annotations

import json

import numpy as np
import pytest

from iesm_agent.cli import run
from iesm_agent.evals.navigation import NavTrials
from iesm_agent.nav.obstacles import obstacle_map
from iesm_agent.sim.ground_truth import GroundTruth
from iesm_agent.sim.layouts import grid_layout
from iesm_agent.store import save_map
from iesm_agent.store.model import InstanceGrid


def ground_truth(scene, extra_block=None) -> GroundTruth:
    """Ground truth equal to `scene`, optionally with a block (rows, cols slices) the map lacks."""
    occupancy = obstacle_map(scene)
    cells = scene.occupancy
    if extra_block is not None:
        occupancy = occupancy.copy()
        occupancy[extra_block] = True
        flat = np.flatnonzero(_mask(occupancy.shape, extra_block))
        old_flat, old_ids, _ = cells.entries()
        cells = InstanceGrid.from_entries(np.concatenate([old_flat, flat]),
                                          np.concatenate([old_ids, np.full(len(flat), 999)]))
    objects = [{"id": i.id, "label": i.label, "center": list(i.centroid), "size": [0.1, 0.1, 0.1]}
               for i in scene.instances]
    return GroundTruth(scene.scene_id, objects, [], scene.grid, np.full(occupancy.shape, -1, np.int32),
                       occupancy, cells)


def _mask(shape, block):
    mask = np.zeros(shape, bool)
    mask[block] = True
    return mask


def fridge(scene) -> int:
    return next(i.id for i in scene.instances if i.label == "refrigerator")


def test_trial_succeeds_when_the_map_is_right():
    scene = grid_layout(2, 1, labels=("bedroom", "kitchen")).scene
    trials = NavTrials.for_map(scene, ground_truth(scene))
    assert trials.to_gt[fridge(scene)] == fridge(scene)          # top-down IoU matching: same masks
    outcome = trials.run(fridge(scene), (1.0, 0.5))
    assert outcome.success and not outcome.collided and outcome.distance_m <= 0.3


def test_an_obstacle_the_map_missed_makes_the_trial_fail():
    scene = grid_layout(2, 1, labels=("bedroom", "kitchen")).scene
    door_block = (slice(25, 56), slice(74, 88))                   # fills the door gap (rows 31-48, cols 80-81)
    outcome = NavTrials.for_map(scene, ground_truth(scene, door_block)).run(fridge(scene), (1.0, 0.5))
    assert outcome.collided and outcome.success is False and outcome.distance_m > 1.0


def test_unmatched_instance_cannot_be_judged():
    scene = grid_layout(2, 1, labels=("bedroom", "kitchen")).scene
    outcome = NavTrials(scene, ground_truth(scene), to_gt={}).run(fridge(scene), (1.0, 0.5))
    assert outcome.success is None and outcome.status == "no_ground_truth"


@pytest.mark.slow
def test_iesm_eval_reports_nsr(tmp_path, monkeypatch, capsys):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    scene = grid_layout(2, 1, labels=("bedroom", "kitchen")).scene
    frames = tmp_path / "frames"
    ground_truth(scene).save(frames)
    save_map(scene, tmp_path / "grid.iesm")
    bed = next(i.id for i in scene.instances if i.label == "bed")
    lines = [{"id": "q1", "map": "grid.iesm", "query": "the refrigerator", "type": "o", "target": fridge(scene),
              "start": [1.0, 0.5]},
             {"id": "q2", "map": "grid.iesm", "query": "the bed", "type": "o", "target": bed, "start": [1.5, 1.5]},
             {"id": "q3", "map": "grid.iesm", "query": "the bed", "type": "o", "target": bed}]
    suite = tmp_path / "suite.jsonl"
    suite.write_text("".join(json.dumps(line) + "\n" for line in lines))
    assert run(["eval", str(suite), "-o", str(tmp_path / "no-gt")]) == 0   # no ground truth: no N-SR
    assert all(json.loads(line).get("nav_success") is None for line in (tmp_path / "no-gt" / "results.jsonl").open())
    assert run(["eval", str(suite), "--gt", str(frames), "-o", str(tmp_path / "run")]) == 0
    records = {json.loads(line)["id"]: json.loads(line) for line in (tmp_path / "run" / "results.jsonl").open()}
    assert all(r["correct"] for r in records.values())
    assert records["q1"]["nav_success"] is True and records["q1"]["path_length_m"] > 4
    assert records["q2"]["nav_success"] is False                  # starts inside the bed
    assert records["q3"]["nav_success"] is None                   # no start
    summary = json.loads((tmp_path / "run" / "summary.json").read_text())
    assert summary["methods"]["mtefr"]["overall"]["nsr"] == pytest.approx(0.5)
    assert "N-SR" in (tmp_path / "run" / "report.md").read_text()
