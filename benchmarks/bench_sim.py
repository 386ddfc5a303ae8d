"""Simulator benchmark: renderer throughput on 320 x 240 frames of a scene with ~80 boxes in view
range (target >= 20 frames/s on one core), and scene generation time (plan + furniture +
trajectory) for --size small and --size hm3d, plus the full `render_frames` time for small
(frames, segmentation, PNG/NPZ writing; the hash embedding space, so no model load).
Run: python benchmarks/bench_sim.py
"""

from __future__ import annotations

import os
import statistics
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

sys.path.insert(0, str(Path(__file__).parent))
from results_io import record  # noqa: E402

from iesm_agent.sim import FaultConfig, generate_scene, render_frames  # noqa: E402
from iesm_agent.sim.catalog import CEILING_RGB, FLOOR_RGB  # noqa: E402
from iesm_agent.sim.render import BoxRenderer  # noqa: E402
from iesm_agent.sim.world import WALL_HEIGHT  # noqa: E402


def _median_time(fn, repeat: int = 3) -> float:
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return statistics.median(times)


def main() -> None:
    os.environ["IESM_EMBEDDINGS"] = "0"
    world = generate_scene(0, "small")
    renderer = BoxRenderer(world.boxes, world.box_rgb(), world.box_instance, world.intrinsics, WALL_HEIGHT,
                           floor_rgb=FLOOR_RGB, ceiling_rgb=CEILING_RGB)
    rng = np.random.default_rng(0)
    renderer.render(world.poses[0], rng)  # warm-up
    start = time.perf_counter()
    for pose in world.poses:
        renderer.render(pose, rng)
    fps = len(world.poses) / (time.perf_counter() - start)
    print(f"render: {len(world.boxes)} boxes, {len(world.poses)} frames of "
          f"{world.intrinsics.width}x{world.intrinsics.height}: {fps:.1f} frames/s")
    record("render_fps", fps, "frames/s", ">= 20 frames/s", fps >= 20,
           note=f"{len(world.boxes)} boxes, 320x240, numpy slab test per projected box rectangle")

    for size in ("small", "hm3d"):
        seconds = _median_time(lambda: generate_scene(0, size), repeat=3 if size == "small" else 1)
        w = generate_scene(0, size)
        print(f"generate_scene({size}): {seconds:.2f} s ({len(w.instances)} instances, {len(w.boxes)} boxes, "
              f"{len(w.poses)} poses)")
    with tempfile.TemporaryDirectory() as tmp:
        start = time.perf_counter()
        summary = render_frames(world, Path(tmp) / "flat", FaultConfig(seed=0))
        seconds = time.perf_counter() - start
    print(f"render_frames(small): {seconds:.1f} s for {summary['frames']} frames "
          f"({summary['frames'] / seconds:.1f} frames/s written)")


if __name__ == "__main__":
    main()
