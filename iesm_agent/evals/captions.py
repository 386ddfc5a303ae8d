"""Caption quality against simulator ground truth (the `captions` section of `iesm eval-map`).

Built instances are paired with ground-truth objects by `evals.matching.match_instances`
(top-down IoU > 0.5, against the observed footprints when the frame directory is given); only pairs whose built instance was seen in at least `MIN_FRAMES` frames
count. Two colour scores:
* `colour_acc`: the caption's colour is in the same colour family as the ground truth's, as the
  lexicon reads them (navy blue ~ navy, light grey ~ grey, dark brown ~ brown, tan ~ beige);
  this is what decides whether a query's colour word matches a caption;
* `colour_name_acc`: the same XKCD name exactly (stricter: "light grey" vs "grey" is a miss).
Instances without a caption colour count as misses.
"""

from __future__ import annotations

from collections import Counter
from pathlib import Path
from typing import Optional

from ..colours import colour_family, colour_name
from ..store.model import SceneMap

#: an instance must be seen in at least this many frames to be scored
MIN_FRAMES = 3


def _gt_colour(obj: dict) -> Optional[str]:
    name = (obj.get("tags") or {}).get("color")
    if not name and obj.get("color_rgb") is not None:
        name = colour_name(obj["color_rgb"])
    return name


def colour_scores(scene: SceneMap, gt, min_frames: int = MIN_FRAMES, frames_dir: Optional[Path] = None) -> dict:
    """{"colour_acc", "colour_name_acc", "n", "min_frames", "truths", "misses"} of the map's caption
    colours (accuracies None when no instance qualifies); `truths` counts the scored instances per
    true colour, `misses` the family misses as {"true colour -> said colour": count}."""
    from ..captioning.views import frames_seen
    from .observed import observed_masks
    from .matching import match_instances

    matched = match_instances(scene, gt, observed=observed_masks(frames_dir, gt))
    seen = (frames_seen(scene.observations) if scene.observations is not None
            else {i.id: len(i.frames) for i in scene.instances})
    objects = {int(o["id"]): o for o in gt.objects}
    family_hits = name_hits = n = 0
    truths: Counter[str] = Counter()
    misses: Counter[str] = Counter()
    for gt_id, pred_id in matched.items():
        truth = _gt_colour(objects.get(gt_id, {}))
        if truth is None or seen.get(pred_id, 0) < min_frames:
            continue
        said = scene.instance(pred_id).tags.get("color")
        n += 1
        truths[truth] += 1
        name_hits += said == truth
        hit = said is not None and colour_family(said) == colour_family(truth)
        family_hits += hit
        if not hit:
            misses[f"{truth} -> {said}"] += 1
    return {"colour_acc": family_hits / n if n else None, "colour_name_acc": name_hits / n if n else None,
            "n": n, "min_frames": min_frames, "truths": dict(truths), "misses": dict(misses)}


def eval_section(scene: SceneMap, gt, frames_dir: Path) -> dict:
    """The `captions` section of `iesm eval-map`. A map captioned before (meta "captioner") is
    scored as it is; otherwise the offline captioner is run on `frames_dir` first (when the map
    has observations), and `source` says which."""
    source = scene.meta.get("captioner")
    if source is None:
        if scene.observations is None or not Path(frames_dir).is_dir():
            return {"captions": {"colour_acc": None, "n": 0, "source": "none (map not captioned)"}}
        from ..captioning.offline import OfflineCaptioner
        from ..captioning.pipeline import caption_map

        scene = caption_map(scene, frames_dir, OfflineCaptioner())
        source = "offline (run by eval-map)"
    return {"captions": {**colour_scores(scene, gt, frames_dir=frames_dir), "source": source}}
