"""Stacked objects object by object, ours beside the 2D baseline (evals/stacked.py), on a hand-made
table holding a cup, a vase and a book."""

from types import SimpleNamespace

import numpy as np

from iesm_agent.config import MappingConfig
from iesm_agent.evals.mapping import EvalContext, Prediction
from iesm_agent.evals.mapping_causes import unmatched_causes
from iesm_agent.evals.stacked import outcome_counts, stacked_outcomes, supports
from iesm_agent.store.model import InstanceGrid

CATEGORIES = ["table", "cup", "vase", "book"]


def _entries(masks: dict[int, tuple[list[int], float]]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(flat cell, id, top) entries of {id: (cells, top height m)}."""
    flat = np.concatenate([np.array(c, np.int64) for c, _t in masks.values()])
    ids = np.concatenate([np.full(len(c), i, np.int64) for i, (c, _t) in masks.items()])
    top = np.concatenate([np.full(len(c), t, np.float32) for c, t in masks.values()])
    return flat, ids, top


def _scene():
    """A table (1, cells 0-19, top 0.75 m) holding a cup (2), a vase (3) and a book (4); a wall (5)
    apart. Ours: the table and the cup matched (the cup's cells at the table's height), the vase in
    an own instance twice its size (IoU 0.5, not above it), the book never segmented. The baseline
    (ground-truth masks): the cup called table, the vase right, the book without a 2D cell."""
    boxes = _entries({1: (list(range(0, 20)), 0.75), 2: ([4, 5, 6, 7], 0.85), 3: ([12, 13, 14, 15], 1.0),
                      4: ([16, 17], 0.8), 5: (list(range(40, 50)), 2.5)})
    gt = SimpleNamespace(cells=InstanceGrid.from_entries(*boxes),
                         objects=[{"id": i, "label": lab} for i, lab in
                                  [(1, "table"), (2, "cup"), (3, "vase"), (4, "book"), (5, "wall")]])
    observed = _entries({1: (list(range(0, 20)), 0.75), 2: ([4, 5, 6, 7], 0.85), 3: ([12, 13, 14, 15], 1.0),
                         4: ([16, 17], 0.8)})
    gt_ids = np.array([1, 2, 3, 4])
    ctx = EvalContext(gt, CATEGORIES, np.eye(4), gt_ids, {1: 0, 2: 1, 3: 2, 4: 3}, observed, np.zeros(0), set(),
                      set(), {2, 3, 4}, MappingConfig())
    ours = Prediction(np.array([11, 12, 13]), np.array([[0, 1, 2, 3], [1, 0, 2, 3], [2, 0, 1, 3]]),
                      _entries({11: (list(range(0, 20)), 0.75), 12: ([4, 5, 6, 7], 0.77),
                                13: (list(range(10, 18)), 0.98)}))
    baseline = Prediction(gt_ids.copy(), np.array([[0, 1, 2, 3], [0, 1, 2, 3], [2, 0, 1, 3], [-1, -1, -1, -1]]),
                          observed, matches={i: i for i in range(1, 5)})
    shows = {(0, 0): 1, (0, 1): 2, (0, 2): 3, (1, 2): 3}
    obs = np.array([[11, 0, 0], [12, 0, 1], [13, 0, 2], [13, 1, 2]], np.float64)
    return ctx, ours, baseline, obs, shows


def test_each_stacked_object_gets_our_outcome_beside_the_baselines():
    ctx, ours, baseline, obs, shows = _scene()
    causes = unmatched_causes(ours.cells[:2], ctx.gt_cells[:2], ctx.gt_ids, {1, 2}, obs, shows)
    records = {r["object"]: r for r in stacked_outcomes(ctx, ours, baseline, obs, shows, causes)}
    assert sorted(records) == [2, 3, 4]
    cup, vase, book = records[2], records[3], records[4]
    assert (cup["ours"], cup["baseline"], cup["support"]) == ("named right", "named wrong", "table")
    assert cup["baseline_label"] == "table" and cup["baseline_label_support"] and not cup["our_label_support"]
    # the cup's instance holds its cells at 0.77 m: the table's height band (0.75), not the cup's (0.85)
    assert cup["band_off"] and cup["instance_top"] == np.float32(0.77)
    assert (vase["ours"], vase["our_label"], vase["iou"], vase["baseline"]) == ("inflated", "vase", 0.5, "named right")
    assert not vase["band_off"]
    assert (book["ours"], book["our_label"], book["baseline"]) == ("never segmented", None, "no reading")
    counts = outcome_counts(list(records.values()))
    assert counts["named right"] == {"named wrong": 1} and counts["inflated"] == {"named right": 1}
    assert counts["never segmented"] == {"no reading": 1} and not counts["swallowed"]


def test_the_support_is_the_object_under_most_of_the_footprint():
    ctx, *_rest = _scene()
    assert supports(ctx) == {2: 1, 3: 1, 4: 1}      # the wall (5) is not stacked and holds nothing
