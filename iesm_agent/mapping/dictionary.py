"""The instance dictionary I^exist: association against it, fusion into it, the second
association-fusion pass (paper Sec. 3.1, "Instance Association" and "Instance Fusion") and the
continuity merge of touching stretches of one object (not in the paper, `merge_continuous`).

Each entry holds its top-down mask (sorted cell keys, see `cells`) with the per-cell top height
and the per-cell depth of the nearest reading that placed the cell (how reliably it is placed),
the embedding f (weighted mean of the fused candidate embeddings), the mean height h (m, weighted
the same way), the weight w (number of fused observations) and its observations
(frame index, mask index, mask area in pixels, mask score).

Fusion of an entry with weight w and an observation of weight v (1 for a frame's candidate):
mask OR (per-cell top = max, nearest reading = min), f <- (w f + v f_c) / (w + v), h likewise,
w <- w + v. With v = 1 these are the paper's equations; the second pass fuses whole entries with
v = their weight.
"""

from __future__ import annotations

import numpy as np

from ..config import MappingConfig
from .association import continuous_link, phi_geo, phi_sem, select_matches
from .cells import dilate, intersections, rowcol_of, union_cells
from .project import TopDownCandidates

_EMPTY = np.zeros(0, np.int64)


class InstanceDictionary:
    """Growing instance dictionary; arrays are indexed by entry (0..len-1)."""

    def __init__(self, dim: int, cfg: MappingConfig):
        self.cfg = cfg
        self.keys: list[np.ndarray] = []          # per entry: sorted cell keys
        self.tops: list[np.ndarray] = []          # per entry: top height (m) of each cell
        self.near: list[np.ndarray] = []          # per entry: nearest reading's depth (m) of each cell
        self.observations: list[list[tuple[int, int, int, float]]] = []
        self._f = np.zeros((16, dim))             # embeddings
        self._w = np.zeros(16)                    # weights
        self._h = np.zeros(16)                    # mean heights, m
        self._size = np.zeros(16, np.int64)       # cells per mask
        self._bbox = np.zeros((16, 4), np.int64)  # global (row_min, row_max, col_min, col_max)

    def __len__(self) -> int:
        return len(self.keys)

    @property
    def embeddings(self) -> np.ndarray:
        return self._f[:len(self)]

    @property
    def weights(self) -> np.ndarray:
        return self._w[:len(self)]

    @property
    def mean_heights(self) -> np.ndarray:
        return self._h[:len(self)]

    @property
    def sizes(self) -> np.ndarray:
        return self._size[:len(self)]

    def add(self, keys: np.ndarray, top: np.ndarray, near: np.ndarray, f: np.ndarray, height: float,
            weight: float, bbox: np.ndarray, observations: list) -> int:
        """Append a new entry; returns its index."""
        n = len(self)
        if n == len(self._w):
            grow = 2 * n
            self._f = np.resize(self._f, (grow, self._f.shape[1]))
            self._w, self._h, self._size = np.resize(self._w, grow), np.resize(self._h, grow), np.resize(self._size, grow)
            self._bbox = np.resize(self._bbox, (grow, 4))
        self.keys.append(keys)
        self.tops.append(top)
        self.near.append(near)
        self.observations.append(list(observations))
        self._f[n], self._w[n], self._h[n], self._size[n], self._bbox[n] = f, weight, height, len(keys), bbox
        return n

    def fuse(self, i: int, keys: np.ndarray, top: np.ndarray, near: np.ndarray, f: np.ndarray, height: float,
             weight: float, bbox: np.ndarray, observations: list) -> None:
        """Fuse an observation (or a whole entry) of weight `weight` into entry `i`."""
        w = self._w[i]
        self.keys[i], self.tops[i], self.near[i] = union_cells(self.keys[i], self.tops[i], self.near[i], keys, top,
                                                               near)
        self._f[i] = (w * self._f[i] + weight * np.asarray(f)) / (w + weight)
        self._h[i] = (w * self._h[i] + weight * height) / (w + weight)
        self._w[i] = w + weight
        self._size[i] = len(self.keys[i])
        box = self._bbox[i]
        self._bbox[i] = (min(box[0], bbox[0]), max(box[1], bbox[1]), min(box[2], bbox[2]), max(box[3], bbox[3]))
        self.observations[i].extend(observations)

    def compare(self, keys: np.ndarray, owners: np.ndarray, areas: np.ndarray, bboxes: np.ndarray,
                f: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
        """phi_geo and phi_sem of every (mask, entry) pair whose masks share a cell.

        The masks to compare are given by their cells (`keys`, `owners` = mask index), `areas`
        (cells), `bboxes` (M, 4) and embeddings `f` (M, D). Entries whose bounding box misses
        every mask's box are skipped before any cell is touched. Returns (mask, entry, geo, sem).
        """
        n = len(self)
        if n == 0 or len(keys) == 0:
            return _EMPTY, _EMPTY, np.zeros(0), np.zeros(0)
        box = self._bbox[:n]
        near = ((bboxes[:, None, 0] <= box[None, :, 1]) & (bboxes[:, None, 1] >= box[None, :, 0])
                & (bboxes[:, None, 2] <= box[None, :, 3]) & (bboxes[:, None, 3] >= box[None, :, 2])).any(axis=0)
        near = np.flatnonzero(near)
        if len(near) == 0:
            return _EMPTY, _EMPTY, np.zeros(0), np.zeros(0)
        entry_keys = np.concatenate([self.keys[e] for e in near])
        entry_owner = np.repeat(near, self._size[near])
        a, e, inter = intersections(keys, owners, entry_keys, entry_owner)
        return a, e, phi_geo(inter, areas[a], self._size[e]), phi_sem(f[a], self._f[e])

    def integrate(self, cands: TopDownCandidates, embeddings: np.ndarray, scores: np.ndarray,
                  frame_index: int) -> np.ndarray:
        """Associate one frame's candidates with the dictionary as it was before the frame and
        fuse them (matched) or add them (new). `embeddings` (K, D) and `scores` (K,) are indexed
        by mask index. Returns the entry index each candidate went to (A,)."""
        f = np.asarray(embeddings, np.float64)[cands.mask_index]
        areas = np.diff(cands.offsets)
        a, e, geo, sem = self.compare(cands.keys, cands.owners(), areas, cands.bbox, f)
        match = select_matches(a, e, geo, sem, len(cands), self.cfg)
        target = np.empty(len(cands), np.int64)
        for c in range(len(cands)):
            keys, top, near = cands.cells(c)
            obs = [(frame_index, int(cands.mask_index[c]), int(cands.area_px[c]),
                    float(scores[cands.mask_index[c]]))]
            args = (keys, top, near, f[c], float(cands.mean_height[c]), 1.0, cands.bbox[c], obs)
            if match[c] >= 0:
                self.fuse(int(match[c]), *args)
                target[c] = match[c]
            else:
                target[c] = self.add(*args)
        return target

    def _regroup(self, link) -> tuple["InstanceDictionary", int]:
        """Every entry i, heaviest first (ties by index), is fused into the entry `link(self, out, i)`
        of the dictionary `out` rebuilt so far, or added to it when that is -1. Returns `out` and the
        number of fusions."""
        out = InstanceDictionary(self._f.shape[1], self.cfg)
        merges = 0
        for i in np.argsort(-self.weights, kind="stable"):
            m = link(self, out, i)
            args = (self.keys[i], self.tops[i], self.near[i], self._f[i], self._h[i], self._w[i], self._bbox[i],
                    self.observations[i])
            if m >= 0:
                out.fuse(int(m), *args)
                merges += 1
            else:
                out.add(*args)
        return out, merges

    def second_pass(self) -> tuple["InstanceDictionary", int]:
        """The second association-fusion pass: every entry, heaviest first, is associated with
        the dictionary rebuilt so far (`select_matches`) and fused into it or added. Returns the
        new dictionary and the number of merges."""
        def link(src: InstanceDictionary, out: InstanceDictionary, i: int) -> int:
            keys = src.keys[i]
            a, e, geo, sem = out.compare(keys, np.zeros(len(keys), np.int64), src._size[i:i + 1],
                                         src._bbox[i:i + 1], src._f[i:i + 1])
            return int(select_matches(a, e, geo, sem, 1, self.cfg)[0])

        return self._regroup(link)

    def merge_continuous(self) -> tuple["InstanceDictionary", int]:
        """Fuse entries whose top-down masks touch (`continuous_link`), repeated until nothing more
        fuses, so a wall seen in stretches that never overlap ends as one entry. Returns the new
        dictionary and the number of merges; `cfg.continuity_gap` None: no change."""
        if self.cfg.continuity_gap is None:
            return self, 0
        radius = 1 + int(round(self.cfg.continuity_gap / self.cfg.cell_size))

        def link(src: InstanceDictionary, out: InstanceDictionary, i: int) -> int:
            near = dilate(src.keys[i], radius)
            box = src._bbox[i:i + 1] + np.array([-radius, radius, -radius, radius])
            _a, e, _geo, sem = out.compare(near, np.zeros(len(near), np.int64), np.array([len(near)]), box,
                                           src._f[i:i + 1])
            return continuous_link(src.keys[i], e, sem, out.keys, self.cfg)

        d, total = self, 0
        while True:
            d, merges = d._regroup(link)
            total += merges
            if merges == 0:
                return d, total

    def reliable_footprints(self, max_depth: float | None) -> "InstanceDictionary":
        """The dictionary with each entry's footprint cut to the cells some reading nearer than
        `max_depth` (m) placed, when it has any; an entry with none (seen only from farther) keeps
        every cell, so no instance is lost. Embeddings, heights, weights and observations (the
        label and caption votes of every view) are unchanged. None: `self` unchanged."""
        if max_depth is None:
            return self
        out = InstanceDictionary(self._f.shape[1], self.cfg)
        for i in range(len(self)):
            keep = self.near[i] <= max_depth
            keys, top, near = ((self.keys[i], self.tops[i], self.near[i]) if not keep.any() else
                               (self.keys[i][keep], self.tops[i][keep], self.near[i][keep]))
            rows, cols = rowcol_of(keys)
            out.add(keys, top, near, self._f[i], self._h[i], self._w[i],
                    np.array([rows.min(), rows.max(), cols.min(), cols.max()]), self.observations[i])
        return out
