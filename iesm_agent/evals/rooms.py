"""Room-map metrics against ground truth (gt/rooms.npy).

Evaluated cells E: cells inside a ground-truth room (gt id >= 0) that the per-cell labels cover
(`evaluated`: every cell some depth pixel of some frame lands in), so the per-cell baseline and
the segmentations are scored on the same cells and the baseline is not charged for cells it never
saw. A predicted map is first resampled onto the ground-truth grid (nearest cell centre; outside
the predicted grid = no room).

Label level (the paper's Table 3), with c over the room types present in E:
  Acc  = |{x in E: pred_label(x) = gt_label(x)}| / |E|
  mAcc = mean_c |pred = c and gt = c| / |gt = c|
  mIoU = mean_c |pred = c and gt = c| / |(pred = c or gt = c) and E|
Instance level (labels ignored; the per-room measure of ipa_room_segmentation), on cells in E:
  precision = mean over predicted rooms P of max_G |P and G| / |P|
  recall    = mean over ground-truth rooms G of max_P |P and G| / |G|
The per-cell baseline's "rooms" are the 4-connected components of each label in its label map.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..store.model import GridSpec, SceneMap


def resample(layer: np.ndarray, src: GridSpec, dst: GridSpec, fill: int = -1) -> np.ndarray:
    """(dst.H, dst.W) values of `layer` (src grid) at the centres of `dst`'s cells."""
    xs = dst.origin[0] + (np.arange(dst.width) + 0.5) * dst.cell_size
    ys = dst.origin[1] + (np.arange(dst.height) + 0.5) * dst.cell_size
    cols = np.floor((xs - src.origin[0]) / src.cell_size).astype(np.int64)
    rows = np.floor((ys - src.origin[1]) / src.cell_size).astype(np.int64)
    ok = (rows[:, None] >= 0) & (rows[:, None] < src.height) & (cols[None, :] >= 0) & (cols[None, :] < src.width)
    out = np.full((dst.height, dst.width), fill, dtype=layer.dtype)
    rr, cc = np.broadcast_arrays(rows[:, None], cols[None, :])
    out[ok] = layer[rr[ok], cc[ok]]
    return out


def label_metrics(pred: np.ndarray, gt: np.ndarray, n_classes: int) -> dict:
    """Acc, mAcc, mIoU of (M,) predicted class indices (-1 = none) against (M,) true ones (>= 0)."""
    if len(gt) == 0:
        return {"acc": 0.0, "macc": 0.0, "miou": 0.0}
    hit = pred == gt
    tp = np.bincount(gt[hit], minlength=n_classes).astype(float)
    gt_count = np.bincount(gt, minlength=n_classes).astype(float)
    pred_count = np.bincount(pred[pred >= 0], minlength=n_classes).astype(float)
    present = gt_count > 0
    return {"acc": float(hit.mean()),
            "macc": float(np.mean(tp[present] / gt_count[present])),
            "miou": float(np.mean(tp[present] / (gt_count + pred_count - tp)[present]))}


def overlap_metrics(pred_rooms: np.ndarray, gt_rooms: np.ndarray) -> dict:
    """Per-room precision and recall by best overlap of (M,) predicted and true room ids
    (-1 = none; every cell given is in E)."""
    gt_ids, gt_idx = np.unique(gt_rooms, return_inverse=True)
    has = pred_rooms >= 0
    pred_ids, pred_idx = np.unique(pred_rooms[has], return_inverse=True)
    if len(pred_ids) == 0 or len(gt_ids) == 0:
        return {"precision": 0.0, "recall": 0.0, "rooms_pred": int(len(pred_ids)), "rooms_gt": int(len(gt_ids))}
    table = np.bincount(pred_idx * len(gt_ids) + gt_idx[has],
                        minlength=len(pred_ids) * len(gt_ids)).reshape(len(pred_ids), len(gt_ids))
    gt_size = np.bincount(gt_idx, minlength=len(gt_ids))
    return {"precision": float(np.mean(table.max(axis=1) / table.sum(axis=1))),
            "recall": float(np.mean(table.max(axis=0) / gt_size)),
            "rooms_pred": int(len(pred_ids)), "rooms_gt": int(len(gt_ids))}


def score_room_map(pred_rooms: np.ndarray, pred_labels: list[str], gt_rooms: np.ndarray,
                   gt_labels: dict[int, str], evaluated: np.ndarray | None = None) -> dict:
    """All metrics of a (H, W) predicted room-id map with a label per id, against a (H, W) true
    room-id map with `gt_labels` (id -> type), on the same grid; only cells where `evaluated`
    (H, W) bool is set count (default: every cell in a room). Adds `cells`: cells scored."""
    inside = (gt_rooms >= 0) if evaluated is None else (gt_rooms >= 0) & evaluated
    names = sorted(set(gt_labels.values()) | set(pred_labels))
    index = {name: i for i, name in enumerate(names)}
    gt_ids = np.array(sorted(gt_labels), np.int64)
    gt_lut = np.array([index[gt_labels[i]] for i in gt_ids.tolist()], np.int64)
    gt_cells = gt_rooms[inside]
    gt_class = gt_lut[np.searchsorted(gt_ids, gt_cells)]
    pred_cells = pred_rooms[inside]
    pred_lut = np.array([index[label] for label in pred_labels] + [-1], np.int64)  # id -1 -> last -> none
    pred_class = pred_lut[np.where(pred_cells >= 0, pred_cells, len(pred_labels))]
    return {**label_metrics(pred_class, gt_class, len(names)), **overlap_metrics(pred_cells, gt_cells),
            "cells": int(inside.sum())}


def label_components(labels: np.ndarray) -> np.ndarray:
    """(H, W) int32 id of the 4-connected component of equal label each cell is in (-1 unlabelled)."""
    import cv2

    out = np.full(labels.shape, -1, np.int32)
    offset = 0
    for label in np.unique(labels[labels >= 0]).tolist():
        n, comp = cv2.connectedComponents((labels == label).astype(np.uint8), connectivity=4)
        inside = comp > 0
        out[inside] = comp[inside] - 1 + offset
        offset += n - 1
    return out


def gt_room_labels(gt) -> dict[int, str]:
    """Ground-truth room id -> type from a `GroundTruth`'s room list."""
    return {int(room["id"]): str(room["label"]) for room in gt.rooms_list}


def eval_section(scene: SceneMap, gt, frames_dir: Path) -> dict:
    """`iesm eval-map` section: {"rooms": metrics of the map's rooms (segmented now with the
    simulated per-cell labels when the map has none), "rooms_baseline": the per-cell labels alone};
    {} when the ground truth lists no rooms."""
    from ..rooms.labels import CellLabels
    from ..rooms.scene import segment_rooms
    from ..sim.room_labels import ViewpointLabels

    if not gt.rooms_list:
        return {}
    cell_labels = ViewpointLabels(frames_dir).cell_labels(scene.grid)
    rooms_scene = scene if scene.room_map is not None else segment_rooms(scene, cell_labels)
    labels = gt_room_labels(gt)
    pred = resample(rooms_scene.room_map, scene.grid, gt.grid)
    pred_labels = [room.label for room in sorted(rooms_scene.rooms, key=lambda r: r.id)]
    pred = _dense_ids(pred, [room.id for room in sorted(rooms_scene.rooms, key=lambda r: r.id)])
    baseline = CellLabels(resample(cell_labels.labels, scene.grid, gt.grid), cell_labels.names)
    evaluated = baseline.labels >= 0
    return {"rooms": score_room_map(pred, pred_labels, gt.rooms, labels, evaluated),
            "rooms_baseline": baseline_scores(baseline, gt.rooms, labels, evaluated)}


def baseline_scores(cell_labels, gt_rooms: np.ndarray, gt_labels: dict[int, str],
                    evaluated: np.ndarray | None = None) -> dict:
    """Metrics of the per-cell labels alone (rooms = components of equal label), on the cells
    `evaluated` (default: the labelled ones)."""
    components = label_components(cell_labels.labels)
    comp_label = np.full(int(components.max(initial=-1)) + 1, -1, np.int64)
    inside = components >= 0
    comp_label[components[inside]] = cell_labels.labels[inside]
    evaluated = cell_labels.labels >= 0 if evaluated is None else evaluated
    return score_room_map(components, [cell_labels.names[i] for i in comp_label.tolist()], gt_rooms, gt_labels,
                          evaluated)


def _dense_ids(room_map: np.ndarray, ids: list[int]) -> np.ndarray:
    """Re-number room ids to their position in `ids` (-1 stays, unknown ids become -1)."""
    lut = {room_id: k for k, room_id in enumerate(ids)}
    flat = room_map.ravel()
    keys = np.array(sorted(lut), np.int64)
    out = np.full(flat.shape, -1, np.int32)
    if len(keys):
        pos = np.clip(np.searchsorted(keys, flat), 0, len(keys) - 1)
        known = (flat >= 0) & (keys[pos] == flat)
        out[known] = np.array([lut[k] for k in keys.tolist()], np.int32)[pos[known]]
    return out.reshape(room_map.shape)
