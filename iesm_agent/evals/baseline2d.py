"""The VLMaps-style 2D point-wise baseline on the same frames and masks.

Every back-projected pixel carries the embedding of the mask it belongs to; a cell keeps ONE
feature, the average over every point that fell into it (stacked objects are blended). Category
scores are linear in the feature, so the map stores per-cell category scores (C, J) = average
feature times E^T instead of (C, D) features. Per-instance descriptors follow the paper's
"VLMaps + GT mask": average the cell features inside each ground-truth top-down mask.
"""

from __future__ import annotations

import numpy as np

from ..config import MappingConfig
from ..frames import Frame, Intrinsics, Segmentation
from ..mapping.cells import run_starts
from ..mapping.project import mask_points


class PointwiseMap2D:
    """Accumulates per-cell category scores frame by frame; `finish()` gives the averages."""

    def __init__(self, intrinsics: Intrinsics, category_embeddings: np.ndarray, cfg: MappingConfig | None = None):
        self.intrinsics = intrinsics
        self.e = np.asarray(category_embeddings, np.float64)
        self.cfg = cfg or MappingConfig()
        self._parts: list[tuple[np.ndarray, np.ndarray, np.ndarray]] = []  # (keys, score sums, points)

    def add(self, frame: Frame, seg: Segmentation) -> None:
        k = self.intrinsics
        mask, keys, _z, _area = mask_points(frame.depth, seg.masks, k.fx, k.fy, k.cx, k.cy, frame.pose,
                                     self.cfg.cell_size, self.cfg.max_depth)
        if len(keys) == 0:
            return
        mask_scores = np.asarray(seg.embeddings, np.float64) @ self.e.T           # (K, J)
        order = np.lexsort((mask, keys))
        keys, mask = keys[order], mask[order]
        pair = np.flatnonzero(np.r_[True, (keys[1:] != keys[:-1]) | (mask[1:] != mask[:-1])])
        n_points = np.diff(np.append(pair, len(keys)))
        pair_keys, pair_mask = keys[pair], mask[pair]
        cell = run_starts(pair_keys)
        sums = np.add.reduceat(n_points[:, None] * mask_scores[pair_mask], cell, axis=0)
        self._parts.append((pair_keys[cell], sums, np.add.reduceat(n_points, cell)))

    def finish(self) -> tuple[np.ndarray, np.ndarray]:
        """(cell keys (C,) sorted, mean category scores (C, J)) over every frame added."""
        if not self._parts:
            return np.zeros(0, np.int64), np.zeros((0, len(self.e)))
        keys = np.concatenate([p[0] for p in self._parts])
        sums = np.concatenate([p[1] for p in self._parts])
        points = np.concatenate([p[2] for p in self._parts])
        order = np.argsort(keys, kind="stable")
        keys, sums, points = keys[order], sums[order], points[order]
        starts = run_starts(keys)
        return keys[starts], np.add.reduceat(sums, starts, axis=0) / np.add.reduceat(points, starts)[:, None]
