"""Single-frame against fused mask categorisation, the figure the realism profile is calibrated on.

    python -m iesm_agent.evals.studies.calibration --seeds 10-12 --out docs/results/calibration

Per frame (`frame_top1`): every segmenter mask whose pixels have IoU >= 0.5 with one ground-truth
instance's pixels in that frame (inst.png) is a matched mask; top-1 = share of matched masks whose
embedding's best category (Z = F E^T over scene.json's categories) is the instance's label
(the matching-normalised top-1 of one frame). Fused: the built map's matching-normalised top-1
(mapping metrics, observed footprint). Paper, real data, fused maps: 0.447 Replica, 0.210 HM3D-Sem.
"""

from __future__ import annotations

import sys
from pathlib import Path

import numpy as np

from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, seeds_note, log_stderr, run_checked, scene_frames, study_command,
               study_main, write_table)


def frame_top1(frames_dir: Path) -> dict:
    """{"masks", "matched", "top1", "top1_small_masks", "top1_large_masks"} over every frame."""
    from ...frames import FrameSet
    from ...mapping.build import category_vectors
    from ...sim.ground_truth import GroundTruth

    frames = FrameSet.open(frames_dir)
    categories, e = category_vectors(frames)
    index = {c.lower(): j for j, c in enumerate(categories)}
    label = {int(o["id"]): index.get(str(o["label"]).lower(), -1) for o in GroundTruth.load(frames_dir).objects}
    hits, areas, masks = [], [], 0
    for frame in frames:
        seg, inst = frame.segmentation, frame.instance_ids.ravel()
        counts = np.bincount(inst)
        for mask, emb in zip(seg.masks, seg.embeddings):
            masks += 1
            ids = inst[mask.ravel()]
            if not len(ids):
                continue
            top = np.bincount(ids).argmax()
            inter = int(np.count_nonzero(ids == top))
            if top == 0 or inter / (len(ids) + counts[top] - inter) < 0.5:
                continue
            hits.append(int(np.argmax(e @ emb)) == label[int(top)])
            areas.append(len(ids))
    hits_a, areas_a = np.array(hits, bool), np.array(areas)
    small = areas_a < 1500
    return {"masks": masks, "matched": len(hits), "top1": float(hits_a.mean()) if len(hits) else 0.0,
            "top1_small_masks": float(hits_a[small].mean()) if small.any() else None,
            "top1_large_masks": float(hits_a[~small].mean()) if (~small).any() else None}


def run_study(seeds: list[int], out: Path, realism: str, seeds_arg: str, work: Path | None = None, log=print) -> dict:
    from ...config import MappingConfig
    from ...sim.ground_truth import GroundTruth
    from ...store import load_map
    from ..mapping import EvalContext, prediction_from_map, score

    rows = {}
    with scene_frames(work) as root:
        for seed in seeds:
            frames_dir = root.prepare(seed, "small", False, realism)
            per_frame = frame_top1(frames_dir)
            scene = load_map(root.built(frames_dir))
            ctx = EvalContext.create(GroundTruth.load(frames_dir), frames_dir, MappingConfig())
            fused = score(prediction_from_map(scene, ctx), ctx)["auc_top"]
            rows[seed] = {**per_frame, "fused_top1": fused["top1_match"], "fused_auc_match": fused["match"]}
            log(f"{realism} seed {seed}: per-frame top-1 {per_frame['top1']:.3f} ({per_frame['matched']} masks), "
                f"fused {fused['top1_match']:.3f}")
    keys = ("top1", "top1_small_masks", "top1_large_masks", "fused_top1", "fused_auc_match")
    mean = {k: float(np.mean([r[k] for r in rows.values() if r[k] is not None])) for k in keys}
    lines = [f"Profile `{realism}`, `--size small` walled scenes, seeds {seeds_arg} ({seeds_note(seeds_arg)}).", "",
             "| seed | matched masks | per-frame top-1 | small masks (< 1500 px) | large masks | fused top-1 (map) | "
             "fused AUC match |", "|---|---:|---:|---:|---:|---:|---:|"]
    fmt = lambda v: "-" if v is None else f"{v:.3f}"  # noqa: E731
    for seed, r in rows.items():
        lines.append(f"| {seed} | {r['matched']} | " + " | ".join(fmt(r[k]) for k in keys) + " |")
    lines.append("| mean | | " + " | ".join(fmt(mean[k]) for k in keys) + " |")
    lines += ["", "Paper, real data (fused maps, matching-normalised top-1): Replica 0.447, HM3D-Sem 0.210."]
    summary = {"seeds": seeds, "realism": realism, "rows": rows, "mean": mean}
    write_table(out, "Per-frame against fused mask categorisation",
                study_command("calibration", seeds_arg, realism, out), "\n".join(lines), summary)
    return summary


def command(seeds: Seeds = "10-14", realism: Realism = "realistic",
            out: Out = Path("docs/results/calibration-realistic"), work: Work = None,
            allow_tuning_seeds: AllowTuningSeeds = False) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, realism, seeds, work, log=log_stderr))


def main(argv: list[str] | None = None) -> int:
    return study_main("calibration", __doc__, command, argv)


if __name__ == "__main__":
    sys.exit(main())
