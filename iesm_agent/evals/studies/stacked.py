"""Stacked objects, ours against the 2D baseline object by object, one command:

    python -m iesm_agent.evals.studies.stacked --seeds 0-4 --realism realistic --allow-tuning-seeds --out docs/results/stacked-tuning

For each seed: render the scene (iesm_agent.sim, the given profile), build our map
(MappingConfig()) and the VLMaps-style 2D point-wise map from the same frames and masks, and give
every stacked ground-truth object (an item on a table, shelf or counter, a picture on its wall:
evals/mapping.py) one outcome on each (evals/stacked.py): ours named right / named wrong /
never segmented / swallowed / split / inflated / partial, the baseline (ground-truth masks) named
right / named wrong / no reading. Writes OUT/table.md (outcomes side by side, per category, every
object the baseline names right and ours not) + OUT/summary.json (every object's record).
"""

from __future__ import annotations

import sys
from collections import Counter
from pathlib import Path
from typing import Optional

import numpy as np

from ...config import MappingConfig
from ...frames import FrameSet
from ...mapping.build import MapBuilder, category_vectors
from ...sim.ground_truth import GroundTruth
from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, log_stderr, run_checked, scene_frames, study_command,
               study_main, write_table)
from ..baseline2d import PointwiseMap2D
from ..mapping import EvalContext, prediction_from_map, prediction_from_pointwise, score
from ..mapping_causes import mask_objects, unmatched_causes
from ..stacked import BASELINE_CLASSES, OUR_CLASSES, outcome_counts, stacked_outcomes

#: our classes where an own instance holds the object but its footprint misses IoU > 0.5
FOOTPRINT_OFF = ("inflated", "partial")


def study_scene(frames_dir: Path) -> dict:
    """{"n_gt", "n_matched", "top1_gt" (ours, the baseline: stacked top-1 over all stacked objects,
    as the mapping table), "objects": `stacked_outcomes`} on one frame directory."""
    frames = FrameSet.open(frames_dir)
    categories, e = category_vectors(frames)
    gt = GroundTruth.load(frames_dir)
    cfg = MappingConfig().model_copy(update={"cell_size": frames.meta.cell_size})
    builder, flat2d = MapBuilder(frames.intrinsics, cfg), PointwiseMap2D(frames.intrinsics, e, cfg)
    for frame in frames:
        builder.add(frame, frame.segmentation)
        flat2d.add(frame, frame.segmentation)
    scene = builder.finish(categories, e, scene_id=frames.meta.scene_id,
                           embedding_space=frames.meta.embedding_space, second_pass=True)
    ctx = EvalContext.create(gt, frames_dir, cfg)
    pred = prediction_from_map(scene, ctx)
    baseline = prediction_from_pointwise(*flat2d.finish(), cfg.cell_size, ctx)
    ours, base = score(pred, ctx), score(baseline, ctx)
    shows = mask_objects(frames, cfg.min_mask_pixels)
    causes = unmatched_causes(pred.cells[:2], ctx.gt_cells[:2], ctx.gt_ids, set(ours["matched_ids"]),
                              scene.observations, shows)
    return {"n_gt": ours["n_gt"], "n_matched": ours["n_matched"],
            "top1_gt": {"ours": ours["stacked"]["top1_gt"], "baseline": base["stacked"]["top1_gt"]},
            "objects": stacked_outcomes(ctx, pred, baseline, scene.observations, shows, causes)}


def _label_right(r: dict) -> bool:
    return r["our_label"] is not None and r["our_label"].lower() == r["category"].lower()


def table_markdown(per_scene: dict[str, dict], realism: str, seeds_arg: str) -> str:
    objects = [(name, r) for name, scene in per_scene.items() for r in scene["objects"]]
    records = [r for _n, r in objects]
    n = len(records)
    counts = outcome_counts(records)
    ours_right = sum(r["ours"] == "named right" for r in records)
    base_right = sum(r["baseline"] == "named right" for r in records)
    mean = {k: float(np.mean([s["top1_gt"][k] for s in per_scene.values()])) for k in ("ours", "baseline")}
    lines = [f"Profile `{realism}`; seeds {seeds_arg}; {len(per_scene)} simulated scenes ({', '.join(per_scene)}); our "
             "map built with `MappingConfig()`, the 2D point-wise baseline (VLMaps-style) from the same frames and "
             "masks, given the ground-truth masks. Stacked objects: ground-truth objects whose box footprint lies "
             "over another's by half or more (evals/mapping.py; an item on a table, shelf or counter, a picture or "
             f"window in its wall); their support is the object under them (evals/stacked.py). {n} stacked objects: "
             f"named right by ours {ours_right} ({ours_right / max(n, 1):.3f} pooled), by the baseline {base_right} "
             f"({base_right / max(n, 1):.3f}); per scene, as the mapping table averages it: ours {mean['ours']:.3f}, "
             f"baseline {mean['baseline']:.3f}.", "",
             "## Outcomes side by side", "",
             "Ours: named right / named wrong (an instance paired by top-down IoU > 0.5), else the cause of "
             "evals/mapping_causes.py: never segmented (no mask showing mostly it reached the map), swallowed (most "
             "of its masks went into other objects' instances, such as its support's), split, inflated / partial "
             "(an own instance holds it but its footprint is too large / too small for IoU > 0.5). Label right: "
             "the paired or own instance carries the object's category (for inflated / partial, the footprint is "
             "the only fault). Label = support: the instance carries its support's category. Height band off: the "
             "instance's top heights on the object's cells lie nearer its support's top than the object's own.", "",
             "| ours | objects | baseline named right | baseline named wrong | baseline no reading | our label right "
             "| our label = support | height band off |",
             "|---|" + "---:|" * 7]
    for cls in OUR_CLASSES:
        got = [r for r in records if r["ours"] == cls]
        lines.append(f"| {cls} | {len(got)} | " + " | ".join(str(counts[cls][b]) for b in BASELINE_CLASSES)
                     + f" | {sum(map(_label_right, got))} | {sum(r['our_label_support'] for r in got)} | "
                     f"{sum(r['band_off'] for r in got)} |")
    base_wrong = [r for r in records if r["baseline"] == "named wrong"]
    ours_wrong = [r for r in records if r["ours"] == "named wrong"]
    lines += ["", f"Named wrong with the support's category: ours {sum(r['our_label_support'] for r in ours_wrong)} of "
              f"{len(ours_wrong)}, the baseline {sum(r['baseline_label_support'] for r in base_wrong)} of "
              f"{len(base_wrong)} (its cells average the support's points under the item)."]
    lines += ["", "## Per category", "",
              "Objects the baseline names right and ours not, by our outcome; objects ours names right and the "
              "baseline not.", "",
              "| category | objects | ours right | baseline right | both right | baseline only (ours) | ours only |",
              "|---|---:|---:|---:|---:|---|---:|"]
    by_category: dict[str, list[dict]] = {}
    for r in records:
        by_category.setdefault(r["category"], []).append(r)
    for cat, got in sorted(by_category.items(), key=lambda kv: (-len(kv[1]), kv[0])):
        right = [r["ours"] == "named right" for r in got]
        base = [r["baseline"] == "named right" for r in got]
        only = Counter(r["ours"] for r, a, b in zip(got, right, base) if b and not a)
        lines.append(f"| {cat} | {len(got)} | {sum(right)} | {sum(base)} | {sum(a and b for a, b in zip(right, base))} | "
                     + ", ".join(f"{c} {k}" for c, k in sorted(only.items())) + " | "
                     f"{sum(a and not b for a, b in zip(right, base))} |")
    lines += ["", "## The objects the baseline names right and ours not", "",
              "IoU: the best top-down IoU of the paired or own instance with the object's observed footprint; "
              "tops (m): the object's observed median top / the instance's on the object's cells / the support's.", "",
              "| scene | object | category | on | ours | our label | IoU | tops (m) |", "|---|---:|---|---|---|---|---:|---|"]
    for name, r in objects:
        if r["baseline"] == "named right" and r["ours"] != "named right":
            tops = " / ".join(f"{t:.2f}" if t is not None else "-" for t in (r["top"], r["instance_top"], r["support_top"]))
            lines.append(f"| {name} | {r['object']} | {r['category']} | {r['support'] or ''} | {r['ours']} | "
                         f"{r['our_label'] or ''} | {r['iou']:.2f} | {tops} |")
    off = [r for r in records if r["ours"] in FOOTPRINT_OFF]
    lines += ["", f"Own instance, footprint off ({' / '.join(FOOTPRINT_OFF)}): {len(off)} objects, "
              f"{sum(map(_label_right, off))} of them labelled right (IoU "
              + ", ".join(f"{r['iou']:.2f}" for r in sorted(off, key=lambda r: r["iou"])) + ")."]
    return "\n".join(lines)


def run_study(seeds: list[int], out: Path, *, realism: str = "realistic", seeds_arg: Optional[str] = None,
              work: Optional[Path] = None, log=print) -> dict:
    """Render (or reuse, under `work`) each seed's frames, classify its stacked objects, write
    table.md and summary.json."""
    seeds_arg = seeds_arg or ",".join(map(str, seeds))
    per_scene: dict[str, dict] = {}
    with scene_frames(work) as cache:
        for seed in seeds:
            result = study_scene(cache.prepare(seed, "small", False, realism))
            per_scene[f"sim-small-{seed}"] = result
            got = Counter((r["ours"], r["baseline"]) for r in result["objects"])
            log(f"{realism} seed {seed}: {len(result['objects'])} stacked; top-1 over all ours "
                f"{result['top1_gt']['ours']:.3f} baseline {result['top1_gt']['baseline']:.3f}; "
                + ", ".join(f"{a} / {b} {k}" for (a, b), k in sorted(got.items())))
    command = study_command("stacked", seeds_arg, realism, out)
    write_table(out, f"Stacked objects, ours against the 2D baseline ({realism} profile)", command,
                table_markdown(per_scene, realism, seeds_arg),
                {"seeds": seeds, "realism": realism, "scenes": per_scene})
    return per_scene


def command(seeds: Seeds = "0-4", realism: Realism = "realistic", out: Out = Path("docs/results/stacked-tuning"),
            work: Work = None, allow_tuning_seeds: AllowTuningSeeds = False) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, realism=realism, seeds_arg=seeds, work=work,
                                            log=log_stderr))


def main(argv: list[str] | None = None) -> int:
    return study_main("stacked", __doc__, command, argv)


if __name__ == "__main__":
    sys.exit(main())
