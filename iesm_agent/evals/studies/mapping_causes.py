"""Why seen objects go unmatched: the per-cause table of the mapping study, one command:

    python -m iesm_agent.evals.studies.mapping_causes --seeds 0-4 --allow-tuning-seeds --realism realistic --out docs/results/mapping-causes-tuning
    python -m iesm_agent.evals.studies.mapping_causes --seeds 10-14 --realism realistic --out docs/results/mapping-causes-realistic

For each seed: render the scene (iesm_agent.sim, the given profile), build the map under each
configuration of `VARIANTS` (the paper's rules, our rules before geometry cleaning, the first
cleaning without depth smoothing, ours), match it
against the observed footprints (evals/mapping.py) and give every unmatched seen object one cause
(evals/mapping_causes.py); then, for ours, what became of each stacked object (named right, named
wrong, unmatched by cause) beside the 2D point-wise baseline with ground-truth masks. Writes
OUT/table.md + OUT/summary.json.
"""

from __future__ import annotations

import sys
from pathlib import Path
from typing import Callable, Optional

import numpy as np

from ...config import MappingConfig
from ...frames import FrameSet
from ...mapping.build import MapBuilder, category_vectors
from ...sim.ground_truth import GroundTruth
from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, log_stderr, run_checked, scene_frames, study_command,
               study_main, write_table)
from ..baseline2d import PointwiseMap2D
from ..mapping import EvalContext, named_right, pairs, prediction_from_map, prediction_from_pointwise, score
from ..mapping_causes import CAUSES, cause_counts, mask_objects, unmatched_causes

#: the configurations compared: name -> (title, factory)
VARIANTS: dict[str, tuple[str, Callable[[], MappingConfig]]] = {
    "paper": ("MappingConfig.paper()", MappingConfig.paper),
    "before": ("Ours before cleaning (MappingConfig.uncleaned())", lambda: MappingConfig.uncleaned()),
    "first-cut": ("Ours without depth smoothing (mask erosion 1 px, 3 points per cell)",
                  lambda: MappingConfig(depth_smooth_px=0, min_cell_points=3, top_fill_max_cos=None)),
    "no-tops": ("Ours without the tops seen at grazing incidence (top_fill_max_cos=None)",
                lambda: MappingConfig(top_fill_max_cos=None)),
    "ours": ("Ours (MappingConfig())", MappingConfig),
}


#: what became of a stacked object on our map: named right, named wrong, or unmatched for a cause
STACKED_GROUPS = ("named right", "named wrong", *CAUSES)


def stacked_groups(ctx: EvalContext, right: dict[int, bool], causes: dict[int, str],
                   baseline_right: dict[int, bool]) -> dict[str, dict[str, int]]:
    """{group: {"objects": n, "baseline_right": n}} over the scene's stacked objects: our group
    (`right`: matched ids -> named right; `causes` of the unmatched) and how many of them the 2D
    point-wise baseline with ground-truth masks names right."""
    out = {group: {"objects": 0, "baseline_right": 0} for group in STACKED_GROUPS}
    for i in sorted(ctx.stacked):
        group = ("named right" if right[i] else "named wrong") if i in right else causes[i]
        out[group]["objects"] += 1
        out[group]["baseline_right"] += int(baseline_right.get(i, False))
    return out


def study_scene(frames_dir: Path) -> dict:
    """{variant: {"n_gt", "n_pred", "n_matched", "instance_diff", "auc_match", "causes": {cause: n}},
    "stacked": `stacked_groups` of ours} on one frame directory."""
    frames = FrameSet.open(frames_dir)
    categories, e = category_vectors(frames)
    gt = GroundTruth.load(frames_dir)
    out: dict = {}
    shows: Optional[dict[tuple[int, int], int]] = None
    flat2d = PointwiseMap2D(frames.intrinsics, e, MappingConfig(cell_size=frames.meta.cell_size))
    for frame in frames:
        flat2d.add(frame, frame.segmentation)
    for name, (_title, make) in VARIANTS.items():
        cfg = make().model_copy(update={"cell_size": frames.meta.cell_size})
        builder = MapBuilder(frames.intrinsics, cfg)
        for frame in frames:
            builder.add(frame, frame.segmentation)
        scene = builder.finish(categories, e, scene_id=frames.meta.scene_id,
                               embedding_space=frames.meta.embedding_space, second_pass=True)
        ctx = EvalContext.create(gt, frames_dir, cfg)
        pred = prediction_from_map(scene, ctx)
        result = score(pred, ctx)
        if shows is None:
            shows = mask_objects(frames, cfg.min_mask_pixels)
        causes = unmatched_causes(pred.cells[:2], ctx.gt_cells[:2], ctx.gt_ids, set(result["matched_ids"]),
                                  scene.observations, shows)
        out[name] = {"n_gt": result["n_gt"], "n_pred": result["n_pred"], "n_matched": result["n_matched"],
                     "instance_diff": result["instance_diff"], "auc_match": result["auc_top"]["match"],
                     "causes": cause_counts(causes)}
        if name == "ours":
            baseline = prediction_from_pointwise(*flat2d.finish(), cfg.cell_size, ctx)
            out["stacked"] = stacked_groups(ctx, named_right(pred, ctx, pairs(pred, ctx)), causes,
                                            named_right(baseline, ctx, pairs(baseline, ctx)))
    return out


def table_markdown(per_scene: dict[str, dict], realism: str, seeds_arg: str) -> str:
    rows = list(per_scene.values())
    lines = [f"Profile `{realism}`; seeds {seeds_arg}; mean per scene over {len(rows)} simulated scenes "
             f"({', '.join(per_scene)}). Every evaluated ground-truth object (seen in at least "
             "`min_mask_pixels` pixels) that no instance matches (top-down IoU > 0.5 against the observed "
             "footprint) gets one cause (evals/mapping_causes.py; an instance is an object's own when most of "
             "its masks show that object): never segmented (no mask showing mostly it reached the map), "
             "swallowed (most of its masks went into other objects' instances), split (its masks went into "
             "two or more own instances, none covering half of it), inflated (an own instance covers half of "
             "it or more but is too large for IoU > 0.5), partial (its own instances cover under half of it).", "",
             "| configuration | seen objects | predicted | matched | " + " | ".join(CAUSES) + " | AUC match |",
             "|---|" + "---:|" * (len(CAUSES) + 4)]
    for name, (title, _make) in VARIANTS.items():
        mean = {k: float(np.mean([r[name][k] for r in rows])) for k in ("n_gt", "n_pred", "n_matched", "auc_match")}
        causes = [float(np.mean([r[name]["causes"][c] for r in rows])) for c in CAUSES]
        lines.append(f"| {title} | {mean['n_gt']:.1f} | {mean['n_pred']:.1f} | {mean['n_matched']:.1f} | "
                     + " | ".join(f"{c:.1f}" for c in causes) + f" | {mean['auc_match']:.3f} |")
    total = {g: {k: sum(r["stacked"][g][k] for r in rows) for k in ("objects", "baseline_right")}
             for g in STACKED_GROUPS}
    n = sum(t["objects"] for t in total.values())
    lines += ["", f"Stacked objects (their box footprint lies over another's by half or more), ours "
              f"(MappingConfig()), {n} over the {len(rows)} scenes: what became of each on our map, and how many of "
              "them the 2D point-wise baseline with ground-truth masks names right (top-1). Top-1 over all "
              f"stacked objects, pooled over the scenes (the mapping table averages per scene): ours {total['named right']['objects'] / max(n, 1):.3f}, baseline "
              f"{sum(t['baseline_right'] for t in total.values()) / max(n, 1):.3f}.", "",
              "| on our map | objects | named right by the baseline |", "|---|---:|---:|"]
    lines += [f"| {g} | {t['objects']} | {t['baseline_right']} |" for g, t in total.items()]
    return "\n".join(lines)


def run_study(seeds: list[int], out: Path, *, realism: str = "realistic", seeds_arg: Optional[str] = None,
              work: Optional[Path] = None, log=print) -> dict:
    """Render (or reuse, under `work`) each seed's frames, diagnose them, write table.md and summary.json."""
    seeds_arg = seeds_arg or ",".join(map(str, seeds))
    per_scene: dict[str, dict] = {}
    with scene_frames(work) as cache:
        for seed in seeds:
            frames_dir = cache.prepare(seed, "small", False, realism)
            result = study_scene(frames_dir)
            per_scene[f"sim-small-{seed}"] = result
            log(f"{realism} seed {seed}: " + "; ".join(
                f"{name} matched {result[name]['n_matched']}/{result[name]['n_gt']} {result[name]['causes']}"
                for name in VARIANTS))
    command = study_command("mapping_causes", seeds_arg, realism, out,
                            *(["--allow-tuning-seeds"] if set(seeds) & set(range(5)) else []))
    write_table(out, f"Unmatched seen objects by cause ({realism} profile)", command,
                table_markdown(per_scene, realism, seeds_arg),
                {"seeds": seeds, "realism": realism, "scenes": per_scene})
    return per_scene


def command(seeds: Seeds = "0-4", realism: Realism = "realistic",
            out: Out = Path("docs/results/mapping-causes-tuning"), work: Work = None,
            allow_tuning_seeds: AllowTuningSeeds = False) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, realism=realism, seeds_arg=seeds, work=work,
                                            log=log_stderr))


def main(argv: list[str] | None = None) -> int:
    return study_main("mapping_causes", __doc__, command, argv)


if __name__ == "__main__":
    sys.exit(main())
