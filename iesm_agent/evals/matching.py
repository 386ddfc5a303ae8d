"""Pairing built-map instances with ground-truth instances (paper Sec. 4.1): top-down mask IoU
above 0.5, one-to-one, highest IoU first. Predicted cells are moved into the ground-truth grid
by their cell centres, so the two grids may differ in origin."""

from __future__ import annotations

import numpy as np

from ..store.model import GridSpec, InstanceGrid, SceneMap
from ..mapping.association import iou
from ..mapping.cells import intersections


def cells_in_grid(flat: np.ndarray, src: GridSpec, dst: GridSpec) -> np.ndarray:
    """Flat indices in `dst` of the centres of flat cells `flat` of `src` (-1 outside `dst`)."""
    rows, cols = np.divmod(np.asarray(flat, np.int64), max(src.width, 1))
    x = src.origin[0] + (cols + 0.5) * src.cell_size
    y = src.origin[1] + (rows + 0.5) * src.cell_size
    r = np.floor((y - dst.origin[1]) / dst.cell_size).astype(np.int64)
    c = np.floor((x - dst.origin[0]) / dst.cell_size).astype(np.int64)
    inside = (r >= 0) & (r < dst.height) & (c >= 0) & (c < dst.width)
    return np.where(inside, r * dst.width + c, -1)


def masks_in_grid(occ: InstanceGrid, src: GridSpec, dst: GridSpec) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(flat cell in `dst`, instance id, top height m) per distinct (cell, id) of `occ`, cells outside dropped."""
    flat, ids, top = occ.entries()
    if src != dst:
        flat = cells_in_grid(flat, src, dst)
        keep = flat >= 0
        flat, ids, top = flat[keep], ids[keep], top[keep]
        moved = InstanceGrid.from_entries(flat, ids, top)  # merges cells that land together
        flat, ids, top = moved.entries()
    return flat, ids, top


def iou_pairs(pred: tuple[np.ndarray, np.ndarray], gt: tuple[np.ndarray, np.ndarray]
              ) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(gt id, pred id, IoU) for every pair of masks sharing a cell; masks given as (flat cells, ids)."""
    g, p, inter = intersections(gt[0], gt[1], pred[0], pred[1])
    if len(g) == 0:
        return g, p, np.zeros(0)
    gt_area = np.bincount(gt[1])
    pred_area = np.bincount(pred[1])
    return g, p, iou(inter, gt_area[g], pred_area[p])


def greedy_pairs(g: np.ndarray, p: np.ndarray, score: np.ndarray, threshold: float) -> dict[int, int]:
    """One-to-one pairs with `score` > `threshold`, highest first (ties: lower gt, then pred id)."""
    ok = score > threshold
    g, p, score = g[ok], p[ok], score[ok]
    out: dict[int, int] = {}
    used: set[int] = set()
    for k in np.lexsort((p, g, -score)):
        gi, pi = int(g[k]), int(p[k])
        if gi not in out and pi not in used:
            out[gi] = pi
            used.add(pi)
    return out


def match_instances(scene: SceneMap, gt, iou_threshold: float = 0.5,
                    observed: tuple[np.ndarray, np.ndarray, np.ndarray] | None = None) -> dict[int, int]:
    """{gt id: built-map id} for pairs whose top-down masks have IoU > `iou_threshold`. `gt` is a
    `GroundTruth`. Its masks: `observed`, the observed footprints of the objects the frames show
    as (flat cell, gt id, top) entries (`evals.observed.observed_masks`, what the mapping table's
    first ground truth scores), else the full box footprints (gt/cells.npz)."""
    gflat, gids, _gtop = observed if observed is not None else gt.cells.entries()
    flat, ids, _top = masks_in_grid(scene.occupancy, scene.grid, gt.grid)
    g, p, score = iou_pairs((flat, ids), (gflat, gids))
    return greedy_pairs(g, p, score, iou_threshold)


def keys_in_grid(keys: np.ndarray, cell_size: float, dst: GridSpec) -> np.ndarray:
    """Flat indices in `dst` of the centres of global cell `keys` (see `cells`), -1 outside."""
    from ..mapping.cells import rowcol_of

    rows, cols = rowcol_of(keys)
    x, y = (cols + 0.5) * cell_size, (rows + 0.5) * cell_size
    r = np.floor((y - dst.origin[1]) / dst.cell_size).astype(np.int64)
    c = np.floor((x - dst.origin[0]) / dst.cell_size).astype(np.int64)
    inside = (r >= 0) & (r < dst.height) & (c >= 0) & (c < dst.width)
    return np.where(inside, r * dst.width + c, -1)
