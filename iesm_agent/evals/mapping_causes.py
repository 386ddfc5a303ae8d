"""Why a seen ground-truth object has no matching instance in a built map: one cause per unmatched
object, from the top-down masks (observed footprint ground truth, `EvalContext`) and the frames'
segmentation.

Causes, tested in this order (`COVER` = 0.5, the share of the object's observed cells):
* "never segmented": no mask of any frame has the object as its majority instance (the segmenter
  missed it, or merged it into a larger neighbour's mask in every view);
* "swallowed": the instance covering most of the object covers at least `COVER` of it but belongs
  to another object (most of its cells are another object's);
* "inflated": that instance covers at least `COVER` of it and is mostly this object's, yet its
  IoU stays at or under the match threshold: its footprint spread beyond what was seen;
* "split": no single instance covers `COVER`, but the instances that are mostly this object's
  cover it together;
* "partial": what remains: the map holds under `COVER` of the object in all.
"""

from __future__ import annotations

from collections import Counter

import numpy as np

from ..frames import FrameSet
from ..mapping.cells import intersections

#: share of an object's observed cells an instance (or its pieces) must cover to explain it
COVER = 0.5
CAUSES = ("never segmented", "swallowed", "inflated", "split", "partial")


def segmented_ids(frames: FrameSet, min_pixels: int) -> set[int]:
    """Ground-truth ids that are the majority instance of some mask (>= `min_pixels` pixels) of
    some frame (frames need seg.npz and inst.png)."""
    out: set[int] = set()
    for frame in frames:
        seg, inst = frame.segmentation, frame.instance_ids
        if seg is None or inst is None:
            continue
        flat = inst.ravel().astype(np.int64)
        for mask in seg.masks.reshape(len(seg.masks), -1):
            ids = flat[mask]
            if len(ids) >= min_pixels:
                out.add(int(np.bincount(ids).argmax()))
    return out


def unmatched_causes(pred_cells: tuple[np.ndarray, np.ndarray], gt_cells: tuple[np.ndarray, np.ndarray],
                     gt_ids: np.ndarray, matched: set[int], segmented: set[int]) -> dict[int, str]:
    """Cause (one of `CAUSES`) of every id of `gt_ids` (N,) not in `matched`. Masks are (flat cell,
    id) entry arrays in one grid: `pred_cells` the map's instances, `gt_cells` the observed
    ground-truth footprints; `segmented` the ids some frame's mask is mostly (`segmented_ids`)."""
    gflat, gid = gt_cells
    pflat, pid = pred_cells
    g, p, inter = intersections(gflat, gid, pflat, pid)
    gt_area = np.bincount(gid, minlength=int(gid.max(initial=0)) + 1)
    # each instance's main object: the ground-truth id it shares the most cells with
    main: dict[int, int] = {}
    for k in np.lexsort((g, -inter, p)):
        main.setdefault(int(p[k]), int(g[k]))
    out: dict[int, str] = {}
    for i in gt_ids.tolist():
        if i in matched:
            continue
        if i not in segmented:
            out[i] = "never segmented"
            continue
        sel = g == i
        cover = inter[sel] / max(int(gt_area[i]), 1)
        owners = p[sel]
        own = np.array([main[int(o)] == i for o in owners.tolist()], bool)
        if len(cover) and cover.max() >= COVER:
            out[i] = "inflated" if own[int(cover.argmax())] else "swallowed"
        elif own.sum() >= 2 and cover[own].sum() >= COVER:
            out[i] = "split"
        else:
            out[i] = "partial"
    return out


def cause_counts(causes: dict[int, str]) -> dict[str, int]:
    """Number of objects per cause, every cause listed."""
    counts = Counter(causes.values())
    return {c: int(counts.get(c, 0)) for c in CAUSES}
