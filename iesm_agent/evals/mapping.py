"""Evaluation of a built map against simulator ground truth (`iesm eval-map`), and of the 2D
point-wise baseline on the same ground truth (see `metrics` for the definitions).

Two ground truths for the top-down masks (`footprint`):
* "observed" (default): every pixel of the ground-truth instance images (DIR/frames/*.inst.png)
  projected with the exact depth (DIR/gt/depth/, written under a realism profile with a depth
  sensor model; else the frames' depth, which is exact under `easy`), the same intrinsics and
  poses. So a tall wardrobe whose top the camera never sees is judged on the faces it did see,
  and what is scored is segmentation, association, fusion and labelling.
* "full": each instance's whole box footprint (gt/cells.npz), what a perfect map of the object
  would hold whether seen or not.
Instances evaluated (both): those with at least `min_mask_pixels` observed pixels. Without
instance images the box footprints of gt/cells.npz and every object are used.

Small objects: per dataset as the paper defines them, categories whose mean instance footprint
is in the bottom 20 % of instance footprints, pooled over the dataset: for simulated scenes over
the tuning worlds (seeds 0-4) of the scene's `--size` (`dataset_small_categories`), else over the
scene itself. Stacked objects: instances more than half of whose footprint cells also hold one
other instance in the ground-truth 2.5D map (gt/cells.npz): a cup on a table, a lamp on a
nightstand, a picture on a wall, and the furniture they stand on when it is small.
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Optional

import functools
import json

import numpy as np

from ..config import MappingConfig
from ..frames import FrameSet
from ..store.model import SceneMap
from ..mapping.build import category_vectors
from ..mapping.categorize import category_ranking, category_scores
from ..mapping.cells import intersections
from ..sim.ground_truth import GroundTruth
from .matching import greedy_pairs, iou_pairs, keys_in_grid, masks_in_grid
from .observed import observed_masks
from .mapping_metrics import auc_top, auc_top_all, gt_ranks, label_map_scores, small_categories, topmost_labels

STACKED_SHARE = 0.5  # share of an instance's footprint another instance must cover to count as stacked


@dataclass
class EvalContext:
    """Ground truth prepared once per scene: category list + embeddings E (J, D), the evaluated
    GT ids and their category index (-1 = not in the list), their top-down masks in the GT grid,
    per-cell GT classes, and the small / stacked subsets."""

    gt: GroundTruth
    categories: list[str]
    e: np.ndarray
    gt_ids: np.ndarray
    gt_class: dict[int, int]
    gt_cells: tuple[np.ndarray, np.ndarray, np.ndarray]
    cell_classes: np.ndarray
    small: set[int]
    small_labels: set[str]
    stacked: set[int]
    cfg: MappingConfig

    footprint: str = "observed"

    @classmethod
    def create(cls, gt: GroundTruth, frames_dir: str | Path, cfg: MappingConfig | None = None,
               footprint: str = "observed") -> "EvalContext":
        """`footprint`: "observed" or "full" ground-truth masks (see the module docstring)."""
        cfg = cfg or MappingConfig()
        frames = FrameSet.open(frames_dir)
        categories, e = category_vectors(frames)
        index = {c.lower(): j for j, c in enumerate(categories)}
        labels = {int(o["id"]): str(o["label"]) for o in gt.objects}
        observed = observed_masks(frames_dir, gt, cfg)
        flat, ids, top = observed if observed is not None else gt.cells.entries()
        keep_ids = np.array(sorted(set(labels) & set(np.unique(ids).tolist())), np.int64)
        if footprint == "full":
            flat, ids, top = gt.cells.entries()
        sel = np.isin(ids, keep_ids)
        flat, ids, top = flat[sel], ids[sel], top[sel]
        gt_class = {i: index.get(labels[i].lower(), -1) for i in keep_ids.tolist()}
        extra = {lab: len(categories) + k for k, lab in enumerate(sorted({labels[i].lower() for i in gt_class
                                                                         if gt_class[i] < 0}))}
        cell_class = {i: (c if c >= 0 else extra[labels[i].lower()]) for i, c in gt_class.items()}
        cell_classes = topmost_labels(flat, ids, top, cell_class, gt.grid.height * gt.grid.width)
        box_flat, box_ids, _ = gt.cells.entries()
        area = np.bincount(box_ids, minlength=int(keep_ids.max(initial=0)) + 1)[keep_ids]
        size = _sim_size(Path(frames_dir))
        small_labels = (dataset_small_categories(size, cfg.small_fraction) if size is not None else
                        small_categories([labels[i] for i in keep_ids.tolist()], area, cfg.small_fraction))
        small = {i for i in keep_ids.tolist() if labels[i] in small_labels}
        in_eval = np.isin(box_ids, keep_ids)
        a, b, inter = intersections(box_flat[in_eval], box_ids[in_eval], box_flat[in_eval], box_ids[in_eval])
        box_area = np.bincount(box_ids)
        on_other = (a != b) & (inter > STACKED_SHARE * box_area[a])
        stacked = set(np.unique(a[on_other]).tolist())
        return cls(gt, categories, e, keep_ids, gt_class, (flat, ids, top), cell_classes, small, small_labels,
                   stacked, cfg, footprint)


def _sim_size(frames_dir: Path) -> Optional[str]:
    """The simulator `--size` a frame directory was made with (gt/sim.json), else None."""
    try:
        return str(json.loads((frames_dir / "gt" / "sim.json").read_text(encoding="utf-8"))["size"])
    except (OSError, ValueError, KeyError, TypeError):
        return None


@functools.lru_cache(maxsize=8)
def dataset_small_categories(size: str, fraction: float = 0.2) -> frozenset[str]:
    """Small categories of a simulated dataset (`--size`), pooled over its tuning worlds (seeds
    0-4, walled): categories whose mean box footprint is within the bottom `fraction` of all
    instance footprints."""
    from ..sim import generate_scene

    labels, areas = [], []
    for seed in range(5):
        world = generate_scene(seed, size)
        _, ids, _ = world.instance_grid().entries()
        count = np.bincount(ids, minlength=len(world.instances) + 1)
        for inst in world.instances:
            labels.append(inst.label)
            areas.append(count[inst.id])
    return frozenset(small_categories(labels, np.array(areas), fraction))


@dataclass
class Prediction:
    """What is scored: instance `ids` (N,), category `ranking` (N, J) best first, top-down masks
    in the GT grid as (flat cell, id, top) entries; optionally per-cell classes (the 2D map's own)
    and fixed gt -> pred `matches` (by construction, for the GT-mask baseline)."""

    ids: np.ndarray
    ranking: np.ndarray
    cells: tuple[np.ndarray, np.ndarray, np.ndarray]
    cell_classes: Optional[np.ndarray] = None
    matches: Optional[dict[int, int]] = None


def prediction_from_map(scene: SceneMap, ctx: EvalContext) -> Prediction:
    """A built (or imported) map as a prediction; its embeddings rank the categories (Z = F E^T),
    or, without embeddings, its label alone (rank 1 or absent)."""
    ids = np.array([inst.id for inst in scene.instances], np.int64)
    j = len(ctx.categories)
    if scene.embeddings is not None and scene.embeddings.shape[1] == ctx.e.shape[1]:
        ranking = stated_first(category_ranking(category_scores(scene.embeddings, ctx.e)), scene, ctx.categories)
    else:
        index = {c.lower(): k for k, c in enumerate(ctx.categories)}
        first = np.array([index.get(inst.label.lower(), -1) for inst in scene.instances], np.int64)
        ranking = np.full((len(ids), j), -1, np.int64)
        ranking[:, 0] = first
    return Prediction(ids, ranking, masks_in_grid(scene.occupancy, scene.grid, ctx.gt.grid))


def stated_first(ranking: np.ndarray, scene: SceneMap, categories: list[str]) -> np.ndarray:
    """`ranking` (N, J) with each instance's own label and alternative labels moved to the front in
    their order (the map's label is its top-1 even when it weighed more than the embedding, such as
    `MappingConfig.size_prior_temperature`); the embedding's order for the rest."""
    index = {c.lower(): k for k, c in enumerate(categories)}
    out = ranking.copy()
    for k, inst in enumerate(scene.instances):
        stated = list(dict.fromkeys(index[name.lower()] for name in (inst.label, *inst.alt_labels)
                                    if name.lower() in index))
        if stated:
            out[k] = np.r_[stated, ranking[k][~np.isin(ranking[k], stated)]]
    return out


def prediction_from_pointwise(keys: np.ndarray, scores: np.ndarray, cell_size: float,
                              ctx: EvalContext) -> Prediction:
    """The 2D point-wise map (cell keys (C,), mean category scores (C, J)) as "VLMaps + GT mask":
    one instance per evaluated GT instance with the GT mask; its descriptor averages the cell
    scores inside the mask (no observed cell: no ranking). Cell classes: per-cell argmax."""
    grid = ctx.gt.grid
    flat = keys_in_grid(keys, cell_size, grid)
    inside = flat >= 0
    flat, scores = flat[inside], scores[inside]
    order = np.argsort(flat, kind="stable")        # cells landing together are averaged
    flat, scores = flat[order], scores[order]
    starts = np.flatnonzero(np.r_[True, flat[1:] != flat[:-1]]) if len(flat) else np.zeros(0, np.int64)
    n_per = np.diff(np.append(starts, len(flat)))
    cell_flat = flat[starts]
    cell_scores = np.add.reduceat(scores, starts, axis=0) / n_per[:, None] if len(flat) else scores
    cell_classes = np.full(grid.height * grid.width, -1, np.int64)
    cell_classes[cell_flat] = cell_scores.argmax(axis=1)
    gflat, gids, gtop = ctx.gt_cells
    pos = np.searchsorted(cell_flat, gflat)
    hit = (pos < len(cell_flat)) & (cell_flat[np.minimum(pos, len(cell_flat) - 1)] == gflat) \
        if len(cell_flat) else np.zeros(len(gflat), bool)
    row_of = np.searchsorted(ctx.gt_ids, gids[hit])
    j = len(ctx.categories)
    sums = np.zeros((len(ctx.gt_ids), j))
    np.add.at(sums, row_of, cell_scores[pos[hit]])
    seen = np.bincount(row_of, minlength=len(ctx.gt_ids)) > 0
    ranking = category_ranking(sums)
    ranking[~seen] = -1
    matches = {int(i): int(i) for i in ctx.gt_ids}
    return Prediction(ctx.gt_ids.copy(), ranking, (gflat, gids, gtop), cell_classes, matches)


def pairs(pred: Prediction, ctx: EvalContext) -> dict[int, int]:
    """{gt id: predicted id}: `pred.matches` when fixed, else top-down IoU > `match_iou`, one-to-one."""
    if pred.matches is not None:
        return pred.matches
    g, p, iou = iou_pairs((pred.cells[0], pred.cells[1]), (ctx.gt_cells[0], ctx.gt_cells[1]))
    keep = np.isin(g, ctx.gt_ids)
    return greedy_pairs(g[keep], p[keep], iou[keep], ctx.cfg.match_iou)


def named_right(pred: Prediction, ctx: EvalContext, matches: dict[int, int]) -> dict[int, bool]:
    """{gt id: True when the predicted instance paired with it (`matches`) ranks its category first}."""
    row = {int(i): k for k, i in enumerate(pred.ids.tolist())}
    return {g: bool(ctx.gt_class[g] >= 0 and pred.ranking[row[p], 0] == ctx.gt_class[g]) for g, p in matches.items()}


def score(pred: Prediction, ctx: EvalContext, only: Optional[set[int]] = None) -> dict:
    """Every mapping metric of `pred` (keys: auc_top {pred, gt, match, top1_match}, instance_diff,
    n_pred, n_gt, n_matched, matched_ids, topdown {acc, macc, miou, fmiou}, small {...}, stacked
    {n_gt, n_matched, top1_match, top1_gt, auc_top_match, auc_top_gt}). `only`: score the
    matched-object metrics on these ground-truth ids alone (a baseline on the objects another
    method matched)."""
    j = len(ctx.categories)
    matches = pairs(pred, ctx)
    if only is not None:
        matches = {g: p for g, p in matches.items() if g in only}
    gt_m = np.array(sorted(matches), np.int64)
    pred_m = np.array([matches[g] for g in gt_m.tolist()], np.int64)
    row = {int(i): k for k, i in enumerate(pred.ids.tolist())}
    rows = np.array([row[p] for p in pred_m.tolist()], np.int64)
    ranks = gt_ranks(pred.ranking[rows] if len(rows) else np.zeros((0, j), np.int64),
                     np.array([ctx.gt_class[g] for g in gt_m.tolist()], np.int64))
    n_pred, n_gt = len(pred.ids), len(ctx.gt_ids)
    out = {"auc_top": auc_top_all(ranks, j, n_pred, n_gt), "instance_diff": abs(n_pred - n_gt),
           "n_pred": n_pred, "n_gt": n_gt, "n_matched": len(gt_m), "matched_ids": gt_m.tolist()}
    cells = pred.cell_classes
    if cells is None:
        top1 = {int(i): int(pred.ranking[k, 0]) for k, i in enumerate(pred.ids.tolist())}
        cells = topmost_labels(*pred.cells, top1, len(ctx.cell_classes))
    out["topdown"] = label_map_scores(ctx.cell_classes, cells)
    small_pairs = np.isin(gt_m, list(ctx.small))
    small_idx = {ctx.categories.index(c) for c in ctx.categories if c in ctx.small_labels}
    pred_small = {int(i) for k, i in enumerate(pred.ids.tolist()) if int(pred.ranking[k, 0]) in small_idx}
    pred_small |= set(pred_m[small_pairs].tolist())
    out["small"] = {"auc_top": auc_top_all(ranks[small_pairs], j, len(pred_small), len(ctx.small)),
                    "instance_diff": abs(len(pred_small) - len(ctx.small)), "n_pred": len(pred_small),
                    "n_gt": len(ctx.small), "categories": sorted(ctx.small_labels)}
    st = np.isin(gt_m, list(ctx.stacked))
    n_st = len(ctx.stacked)
    out["stacked"] = {"n_gt": n_st, "n_matched": int(st.sum()),
                      "top1_match": float(np.count_nonzero(ranks[st] == 1) / st.sum()) if st.any() else 0.0,
                      "top1_gt": float(np.count_nonzero(ranks[st] == 1) / n_st) if n_st else 0.0,
                      "auc_top_match": auc_top(ranks[st], j, int(st.sum())), "auc_top_gt": auc_top(ranks[st], j, n_st)}
    return out


def evaluate_map(scene: SceneMap, gt: GroundTruth, frames_dir: str | Path, cfg: MappingConfig | None = None) -> dict:
    """All mapping metrics of `scene` against `gt`, then the room and caption sections."""
    from .captions import eval_section as caption_section
    from .rooms import eval_section as room_section

    ctx = EvalContext.create(gt, frames_dir, cfg)
    result = score(prediction_from_map(scene, ctx), ctx)
    for section in (room_section, caption_section):
        result.update(section(scene, gt, Path(frames_dir)))
    return result
