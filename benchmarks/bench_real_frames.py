"""Real-frame mapping benchmark (DESIGN.md: back-projection + association + fusion on real
640 x 480 frames >= 30 frames/s on one core, segmentation excluded).

The 100 7-Scenes redkitchen frames in ../shared/data/real_rgbd/7scenes are converted into our
layout (checked, gravity-aligned) and segmented with the `geometric` segmenter once; the frames and
masks are then held in memory and `MapBuilder.add` (back-projection, top-down binning, association,
fusion) is timed over all of them. Skipped (no figure) when the data folder is missing.

Run: python benchmarks/bench_real_frames.py [--figures DIR]   (DIR: top-down PNGs of the real maps)
"""

from __future__ import annotations

import os

for _var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ[_var] = "1"

import argparse  # noqa: E402
import sys  # noqa: E402
import tempfile  # noqa: E402
import time  # noqa: E402
from pathlib import Path  # noqa: E402

import numpy as np  # noqa: E402

sys.path.insert(0, str(Path(__file__).parent))
from results_io import record  # noqa: E402

from iesm_agent.frames import FrameSet, open_recording  # noqa: E402
from iesm_agent.frames.convert import import_recording  # noqa: E402
from iesm_agent.mapping.build import MapBuilder  # noqa: E402
from iesm_agent.segment.geometric import GeometricSegmenter  # noqa: E402

DATA = Path(__file__).resolve().parents[2] / "shared" / "data" / "real_rgbd"


def prepare(name: str, out: Path) -> FrameSet:
    """Convert and segment one recording into `out` (our layout)."""
    from iesm_agent.segment import SegmenterSpec
    from iesm_agent.segment.run import segment_frame_set

    rec = open_recording(DATA / name)
    import_recording(rec, out, scene_id=Path(name).name, embedding_space="none", categories=[])
    frames = FrameSet.open(out)
    segment_frame_set(frames, out / "frames", spec=SegmenterSpec(name="geometric"), segmenter=GeometricSegmenter())
    return FrameSet.open(out)


def bench_fps(frames: FrameSet, repeats: int = 3) -> tuple[float, int, float]:
    """Frames per second of MapBuilder.add over `frames` held in memory (wall clock, best of
    `repeats`), the instance count of the first pass, and the process CPU time per frame (ms,
    best of `repeats`: less disturbed than the wall clock when other jobs share the cores)."""
    loaded = [frames.read(i) for i in range(len(frames))]
    best, best_cpu, n_inst = float("inf"), float("inf"), 0
    for _ in range(repeats):
        builder = MapBuilder(frames.intrinsics)
        t0, c0 = time.perf_counter(), time.process_time()
        for f in loaded:
            builder.add(f, f.segmentation)
        best = min(best, time.perf_counter() - t0)
        best_cpu = min(best_cpu, time.process_time() - c0)
        n_inst = len(builder.dictionary)
    return len(loaded) / best, n_inst, 1000 * best_cpu / len(loaded)


def topdown_figure(map_path: Path, png: Path, title: str) -> None:
    """Two panels: the top instance of every cell (random colours) and the highest point (m)."""
    from iesm_agent.fileio import pyplot, save_figure
    from iesm_agent.store import load_map

    scene = load_map(map_path)
    g, occ = scene.grid, scene.occupancy
    inst = np.zeros(g.height * g.width, np.int64)
    top = np.full(g.height * g.width, np.nan)
    for k, cell in enumerate(occ.cells):
        s, e = occ.indptr[k], occ.indptr[k + 1]
        j = s + int(np.nanargmax(occ.top[s:e])) if np.isfinite(occ.top[s:e]).any() else s
        inst[cell], top[cell] = occ.ids[j], occ.top[j]
    rng = np.random.default_rng(0)
    colours = np.vstack([[1, 1, 1], rng.uniform(0.15, 0.95, (int(inst.max()) + 1, 3))])
    rgb = colours[np.where(inst > 0, inst + 1, 0)].reshape(g.height, g.width, 3)
    extent = (g.origin[0], g.origin[0] + g.width * g.cell_size, g.origin[1], g.origin[1] + g.height * g.cell_size)
    plt = pyplot("figures")
    fig, axes = plt.subplots(1, 2, figsize=(12, 5))
    axes[0].imshow(rgb, origin="lower", extent=extent, interpolation="nearest")
    axes[0].set_title(f"{title}: {len(scene.instances)} instances (top one per cell)")
    im = axes[1].imshow(top.reshape(g.height, g.width), origin="lower", extent=extent, cmap="viridis",
                        interpolation="nearest", vmin=0, vmax=2.2)
    axes[1].set_title("highest point per cell (m above the floor)")
    fig.colorbar(im, ax=axes[1], shrink=0.8)
    for ax in axes:
        ax.set_xlabel("x (m)"), ax.set_ylabel("y (m)")
    save_figure(fig, png)


def main() -> None:
    parser = argparse.ArgumentParser()
    parser.add_argument("--figures", type=Path, help="write top-down PNGs of the real maps here")
    args = parser.parse_args()
    if not (DATA / "7scenes").is_dir():
        print(f"skipped: {DATA / '7scenes'} is missing")
        return
    with tempfile.TemporaryDirectory() as tmp:
        frames = prepare("7scenes", Path(tmp) / "7scenes")
        fps, n_inst, cpu_ms = bench_fps(frames)
        k = frames.intrinsics
        masks = np.mean([len(frames.read(i).segmentation.scores) for i in range(len(frames))])
        print(f"real frames ({k.width} x {k.height}, {len(frames)} 7-Scenes frames, {masks:.1f} geometric masks per "
              f"frame): back-projection + association + fusion {fps:.1f} frames/s on one core "
              f"({1000 / fps:.1f} ms per frame, {cpu_ms:.1f} ms CPU), {n_inst} instances before the second pass")
        record("real_frames_mapping_fps", fps, "frames/s", ">= 30 frames/s", fps >= 30,
               note="" if fps >= 30 else "per-frame mapping of real 640 x 480 frames is below target")
        if args.figures:
            from iesm_agent.mapping.build import build_map
            from iesm_agent.store import save_map

            args.figures.mkdir(parents=True, exist_ok=True)
            for name in ("7scenes", "3dmatch", "replica/office0"):
                short = Path(name).name
                fs = frames if short == "7scenes" else prepare(name, Path(tmp) / short)
                save_map(build_map(fs), Path(tmp) / f"{short}.iesm")
                topdown_figure(Path(tmp) / f"{short}.iesm", args.figures / f"real-{short}-topdown.png", short)
                print(f"wrote {args.figures / f'real-{short}-topdown.png'}")


if __name__ == "__main__":
    main()
