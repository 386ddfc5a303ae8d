"""What became of each stacked ground-truth object (an item on a table, shelf or counter, a picture
on its wall: `EvalContext.stacked`) on a built map and on the 2D point-wise baseline with
ground-truth masks, object by object, side by side.

Ours, one class per object (`OUR_CLASSES`): "named right" / "named wrong" when an instance is
paired with it (top-down IoU > 0.5), else its cause from `mapping_causes.unmatched_causes`
("never segmented", "swallowed" into another object's instance such as its support, "split",
and "inflated" / "partial": an own instance whose footprint is too large / too small to match).
Beside it, for a paired or own instance, its label, whether that label is the support's category,
its best IoU with the object, and its height band on the object's cells: the median of the
instance's per-cell top heights there against the object's observed top (exact depth) and its
support's top ("band off" when the instance's tops lie nearer the support's than the object's).

The baseline (`BASELINE_CLASSES`): "named right" / "named wrong" (its descriptor, the mean of the
2D cells under the ground-truth mask, ranks another category first), "no reading" (no 2D cell
under the mask).

An object's support is the other ground-truth object whose box footprint covers most of its own
(the overlap that makes it stacked; ties: the lower id).
"""

from __future__ import annotations

from collections import Counter

import numpy as np

from ..mapping.cells import intersections
from .mapping import EvalContext, Prediction, named_right, pairs
from .mapping_causes import CAUSES, mask_attribution, own_instances
from .matching import iou_pairs

OUR_CLASSES = ("named right", "named wrong", *CAUSES)
BASELINE_CLASSES = ("named right", "named wrong", "no reading")


def supports(ctx: EvalContext) -> dict[int, int]:
    """{stacked gt id: its support}: the other evaluated-or-not ground-truth object whose box
    footprint (gt/cells.npz) shares most cells with the object's (ties: the lower id)."""
    flat, ids, _top = ctx.gt.cells.entries()
    a, b, inter = intersections(flat, ids, flat, ids)
    out: dict[int, int] = {}
    best: dict[int, int] = {}
    for i, j, n in zip(a.tolist(), b.tolist(), inter.tolist()):
        if i != j and i in ctx.stacked and (n > best.get(i, 0) or (n == best.get(i, 0) and j < out[i])):
            out[i], best[i] = j, n
    return out


def _median_top(flat: np.ndarray, ids: np.ndarray, top: np.ndarray, which: int, cells: np.ndarray) -> float | None:
    """Median top height (m) of instance `which` over flat cells `cells` of its (flat, id, top)
    entries; None when it holds none of them."""
    sel = (ids == which) & np.isin(flat, cells)
    return float(np.median(top[sel])) if sel.any() else None


def stacked_outcomes(ctx: EvalContext, pred: Prediction, baseline: Prediction, observations: np.ndarray,
                     shows: dict[tuple[int, int], int], causes: dict[int, str]) -> list[dict]:
    """One record per stacked object of `ctx`, by id: {"object", "category", "support" (its
    category), "ours" (one of `OUR_CLASSES`), "our_label" (None: no instance holds it), "our_label_support"
    (that label is the support's category), "iou" (best top-down IoU of the instance with the object),
    "top", "instance_top", "support_top" (m: the object's observed median top, the instance's and
    the support's box median top on the object's cells; None when missing), "band_off", "baseline" (one
    of `BASELINE_CLASSES`), "baseline_label", "baseline_label_support"}. `pred` is our map,
    `baseline` the 2D point-wise map with ground-truth masks, `observations` our map's rows
    [instance id, frame, mask, ...], `shows` (`mapping_causes.mask_objects`), `causes` of the
    unmatched objects (`mapping_causes.unmatched_causes`)."""
    labels = {int(o["id"]): str(o["label"]) for o in ctx.gt.objects}
    support = supports(ctx)
    ours_pairs, base_pairs = pairs(pred, ctx), pairs(baseline, ctx)
    ours_right, base_right = named_right(pred, ctx, ours_pairs), named_right(baseline, ctx, base_pairs)
    went, main = mask_attribution(observations, shows)
    g, p, iou = iou_pairs((pred.cells[0], pred.cells[1]), (ctx.gt_cells[0], ctx.gt_cells[1]))
    pred_row = {int(i): k for k, i in enumerate(pred.ids.tolist())}
    base_row = {int(i): k for k, i in enumerate(baseline.ids.tolist())}
    gflat, gid, gtop = ctx.gt_cells
    bflat, bid, btop = ctx.gt.cells.entries()

    def name(ranking: np.ndarray, row: int) -> str | None:
        j = int(ranking[row, 0])
        return ctx.categories[j] if j >= 0 else None

    out = []
    for obj in sorted(ctx.stacked):
        sup = support.get(obj)
        sup_label = labels.get(sup) if sup is not None else None
        if obj in ours_pairs:
            ours, inst = ("named right" if ours_right[obj] else "named wrong"), ours_pairs[obj]
        else:
            ours = causes[obj]
            own = own_instances(obj, went, main)
            inst = own[0] if own else (went[obj].most_common(1)[0][0] if went.get(obj) else None)
        label = name(pred.ranking, pred_row[inst]) if inst is not None and inst in pred_row else None
        cells = gflat[gid == obj]
        obj_top = float(np.median(gtop[gid == obj])) if len(cells) else None
        inst_top = _median_top(*pred.cells, inst, cells) if inst is not None else None
        sup_top = _median_top(bflat, bid, btop, sup, cells) if sup is not None else None
        band_off = (inst_top is not None and obj_top is not None and sup_top is not None
                    and abs(inst_top - sup_top) < abs(inst_top - obj_top))
        best_iou = iou[(g == obj) & (p == inst)] if inst is not None else np.zeros(0)
        base_label = name(baseline.ranking, base_row[obj]) if obj in base_row else None
        base = ("no reading" if base_label is None else "named right" if base_right.get(obj) else "named wrong")
        out.append({"object": obj, "category": labels[obj], "support": sup_label, "ours": ours, "our_label": label,
                    "our_label_support": label is not None and sup_label is not None and label.lower() == sup_label.lower(),
                    "iou": round(float(best_iou.max()), 3) if len(best_iou) else 0.0,
                    "top": obj_top, "instance_top": inst_top, "support_top": sup_top, "band_off": bool(band_off),
                    "baseline": base, "baseline_label": base_label,
                    "baseline_label_support": base_label is not None and sup_label is not None
                    and base_label.lower() == sup_label.lower()})
    return out


def outcome_counts(records: list[dict]) -> dict[str, Counter]:
    """{our class: Counter of the baseline's classes} over `records` (`stacked_outcomes`), every
    class of ours listed."""
    out = {c: Counter() for c in OUR_CLASSES}
    for r in records:
        out[r["ours"]][r["baseline"]] += 1
    return out
