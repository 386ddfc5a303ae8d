"""Observed ground-truth footprints: what the frames of a simulated scene show of each object
(every pixel of the instance images projected top-down with the exact depth), the ground truth
that `evals.mapping`, `evals.captions`, `evals.navigation` and `evals.gt_queries` pair built
instances with. Below all of them, so none imports another for it."""

from __future__ import annotations

from pathlib import Path
from typing import Optional

import numpy as np

from ..config import MappingConfig
from ..fileio import read_image
from ..frames import FrameSet
from ..mapping.project import pixel_cells
from ..sim.ground_truth import GroundTruth
from ..store.model import GridSpec, InstanceGrid
from .matching import keys_in_grid


def observed_footprints(frames: FrameSet, grid: GridSpec, cfg: MappingConfig, exact_depth: Optional[Path] = None
                        ) -> Optional[tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]]:
    """(flat cell in `grid`, gt id, top m) per observed (cell, id), and pixel counts per id, from
    the instance images, depth and poses of `frames`; None when no frame has an instance image.
    Depth comes from `exact_depth`/NNNNNN.png (millimetres) where that file exists."""

    k = frames.intrinsics
    parts, counts = [], np.zeros(1, np.int64)
    for i in range(len(frames)):
        if not frames.path(i, "inst.png").is_file():
            continue
        frame = frames.read(i)
        inst = frame.instance_ids.ravel()
        depth = frame.depth
        exact = exact_depth / f"{i:06d}.png" if exact_depth is not None else None
        if exact is not None and exact.is_file():
            depth = read_image(exact, color=False).astype(np.float32) / 1000.0
        pixels = np.flatnonzero((inst > 0) & (depth.ravel() > 0) & (depth.ravel() <= cfg.max_depth))
        keys, z = pixel_cells(depth, pixels, k.fx, k.fy, k.cx, k.cy, frame.pose, cfg.cell_size)
        flat = keys_in_grid(keys, cfg.cell_size, grid)
        ids = inst[pixels].astype(np.int64)
        c = np.bincount(ids)
        counts = np.pad(counts, (0, max(0, len(c) - len(counts))))
        counts[:len(c)] += c
        inside = flat >= 0
        parts.append(InstanceGrid.from_entries(flat[inside], ids[inside], z[inside]).entries())
    if not parts:
        return None
    merged = InstanceGrid.from_entries(*(np.concatenate([p[j] for p in parts]) for j in range(3)))
    return (*merged.entries(), counts)


def observed_masks(frames_dir: str | Path | None, gt: GroundTruth, cfg: MappingConfig | None = None
                   ) -> Optional[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """The observed footprints of the objects seen in at least `cfg.min_mask_pixels` pixels, as
    (flat cell in `gt.grid`, gt id, top m) entries, from `observed_footprints` of the frames in
    `frames_dir` with the exact depth of DIR/gt/depth; None when `frames_dir` is None or holds no
    frames (no scene.json: a ground truth alone) or no frame has an instance image."""
    cfg = cfg or MappingConfig()
    if frames_dir is None or not (Path(frames_dir) / "scene.json").is_file():
        return None
    frames_dir = Path(frames_dir)
    observed = observed_footprints(FrameSet.open(frames_dir), gt.grid, cfg, frames_dir / "gt" / "depth")
    if observed is None:
        return None
    flat, ids, top, counts = observed
    keep = counts[ids] >= cfg.min_mask_pixels
    return flat[keep], ids[keep], top[keep]
