"""Where a room segmentation loses cells against the per-cell baseline, and why.

A lost cell is an evaluated cell (inside a ground-truth room, covered by the per-cell labels; see
evals/rooms.py) whose per-cell label names its true room type while the segmentation's room label
does not; a won cell the reverse. Each lost cell of true room G, in predicted room P, gets one
cause, the first that holds:

  "no room: wall"        the cell is in no predicted room and is a mapped wall cell (farther from
                         the room than the share of the wall it gets);
  "no room: line"        ... is on a drawn boundary line (or its dilation), which rooms do not
                         grow over;
  "no room: pocket"      ... is free space no room reached (a pocket closed off by drawn lines,
                         its free space under the area floor or too little of it observed);
  "swallowed, no line"   G is the best overlap of no predicted room (it has no room of its own) and
                         had none on the map without the split either: no boundary closed it off
                         (a hallway or open kitchen), or its own free space was under the area floor;
  "swallowed by split"   G has no room of its own but had one without the split (the split or its
                         rejoining gave it to a neighbour);
  "wrong label"          P is G's own room (G is its best overlap) but P's label is another type:
                         "named by neighbour" when a ground-truth room touching G has that type,
                         else "wrong label"; either way "(objects)" when P's per-cell labels alone
                         would have named it right (the room-typical object votes turned it);
  "split cut misplaced"  G has its own room elsewhere and P is a neighbour's; without the split the
                         cell and most of G were in one room (the split's cut put them apart);
  "line misplaced"       as above, but already apart without the split (a drawn LSD line, e.g. on a
                         furniture edge, or the growth over the boundary margin, put them apart).
"""

from __future__ import annotations

import numpy as np

#: the causes of a lost cell, in the order they are tested
CAUSES = ("no room: wall", "no room: line", "no room: pocket", "swallowed, no line", "swallowed by split", "named by neighbour",
          "named by neighbour (objects)", "wrong label", "wrong label (objects)", "split cut misplaced",
          "line misplaced")


def _best_overlap(pred: np.ndarray, gt: np.ndarray, n_pred: int, n_gt: int) -> np.ndarray:
    """(n_pred,) the true room (index) holding most cells of each predicted room, -1 for none;
    `pred`, `gt` (M,) indices >= -1."""
    both = (pred >= 0) & (gt >= 0)
    table = np.bincount(pred[both] * n_gt + gt[both], minlength=n_pred * n_gt).reshape(n_pred, n_gt)
    return np.where(table.any(axis=1), table.argmax(axis=1), -1)


def _touching(gt_rooms: np.ndarray, n_gt: int) -> np.ndarray:
    """(n_gt, n_gt) bool: true rooms (indices of (H, W) `gt_rooms`, -1 none) whose cells are within
    two cells of each other (a wall between them counts as touching)."""
    import cv2

    out = np.zeros((n_gt, n_gt), bool)
    kernel = np.ones((5, 5), np.uint8)
    for room in range(n_gt):
        near = cv2.dilate((gt_rooms == room).astype(np.uint8), kernel).astype(bool)
        out[room, np.unique(gt_rooms[near & (gt_rooms >= 0)])] = True
    np.fill_diagonal(out, False)
    return out


def lost_cells(gt_rooms: np.ndarray, gt_types: list[str], pred_rooms: np.ndarray, pred_types: list[str],
               plain_rooms: np.ndarray, cell_types: np.ndarray, cell_names: list[str],
               evaluated: np.ndarray, walls: np.ndarray, lines: np.ndarray) -> list[dict]:
    """Per true room, its cells lost and won against the per-cell baseline, the lost ones by cause.

    All maps (H, W) on the ground-truth grid: `gt_rooms` true room index (0..G-1, -1 none) with
    `gt_types` its type; `pred_rooms` predicted room index (-1 none) with `pred_types`;
    `plain_rooms` the same segmentation without the split (its labels are not used); `cell_types`
    index into `cell_names` of each cell's per-cell label (-1 none); `evaluated` bool, the cells
    scored; `walls` and `lines` bool, the mapped walls and the drawn boundary raster. Returns one dict per true room: "room", "type", "cells" (evaluated), "baseline_right",
    "ours_right", "lost", "won", "causes" {cause: cells}."""
    n_gt, n_pred, n_plain = len(gt_types), len(pred_types), int(plain_rooms.max(initial=-1)) + 1
    inside = evaluated & (gt_rooms >= 0)
    gt, pred, plain = gt_rooms[inside], pred_rooms[inside], plain_rooms[inside]
    unroomed = np.where(walls[inside], 0, np.where(lines[inside], 1, 2))  # the "no room" cause of each cell
    names = sorted(set(gt_types) | set(pred_types) | set(cell_names))
    index = {name: i for i, name in enumerate(names)}
    gt_class = np.array([index[t] for t in gt_types], np.int64)[gt]
    pred_lut = np.array([index[t] for t in pred_types] + [-1], np.int64)
    pred_class = pred_lut[np.where(pred >= 0, pred, n_pred)]
    cell_lut = np.array([index[t] for t in cell_names] + [-1], np.int64)
    cell_class = cell_lut[np.where(cell_types[inside] >= 0, cell_types[inside], len(cell_names))]

    owner = _best_overlap(pred, gt, n_pred, n_gt)  # predicted room -> its true room
    plain_owner = _best_overlap(plain, gt, n_plain, n_gt)
    has_room = np.isin(np.arange(n_gt), owner)
    had_room = np.isin(np.arange(n_gt), plain_owner)
    touching = _touching(gt_rooms, n_gt)
    # the per-cell labels' majority in each predicted room (what it would be named without objects)
    labelled = (pred >= 0) & (cell_class >= 0)
    votes = np.bincount(pred[labelled] * len(names) + cell_class[labelled],
                        minlength=n_pred * len(names)).reshape(n_pred, len(names))
    plain_majority = np.where(votes.any(axis=1), votes.argmax(axis=1), -1)

    rows = []
    for room in range(n_gt):
        mine = gt == room
        base_right, ours_right = cell_class[mine] == gt_class[mine], pred_class[mine] == gt_class[mine]
        lost = base_right & ~ours_right
        causes = dict.fromkeys(CAUSES, 0)
        if lost.any():
            rooms_here = pred[mine]
            main = np.bincount(np.maximum(rooms_here, 0), weights=rooms_here >= 0, minlength=max(n_pred, 1)).argmax()
            plain_here, unroomed_here = plain[mine], unroomed[mine]
            plain_main = np.bincount(np.maximum(plain_here, 0), weights=plain_here >= 0,
                                     minlength=max(n_plain, 1)).argmax()
            for p, q, u in zip(rooms_here[lost].tolist(), plain_here[lost].tolist(), unroomed_here[lost].tolist()):
                causes[CAUSES[u] if p < 0 else _cause(room, p, q, owner, has_room, had_room, pred_types, gt_types,
                                                      touching, plain_majority, index, int(main),
                                                      int(plain_main))] += 1
        rows.append({"room": room, "type": gt_types[room], "cells": int(mine.sum()),
                     "baseline_right": int(base_right.sum()), "ours_right": int(ours_right.sum()),
                     "lost": int(lost.sum()), "won": int((ours_right & ~base_right).sum()),
                     "causes": {cause: n for cause, n in causes.items() if n}})
    return rows


def _cause(room: int, p: int, q: int, owner: np.ndarray, has_room: np.ndarray, had_room: np.ndarray,
           pred_types: list[str], gt_types: list[str], touching: np.ndarray, plain_majority: np.ndarray,
           index: dict[str, int], main: int, plain_main: int) -> str:
    """The cause of one lost cell of true room `room` in predicted room `p` >= 0 (plain room `q`);
    see the module docstring."""
    if not has_room[room]:
        return "swallowed by split" if had_room[room] else "swallowed, no line"
    if owner[p] == room:
        neighbour = any(gt_types[other] == pred_types[p] for other in np.flatnonzero(touching[room]).tolist())
        objects = plain_majority[p] == index[gt_types[room]]
        return ("named by neighbour" if neighbour else "wrong label") + (" (objects)" if objects else "")
    return "split cut misplaced" if q == plain_main and p != main else "line misplaced"
