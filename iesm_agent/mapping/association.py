"""Instance association (paper Sec. 3.1, Eq. phi_geo, phi_sem, phi and the argmax).

phi_geo is max-overlap: max(|a & b| / |a|, |a & b| / |b|) = |a & b| / min(|a|, |b|), on
top-down masks; phi_sem is the cosine of the two embeddings; phi = w_geo phi_geo + w_sem phi_sem.
A candidate matches the instance with the largest phi among the linkable pairs; none linkable
means a new instance. The paper's rule (`MappingConfig.paper()`): a pair is linkable when it passes
BOTH thresholds, phi_geo > delta_geo and phi_sem > delta_sem. The default adds one more linkable
case (`linkable`): top-down masks that overlap, phi_geo > delta_geo_strong (0.4, the paper's
delta_geo), need only phi_sem > delta_sem_weak, because per-view embeddings of one object scatter
(realistic simulator: median view-to-view cosine ~0.89, one pair in five under 0.85; a view seen
once and named as another category becomes a second instance of its object, a split fragment)
while different objects sharing a footprint (a cup on a table: max-overlap 1) stay far apart in
embedding space.

After association (not in the paper; `MappingConfig.paper()` turns it off) the continuity merge
(`InstanceDictionary.merge_continuous`) links instances whose top-down masks touch but do not
overlap, the stretches of one long wall that views never saw together: `continuous_link`, a cosine
above delta_sem_continuous and shapes that `continues` allows.
"""

from __future__ import annotations

import numpy as np

from ..config import MappingConfig
from .cells import rowcol_of


def phi_geo(inter: np.ndarray, area_a: np.ndarray, area_b: np.ndarray) -> np.ndarray:
    """Max-overlap of mask pairs from their intersection and areas (cells), elementwise."""
    inter = np.asarray(inter, np.float64)
    return inter / np.maximum(np.minimum(area_a, area_b), 1)


def iou(inter: np.ndarray, area_a: np.ndarray, area_b: np.ndarray) -> np.ndarray:
    """Intersection over union of mask pairs, elementwise (what max-overlap is compared with)."""
    inter = np.asarray(inter, np.float64)
    return inter / np.maximum(np.asarray(area_a) + np.asarray(area_b) - inter, 1)


def unit_rows(f: np.ndarray) -> np.ndarray:
    """Rows of `f` (n, D) scaled to unit length (zero rows stay zero)."""
    f = np.asarray(f, np.float64)
    norm = np.linalg.norm(f, axis=-1, keepdims=True)
    return f / np.where(norm > 0, norm, 1)


def phi_sem(f_a: np.ndarray, f_b: np.ndarray) -> np.ndarray:
    """Cosine similarity of paired rows of `f_a` and `f_b` (n, D) -> (n,)."""
    return np.einsum("nd,nd->n", unit_rows(f_a), unit_rows(f_b))


def linkable(geo: np.ndarray, sem: np.ndarray, cfg: MappingConfig) -> np.ndarray:
    """Which (candidate, instance) pairs may be fused, elementwise over phi_geo `geo` (max-overlap,
    0-1) and phi_sem `sem` (cosine, -1-1): both paper thresholds passed, or (when
    `cfg.delta_geo_strong` is set) phi_geo > delta_geo_strong and phi_sem > delta_sem_weak."""
    ok = (geo > cfg.delta_geo) & (sem > cfg.delta_sem)
    if cfg.delta_geo_strong is not None:
        ok |= (geo > cfg.delta_geo_strong) & (sem > cfg.delta_sem_weak)
    return ok


def select_matches(pair_a: np.ndarray, pair_b: np.ndarray, geo: np.ndarray, sem: np.ndarray,
                   n_candidates: int, cfg: MappingConfig) -> np.ndarray:
    """For each candidate 0..n_candidates-1, the instance it is fused into, or -1.

    Inputs are parallel arrays over the (candidate, instance) pairs that were compared. Among a
    candidate's `linkable` pairs the largest phi wins; ties go to the lower instance index.
    """
    match = np.full(n_candidates, -1, np.int64)
    ok = linkable(geo, sem, cfg)
    if not ok.any():
        return match
    a, b = np.asarray(pair_a)[ok], np.asarray(pair_b)[ok]
    phi = cfg.w_geo * geo[ok] + cfg.w_sem * sem[ok]
    order = np.lexsort((b, -phi, a))
    a, b = a[order], b[order]
    first = np.r_[True, a[1:] != a[:-1]]
    match[a[first]] = b[first]
    return match


# The three shape constants were chosen on tuning seeds 0-4 (both profiles) from elongation
# {1.5, 2, 3} x angle {15, 20, 30} deg x offset {0.15, 0.25} m: the lowest realistic Inst. Diff among
# settings losing at most one matched instance per scene on either profile (docs/results.md).
#: a footprint is planar (a wall, a door, a window seen from above) when its long axis spreads this
#: many times more than its short axis (standard deviations)
PLANAR_ELONGATION = 2.0
#: two planar footprints are stretches of one plane when their long axes differ by at most this
#: many degrees ...
COLLINEAR_DEG = 30.0
#: ... and the centroid of each lies within this distance (m) of the other's long axis
COLLINEAR_OFFSET_M = 0.25


def planar_line(keys: np.ndarray, cell_size: float) -> tuple[np.ndarray, np.ndarray] | None:
    """(centroid (2,), unit long axis (2,)) in metres, (x, y), of a top-down mask (sorted cell
    keys), or None when the mask is not planar (elongation under PLANAR_ELONGATION, < 3 cells)."""
    if len(keys) < 3:
        return None
    rows, cols = rowcol_of(keys)
    pts = np.stack([cols, rows]).astype(np.float64) * cell_size
    var, vec = np.linalg.eigh(np.cov(pts))
    if var[1] < PLANAR_ELONGATION ** 2 * max(var[0], 1e-12):
        return None
    return pts.mean(axis=1), vec[:, 1]


def continues(keys_a: np.ndarray, keys_b: np.ndarray, cell_size: float) -> bool:
    """Whether touching top-down masks `keys_a`, `keys_b` (sorted cell keys) may be one object by
    their shapes: two planar footprints (`planar_line`) only when collinear (axes within
    COLLINEAR_DEG, each centroid within COLLINEAR_OFFSET_M of the other's axis), so two walls
    meeting at an L or T stay apart; a planar and a non-planar one (a stretch of wall whose mask
    leaked into the floor) may; two non-planar ones never (two objects side by side look the same
    as one object seen in two parts)."""
    a, b = planar_line(keys_a, cell_size), planar_line(keys_b, cell_size)
    if a is None or b is None:
        return (a is None) != (b is None)
    if abs(float(a[1] @ b[1])) < np.cos(np.radians(COLLINEAR_DEG)):
        return False
    gap = b[0] - a[0]
    off_a = abs(float(gap @ np.array([-a[1][1], a[1][0]])))
    off_b = abs(float(gap @ np.array([-b[1][1], b[1][0]])))
    return max(off_a, off_b) <= COLLINEAR_OFFSET_M


def continuous_link(keys: np.ndarray, entries: np.ndarray, sem: np.ndarray, entry_keys: list[np.ndarray],
                    cfg: MappingConfig) -> int:
    """The entry that continues mask `keys` (sorted cell keys), or -1. `entries` (n,) are the
    entries whose masks touch it (within `cfg.continuity_gap`), `sem` (n,) their cosines with it,
    `entry_keys` every entry's cell keys. The entry of largest cosine above
    `cfg.delta_sem_continuous` (ties: lower index) whose shape `continues` the mask's."""
    ok = sem > cfg.delta_sem_continuous
    e, s = np.asarray(entries)[ok], sem[ok]
    for j in e[np.lexsort((e, -s))].tolist():
        if continues(keys, entry_keys[j], cfg.cell_size):
            return int(j)
    return -1
