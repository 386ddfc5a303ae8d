"""Why a matched instance of a built map carries the wrong label: one cause per instance paired
(top-down IoU) with a ground-truth object whose category its label is not, from the instance's
fused masks (the map's observations), what each mask shows (the ground-truth instance image) and
what the segmenter called it (its embedding's best category, Z = f E^T per mask).

An instance's label is the best category of the mean of its masks' embeddings (every mask weighs
1, `mapping.dictionary`). Its *own* masks are those that mostly show its object; the others show
a neighbour. Causes, tested in this order:
* "neighbour": its votes were drowned by another object's: the mean embedding of its own masks
  alone is named right (the masks of other objects fused in turned it), or the label is the
  category of another object whose pixels make up at least `NEIGHBOUR_SHARE` of the instance's
  mask pixels (its masks spilling onto its support or its neighbour carry that one's look);
* "near-synonym": the label and the true category are near-synonyms (`near_synonyms`: one name
  ends with the other, armchair / chair, or both end with the same word, coffee table / dining
  table), whatever the mechanism;
* "segmenter": the mean embedding of its own masks alone is not named right: the segmenter's
  view of the object, fused over the frames, is wrong (a per-object look the frames share);
* "other": what remains (the true category is not in the scene's category list).
"""

from __future__ import annotations

from collections import Counter

import numpy as np

from ..frames import FrameSet

#: share of an instance's mask pixels a neighbour must make up for its category to explain the label
NEIGHBOUR_SHARE = 0.1
CAUSES = ("neighbour", "near-synonym", "segmenter", "other")


def near_synonyms(a: str, b: str) -> bool:
    """Whether two different category names are near-synonyms by their words: one ends with the
    other (armchair / chair, office chair / chair, bookshelf / shelf) or both end with the same
    word (coffee table / dining table)."""
    a, b = a.lower().strip(), b.lower().strip()
    if a == b:
        return False
    return a.endswith(b) or b.endswith(a) or a.split()[-1] == b.split()[-1]


def mask_evidence(frames: FrameSet, wanted: set[tuple[int, int]], e: np.ndarray
                  ) -> dict[tuple[int, int], dict]:
    """(frame index, mask index) -> {"pixels": Counter of ground-truth ids over the mask's pixels (0 =
    none), "category": index of the best category of the mask's embedding (Z = f E^T), "embedding"
    (D,)} for every
    mask in `wanted` (frames need seg.npz and inst.png); `e` (J, D) the category embeddings."""
    out: dict[tuple[int, int], dict] = {}
    by_frame: dict[int, list[int]] = {}
    for f, m in wanted:
        by_frame.setdefault(f, []).append(m)
    for i in range(len(frames)):
        frame = frames.read(i)
        masks = by_frame.get(frame.index)
        seg, inst = frame.segmentation, frame.instance_ids
        if not masks or seg is None or inst is None:
            continue
        flat = inst.ravel().astype(np.int64)
        best = (np.asarray(seg.embeddings, np.float64) @ np.asarray(e, np.float64).T).argmax(axis=1)
        for m in masks:
            ids, counts = np.unique(flat[seg.masks[m].ravel()], return_counts=True)
            out[(frame.index, m)] = {"pixels": Counter(dict(zip(ids.tolist(), counts.tolist()))),
                                     "category": int(best[m]), "embedding": np.asarray(seg.embeddings[m], np.float64)}
    return out


def label_error(obj: int, true_class: int, label_class: int, masks: list[dict], labels: dict[int, str],
                categories: list[str], e: np.ndarray) -> dict:
    """The cause (one of `CAUSES`) and the evidence for one mislabelled instance paired with object
    `obj`. `true_class` / `label_class` index `categories` (-1: the true category is not in the
    list), `masks` the instance's masks as `mask_evidence` gives them, `labels` object id -> true
    category name, `e` (J, D) the category embeddings. Returns {"cause", "own_masks", "own_right"
    (own masks the segmenter calls right), "own_label" (the best category of the mean of the own
    masks' embeddings, None without own masks), "other_masks", "neighbour" and "neighbour_share"
    (the other object with most pixels in the instance's masks)}."""
    pixels: Counter = Counter()
    own = [mask for mask in masks if mask["pixels"].most_common(1)[0][0] == obj]
    for mask in masks:
        pixels.update(mask["pixels"])
    total = sum(pixels.values())
    label = categories[label_class]
    shares = {o: n / max(total, 1) for o, n in pixels.items() if o not in (0, obj) and o in labels}
    own_class = (int((np.mean([m["embedding"] for m in own], axis=0) @ np.asarray(e, np.float64).T).argmax())
                 if own else -1)
    right = sum(m["category"] == true_class for m in own) if true_class >= 0 else 0
    named = [o for o, s in shares.items() if s >= NEIGHBOUR_SHARE and labels[o].lower() == label.lower()]
    if named or (true_class >= 0 and own_class == true_class):
        cause = "neighbour"
    elif true_class >= 0 and near_synonyms(label, categories[true_class]):
        cause = "near-synonym"
    elif true_class >= 0 and own_class != true_class:
        cause = "segmenter"
    else:
        cause = "other"
    biggest = max(shares, key=lambda o: (shares[o], -o)) if shares else None
    return {"cause": cause, "own_masks": len(own), "own_right": int(right),
            "own_label": categories[own_class] if own_class >= 0 else None, "other_masks": len(masks) - len(own),
            "neighbour": labels[biggest] if biggest is not None else None,
            "neighbour_share": round(shares[biggest], 3) if biggest is not None else None}
