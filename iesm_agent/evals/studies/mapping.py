"""The mapping study (paper Tables 1-3 on simulated scenes), one command per profile:

    python -m iesm_agent.evals.studies.mapping --seeds 10-14 --realism realistic --out docs/results/mapping-realistic

For each seed: generate a scene and render its frames (iesm_agent.sim, the given realism profile),
build our 2.5D map with and without the second pass, without geometry cleaning
(`MappingConfig.uncleaned()`) and under the paper's rules (`MappingConfig.paper()`), and the
VLMaps-style 2D point-wise map from the same frames and masks, score them all against both ground truths (observed footprint, full
object footprint; evals/mapping.py), and write OUT/table.md + OUT/summary.json.
"""

from __future__ import annotations

import sys
import time
from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import numpy as np
import typer

from ...config import MappingConfig
from ...frames import FrameSet
from ...mapping.build import MapBuilder, category_vectors
from ...sim.ground_truth import GroundTruth
from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, seeds_note, log_stderr, run_checked, scene_frames, study_command,
               study_main, write_table)
from ..baseline2d import PointwiseMap2D
from ..mapping import EvalContext, prediction_from_map, prediction_from_pointwise, score

METHODS = ("ours", "ours_no_second_pass", "ours_uncleaned", "paper", "pointwise_2d", "pointwise_2d_same")
TITLES = {"ours": "Ours (2.5D)", "ours_no_second_pass": "Ours w/o second pass",
          "ours_uncleaned": "Ours before issue 29 (no geometry cleaning, MappingConfig.uncleaned())",
          "paper": "Paper's rules (MappingConfig.paper())", "pointwise_2d": "2D point-wise + GT mask",
          "pointwise_2d_same": "2D point-wise + GT mask, on the objects ours matched"}
#: the baseline's rows: its instances are the ground-truth masks, so instance counts are undefined;
#: the "same objects" row differs from the full one only in the matched-object columns
BASELINES = ("pointwise_2d", "pointwise_2d_same")


FOOTPRINTS = {"observed": "observed footprint", "full": "full object footprint"}


def study_scene(frames_dir: Path, cfg: MappingConfig) -> dict:
    """Metrics of the three methods on one frame directory (with gt/), per ground truth:
    {"observed": {method: score}, "full": {...}, "scene": {...}}."""
    frames = FrameSet.open(frames_dir)
    cfg = cfg.model_copy(update={"cell_size": frames.meta.cell_size})
    categories, e = category_vectors(frames)
    builder, flat2d = MapBuilder(frames.intrinsics, cfg), PointwiseMap2D(frames.intrinsics, e, cfg)
    others = {name: MapBuilder(frames.intrinsics, make(cell_size=cfg.cell_size))
              for name, make in (("ours_uncleaned", MappingConfig.uncleaned), ("paper", MappingConfig.paper))}
    t0 = time.perf_counter()
    for frame in frames:
        builder.add(frame, frame.segmentation)
        flat2d.add(frame, frame.segmentation)
    build_s = time.perf_counter() - t0
    for frame in frames:
        for other in others.values():
            other.add(frame, frame.segmentation)
    kw = dict(scene_id=frames.meta.scene_id, embedding_space=frames.meta.embedding_space)
    maps = {"ours": builder.finish(categories, e, second_pass=True, **kw),
            "ours_no_second_pass": builder.finish(categories, e, second_pass=False, **kw),
            **{name: other.finish(categories, e, second_pass=True, **kw) for name, other in others.items()}}
    keys, scores = flat2d.finish()
    gt = GroundTruth.load(frames_dir)
    out: dict = {}
    for footprint in FOOTPRINTS:
        ctx = EvalContext.create(gt, frames_dir, cfg, footprint)
        out[footprint] = {name: score(prediction_from_map(scene, ctx), ctx) for name, scene in maps.items()}
        flat = prediction_from_pointwise(keys, scores, cfg.cell_size, ctx)
        out[footprint]["pointwise_2d"] = score(flat, ctx)
        out[footprint]["pointwise_2d_same"] = score(flat, ctx, only=set(out[footprint]["ours"]["matched_ids"]))
        for result in out[footprint].values():
            del result["matched_ids"]  # used above; the table needs only the counts
    out["scene"] = {"scene_id": frames.meta.scene_id, "frames": len(frames), "build_s": round(build_s, 2),
                    "embedding_space": frames.meta.embedding_space, "gt_instances": len(ctx.gt_ids),
                    "small_categories": sorted(ctx.small_labels), "stacked": len(ctx.stacked),
                    "single_view": {name: sum(len(i.frames) <= 1 for i in scene.instances) for name, scene in maps.items()}}
    return out


def _mean(results: list[dict], path: tuple[str, ...]) -> Optional[float]:
    values = []
    for r in results:
        for key in path:
            r = r.get(key) if isinstance(r, dict) else None
        if r is None:
            return None
        values.append(float(r))
    return float(np.mean(values))


COLUMNS = [  # (group, header, path into a method's result, shown for the 2D baseline)
    ("all", "predicted", ("n_pred",), False), ("all", "matched", ("n_matched",), False),
    ("all", "AUC pred", ("auc_top", "pred"), False), ("all", "AUC gt", ("auc_top", "gt"), False),
    ("all", "AUC match", ("auc_top", "match"), True), ("all", "top-1 match", ("auc_top", "top1_match"), True),
    ("all", "Inst. Diff", ("instance_diff",), False),
    ("topdown", "Acc", ("topdown", "acc"), True), ("topdown", "mAcc", ("topdown", "macc"), True),
    ("topdown", "mIoU", ("topdown", "miou"), True), ("topdown", "F-mIoU", ("topdown", "fmiou"), True),
    ("small", "AUC pred", ("small", "auc_top", "pred"), False), ("small", "AUC gt", ("small", "auc_top", "gt"), False),
    ("small", "AUC match", ("small", "auc_top", "match"), True),
    ("small", "top-1 match", ("small", "auc_top", "top1_match"), True),
    ("small", "Inst. Diff", ("small", "instance_diff"), False),
    ("stacked", "top-1 match", ("stacked", "top1_match"), True), ("stacked", "top-1 gt", ("stacked", "top1_gt"), True),
    ("stacked", "AUC match", ("stacked", "auc_top_match"), True),
]
INTEGER_COLUMNS = ("predicted", "matched", "Inst. Diff")
GROUPS = {"all": "Instances (Table 1)", "topdown": "Top-down label map (Table 2)",
          "small": "Small objects (Table 3)", "stacked": "Stacked objects"}


def summarise(per_scene: dict[str, dict]) -> dict:
    """Mean of every column over the scenes, per ground truth and method (None where a method
    has no value)."""
    results = list(per_scene.values())
    def shown_for(m: str, group: str, shown: bool) -> bool:
        if m not in BASELINES:
            return True
        return shown and not (m == "pointwise_2d_same" and group == "topdown")

    return {fp: {m: {f"{g}.{h}": (_mean([r[fp][m] for r in results], path) if shown_for(m, g, shown) else None)
                     for g, h, path, shown in COLUMNS} for m in METHODS} for fp in FOOTPRINTS}


def table_markdown(mean: dict, per_scene: dict[str, dict], realism: str, seeds_arg: str) -> str:
    gt = np.mean([r["scene"]["gt_instances"] for r in per_scene.values()])
    small = sorted({c for r in per_scene.values() for c in r["scene"]["small_categories"]})
    single = np.mean([r["scene"]["single_view"]["ours"] for r in per_scene.values()])
    lines = [f"Profile `{realism}`; seeds {seeds_arg} ({seeds_note(seeds_arg)}); mean over {len(per_scene)} simulated "
             f"scenes ({', '.join(per_scene)}; {gt:.1f} ground-truth instances seen per scene). Higher is better "
             "except Inst. Diff. '-': not defined for the 2D baseline, whose instances are the ground-truth masks by "
             "construction (as in the paper's Table 1). The 2D baseline's 'match' columns cover every ground-truth "
             "object (its masks are the ground truth); the row 'on the objects ours matched' scores it on the objects "
             "our map matched, the same population as ours.", "",
             f"Small categories (per dataset, bottom 20 % of footprints over the tuning worlds): {', '.join(small)}.", "",
             f"Instances of our map seen in one frame only: {single:.1f} per scene.", ""]
    for fp, fp_title in FOOTPRINTS.items():
        lines += [f"## Ground truth: {fp_title}", ""]
        for group, title in GROUPS.items():
            cols = [(h, f"{g}.{h}") for g, h, _p, _s in COLUMNS if g == group]
            lines += [f"### {title}", "", "| method | " + " | ".join(h for h, _ in cols) + " |",
                      "|---|" + "---:|" * len(cols)]
            for m in METHODS:
                v = mean[fp][m]
                cells = [("-" if v[k] is None else (f"{v[k]:.1f}" if h in INTEGER_COLUMNS else f"{v[k]:.3f}"))
                         for h, k in cols]
                lines.append(f"| {TITLES[m]} | " + " | ".join(cells) + " |")
            lines.append("")
    return "\n".join(lines)


def run_study(seeds: list[int], out: Path, *, realism: str = "realistic", seeds_arg: Optional[str] = None,
              size: str = "small", work: Optional[Path] = None, space: Optional[str] = None, log=print) -> dict:
    """Render (or reuse, under `work`) each seed's frames, study them, write table.md and summary.json."""
    seeds_arg = seeds_arg or ",".join(map(str, seeds))
    cfg = MappingConfig()
    per_scene: dict[str, dict] = {}
    with scene_frames(work) as cache:
        for seed in seeds:
            frames_dir = cache.prepare(seed, size, False, realism, space)
            result = study_scene(frames_dir, cfg)
            per_scene[result["scene"]["scene_id"]] = result
            o = result["observed"]
            log(f"{realism} {result['scene']['scene_id']}: AUC match {o['ours']['auc_top']['match']:.3f}, top-1 "
                f"{o['ours']['auc_top']['top1_match']:.3f}, Inst. Diff {o['ours']['instance_diff']} of "
                f"{o['ours']['n_gt']} (w/o 2nd pass {o['ours_no_second_pass']['instance_diff']})")
    mean = summarise(per_scene)
    command = study_command("mapping", seeds_arg, realism, out, f"--size {size}")
    summary = {"seeds": seeds, "realism": realism, "size": size, "config": cfg.model_dump(), "mean": mean,
               "scenes": per_scene}
    write_table(out, f"Mapping study ({realism} profile)", command,
                table_markdown(mean, per_scene, realism, seeds_arg), summary)
    return summary


class SceneSize(str, Enum):
    """--size: the simulator's scene sizes."""

    small = "small"
    hm3d = "hm3d"


def command(seeds: Seeds = "10-14", realism: Realism = "realistic",
            out: Out = Path("docs/results/mapping-realistic"), work: Work = None,
            allow_tuning_seeds: AllowTuningSeeds = False,
            size: Annotated[SceneSize, typer.Option(help="scene size")] = SceneSize.small,
            space: Annotated[Optional[str], typer.Option(help="embedding space (default: the best available)")] = None) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, realism=realism, seeds_arg=seeds, size=size.value,
                                            work=work, space=space, log=log_stderr))


def main(argv: list[str] | None = None) -> int:
    return study_main("mapping", __doc__, command, argv)


if __name__ == "__main__":
    sys.exit(main())
