"""Why matched instances of built maps carry the wrong label: the per-cause table, one command:

    python -m iesm_agent.evals.studies.label_errors --seeds 0-4 --allow-tuning-seeds --realism realistic --out docs/results/label-errors-tuning

For each seed: render the scene (iesm_agent.sim, the given profile), build the map (MappingConfig()),
pair its instances with the observed ground-truth footprints (top-down IoU > 0.5, evals/mapping.py)
and give every paired instance whose label is not its object's category one cause
(evals/label_errors.py: drowned by a neighbour, near-synonym, segmenter wrong in most own masks,
other). Writes OUT/table.md (counts per cause, then every mislabelled instance) + OUT/summary.json.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Optional

import numpy as np

from ...config import MappingConfig
from ...frames import FrameSet
from ...mapping.build import MapBuilder, category_vectors
from ...sim.ground_truth import GroundTruth
from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, log_stderr, run_checked, scene_frames, study_command,
               study_main, write_table)
from ..label_errors import CAUSES, NEIGHBOUR_SHARE, label_error, mask_evidence
from ..mapping import EvalContext, named_right, pairs, prediction_from_map


def study_scene(frames_dir: Path) -> dict:
    """{"n_gt", "n_matched", "n_wrong", "errors": [per mislabelled matched instance: {"object",
    "true", "label", "small", "stacked", "cells" (observed footprint), **`label_error`}]} on one
    frame directory, the map built with MappingConfig()."""
    frames = FrameSet.open(frames_dir)
    categories, e = category_vectors(frames)
    gt = GroundTruth.load(frames_dir)
    cfg = MappingConfig().model_copy(update={"cell_size": frames.meta.cell_size})
    builder = MapBuilder(frames.intrinsics, cfg)
    for frame in frames:
        builder.add(frame, frame.segmentation)
    scene = builder.finish(categories, e, scene_id=frames.meta.scene_id,
                           embedding_space=frames.meta.embedding_space, second_pass=True)
    ctx = EvalContext.create(gt, frames_dir, cfg)
    pred = prediction_from_map(scene, ctx)
    matches = pairs(pred, ctx)
    wrong = {g: matches[g] for g, ok in named_right(pred, ctx, matches).items() if not ok}
    row = {int(i): k for k, i in enumerate(pred.ids.tolist())}
    obs = scene.observations[:, :3].astype(int).tolist() if scene.observations is not None else []
    masks_of: dict[int, list[tuple[int, int]]] = {}
    for inst, frame_index, mask in obs:
        masks_of.setdefault(inst, []).append((frame_index, mask))
    evidence = mask_evidence(frames, {m for p in wrong.values() for m in masks_of.get(p, [])}, e)
    labels = {int(o["id"]): str(o["label"]) for o in gt.objects}
    cells = dict(zip(*[a.tolist() for a in np.unique(ctx.gt_cells[1], return_counts=True)]))
    errors = []
    for g, p in sorted(wrong.items()):
        label_class = int(pred.ranking[row[p], 0])
        masks = [evidence[m] for m in masks_of.get(p, []) if m in evidence]
        errors.append({"object": g, "true": labels[g], "label": categories[label_class], "small": g in ctx.small,
                       "stacked": g in ctx.stacked, "cells": int(cells.get(g, 0)),
                       **label_error(g, ctx.gt_class[g], label_class, masks, labels, categories, e)})
    return {"n_gt": len(ctx.gt_ids), "n_matched": len(matches), "n_wrong": len(wrong), "errors": errors}


def table_markdown(per_scene: dict[str, dict], realism: str, seeds_arg: str) -> str:
    rows = list(per_scene.values())
    errors = [(name, err) for name, r in per_scene.items() for err in r["errors"]]
    n_gt, n_matched, n_wrong = (sum(r[k] for r in rows) for k in ("n_gt", "n_matched", "n_wrong"))
    lines = [f"Profile `{realism}`; seeds {seeds_arg}; {len(rows)} simulated scenes ({', '.join(per_scene)}); the map "
             f"built with `MappingConfig()`. Of {n_gt} seen ground-truth objects, {n_matched} are matched (top-down "
             f"IoU > 0.5) and {n_wrong} of those carry another category's label. Each gets one cause "
             "(evals/label_errors.py), tested in this order: **neighbour** (the label is the category of another "
             f"object making up >= {NEIGHBOUR_SHARE:g} of the instance's mask pixels, or the mean embedding of "
             "the object's own masks alone is named right: other objects' masks or pixels turned it), "
             "**near-synonym** (one name ends with the other, or both end with the same word), **segmenter** (the "
             "mean embedding of the object's own masks alone is named wrong), **other** (the category is not in "
             "the list). Totals over the scenes; small = the dataset's small categories, stacked = footprint over "
             "another object's by half or more.", "",
             "| cause | mislabelled | small | stacked |", "|---|---:|---:|---:|"]
    for cause in CAUSES:
        got = [err for _n, err in errors if err["cause"] == cause]
        lines.append(f"| {cause} | {len(got)} | {sum(err['small'] for err in got)} | "
                     f"{sum(err['stacked'] for err in got)} |")
    lines.append(f"| all | {len(errors)} | {sum(err['small'] for _n, err in errors)} | "
                 f"{sum(err['stacked'] for _n, err in errors)} |")
    lines += ["", "Every mislabelled matched instance: own masks = masks that mostly show the object (those the "
              "segmenter calls right / all), own-mask label = the best category of the mean of their embeddings, "
              "other masks = masks of other objects fused in, largest neighbour = the other object with most "
              "pixels in the instance's masks (its share).", "",
              "| scene | object | true | label | cause | cells | small | stacked | own masks right / all | "
              "own-mask label | other masks | largest neighbour (share) |",
              "|---|---:|---|---|---|---:|---|---|---:|---|---:|---|"]
    for name, err in sorted(errors, key=lambda ne: (CAUSES.index(ne[1]["cause"]), ne[0], ne[1]["object"])):
        neighbour = f"{err['neighbour']} ({err['neighbour_share']:.2f})" if err["neighbour"] else ""
        lines.append(f"| {name} | {err['object']} | {err['true']} | {err['label']} | {err['cause']} | {err['cells']} | "
                     f"{'yes' if err['small'] else ''} | {'yes' if err['stacked'] else ''} | "
                     f"{err['own_right']} / {err['own_masks']} | {err['own_label'] or ''} | {err['other_masks']} | "
                     f"{neighbour} |")
    return "\n".join(lines)


def run_study(seeds: list[int], out: Path, *, realism: str = "realistic", seeds_arg: Optional[str] = None,
              work: Optional[Path] = None, log=print) -> dict:
    """Render (or reuse, under `work`) each seed's frames, diagnose them, write table.md and summary.json."""
    seeds_arg = seeds_arg or ",".join(map(str, seeds))
    per_scene: dict[str, dict] = {}
    with scene_frames(work) as cache:
        for seed in seeds:
            result = study_scene(cache.prepare(seed, "small", False, realism))
            per_scene[f"sim-small-{seed}"] = result
            causes = [err["cause"] for err in result["errors"]]
            log(f"{realism} seed {seed}: {result['n_wrong']} of {result['n_matched']} matched mislabelled; "
                + ", ".join(f"{c} {causes.count(c)}" for c in CAUSES))
    command = study_command("label_errors", seeds_arg, realism, out)
    write_table(out, f"Mislabelled matched instances by cause ({realism} profile)", command,
                table_markdown(per_scene, realism, seeds_arg),
                {"seeds": seeds, "realism": realism, "scenes": per_scene})
    return per_scene


def command(seeds: Seeds = "0-4", realism: Realism = "realistic",
            out: Out = Path("docs/results/label-errors-tuning"), work: Work = None,
            allow_tuning_seeds: AllowTuningSeeds = False) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, realism=realism, seeds_arg=seeds, work=work,
                                            log=log_stderr))


def main(argv: list[str] | None = None) -> int:
    return study_main("label_errors", __doc__, command, argv)


if __name__ == "__main__":
    sys.exit(main())
