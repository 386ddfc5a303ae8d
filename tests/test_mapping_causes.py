"""Causes of unmatched seen objects (evals/mapping_causes.py) on hand-made masks and observations."""

import numpy as np

from iesm_agent.evals.mapping_causes import cause_counts, unmatched_causes


def _entries(masks: dict[int, list[int]]) -> tuple[np.ndarray, np.ndarray]:
    flat = np.concatenate([np.array(c, np.int64) for c in masks.values()])
    ids = np.concatenate([np.full(len(c), i, np.int64) for i, c in masks.items()])
    return flat, ids


def test_each_cause_is_told_apart():
    gt = _entries({1: list(range(0, 10)), 2: list(range(20, 30)), 3: list(range(24, 28)),
                   4: list(range(60, 70)), 5: list(range(80, 90)), 6: list(range(100, 110)),
                   7: list(range(120, 130))})
    pred = _entries({
        11: list(range(0, 10)),                              # matches object 1
        12: list(range(20, 30)),                             # object 2 (a table), holding object 3 (a cup)
        14: list(range(60, 68)) + list(range(140, 160)),     # object 4, inflated (IoU 8/30)
        15: list(range(80, 83)), 16: list(range(86, 89)),     # object 5 in two pieces
        17: list(range(100, 102)),                           # object 6: a sliver
    })
    # (frame, mask) -> object the mask shows; observations: [instance, frame, mask, area, score]
    shows = {(0, 0): 1, (0, 1): 2, (1, 1): 2, (0, 2): 3, (1, 2): 3, (0, 3): 4, (0, 4): 5, (1, 4): 5,
             (0, 5): 6, (1, 7): 7}
    obs = np.array([[11, 0, 0, 1, 1], [12, 0, 1, 1, 1], [12, 1, 1, 1, 1], [12, 0, 2, 1, 1], [12, 1, 2, 1, 1],
                    [14, 0, 3, 1, 1], [15, 0, 4, 1, 1], [16, 1, 4, 1, 1], [17, 0, 5, 1, 1]], np.float64)
    causes = unmatched_causes(pred, gt, np.arange(1, 8), {1, 2}, obs, shows)
    assert causes == {3: "swallowed", 4: "inflated", 5: "split", 6: "partial", 7: "never segmented"}
    assert cause_counts(causes) == {"never segmented": 1, "swallowed": 1, "split": 1, "inflated": 1,
                                    "partial": 1}


def test_an_instance_belongs_to_the_object_most_of_its_masks_show():
    gt = _entries({1: [0, 1, 2, 3], 2: [0, 1]})
    pred = _entries({9: [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]})
    shows = {(0, 0): 1, (1, 0): 1, (2, 0): 2}
    obs = np.array([[9, 0, 0, 1, 1], [9, 1, 0, 1, 1], [9, 2, 0, 1, 1]], np.float64)
    # object 1 owns instance 9 (two masks of three), which is too large: inflated; object 2 swallowed
    assert unmatched_causes(pred, gt, np.array([1, 2]), set(), obs, shows) == {1: "inflated", 2: "swallowed"}


def test_stacked_groups_count_ours_and_the_baselines_names():
    from types import SimpleNamespace

    from iesm_agent.evals.studies.mapping_causes import stacked_groups

    ctx = SimpleNamespace(stacked={3, 4, 5, 6})
    groups = stacked_groups(ctx, right={3: True, 4: False, 9: True}, causes={5: "inflated", 6: "partial"},
                            baseline_right={3: True, 4: True, 5: True, 6: False, 9: True})
    assert groups["named right"] == {"objects": 1, "baseline_right": 1}
    assert groups["named wrong"] == {"objects": 1, "baseline_right": 1}
    assert groups["inflated"] == {"objects": 1, "baseline_right": 1}
    assert groups["partial"] == {"objects": 1, "baseline_right": 0}
    assert sum(g["objects"] for g in groups.values()) == 4        # object 9 is not stacked
