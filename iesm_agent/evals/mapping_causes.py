"""Why a seen ground-truth object has no matching instance in a built map: one cause per unmatched
object, from the frames' masks (which object each mask mostly shows), the map's observations
(which instance each mask went to) and the top-down masks (observed footprint ground truth).

An instance's main object is the object most of its fused masks show (ties: the lower id); an
instance is the object's own when that is the object. Causes, tested in this order (`COVER` =
0.5 of the object's observed cells):
* "never segmented": no mask that shows mostly the object reached the map (the segmenter missed
  it or merged it into a neighbour's mask in every view, or its masks had too few depth pixels);
* "swallowed": most of the masks that show it went into instances of other objects (fused into
  its support, its wall, its neighbour);
* "split": its masks went into two or more own instances, none covering `COVER` of it;
* "inflated": an own instance covers at least `COVER` of it, yet the IoU stays at or under the
  match threshold: the footprint spread beyond what was seen;
* "partial": what remains: its own instances cover under `COVER` of it (misplaced or thin).

`built_instances` gives the instances that hold an object for queries and navigation: its IoU pair
and its own instances, which hold it even when too large, too small or in pieces for IoU > 0.5.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path

import numpy as np

from ..config import MappingConfig
from ..frames import FrameSet
from ..store.model import SceneMap
from ..mapping.association import continues, linkable, phi_geo, planar_line
from ..mapping.cells import dilate, intersections, keys_of
from .matching import match_instances

#: share of an object's observed cells an own instance must cover to explain it
COVER = 0.5
CAUSES = ("never segmented", "swallowed", "split", "inflated", "partial")


def mask_objects(frames: FrameSet, min_pixels: int) -> dict[tuple[int, int], int]:
    """(frame index, mask index) -> the ground-truth id most of the mask's pixels show, for every
    mask of at least `min_pixels` pixels (frames need seg.npz and inst.png)."""
    out: dict[tuple[int, int], int] = {}
    for i in range(len(frames)):
        frame = frames.read(i)
        seg, inst = frame.segmentation, frame.instance_ids
        if seg is None or inst is None:
            continue
        flat = inst.ravel().astype(np.int64)
        for m, mask in enumerate(seg.masks.reshape(len(seg.masks), flat.size)):  # a frame may hold no mask
            ids = flat[mask]
            if len(ids) >= min_pixels:
                out[(frame.index, m)] = int(np.bincount(ids).argmax())
    return out


def mask_attribution(observations: np.ndarray, shows: dict[tuple[int, int], int]
                     ) -> tuple[dict[int, Counter], dict[int, int]]:
    """(object -> Counter of the instances its masks went to, instance -> its main object: the object
    most of its masks show, ties to the lower id), from the map's `observations` (M, >= 3) rows
    [instance id, frame, mask, ...] and `shows` (`mask_objects`); masks `shows` lacks are left out."""
    went: dict[int, Counter] = {}
    holds: dict[int, Counter] = {}
    for inst, frame, mask in np.asarray(observations, np.float64)[:, :3].astype(np.int64).tolist():
        obj = shows.get((frame, mask))
        if obj is not None:
            went.setdefault(obj, Counter())[inst] += 1
            holds.setdefault(inst, Counter())[obj] += 1
    return went, {inst: min(c.items(), key=lambda kv: (-kv[1], kv[0]))[0] for inst, c in holds.items()}


def own_instances(obj: int, went: dict[int, Counter], main: dict[int, int]) -> list[int]:
    """The object's own instances (whose main object it is), most of its masks first (ties: lower
    id); [] when it has none or when most of its masks went into other objects' instances."""
    masks = went.get(obj, Counter())
    own = sorted((inst for inst in masks if main.get(inst) == obj), key=lambda inst: (-masks[inst], inst))
    return own if sum(masks[inst] for inst in own) * 2 >= sum(masks.values()) > 0 else []


def built_instances(scene: SceneMap, gt, frames_dir: str | Path,
                    observed: tuple[np.ndarray, np.ndarray, np.ndarray] | None) -> tuple[dict[int, list[int]], set[int]]:
    """({gt id: built ids, the one to name first}, gt ids paired by IoU): the `match_instances`
    pair first, then the object's own instances (`own_instances`, most of its masks first) paired
    with no other object: the pieces of a split object are all of it. `gt` is a `GroundTruth`,
    `observed` the observed footprints of `frames_dir`'s objects (`evals.observed.observed_masks`).
    Own instances need those, the map's observations and the frames' masks (seg.npz); without
    them only IoU pairs count."""
    matches = match_instances(scene, gt, observed=observed)
    out = {g: [p] for g, p in matches.items()}
    if observed is None or scene.observations is None or not len(scene.observations):
        return out, set(matches)
    shows = mask_objects(FrameSet.open(frames_dir), MappingConfig().min_mask_pixels)
    went, main = mask_attribution(scene.observations, shows)
    paired = set(matches.values())
    for obj in went:
        pieces = out.get(obj, []) + [inst for inst in own_instances(obj, went, main) if inst not in paired]
        if pieces:
            out[obj] = pieces
    return out, set(matches)


def unmatched_causes(pred_cells: tuple[np.ndarray, np.ndarray], gt_cells: tuple[np.ndarray, np.ndarray],
                     gt_ids: np.ndarray, matched: set[int], observations: np.ndarray,
                     shows: dict[tuple[int, int], int]) -> dict[int, str]:
    """Cause (one of `CAUSES`) of every id of `gt_ids` (N,) not in `matched`. Masks are (flat cell,
    id) entry arrays in one grid: `pred_cells` the map's instances, `gt_cells` the observed
    ground-truth footprints; `observations` (M, >= 3) the map's rows [instance id, frame, mask,
    ...]; `shows` the object each frame mask mostly shows (`mask_objects`)."""
    went, main = mask_attribution(observations, shows)
    gflat, gid = gt_cells
    g, p, inter = intersections(gflat, gid, *pred_cells)
    gt_area = np.bincount(gid, minlength=int(gid.max(initial=0)) + 1)
    out: dict[int, str] = {}
    for i in gt_ids.tolist():
        if i in matched:
            continue
        if not went.get(i):
            out[i] = "never segmented"
            continue
        own = own_instances(i, went, main)
        if not own:
            out[i] = "swallowed"
            continue
        sel = (g == i) & np.isin(p, own)
        cover = inter[sel] / max(int(gt_area[i]), 1)
        best = float(cover.max()) if len(cover) else 0.0
        if best >= COVER:
            out[i] = "inflated"
        elif len(own) >= 2:
            out[i] = "split"
        else:
            out[i] = "partial"
    return out


def cause_counts(causes: dict[int, str]) -> dict[str, int]:
    """Number of objects per cause, every cause listed."""
    counts = Counter(causes.values())
    return {c: int(counts.get(c, 0)) for c in CAUSES}


#: why two instances whose masks show one object stayed apart, by the association rule the pair
#: fails as built (`fragment_cause`, tested in this order; "linkable as built" = the pair would link
#: now, having grown after it was compared)
FRAGMENT_CAUSES = ("overlap, cosine under the thresholds", "touching, no continuity merge",
                   "touching, cosine under the continuity threshold", "touching, compact shapes",
                   "touching, planar shapes not collinear", "footprints apart", "linkable as built")


def grid_keys(flat: np.ndarray, grid) -> np.ndarray:
    """Global cell keys (`mapping.cells`, cells of `grid.cell_size`) of the centres of flat cells
    `flat` of `grid` (a `GridSpec`)."""
    rows, cols = np.divmod(np.asarray(flat, np.int64), max(grid.width, 1))
    return keys_of(np.floor(grid.origin[1] / grid.cell_size + rows + 0.5).astype(np.int64),
                   np.floor(grid.origin[0] / grid.cell_size + cols + 0.5).astype(np.int64))


def instance_keys(scene: SceneMap) -> dict[int, np.ndarray]:
    """{instance id: its top-down mask as sorted global cell keys (`mapping.cells`)} of a built map."""
    flat, ids, _top = scene.occupancy.entries()
    keys = grid_keys(flat, scene.grid)
    return {int(i): np.unique(keys[ids == i]) for i in np.unique(ids).tolist()}


def fragment_cause(keys_a: np.ndarray, keys_b: np.ndarray, cos: float, cfg: MappingConfig) -> str:
    """Which association rule keeps two instances (top-down masks `keys_a`, `keys_b`, sorted cell
    keys; embedding cosine `cos`) apart, one of `FRAGMENT_CAUSES`: their masks overlap by phi_geo >
    delta_geo but the pair is not `linkable`; they share or touch cells (the continuity merge's
    reach) but there is no continuity merge (`MappingConfig.paper()`), the cosine is at most
    delta_sem_continuous, or their shapes do not `continue` each other (both compact, or planar and
    not collinear); no cell within reach ("footprints apart")."""
    inter = len(np.intersect1d(keys_a, keys_b, assume_unique=True))
    geo = float(phi_geo(np.array([inter]), np.array([len(keys_a)]), np.array([len(keys_b)]))[0])
    if geo > cfg.delta_geo:
        return "linkable as built" if linkable(np.array([geo]), np.array([cos]), cfg)[0] else \
            "overlap, cosine under the thresholds"
    reach = 1 + int(round((cfg.continuity_gap or 0.0) / cfg.cell_size))
    if not len(np.intersect1d(dilate(keys_a, reach), keys_b, assume_unique=True)):
        return "footprints apart"
    if cfg.continuity_gap is None:
        return "touching, no continuity merge"
    if cos <= cfg.delta_sem_continuous:
        return "touching, cosine under the continuity threshold"
    if continues(keys_a, keys_b, cfg.cell_size):
        return "linkable as built"
    compact = planar_line(keys_a, cfg.cell_size) is None and planar_line(keys_b, cfg.cell_size) is None
    return "touching, compact shapes" if compact else "touching, planar shapes not collinear"


def _cosine(scene: SceneMap, row: dict[int, int], a: int, b: int) -> float:
    """Cosine of the (unit) embeddings of instances `a` and `b` (`row`: id -> embedding row); 1
    for a map without embeddings."""
    return float(scene.embeddings[row[a]] @ scene.embeddings[row[b]]) if scene.embeddings is not None else 1.0


def same_label_pairs(scene: SceneMap, main: dict[int, int], labels: dict[int, str],
                     cfg: MappingConfig) -> list[dict]:
    """Every pair of instances of a built map that carry the same label: {"label", "a", "b" (ids),
    "same_object" (both instances' main object, `mask_attribution`, is one ground-truth object: a
    split fragment), "named_wrong" (for different objects: one of them is of another category than
    the label, `labels` = gt id -> category), "shared_frames" (frames both were seen in), "cause"
    (`fragment_cause`, split fragments only, else None)}."""
    keys = instance_keys(scene)
    row = {inst.id: k for k, inst in enumerate(scene.instances)}
    by_label: dict[str, list] = {}
    for inst in scene.instances:
        by_label.setdefault(inst.label, []).append(inst)
    out = []
    for label, group in sorted(by_label.items()):
        for k, a in enumerate(group):
            for b in group[k + 1:]:
                ma, mb = main.get(a.id), main.get(b.id)
                same = ma is not None and ma == mb
                wrong = not same and any(labels.get(m, label).lower() != label.lower() for m in (ma, mb) if m is not None)
                out.append({"label": label, "a": a.id, "b": b.id, "same_object": same, "named_wrong": wrong,
                            "shared_frames": len(set(a.frames) & set(b.frames)),
                            "cause": (fragment_cause(keys[a.id], keys[b.id], _cosine(scene, row, a.id, b.id), cfg)
                                      if same else None)})
    return out


def extra_instances(scene: SceneMap, main: dict[int, int], cfg: MappingConfig) -> list[dict]:
    """The instances beyond one per ground-truth object (what Instance Diff counts over the seen
    objects): for every object that is the main object (`mask_attribution`) of several instances,
    each but the heaviest (most fused observations; ties: more cells, lower id) as {"object",
    "primary", "extra" (ids), "same_label" (the extra carries the primary's label), "cause"
    (`fragment_cause` of the pair)}."""
    keys = instance_keys(scene)
    row = {inst.id: k for k, inst in enumerate(scene.instances)}
    by_object: dict[int, list] = {}
    for inst in scene.instances:
        if main.get(inst.id) is not None:
            by_object.setdefault(main[inst.id], []).append(inst)
    out = []
    for obj, group in sorted(by_object.items()):
        group.sort(key=lambda inst: (-inst.weight, -len(keys.get(inst.id, ())), inst.id))
        first = group[0]
        for inst in group[1:]:
            cos = _cosine(scene, row, first.id, inst.id)
            out.append({"object": obj, "primary": first.id, "extra": inst.id, "same_label": inst.label == first.label,
                        "cause": fragment_cause(keys[first.id], keys[inst.id], cos, cfg)})
    return out
