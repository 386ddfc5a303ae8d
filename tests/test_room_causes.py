"""Causes of room cells lost against the per-cell baseline, on tiny hand-made maps."""

from __future__ import annotations

import numpy as np

from iesm_agent.evals.room_causes import lost_cells

NAMES = ["bathroom", "bedroom", "hallway", "kitchen"]
K, B, H, BA = NAMES.index("kitchen"), NAMES.index("bedroom"), NAMES.index("hallway"), NAMES.index("bathroom")


def _rows(gt, gt_types, pred, pred_types, plain, cells, walls=None, lines=None):
    gt, pred, plain, cells = (np.array([row]) for row in (gt, pred, plain, cells))
    walls = np.zeros(gt.shape, bool) if walls is None else np.array([walls])
    lines = np.zeros(gt.shape, bool) if lines is None else np.array([lines])
    return lost_cells(gt, gt_types, pred, pred_types, plain, cells, NAMES, np.ones(gt.shape, bool), walls, lines)


def test_cells_without_a_room_and_cells_put_with_a_neighbour():
    gt = [0, 0, 0, 0, 1, 1, 1, 1]
    cells = [K, K, K, K, B, B, B, B]  # the per-cell labels are right everywhere
    pred = [-1, 0, 0, 0, 0, 1, 1, -1]
    walls = [True] + [False] * 7
    lines = [False] * 7 + [True]
    # without the split, cell 4 was in the bedroom's room: the split's cut moved it
    rows = _rows(gt, ["kitchen", "bedroom"], pred, ["kitchen", "bedroom"], [0, 0, 0, 0, 1, 1, 1, 1], cells, walls,
                 lines)
    assert [r["causes"] for r in rows] == [{"no room: wall": 1}, {"split cut misplaced": 1, "no room: line": 1}]
    assert [(r["lost"], r["won"], r["baseline_right"], r["ours_right"]) for r in rows] == [(1, 0, 4, 3), (2, 0, 4, 2)]
    # already with the kitchen without the split: a line (or the growth) put it there
    rows = _rows(gt, ["kitchen", "bedroom"], pred, ["kitchen", "bedroom"], [0, 0, 0, 0, 0, 1, 1, 1], cells, walls,
                 lines)
    assert rows[1]["causes"] == {"line misplaced": 1, "no room: line": 1}
    # free space no room reached: a pocket
    assert _rows(gt, ["kitchen", "bedroom"], pred, ["kitchen", "bedroom"], gt, cells)[0]["causes"] == {
        "no room: pocket": 1}


def test_a_room_swallowed_by_its_neighbour():
    gt, cells = [0, 0, 0, 1, 1], [K, K, K, H, H]
    one_room = [0, 0, 0, 0, 0]
    rows = _rows(gt, ["kitchen", "hallway"], one_room, ["kitchen"], one_room, cells)
    assert rows[1]["causes"] == {"swallowed, no line": 2} and rows[0]["lost"] == 0
    rows = _rows(gt, ["kitchen", "hallway"], one_room, ["kitchen"], gt, cells)  # it had a room without the split
    assert rows[1]["causes"] == {"swallowed by split": 2}


def test_a_room_named_by_its_neighbour_or_wrongly():
    gt = [0, 0, 1, 1, 2, 2, 2]
    cells = [K, B, B, B, BA, H, H]
    rows = _rows(gt, ["kitchen", "bedroom", "bathroom"], gt, ["kitchen", "kitchen", "hallway"], gt, cells)
    # the kitchen is named right where its per-cell label was not (won)
    assert (rows[0]["lost"], rows[0]["won"]) == (0, 1)
    # the bedroom named as the kitchen it touches, though its own per-cell labels said bedroom
    assert rows[1]["causes"] == {"named by neighbour (objects)": 2}
    # the bathroom named hallway (no room touching it is one), as most of its per-cell labels said
    assert rows[2]["causes"] == {"wrong label": 1}
