"""Caption colour accuracy on built maps (the `captions` section of `iesm eval-map`), one command
per profile:

    python -m iesm_agent.evals.studies.captions --seeds 10-14 --realism realistic --out docs/results/captions-realistic

For each seed: simulate a walled `--size small` scene, build the map, caption it with the offline
captioner (`iesm caption --frames`), and score its colours against the ground truth
(evals/captions.py: colour family and exact XKCD name, instances seen in >= 3 frames). Beside it,
the plain rule: the nearest XKCD name (CIEDE2000) of the median colour of the masked pixels of the
keyframes as recorded (no white balance, no allowance for room lighting).
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path
from typing import Optional

from . import (TUNING_SEEDS, AllowTuningSeeds, Out, Realism, Seeds, Work, log_stderr, run_checked, scene_frames,
               study_command, study_main, write_table)


class PlainColourCaptioner:
    """The plain rule: the nearest table name (`colours.name_lab` without shading) of the per-channel
    median of every keyframe's masked pixels as recorded (`Crop.rgb`, no gain)."""

    name = "plain colour"

    async def acaption(self, view):
        import numpy as np

        from ...captioning.schema import CaptionResult
        from ...colours import colour_table, name_lab, rgb_to_lab

        pixels = [crop.rgb[crop.mask] for crop in view.crops if crop.mask.any()]
        if not pixels:
            return CaptionResult(caption=view.instance.label)
        lab = rgb_to_lab(np.median(np.concatenate(pixels), axis=0))
        return CaptionResult(caption=view.instance.label,
                             tags={"color": colour_table().names[int(name_lab(lab, shading=None))]})


def score_scene(frames: Path, built: Path) -> dict:
    """Our colour scores (`colour_acc`, `colour_name_acc`, `n`) and the plain rule's
    (`plain_colour_acc`, `plain_colour_name_acc`) on one built scene."""
    from ...captioning.offline import OfflineCaptioner
    from ...captioning.pipeline import caption_map
    from ...sim.ground_truth import GroundTruth
    from ...store import load_map
    from ..captions import colour_scores

    scene, gt = load_map(built), GroundTruth.load(frames)
    ours = colour_scores(caption_map(scene, frames, OfflineCaptioner()), gt, frames_dir=frames)
    plain = colour_scores(caption_map(scene, frames, PlainColourCaptioner()), gt, frames_dir=frames)
    return {**ours, "plain_colour_acc": plain["colour_acc"], "plain_colour_name_acc": plain["colour_name_acc"],
            "plain_misses": plain["misses"]}


def _confusion_table(rows: dict) -> list[str]:
    """Per true colour over all seeds: instances, family hits of the plain rule and of ours, and
    what ours said when it missed."""
    from collections import Counter

    truths: Counter[str] = Counter()
    misses = {"plain": Counter(), "ours": Counter()}
    for r in rows.values():
        truths.update(r["truths"])
        misses["ours"].update(r["misses"])
        misses["plain"].update(r["plain_misses"])
    lines = ["## Misses by true colour (all seeds)", "", "| true colour | instances | family hits, plain | "
             "family hits, ours | ours said instead |", "|---|---:|---:|---:|---|"]
    for truth, n in sorted(truths.items(), key=lambda t: (-t[1], t[0])):
        missed = {k: Counter({key.split(" -> ", 1)[1]: c for key, c in m.items() if key.split(" -> ", 1)[0] == truth})
                  for k, m in misses.items()}
        said = ", ".join(f"{name} {c}" for name, c in missed["ours"].most_common())
        lines.append(f"| {truth} | {n} | {n - sum(missed['plain'].values())} | {n - sum(missed['ours'].values())} | "
                     f"{said} |")
    return lines


def run_study(seeds: list[int], out: Path, realism: str, seeds_arg: str, work: Optional[Path] = None,
              log=print) -> dict:
    rows = {}
    with scene_frames(work) as cache:
        for seed in seeds:
            frames = cache.prepare(seed, "small", False, realism)
            rows[seed] = score_scene(frames, cache.built(frames))
            log(f"{realism} seed {seed}: colour family {rows[seed]['colour_acc']:.3f}, name "
                f"{rows[seed]['colour_name_acc']:.3f} (n={rows[seed]['n']})")
    mean = {k: statistics.fmean(r[k] for r in rows.values() if r[k] is not None)
            for k in ("colour_acc", "colour_name_acc", "plain_colour_acc", "plain_colour_name_acc")}
    tuning = "tuning seeds: the colour rule's constants were chosen on them" if set(seeds) & TUNING_SEEDS \
        else "not used for tuning"
    lines = [f"Profile `{realism}`; walled `--size small` scenes, seeds {seeds_arg} ({tuning}); offline "
             "captioner on the built map; instances matched to ground truth (observed footprint, top-down IoU > 0.5) "
             "and seen in >= 3 "
             "frames. Plain rule: nearest name of the median recorded pixel colour; ours: keyframes brought to the "
             "scene's white balance, lit faces, named allowing for room lighting (`captioning/offline.py`).", "",
             "| seed | instances scored | colour family, plain | colour family, ours | exact name, plain | "
             "exact name, ours |", "|---|---:|---:|---:|---:|---:|"]
    keys = ("plain_colour_acc", "colour_acc", "plain_colour_name_acc", "colour_name_acc")
    for seed, r in rows.items():
        lines.append(f"| {seed} | {r['n']} | " + " | ".join(f"{r[k]:.3f}" for k in keys) + " |")
    lines.append(f"| mean | {statistics.fmean(r['n'] for r in rows.values()):.1f} | "
                 + " | ".join(f"{mean[k]:.3f}" for k in keys) + " |")
    lines += ["", *_confusion_table(rows)]
    summary = {"seeds": seeds, "realism": realism, "rows": rows, "mean": mean}
    write_table(out, f"Caption colours on built maps ({realism} profile)",
                study_command("captions", seeds_arg, realism, out), "\n".join(lines), summary)
    return summary


def command(seeds: Seeds = "10-14", realism: Realism = "realistic",
            out: Out = Path("docs/results/captions-realistic"), work: Work = None,
            allow_tuning_seeds: AllowTuningSeeds = False) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, realism, seeds, work, log=log_stderr))


def main(argv: list[str] | None = None) -> int:
    return study_main("captions", __doc__, command, argv)


if __name__ == "__main__":
    sys.exit(main())
