"""Where LSD + contextual split loses cells against the per-cell baseline, per cause, one command:

    python -m iesm_agent.evals.studies.room_causes --seeds 0-4 --realism realistic --allow-tuning-seeds --out docs/results/room-causes-tuning

The scenes and maps of the rooms study (walled and open plan, `iesm sim` + `iesm build-map`), the
same simulated per-cell labels and evaluated cells; every evaluated cell whose per-cell label is
right and whose room label (LSD + split) is wrong is lost, and gets one cause
(evals/room_causes.py); won cells are the reverse. Writes OUT/table.md + OUT/summary.json: lost
cells per cause and setting, per scene, and per ground-truth room that lost cells.
"""

from __future__ import annotations

import statistics
from pathlib import Path
from typing import Optional

import numpy as np

from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, run_checked, scene_frames, scene_rows, study_command,
               study_main, write_table)
from ..room_causes import CAUSES, lost_cells
from .rooms import scene_rooms

SETTINGS = {"walled": "Walled", "open": "Open plan"}
#: the room configurations compared: name -> (title, settings over `RoomConfig()`)
VARIANTS: dict[str, tuple[str, dict]] = {
    "before": ("`RoomConfig(wall_share=0.15)`, the wall share before issue 29's diagnosis", {"wall_share": 0.15}),
    "ours": ("`RoomConfig()`", {}),
}


def scene_causes(frames: Path, built: Path, seed: int) -> dict:
    """mIoU of the baseline, and per variant the mIoU of LSD + split and the per-room lost/won
    cells, of one scene."""
    from ...rooms import RoomConfig, segment_scene
    from ...rooms.scene import structural_masks
    from ..rooms import baseline_scores, gt_room_labels, resample, score_room_map

    scene, gt, labels, baseline, evaluated = scene_rooms(frames, built, seed)
    gt_labels = gt_room_labels(gt)
    ids = sorted(gt_labels)
    lut = np.full(int(gt.rooms.max(initial=-1)) + 2, -1, np.int64)  # true room id -> index, [-1] = none
    lut[ids] = np.arange(len(ids))
    gt_index = lut[gt.rooms]
    area = np.bincount(gt_index[gt_index >= 0], minlength=len(ids)) * gt.grid.cell_size ** 2
    walls = resample(structural_masks(scene)[0].astype(np.uint8), scene.grid, gt.grid, 0) > 0
    out: dict = {"baseline_miou": baseline_scores(baseline, gt.rooms, gt_labels, evaluated)["miou"]}
    for name, (_, settings) in VARIANTS.items():
        seg = segment_scene(scene, labels, RoomConfig(**settings))
        plain = segment_scene(scene, labels, RoomConfig(**settings, split=False))
        pred = resample(seg.room_map, scene.grid, gt.grid)
        rows = lost_cells(gt_index, [gt_labels[i] for i in ids], pred, seg.labels,
                          resample(plain.room_map, scene.grid, gt.grid), baseline.labels, baseline.names, evaluated,
                          walls, resample(seg.boundaries.raster.astype(np.uint8), scene.grid, gt.grid, 0) > 0)
        out[name] = {"miou": score_room_map(pred, seg.labels, gt.rooms, gt_labels, evaluated)["miou"],
                     "rooms": [{**row, "area": round(float(area[row["room"]]), 2)} for row in rows]}
    return out


def _scene_causes(scene: dict) -> dict[str, int]:
    """Lost cells per cause over one scene's rooms (one variant's entry)."""
    causes: dict[str, int] = {}
    for room in scene["rooms"]:
        for cause, n in room["causes"].items():
            causes[cause] = causes.get(cause, 0) + n
    return causes


def render_table(summary: dict) -> str:
    variants = "; ".join(f"{name}: {title}" for name, (title, _) in VARIANTS.items())
    lines = [f"Profile `{summary['realism']}`; seeds {summary['seeds_arg']}; LSD + split under two room "
             f"configurations ({variants}). A cell is "
             "lost when its per-cell label names its true room type and LSD + split's room label does not (won: the "
             "reverse); evaluated cells as in the rooms study. Causes (`iesm_agent/evals/room_causes.py`, first that "
             "holds): in no room, on a mapped wall, on a drawn line, or in free space no room reached (a pocket); "
             "swallowed, no line (the true room has no predicted room of its own, nor had it without the split); "
             "swallowed by split (it had one without the split); named by neighbour (its own room labelled as a "
             "room it touches; \"(objects)\": its per-cell labels alone would have named it right); wrong label "
             "(another type); split cut misplaced (cells of it put with a neighbour by the split's cut); line "
             "misplaced (put with a neighbour by a drawn line, the growth or the wall share, already without the "
             "split).", "", "## Lost cells per cause", "",
             "| cause | " + " | ".join(f"{title}, {name}" for title in SETTINGS.values() for name in VARIANTS) + " |",
             "|---|" + "---:|" * (len(SETTINGS) * len(VARIANTS))]
    scenes = summary["scenes"]
    totals = {(s, v): [_scene_causes(scene[v]) for scene in scenes.get(s, [])] for s in SETTINGS for v in VARIANTS}
    for cause in CAUSES:
        lines.append(f"| {cause} | " + " | ".join(str(sum(c.get(cause, 0) for c in totals[s, v]))
                                                  for s in SETTINGS for v in VARIANTS) + " |")
    for key, title in (("lost", "lost, all causes"), ("won", "won")):
        lines.append(f"| **{title}** | " + " | ".join(
            str(sum(r[key] for scene in scenes.get(s, []) for r in scene[v]["rooms"]))
            for s in SETTINGS for v in VARIANTS) + " |")
    lines.append("| **mean mIoU** (baseline " + ", ".join(
        f"{title.lower()} {summary['baseline_miou'][s]:.3f}" for s, title in SETTINGS.items() if s in summary["baseline_miou"])
        + ") | " + " | ".join(f"{summary['mean_miou'][s][v]:.3f}" if s in summary["mean_miou"] else "-"
                              for s in SETTINGS for v in VARIANTS) + " |")
    lines += ["", "## Per scene", "", "| setting | seed | baseline mIoU | " + " | ".join(
        f"{v} mIoU | {v} lost" for v in VARIANTS) + " | largest causes (ours) |",
              "|---|---:|---:|" + "---:|---:|" * len(VARIANTS) + "---|"]
    for setting in SETTINGS:
        for scene in scenes.get(setting, []):
            causes = _scene_causes(scene["ours"])
            top = ", ".join(f"{c} {n}" for c, n in sorted(causes.items(), key=lambda kv: -kv[1])[:3]) or "-"
            lines.append(f"| {setting} | {scene['seed']} | {scene['baseline_miou']:.3f} | " + " | ".join(
                f"{scene[v]['miou']:.3f} | {sum(r['lost'] for r in scene[v]['rooms'])}" for v in VARIANTS)
                + f" | {top} |")
    lines += ["", f"## True rooms with at least {summary['min_lost']} lost cells", "",
              "| variant | setting | seed | room | area m^2 | cells | baseline right | LSD + split right | lost | won | causes |",
              "|---|---|---:|---|---:|---:|---:|---:|---:|---:|---|"]
    for variant in VARIANTS:
        for setting in SETTINGS:
            for scene in scenes.get(setting, []):
                for r in scene[variant]["rooms"]:
                    if r["lost"] >= summary["min_lost"]:
                        causes = ", ".join(f"{c} {n}" for c, n in sorted(r["causes"].items(), key=lambda kv: -kv[1]))
                        lines.append(f"| {variant} | {setting} | {scene['seed']} | {r['type']} {r['room']} | "
                                     f"{r['area']:.1f} | {r['cells']} | {r['baseline_right']} | {r['ours_right']} | "
                                     f"{r['lost']} | {r['won']} | {causes} |")
    if summary["skipped"]:
        lines += ["", f"Skipped: {'; '.join(summary['skipped'])}"]
    return "\n".join(lines + [""])


def summarise(seeds: list[int], seeds_arg: str, realism: str, scenes: dict[str, list[dict]], skipped: list[str],
              min_lost: int = 50) -> dict:
    """The study's summary.json: the scenes' rows and their mean mIoU per setting and variant."""
    return {"seeds": seeds, "seeds_arg": seeds_arg, "realism": realism, "min_lost": min_lost, "scenes": scenes,
            "skipped": skipped,
            "baseline_miou": {s: statistics.fmean(r["baseline_miou"] for r in rows) for s, rows in scenes.items() if rows},
            "mean_miou": {s: {v: statistics.fmean(r[v]["miou"] for r in rows) for v in VARIANTS}
                          for s, rows in scenes.items() if rows}}


def run_study(seeds: list[int], out: Path, work: Optional[Path], seeds_arg: str, realism: str) -> dict:
    scenes: dict[str, list[dict]] = {}
    skipped: list[str] = []
    with scene_frames(work) as cache:
        for setting in SETTINGS:
            def score(seed: int, setting: str = setting) -> dict:
                frames = cache.prepare(seed, "small", setting == "open", realism)
                return scene_causes(frames, cache.built(frames), seed)

            scenes[setting], missed = scene_rows(
                seeds, score, lambda r: f"baseline {r['baseline_miou']:.3f}, " + ", ".join(
                    f"{v} miou {r[v]['miou']:.3f} lost {sum(x['lost'] for x in r[v]['rooms'])}" for v in VARIANTS),
                f"{realism} {setting}")
            skipped += missed
    summary = summarise(seeds, seeds_arg, realism, scenes, skipped)
    write_table(out, f"Room cells lost against the per-cell baseline, per cause ({realism} profile)",
                study_command("room_causes", seeds_arg, realism, out), render_table(summary), summary)
    return summary


def command(seeds: Seeds = "0-4", realism: Realism = "realistic",
            out: Out = Path("docs/results/room-causes-tuning"), work: Work = None,
            allow_tuning_seeds: AllowTuningSeeds = False) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, work, seeds, realism))


def main(argv: list[str] | None = None) -> int:
    return study_main("room_causes", __doc__, command, argv)


if __name__ == "__main__":
    raise SystemExit(main())
