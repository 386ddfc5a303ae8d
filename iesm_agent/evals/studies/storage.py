"""The storage table (paper Table 5): our saved `.iesm` map against the bytes a VLMaps-style dense
per-cell feature grid and a HOV-SG-style per-point 3D map would take for the same frames.

    python -m iesm_agent.evals.studies.storage --seeds 10-12 --realism realistic --out docs/results/storage-realistic

Per seed: simulate a `--size small` scene (hm3d-sized scenes are too slow for a study; the paper's
scenes are larger, so absolute sizes here are smaller), build the map (default MappingConfig),
segment rooms with the simulator's viewpoint labels, caption offline, save, and size both baselines
with `iesm_agent/evals/storage.py` `storage_comparison` (its `ASSUMPTIONS` are quoted in the table).
"""

from __future__ import annotations

import statistics
from pathlib import Path
from typing import Optional

from . import (AllowTuningSeeds, Out, Realism, Seeds, Work, seeds_note, run_checked, scene_frames, scene_rows, study_command,
               study_main, write_table)

KEYS = ("ours", "vlmaps", "hovsg", "vs_vlmaps", "vs_hovsg")


def captioned_map(frames: Path, seed: int, map_path: Path):
    """Build (default MappingConfig), segment rooms (simulator labels), caption offline and save the
    map of `frames` to `map_path`; returns the scene."""
    from ...captioning import OfflineCaptioner, caption_map
    from ...frames import FrameSet
    from ...mapping.build import build_map
    from ...rooms import segment_rooms
    from ...sim.room_labels import ViewpointLabels
    from ...store import save_map

    frameset = FrameSet.open(frames)
    scene = build_map(frameset)
    scene = segment_rooms(scene, ViewpointLabels(frames, seed=seed).cell_labels(scene.grid))
    scene = caption_map(scene, frameset, OfflineCaptioner())
    save_map(scene, map_path)
    return scene


def measure_scene(frames: Path, seed: int, map_path: Path) -> dict:
    """The captioned map of `frames` saved to `map_path`; bytes of ours and both baselines."""
    from ..storage import storage_comparison

    scene = captioned_map(frames, seed, map_path)
    report = storage_comparison(frames, map_path)
    return {"ours": report.ours_bytes, "vlmaps": report.vlmaps_bytes, "hovsg": report.hovsg_bytes,
            "vs_vlmaps": report.saving_vs_vlmaps, "vs_hovsg": report.saving_vs_hovsg,
            "vlmaps_dense": report.vlmaps_dense_bytes, "instances": len(scene.instances),
            "observed_cells": report.observed_cells, "voxels": report.voxels}


def mean_rows(rows: list[dict]) -> dict:
    """Mean of each of KEYS over `rows` (empty dict if none)."""
    return {k: statistics.fmean(r[k] for r in rows) for k in KEYS} if rows else {}


def render_table(summary: dict) -> str:
    from ..storage import ASSUMPTIONS

    lines = [f"Profile `{summary['realism']}`; seeds {summary['seeds_arg']} ({seeds_note(summary['seeds_arg'])}); simulated "
             "`--size small` scenes (hm3d-sized scenes are too slow for a study run, so absolute sizes are smaller "
             "than the paper's); map built with the default MappingConfig, rooms from the simulator's viewpoint "
             "labels, offline captions. Baselines are sized, not run: " + ASSUMPTIONS + ".", "",
             "| Seed | ours (MB) | VLMaps (MB) | HOV-SG (MB) | saving vs VLMaps | saving vs HOV-SG |",
             "|---|---:|---:|---:|---:|---:|"]
    rows = summary["scenes"] + ([{"seed": "mean", **summary["mean"]}] if summary["mean"] else [])
    for r in rows:
        lines.append(f"| {r['seed']} | {r['ours'] / 1e6:.3f} | {r['vlmaps'] / 1e6:.2f} | {r['hovsg'] / 1e6:.2f} | "
                     f"{r['vs_vlmaps']:.1%} | {r['vs_hovsg']:.1%} |")
    lines += ["", f"Skipped: {'; '.join(summary['skipped'])}"] if summary["skipped"] else []
    lines += ["", "Paper (Table 5): ours 10 MB, VLMaps 118 MB (92% saving), HOV-SG 248 MB (96% saving).", ""]
    return "\n".join(lines)


def run_study(seeds: list[int], out: Path, work: Optional[Path], seeds_arg: str, realism: str = "realistic") -> dict:
    with scene_frames(work) as cache:
        def score(seed: int) -> dict:
            frames = cache.prepare(seed, "small", False, realism)
            return measure_scene(frames, seed, frames.with_suffix(".captioned.iesm"))

        rows, skipped = scene_rows(seeds, score, lambda r: f"ours {r['ours'] / 1e6:.3f} MB, saving "
                                   f"{r['vs_vlmaps']:.1%} vs VLMaps, {r['vs_hovsg']:.1%} vs HOV-SG", realism)
    summary = {"seeds": seeds, "seeds_arg": seeds_arg, "realism": realism, "size": "small", "scenes": rows,
               "skipped": skipped, "mean": mean_rows(rows)}
    write_table(out, f"Storage on simulated small scenes ({realism} profile)",
                study_command("storage", seeds_arg, realism, out), render_table(summary), summary)
    return summary


def command(seeds: Seeds = "10-12", realism: Realism = "realistic",
            out: Out = Path("docs/results/storage-realistic"), work: Work = None,
            allow_tuning_seeds: AllowTuningSeeds = False) -> None:
    run_checked(seeds, realism, allow_tuning_seeds, out,
                lambda seed_list: run_study(seed_list, out, work, seeds, realism))


def main(argv: list[str] | None = None) -> int:
    return study_main("storage", __doc__, command, argv)


if __name__ == "__main__":
    raise SystemExit(main())
