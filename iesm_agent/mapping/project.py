"""Per-frame geometry: back-project candidate masks with depth, move them to the world with the
camera pose, and bin them into top-down sparse masks with heights (paper Sec. 3.1, step 1).

Camera convention (frames.md): pinhole intrinsics in pixels, OpenCV camera frame (x right,
y down, z forward), `pose` = 4x4 camera-to-world, world metres with z up.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from .cells import OFFSET, SPAN, group_ids, keys_of


@dataclass
class TopDownCandidates:
    """The candidates of one frame as sparse top-down masks (A candidates, nnz cells in all).

    `mask_index` (A,) index of each candidate's mask in the frame's segmentation;
    `offsets` (A + 1,): candidate a owns `keys[offsets[a]:offsets[a + 1]]` (sorted cell keys, see
    `cells`) and the matching `top` (per-cell highest point, m) and `near` (per-cell nearest
    reading's depth along the camera axis, m: how reliably the cell is placed, the sensor's noise
    growing with depth); `mean_height` (A,) m, the mean
    over the candidate's cells of the per-cell mean point height; `area_px` (A,) mask pixels;
    `bbox` (A, 4) int64 global (row_min, row_max, col_min, col_max).
    """

    mask_index: np.ndarray
    offsets: np.ndarray
    keys: np.ndarray
    top: np.ndarray
    near: np.ndarray
    mean_height: np.ndarray
    area_px: np.ndarray
    bbox: np.ndarray

    def __len__(self) -> int:
        return len(self.mask_index)

    def cells(self, a: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(keys, top, near) of candidate `a`."""
        s, e = self.offsets[a], self.offsets[a + 1]
        return self.keys[s:e], self.top[s:e], self.near[s:e]

    def owners(self) -> np.ndarray:
        """Candidate index of every entry of `keys`."""
        return np.repeat(np.arange(len(self), dtype=np.int64), np.diff(self.offsets))


@lru_cache(maxsize=8)
def _rays(height: int, width: int, fx: float, fy: float, cx: float, cy: float) -> tuple[np.ndarray, np.ndarray]:
    """Per-pixel (u - cx) / fx and (v - cy) / fy, flat (H * W,) float32 (cached per camera)."""
    v, u = np.divmod(np.arange(height * width), width)
    return ((u - cx) / fx).astype(np.float32), ((v - cy) / fy).astype(np.float32)


def world_points(depth: np.ndarray, pixels: np.ndarray | None, fx: float, fy: float, cx: float, cy: float,
                 pose: np.ndarray) -> np.ndarray:
    """World points (3, n) float32 in metres of flat pixel indices `pixels` (n,) of `depth` (H, W)
    metres, or of every pixel (n = H * W, row-major) when `pixels` is None.

    Per coordinate i, in float32: z * (R[i, 0] a + R[i, 1] b + R[i, 2]) + t[i] with (a, b) the
    pixel's ray (`_rays`) and (R, t) = `pose` (4, 4) camera-to-world.
    """
    a, b = _rays(depth.shape[0], depth.shape[1], fx, fy, cx, cy)
    z = depth.ravel()
    if pixels is not None:
        a, b, z = a[pixels], b[pixels], z[pixels]
    z = z.astype(np.float32, copy=False)
    r, t = pose[:3, :3].astype(np.float32), pose[:3, 3].astype(np.float32)
    out = np.empty((3, len(z)), np.float32)
    tmp = np.empty(len(z), np.float32)
    for i in range(3):  # the same float32 operations, in the same order, as the expression above
        row = out[i]
        np.multiply(r[i, 0], a, out=row)
        np.multiply(r[i, 1], b, out=tmp)
        row += tmp
        row += r[i, 2]
        row *= z
        row += t[i]
    return out


def cell_rowcol(x: np.ndarray, y: np.ndarray, cell_size: float) -> tuple[np.ndarray, np.ndarray]:
    """Global cells (rows floor(y / s), cols floor(x / s)) (n,) int64 of world x, y (n,) metres."""
    return np.floor(y / cell_size).astype(np.int64), np.floor(x / cell_size).astype(np.int64)


@dataclass
class CellImage:
    """Every pixel of one frame binned top-down: the frame's cells are numbered row-major inside
    their bounding box of `n_rows` x `n_cols` global cells starting at global (`row0`, `col0`).

    `cell` (H * W,) int64 box index of each pixel, `n_box` (= n_rows * n_cols) for pixels without
    a usable depth reading; `z` (H * W,) float32 world height in metres (meaningless where
    `cell == n_box`).
    """

    cell: np.ndarray
    z: np.ndarray
    row0: int
    col0: int
    n_cols: int
    n_box: int

    def keys(self, box_index: np.ndarray) -> np.ndarray:
        """Global cell keys (int64, see `cells`) of box indices (< `n_box`)."""
        rows, cols = self.rowcol(box_index)
        return keys_of(rows, cols)

    def rowcol(self, box_index: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Global (rows, cols) int64 of box indices (< `n_box`)."""
        r, c = np.divmod(np.asarray(box_index, np.int64), self.n_cols)
        return r + self.row0, c + self.col0


def cell_image(depth: np.ndarray, fx: float, fy: float, cx: float, cy: float, pose: np.ndarray,
               cell_size: float, max_depth: float = np.inf) -> CellImage:
    """Bin every pixel of `depth` (H, W) metres into global cells of `cell_size` m (row
    floor(y / s), col floor(x / s) of the world point: `cell_rowcol`, as `pixel_cells`). Readings
    that are 0, not finite or beyond `max_depth` are not usable. One dense pass, no gather.
    """
    usable = (depth > 0) & (depth <= max_depth) & np.isfinite(depth)
    # unusable pixels are placed at the camera (depth 0): a finite point inside the frame's reach
    x, y, z = world_points(np.where(usable, depth, 0), None, fx, fy, cx, cy, pose)
    rows, cols = cell_rowcol(x, y, cell_size)
    if rows.size == 0:
        return CellImage(cell=rows, z=z, row0=0, col0=0, n_cols=1, n_box=0)
    row0, col0, row1, col1 = int(rows.min()), int(cols.min()), int(rows.max()), int(cols.max())
    if min(row0, col0) < -OFFSET or max(row1, col1) >= SPAN - OFFSET:
        # beyond the keys' range (+-50 km, see `cells`): such cells have no key of their own; held
        # at its edge so keys stay sorted and the box small (never the case for a valid scene)
        for a in (rows, cols):
            np.clip(a, -OFFSET, SPAN - OFFSET - 1, out=a)
        row0, col0, row1, col1 = int(rows.min()), int(cols.min()), int(rows.max()), int(cols.max())
    n_cols = col1 - col0 + 1
    n_box = (row1 - row0 + 1) * n_cols
    rows -= row0
    rows *= n_cols
    rows += cols
    rows -= col0
    np.copyto(rows, n_box, where=~usable.ravel())
    return CellImage(cell=rows, z=z, row0=row0, col0=col0, n_cols=n_cols, n_box=n_box)


def mask_pixels(masks: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Flat pixel indices of every mask of `masks` (K, H, W) bool, mask after mask (P,) int64
    (ascending inside a mask), and each mask's pixel count (K,) int64."""
    flat = masks.reshape(masks.shape[0], masks[0].size if len(masks) else 0)
    per_mask = [np.flatnonzero(m) for m in flat]  # a loop over masks: 2-D nonzero is ~10x slower
    area_px = np.fromiter(map(len, per_mask), np.int64, len(per_mask))
    return (np.concatenate(per_mask) if per_mask else np.zeros(0, np.int64)), area_px


def mask_points(depth: np.ndarray, masks: np.ndarray, fx: float, fy: float, cx: float, cy: float,
                pose: np.ndarray, cell_size: float, max_depth: float = np.inf
                ) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Every (mask, pixel) with a usable depth reading as (mask index, global cell key, world z m),
    each (P,) int64 / int64 / float32, mask after mask, plus each mask's pixel count (K,) int64
    with or without depth.

    `masks` (K, H, W) bool, `depth` (H, W) metres (0 = none; readings beyond `max_depth` dropped).
    """
    img = cell_image(depth, fx, fy, cx, cy, pose, cell_size, max_depth)
    pix, area_px = mask_pixels(masks)
    k = np.repeat(np.arange(masks.shape[0], dtype=np.int64), area_px)
    cell = img.cell[pix]
    ok = cell < img.n_box
    pix = pix[ok]
    return k[ok], img.keys(cell[ok]), img.z[pix], area_px


def pixel_cells(depth: np.ndarray, pixels: np.ndarray, fx: float, fy: float, cx: float, cy: float,
                pose: np.ndarray, cell_size: float) -> tuple[np.ndarray, np.ndarray]:
    """(global cell key (n,) int64, world z (n,) float32 m) of flat pixel indices `pixels` (n,) of
    `depth` (H, W) metres."""
    x, y, z = world_points(depth, pixels, fx, fy, cx, cy, pose)
    return keys_of(*cell_rowcol(x, y, cell_size)), z


def project_candidates(depth: np.ndarray, masks: np.ndarray, fx: float, fy: float, cx: float, cy: float,
                       pose: np.ndarray, cell_size: float, *, min_pixels: int = 1,
                       max_depth: float = np.inf, min_cell_points: int = 1) -> TopDownCandidates:
    """Top-down masks and heights of every mask in `masks` (K, H, W) bool, given `depth` (H, W)
    metres (0 = no reading), intrinsics in pixels (OpenCV: pixel (u, v) centred at integer
    coordinates), `pose` (4, 4) camera-to-world and `cell_size` m.

    Pixels without depth or farther than `max_depth` are ignored; masks with fewer than
    `min_pixels` usable pixels are dropped; a candidate's cells holding fewer than
    `min_cell_points` of its points are left out of its footprint (and its heights). Vectorised: the frame's pixels
    are binned once (`cell_image`), each (mask, pixel) gets the integer code
    mask * (n_box + 1) + box cell, and the codes are grouped by counting (`cells.group_ids`):
    no sort of points, no per-mask loop beyond one `flatnonzero` per mask.
    """
    k_all = masks.shape[0]
    img = cell_image(depth, fx, fy, cx, cy, pose, cell_size, max_depth)
    pix, area_px = mask_pixels(masks)
    n = img.n_box + 1                             # per mask: the box's cells, then "no depth"
    code = np.repeat(np.arange(k_all, dtype=np.int64) * n, area_px)
    code += img.cell[pix]
    groups, inverse, n_pts = group_ids(code, k_all * n)
    z = img.z[pix]
    sums = np.bincount(inverse, weights=z, minlength=len(groups))        # float64
    top = np.full(len(groups), -np.inf, np.float32)
    np.maximum.at(top, inverse, z)
    near = np.full(len(groups), np.inf, np.float32)
    # fmin: the unusable readings (NaN among them) fall in the "no depth" groups, dropped below
    np.fmin.at(near, inverse, depth.ravel()[pix])
    group_k, group_cell = np.divmod(groups, n)
    has_depth = group_cell < img.n_box
    usable_px = np.bincount(group_k[has_depth], weights=n_pts[has_depth], minlength=k_all)
    supported = has_depth & (n_pts >= min_cell_points)
    keep = (usable_px >= max(min_pixels, 1)) & (np.bincount(group_k[supported], minlength=k_all) > 0)
    # one entry per (candidate, cell): candidate-major, cells row-major inside each candidate
    sel = np.flatnonzero(supported & keep[group_k])
    cell_k, box = group_k[sel], group_cell[sel]
    top, near = top[sel], near[sel]
    cell_mean = sums[sel] / n_pts[sel]
    kept = np.flatnonzero(keep)
    remap = np.full(k_all, -1, np.int64)
    remap[kept] = np.arange(len(kept))
    owner = remap[cell_k]
    n_cells = np.bincount(owner, minlength=len(kept))
    offsets = np.zeros(len(kept) + 1, np.int64)
    np.cumsum(n_cells, out=offsets[1:])
    mean_height = np.bincount(owner, weights=cell_mean, minlength=len(kept)) / np.maximum(n_cells, 1)
    r, c = img.rowcol(box)
    bbox = np.zeros((len(kept), 4), np.int64)
    if len(kept):
        first = offsets[:-1]
        bbox[:, 0] = r[first]                       # cells are row-major: first/last give the rows
        bbox[:, 1] = r[offsets[1:] - 1]
        bbox[:, 2] = np.minimum.reduceat(c, first)
        bbox[:, 3] = np.maximum.reduceat(c, first)
    return TopDownCandidates(mask_index=kept.astype(np.int64), offsets=offsets, keys=keys_of(r, c), top=top,
                             near=near, mean_height=mean_height, area_px=area_px[kept].astype(np.int64), bbox=bbox)
