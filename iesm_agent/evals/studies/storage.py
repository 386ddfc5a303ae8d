"""The storage table (paper Table 5): our saved `.iesm` map against the bytes a VLMaps-style dense
per-cell feature grid and a HOV-SG-style per-point 3D map would take for the same frames.

    python -m iesm_agent.evals.studies.storage --seeds 10-12 --realism realistic --out docs/results/storage-realistic

Per seed: simulate a `--size small` scene (hm3d-sized scenes are too slow for a study; the paper's
scenes are larger, so absolute sizes here are smaller), build the map (default MappingConfig),
segment rooms with the simulator's viewpoint labels, caption offline, save, and size both baselines
with `iesm_agent/evals/storage.py` `storage_comparison` (its `ASSUMPTIONS` are quoted in the table).
"""

from __future__ import annotations

import argparse
import statistics
import sys
from pathlib import Path
from typing import Optional

from ...errors import IesmError
from . import check_seeds, common_args, parse_seeds, scene_frames, write_table

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

    lines = [f"Profile `{summary['realism']}`; seeds {summary['seeds_arg']} (not used for tuning); simulated "
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
    rows: list[dict] = []
    skipped: list[str] = []
    with scene_frames(work) as cache:
        for seed in seeds:
            try:
                frames = cache.prepare(seed, "small", False, realism)
                rows.append({"seed": seed, **measure_scene(frames, seed, frames.with_suffix(".captioned.iesm"))})
            except IesmError as exc:  # a scene the simulator or mapper cannot make is reported, not fatal
                skipped.append(f"seed {seed}: {exc}")
                print(f"skipped {skipped[-1]}", file=sys.stderr, flush=True)
                continue
            print(f"{realism} seed {seed}: ours {rows[-1]['ours'] / 1e6:.3f} MB, saving {rows[-1]['vs_vlmaps']:.1%} "
                  f"vs VLMaps, {rows[-1]['vs_hovsg']:.1%} vs HOV-SG", file=sys.stderr, flush=True)
    summary = {"seeds": seeds, "seeds_arg": seeds_arg, "realism": realism, "size": "small", "scenes": rows,
               "skipped": skipped, "mean": mean_rows(rows)}
    command = (f"python -m iesm_agent.evals.studies.storage --seeds {seeds_arg} --realism {realism} "
               f"--out {out.as_posix()}")
    write_table(out, f"Storage on simulated small scenes ({realism} profile)", command, render_table(summary),
                summary)
    return summary


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(prog="python -m iesm_agent.evals.studies.storage",
                                     description=__doc__.split("\n\n")[0])
    common_args(parser, "10-12", "docs/results/storage-realistic")
    args = parser.parse_args(argv)
    try:
        seeds = parse_seeds(args.seeds)
        check_seeds(seeds, args.allow_tuning_seeds)
        summary = run_study(seeds, args.out, args.work, args.seeds, args.realism)
    except IesmError as exc:
        print(f"iesm: error: {exc}")
        return 2
    print(render_table(summary))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
