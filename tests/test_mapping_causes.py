"""Causes of unmatched seen objects (evals/mapping_causes.py) on hand-made top-down masks."""

import numpy as np

from iesm_agent.evals.mapping_causes import cause_counts, unmatched_causes


def _entries(masks: dict[int, list[int]]) -> tuple[np.ndarray, np.ndarray]:
    flat = np.concatenate([np.array(c, np.int64) for c in masks.values()])
    ids = np.concatenate([np.full(len(c), i, np.int64) for i, c in masks.items()])
    return flat, ids


def test_each_cause_is_told_apart():
    gt = _entries({1: list(range(0, 10)), 2: list(range(20, 30)), 3: list(range(40, 50)),
                   4: list(range(60, 70)), 5: list(range(80, 90)), 6: list(range(100, 110)),
                   7: list(range(120, 130))})
    pred = _entries({
        11: list(range(0, 10)),                              # matches object 1
        12: list(range(20, 30)) + list(range(30, 50)),       # object 2 swallows ... object 3
        14: list(range(60, 68)) + list(range(140, 160)),     # object 4, inflated (IoU 8/30)
        15: list(range(80, 84)), 16: list(range(84, 88)),     # object 5 in two pieces
        17: list(range(100, 102)),                           # object 6: a sliver
    })
    causes = unmatched_causes(pred, gt, np.arange(1, 8), matched={1, 2}, segmented={1, 2, 3, 4, 5, 6})
    assert causes == {3: "swallowed", 4: "inflated", 5: "split", 6: "partial", 7: "never segmented"}
    counts = cause_counts(causes)
    assert counts == {"never segmented": 1, "swallowed": 1, "inflated": 1, "split": 1, "partial": 1}


def test_an_object_the_segmenter_saw_but_the_map_lacks_is_partial():
    gt = _entries({1: [0, 1, 2]})
    pred = _entries({9: [50]})
    assert unmatched_causes(pred, gt, np.array([1]), matched=set(), segmented={1}) == {1: "partial"}
