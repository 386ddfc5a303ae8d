"""Mapping metrics exactly as the paper defines them (Sec. 4.1, Tables 1-3).

AUC^top: for every matched (gt, pred) pair, the rank r (1-based) of the ground-truth category in
the prediction's category ranking (Z row sorted best first; r = J + 1 when the ground-truth label
is not in the category list). f(k) = |S_k| / denominator with S_k = pairs with r <= k, for
k = 0..J (f(0) = 0), on x = k / J in [0, 1]; AUC = trapezoid area. Denominators: |P| predicted
instances (pred), |G| ground-truth instances (gt), |M| matched pairs (match).

Top-down label maps (Table 2): each cell takes the label of its top-most instance (largest top
height; ties: lower id). Scored over the cells that are occupied in the ground truth (a cell the
prediction leaves empty is wrong there): Acc = correct / cells, mAcc = mean per-class recall,
mIoU = mean per-class IoU, F-mIoU = per-class IoU weighted by ground-truth class frequency; the
means run over the classes present in the ground truth.
"""

from __future__ import annotations

import numpy as np


def gt_ranks(ranking: np.ndarray, gt_class: np.ndarray) -> np.ndarray:
    """1-based rank of `gt_class[i]` in `ranking[i]` ((n, J) category indices, best first);
    J + 1 when the class is -1 (not in the category list)."""
    ranking = np.asarray(ranking).reshape(len(gt_class), -1)
    j = ranking.shape[1]
    hit = ranking == np.asarray(gt_class)[:, None]
    return np.where(hit.any(axis=1), hit.argmax(axis=1) + 1, j + 1)


def topk_curve(ranks: np.ndarray, n_categories: int, denominator: int) -> np.ndarray:
    """f(k) for k = 0..J: share (of `denominator`) of pairs whose rank is <= k."""
    counts = np.bincount(np.minimum(ranks, n_categories + 1), minlength=n_categories + 2)[:n_categories + 1]
    return np.cumsum(counts) / max(denominator, 1)


def auc_top(ranks: np.ndarray, n_categories: int, denominator: int) -> float:
    """Trapezoid area under f(k) over x = k / J."""
    x = np.arange(n_categories + 1) / n_categories
    return float(np.trapezoid(topk_curve(ranks, n_categories, denominator), x))


def auc_top_all(ranks: np.ndarray, n_categories: int, n_pred: int, n_gt: int) -> dict[str, float]:
    """AUC^top with prediction-, ground-truth- and matching-normalisation, plus top-1 (match)."""
    n_match = len(ranks)
    return {"pred": auc_top(ranks, n_categories, n_pred), "gt": auc_top(ranks, n_categories, n_gt),
            "match": auc_top(ranks, n_categories, n_match),
            "top1_match": float(np.count_nonzero(ranks == 1) / n_match) if n_match else 0.0}


def topmost_labels(flat: np.ndarray, ids: np.ndarray, top: np.ndarray, label_of: dict[int, int],
                   n_cells: int) -> np.ndarray:
    """(n_cells,) class of the top-most instance per cell (-1 where empty); `label_of` maps id -> class."""
    out = np.full(n_cells, -1, np.int64)
    if len(flat) == 0:
        return out
    order = np.lexsort((ids, -np.nan_to_num(top, nan=-np.inf), flat))  # per cell: highest top first
    flat, ids = flat[order], ids[order]
    first = np.r_[True, flat[1:] != flat[:-1]]
    lookup = np.full(int(max(ids.max(), max(label_of, default=0))) + 1, -1, np.int64)
    lookup[np.fromiter(label_of.keys(), np.int64, len(label_of))] = np.fromiter(label_of.values(), np.int64,
                                                                               len(label_of))
    out[flat[first]] = lookup[ids[first]]
    return out


def label_map_scores(gt: np.ndarray, pred: np.ndarray) -> dict[str, float]:
    """Acc, mAcc, mIoU, F-mIoU of per-cell classes (-1 = none) over the cells where `gt` >= 0."""
    sel = gt >= 0
    g, p = gt[sel], pred[sel]
    if len(g) == 0:
        return {"acc": 0.0, "macc": 0.0, "miou": 0.0, "fmiou": 0.0}
    classes = np.unique(g)
    n_cls = int(max(g.max(), p.max(initial=0))) + 1
    correct = g == p
    tp = np.bincount(g[correct], minlength=n_cls).astype(float)
    gt_count = np.bincount(g, minlength=n_cls).astype(float)
    pred_count = np.bincount(p[p >= 0], minlength=n_cls).astype(float)
    recall = tp[classes] / gt_count[classes]
    iou = tp[classes] / (gt_count[classes] + pred_count[classes] - tp[classes])
    freq = gt_count[classes] / len(g)
    return {"acc": float(correct.mean()), "macc": float(recall.mean()), "miou": float(iou.mean()),
            "fmiou": float((freq * iou).sum())}


def small_categories(labels: list[str], areas: np.ndarray, fraction: float = 0.2) -> set[str]:
    """Categories whose mean instance area falls within the bottom `fraction` of all instance
    areas (the paper's small objects); `labels` and `areas` (cells) are per instance."""
    if len(areas) == 0:
        return set()
    cut = np.quantile(np.asarray(areas, float), fraction)
    sums: dict[str, list[float]] = {}
    for label, area in zip(labels, areas):
        sums.setdefault(label, []).append(float(area))
    return {label for label, a in sums.items() if np.mean(a) <= cut}
