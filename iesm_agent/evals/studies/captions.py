"""Caption colour accuracy on built maps (the `captions` section of `iesm eval-map`), one command
per profile:

    python -m iesm_agent.evals.studies.captions --seeds 10-14 --realism realistic --out docs/results/captions-realistic

For each seed: simulate a walled `--size small` scene, build the map, caption it with the offline
captioner (`iesm caption --frames`), and score its colours against the ground truth
(evals/captions.py: colour family and exact XKCD name, instances seen in >= 3 frames).
"""

from __future__ import annotations

import statistics
import sys
from pathlib import Path
from typing import Optional

from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, log_stderr, run_checked, scene_frames, study_command,
               study_main, write_table)


def score_scene(frames: Path, built: Path) -> dict:
    from ...captioning.offline import OfflineCaptioner
    from ...captioning.pipeline import caption_map
    from ...sim.ground_truth import GroundTruth
    from ...store import load_map
    from ..captions import colour_scores

    scene = caption_map(load_map(built), frames, OfflineCaptioner())
    return colour_scores(scene, GroundTruth.load(frames), frames_dir=frames)


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
            for k in ("colour_acc", "colour_name_acc")}
    lines = [f"Profile `{realism}`; walled `--size small` scenes, seeds {seeds_arg} (not used for tuning); offline "
             "captioner on the built map; instances matched to ground truth (observed footprint, top-down IoU > 0.5) "
             "and seen in >= 3 "
             "frames.", "", "| seed | instances scored | colour family acc | exact colour name acc |",
             "|---|---:|---:|---:|"]
    for seed, r in rows.items():
        lines.append(f"| {seed} | {r['n']} | {r['colour_acc']:.3f} | {r['colour_name_acc']:.3f} |")
    lines.append(f"| mean | {statistics.fmean(r['n'] for r in rows.values()):.1f} | {mean['colour_acc']:.3f} | "
                 f"{mean['colour_name_acc']:.3f} |")
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
