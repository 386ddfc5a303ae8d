"""Sparse top-down masks as sorted integer cell keys, and the set operations mapping needs.

A global cell (row, col) = (floor(y / s), floor(x / s)) for world (x, y) in metres and cell size
s; its key is `(row + OFFSET) * SPAN + (col + OFFSET)`, so sorting keys sorts cells row-major and
any scene within +-50 km fits. A top-down mask is a sorted, duplicate-free int64 key array.
"""

from __future__ import annotations

import numpy as np

OFFSET = 1 << 20
SPAN = 1 << 21


def keys_of(rows: np.ndarray, cols: np.ndarray) -> np.ndarray:
    """Keys (int64) of global cells `rows`, `cols`."""
    return (np.asarray(rows, np.int64) + OFFSET) * SPAN + (np.asarray(cols, np.int64) + OFFSET)


def rowcol_of(keys: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Global (rows, cols) of `keys`."""
    keys = np.asarray(keys, np.int64)
    return keys // SPAN - OFFSET, keys % SPAN - OFFSET


def run_starts(sorted_values: np.ndarray) -> np.ndarray:
    """Indices where a new run of equal values begins in a sorted 1-D array."""
    if len(sorted_values) == 0:
        return np.zeros(0, np.int64)
    new = np.empty(len(sorted_values), bool)
    new[0] = True
    np.not_equal(sorted_values[1:], sorted_values[:-1], out=new[1:])
    return np.flatnonzero(new)


def group_ids(values: np.ndarray, size: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Group equal integers without sorting floats or pairs.

    `values` (n,) integers in [0, size). Returns (distinct (G,) int64 ascending, inverse (n,) int64
    with distinct[inverse] == values, counts (G,) int64). Counting over a dense (size,) table when
    `size` is at most 4 n (or 65,536), which is O(n + size); else `np.unique` (a sort).
    """
    values = np.asarray(values, np.int64)
    if size <= max(4 * len(values), 1 << 16):
        counts = np.bincount(values, minlength=size)
        distinct = np.flatnonzero(counts)
        rank = np.empty(size, np.int64)  # read only at `values`, all of which are in `distinct`
        rank[distinct] = np.arange(len(distinct))
        return distinct, rank[values], counts[distinct]
    distinct, inverse, counts = np.unique(values, return_inverse=True, return_counts=True)
    return distinct, inverse.reshape(-1), counts


def union_cells(keys_a: np.ndarray, top_a: np.ndarray, near_a: np.ndarray, keys_b: np.ndarray,
                top_b: np.ndarray, near_b: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Mask OR of two sparse masks with their per-cell values: a cell in both keeps the larger top
    height (m) and the nearer reading depth (m)."""
    keys = np.concatenate([keys_a, keys_b])
    tops = np.concatenate([top_a, top_b])
    near = np.concatenate([near_a, near_b])
    order = np.argsort(keys, kind="stable")
    keys, tops, near = keys[order], tops[order], near[order]
    if not len(keys):
        return keys, tops, near
    starts = run_starts(keys)
    return keys[starts], np.maximum.reduceat(tops, starts), np.minimum.reduceat(near, starts)


def intersections(keys_a: np.ndarray, owner_a: np.ndarray, keys_b: np.ndarray,
                  owner_b: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Pairwise intersection areas (in cells) between two families of sparse masks.

    `keys_a` / `owner_a` (n,) list every cell of every mask of family A with its mask index
    (a mask's cells are distinct); likewise B. Returns (a, b, count) for every pair (a, b) that
    shares at least one cell, sorted by (a, b).
    """
    empty = np.zeros(0, np.int64)
    if len(keys_a) == 0 or len(keys_b) == 0:
        return empty, empty, empty
    order = np.argsort(keys_b, kind="stable")
    kb, ob = keys_b[order], np.asarray(owner_b, np.int64)[order]
    lo = np.searchsorted(kb, keys_a, "left")
    hits = np.searchsorted(kb, keys_a, "right") - lo
    total = int(hits.sum())
    if total == 0:
        return empty, empty, empty
    first = np.cumsum(hits) - hits
    pos = np.arange(total) - np.repeat(first - lo, hits)
    pa = np.repeat(np.asarray(owner_a, np.int64), hits)
    pb = ob[pos]
    base = int(pb.max()) + 1
    codes, counts = np.unique(pa * base + pb, return_counts=True)
    return codes // base, codes % base, counts


def dilate(keys: np.ndarray, radius: int) -> np.ndarray:
    """Sorted keys of every cell within Chebyshev distance `radius` (cells) of a cell of `keys`."""
    steps = np.arange(-radius, radius + 1, dtype=np.int64)
    offsets = (steps[:, None] * SPAN + steps[None, :]).ravel()
    return np.unique((np.asarray(keys, np.int64)[:, None] + offsets[None, :]).ravel())
