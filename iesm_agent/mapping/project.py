"""Per-frame geometry: back-project candidate masks with depth, move them to the world with the
camera pose, and bin them into top-down sparse masks with heights (paper Sec. 3.1, step 1).

Camera convention (frames.md): pinhole intrinsics in pixels, OpenCV camera frame (x right,
y down, z forward), `pose` = 4x4 camera-to-world, world metres with z up.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .cells import keys_of, rowcol_of


@dataclass
class TopDownCandidates:
    """The candidates of one frame as sparse top-down masks (A candidates, nnz cells in all).

    `mask_index` (A,) index of each candidate's mask in the frame's segmentation;
    `offsets` (A + 1,): candidate a owns `keys[offsets[a]:offsets[a + 1]]` (sorted cell keys, see
    `cells`) and the matching `top` (per-cell highest point, m); `mean_height` (A,) m, the mean
    over the candidate's cells of the per-cell mean point height; `area_px` (A,) mask pixels;
    `bbox` (A, 4) int64 global (row_min, row_max, col_min, col_max).
    """

    mask_index: np.ndarray
    offsets: np.ndarray
    keys: np.ndarray
    top: np.ndarray
    mean_height: np.ndarray
    area_px: np.ndarray
    bbox: np.ndarray

    def __len__(self) -> int:
        return len(self.mask_index)

    def cells(self, a: int) -> tuple[np.ndarray, np.ndarray]:
        """(keys, top) of candidate `a`."""
        s, e = self.offsets[a], self.offsets[a + 1]
        return self.keys[s:e], self.top[s:e]

    def owners(self) -> np.ndarray:
        """Candidate index of every entry of `keys`."""
        return np.repeat(np.arange(len(self), dtype=np.int64), np.diff(self.offsets))


@lru_cache(maxsize=8)
def _rays(height: int, width: int, fx: float, fy: float, cx: float, cy: float) -> tuple[np.ndarray, np.ndarray]:
    """Per-pixel (u - cx) / fx and (v - cy) / fy, flat (H * W,) float32 (cached per camera)."""
    v, u = np.divmod(np.arange(height * width), width)
    return ((u - cx) / fx).astype(np.float32), ((v - cy) / fy).astype(np.float32)


def world_points(depth: np.ndarray, pixels: np.ndarray, fx: float, fy: float, cx: float, cy: float,
                 pose: np.ndarray) -> np.ndarray:
    """World points (3, n) float32 in metres of flat pixel indices `pixels` of `depth` (H, W) metres."""
    a, b = _rays(depth.shape[0], depth.shape[1], fx, fy, cx, cy)
    a, b = a[pixels], b[pixels]
    z = depth.ravel()[pixels].astype(np.float32, copy=False)
    r, t = pose[:3, :3].astype(np.float32), pose[:3, 3].astype(np.float32)
    return np.stack([z * (r[i, 0] * a + r[i, 1] * b + r[i, 2]) + t[i] for i in range(3)])


def mask_points(depth: np.ndarray, masks: np.ndarray, fx: float, fy: float, cx: float, cy: float,
                pose: np.ndarray, cell_size: float, max_depth: float = np.inf
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Every (mask, pixel) with a usable depth reading as (mask index, global cell key, world z m),
    plus each mask's pixel count (K,) with or without depth.

    `masks` (K, H, W) bool, `depth` (H, W) metres (0 = none; readings beyond `max_depth` dropped).
    """
    k_all = masks.shape[0]
    flat_masks = masks.reshape(k_all, depth.size)
    usable = ((depth > 0) & (depth <= max_depth) & np.isfinite(depth)).ravel()
    per_mask = [np.flatnonzero(m) for m in flat_masks]  # a loop over masks: 2-D nonzero is ~10x slower
    pix = np.concatenate(per_mask) if per_mask else np.zeros(0, np.int64)
    area_px = np.array([len(p) for p in per_mask], np.int64)
    k = np.repeat(np.arange(k_all), area_px)
    ok = usable[pix]
    k, pix = k[ok], pix[ok]
    hit = np.zeros(depth.size, bool)
    hit[pix] = True
    pixels = np.flatnonzero(hit)
    row_of = np.empty(depth.size, np.int64)
    row_of[pixels] = np.arange(len(pixels))
    keys, z = pixel_cells(depth, pixels, fx, fy, cx, cy, pose, cell_size)
    j = row_of[pix]
    return k.astype(np.int64), keys[j], z[j], area_px


def pixel_cells(depth: np.ndarray, pixels: np.ndarray, fx: float, fy: float, cx: float, cy: float,
                pose: np.ndarray, cell_size: float) -> tuple[np.ndarray, np.ndarray]:
    """(global cell key, world z m) of flat pixel indices `pixels` of `depth` (H, W) metres."""
    x, y, z = world_points(depth, pixels, fx, fy, cx, cy, pose)
    rows = np.floor(y / cell_size).astype(np.int64)
    cols = np.floor(x / cell_size).astype(np.int64)
    return keys_of(rows, cols), z


def project_candidates(depth: np.ndarray, masks: np.ndarray, fx: float, fy: float, cx: float, cy: float,
                       pose: np.ndarray, cell_size: float, *, min_pixels: int = 1,
                       max_depth: float = np.inf) -> TopDownCandidates:
    """Top-down masks and heights of every mask in `masks` (K, H, W) bool, given `depth` (H, W)
    metres (0 = no reading), intrinsics in pixels (OpenCV: pixel (u, v) centred at integer coordinates) and `pose` (4, 4).

    Pixels without depth or farther than `max_depth` are ignored; masks with fewer than
    `min_pixels` usable pixels are dropped. Fully vectorised over pixels and cells.
    """
    k_all = masks.shape[0]
    k, keys, z, area_px = mask_points(depth, masks, fx, fy, cx, cy, pose, cell_size, max_depth)
    counts = np.bincount(k, minlength=k_all)
    keep = counts >= max(min_pixels, 1)
    if not keep.all():
        sel = keep[k]
        k, keys, z = k[sel], keys[sel], z[sel]
    # one entry per (candidate, cell): candidate-major, keys row-major inside each candidate
    order = np.argsort((k << 42) | keys) if len(k) else k  # keys < 2**42 (see cells.SPAN)
    k, keys, z = k[order], keys[order], z[order]
    starts = np.flatnonzero(np.r_[True, (k[1:] != k[:-1]) | (keys[1:] != keys[:-1])]) if len(k) else k
    cell_k = k[starts]
    cell_keys = keys[starts]
    top = np.maximum.reduceat(z, starts).astype(np.float32) if len(z) else z.astype(np.float32)
    n_pts = np.diff(np.append(starts, len(z)))
    cell_mean = np.add.reduceat(z, starts) / n_pts if len(z) else z
    kept = np.flatnonzero(keep)
    remap = np.full(k_all, -1, np.int64)
    remap[kept] = np.arange(len(kept))
    owner = remap[cell_k]
    n_cells = np.bincount(owner, minlength=len(kept))
    offsets = np.zeros(len(kept) + 1, np.int64)
    np.cumsum(n_cells, out=offsets[1:])
    mean_height = np.bincount(owner, weights=cell_mean, minlength=len(kept)) / np.maximum(n_cells, 1)
    r, c = rowcol_of(cell_keys)
    bbox = np.zeros((len(kept), 4), np.int64)
    if len(kept):
        first = offsets[:-1]
        bbox[:, 0] = r[first]                       # keys are row-major: first/last give the rows
        bbox[:, 1] = r[offsets[1:] - 1]
        bbox[:, 2] = np.minimum.reduceat(c, first)
        bbox[:, 3] = np.maximum.reduceat(c, first)
    return TopDownCandidates(mask_index=kept.astype(np.int64), offsets=offsets, keys=cell_keys, top=top,
                             mean_height=mean_height, area_px=area_px[kept].astype(np.int64), bbox=bbox)
