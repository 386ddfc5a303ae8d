"""The room-segmentation table over seeded simulator scenes (walled and open-plan):
per-cell CLIP-like labels alone (the paper's baseline), LSD components with majority labels (the
paper's method) and LSD components with the contextual open-plan split (ours).

    python -m iesm_agent.evals.studies.rooms --seeds 0-4 --out evals/rooms [--work DIR]

Scenes are simulated and mapped with `iesm sim` and `iesm build-map` into the work directory
(kept between runs); writes OUT/table.md and OUT/summary.json (metric definitions: evals/rooms.py).
"""

from __future__ import annotations

import argparse
import json
import statistics
import tempfile
from pathlib import Path

from ...errors import IesmError
from ...fileio import write_text
from . import parse_seeds

METHODS = {"baseline": "per-cell labels (CLIP-like baseline)", "lsd": "LSD components + majority (paper)",
           "split": "LSD + contextual split (ours)"}
METRICS = ("acc", "macc", "miou", "precision", "recall")


def prepare_scene(work: Path, seed: int, open_plan: bool) -> tuple[Path, Path]:
    """(frame dir, built map) of one scene, simulated and mapped unless already in `work`."""
    from ...frames import FrameSet
    from ...mapping.build import build_map
    from ...sim import generate_scene, render_frames
    from ...store import save_map

    frames = work / f"{'open' if open_plan else 'walled'}-{seed}"
    built = frames.with_suffix(".iesm")
    if not (frames / "gt" / "rooms.npy").is_file():
        render_frames(generate_scene(seed, "small", open_plan), frames)
    if not built.is_file():
        save_map(build_map(FrameSet.open(frames)), built)
    return frames, built


def score_scene(frames: Path, built: Path, seed: int) -> dict:
    """Metrics of the three methods on one built map against its ground truth."""
    from ...rooms import CellLabels, RoomConfig, segment_scene
    from ...sim.ground_truth import GroundTruth
    from ...sim.room_labels import ViewpointLabels
    from ...store import load_map
    from ..rooms import baseline_scores, gt_room_labels, resample, score_room_map

    scene, gt = load_map(built), GroundTruth.load(frames)
    labels = ViewpointLabels(frames, seed=seed).cell_labels(scene.grid)
    gt_labels = gt_room_labels(gt)
    out = {"baseline": baseline_scores(CellLabels(resample(labels.labels, scene.grid, gt.grid), labels.names),
                                       gt.rooms, gt_labels)}
    for name, split in (("lsd", False), ("split", True)):
        seg = segment_scene(scene, labels, RoomConfig(split=split))
        out[name] = {**score_room_map(resample(seg.room_map, scene.grid, gt.grid), seg.labels, gt.rooms, gt_labels),
                     "splits": seg.splits}
    return out


def _mean(rows: list[dict], method: str) -> dict:
    return {m: statistics.fmean(r[method][m] for r in rows) for m in METRICS}


def render_table(summary: dict) -> str:
    lines = ["# Room segmentation on simulated scenes", "",
             f"Seeds {summary['seeds']}; built maps (`iesm sim` + `iesm build-map`), simulated viewpoint-dependent",
             "per-cell labels (`sim/room_labels.py`); metrics as defined in `iesm_agent/evals/rooms.py`",
             "(Acc/mAcc/mIoU over cells inside ground-truth rooms; per-room precision/recall by best overlap).",
             "Regenerate: `python -m iesm_agent.evals.studies.rooms --seeds "
             f"{summary['seeds_arg']} --out evals/rooms`.", ""]
    for setting in ("walled", "open"):
        lines += [f"## {'Walled scenes' if setting == 'walled' else 'Open-plan scenes'} "
                  f"({len(summary['scenes'][setting])} scenes)", "",
                  "| Method | Acc | mAcc | mIoU | precision | recall |", "|---|---:|---:|---:|---:|---:|"]
        for method, title in METHODS.items():
            m = summary["mean"][setting][method]
            lines.append(f"| {title} | " + " | ".join(f"{m[k]:.3f}" for k in METRICS) + " |")
        lines.append("")
    lines += [f"Skipped: {'; '.join(summary['skipped'])}", ""] if summary["skipped"] else []
    lines += ["Paper (Table 3, MP3D): CLIP baseline 0.73 / 0.72 / 0.53 -> ours 0.89 / 0.86 / 0.75 (Acc / mAcc / mIoU).",
              ""]
    return "\n".join(lines)


def run_study(seeds: list[int], out: Path, work: Path, seeds_arg: str) -> dict:
    scenes: dict[str, list[dict]] = {"walled": [], "open": []}
    skipped: list[str] = []
    for seed in seeds:
        for setting in scenes:
            try:
                frames, built = prepare_scene(work, seed, setting == "open")
            except Exception as exc:  # a scene the simulator or mapper cannot make is reported, not fatal
                skipped.append(f"{setting} seed {seed}: {type(exc).__name__}: {exc}")
                print(f"skipped {skipped[-1]}", flush=True)
                continue
            scenes[setting].append({"seed": seed, **score_scene(frames, built, seed)})
            print(f"{setting} seed {seed}: " + ", ".join(
                f"{method} miou {scenes[setting][-1][method]['miou']:.3f}" for method in METHODS), flush=True)
    summary = {"seeds": seeds, "seeds_arg": seeds_arg, "scenes": scenes, "skipped": skipped,
               "mean": {s: {m: _mean(rows, m) for m in METHODS} for s, rows in scenes.items()}}
    out.mkdir(parents=True, exist_ok=True)
    for name, text in (("summary.json", json.dumps(summary, indent=2) + "\n"), ("table.md", render_table(summary))):
        write_text(out / name, text)
    return summary


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m iesm_agent.evals.studies.rooms", description=__doc__.split("\n\n")[0])
    parser.add_argument("--seeds", default="0-4")
    parser.add_argument("--out", type=Path, default=Path("evals/rooms"))
    parser.add_argument("--work", type=Path, default=None, help="scene cache (default: a temporary directory)")
    args = parser.parse_args(argv)
    try:
        seeds = parse_seeds(args.seeds)
        if args.work is None:
            with tempfile.TemporaryDirectory() as tmp:
                summary = run_study(seeds, args.out, Path(tmp), args.seeds)
        else:
            args.work.mkdir(parents=True, exist_ok=True)
            summary = run_study(seeds, args.out, args.work, args.seeds)
    except IesmError as exc:
        print(f"iesm: error: {exc}")
        return 2
    print(render_table(summary))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
