"""Instance association (paper Sec. 3.1, Eq. phi_geo, phi_sem, phi and the argmax).

phi_geo is max-overlap: max(|a & b| / |a|, |a & b| / |b|) = |a & b| / min(|a|, |b|), on
top-down masks; phi_sem is the cosine of the two embeddings; phi = w_geo phi_geo + w_sem phi_sem.
A candidate matches the instance with the largest phi among the linkable pairs; none linkable
means a new instance. The paper's rule (`MappingConfig.paper()`): a pair is linkable when it passes
BOTH thresholds, phi_geo > delta_geo and phi_sem > delta_sem. The default adds one more linkable
case (`linkable`): top-down masks that nearly coincide, phi_geo > delta_geo_strong, need only
phi_sem > delta_sem_weak, because per-view embeddings of one object scatter (realistic simulator:
median view-to-view cosine ~0.89, one pair in five under 0.85) while different objects sharing a
footprint (a cup on a table: max-overlap 1) stay far apart in embedding space.
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



#: a footprint is planar (a wall, a door, a long shelf seen edge-on) when its long axis spreads
#: this many times more than its short axis (standard deviations)
PLANAR_ELONGATION = 3.0
#: two planar footprints whose long axes differ by more than this many degrees meet at a corner
CORNER_DEG = 45.0


def planar_axis(keys: np.ndarray) -> np.ndarray | None:
    """Unit long axis (2,) in (col, row) cell units of a top-down mask (sorted cell keys), or None
    when the mask is not planar (elongation under PLANAR_ELONGATION, or fewer than 3 cells)."""
    if len(keys) < 3:
        return None
    rows, cols = rowcol_of(keys)
    pts = np.stack([cols, rows]).astype(np.float64)
    var, vec = np.linalg.eigh(np.cov(pts))
    if var[1] < PLANAR_ELONGATION ** 2 * max(var[0], 1e-9):
        return None
    return vec[:, 1]


def meet_at_corner(keys_a: np.ndarray, keys_b: np.ndarray) -> bool:
    """Whether two top-down masks are both planar with long axes more than CORNER_DEG apart (two
    walls meeting at an L or T, not one wall in two stretches)."""
    a, b = planar_axis(keys_a), planar_axis(keys_b)
    return a is not None and b is not None and abs(float(a @ b)) < np.cos(np.radians(CORNER_DEG))


def continuous_link(keys: np.ndarray, entries: np.ndarray, sem: np.ndarray, entry_keys: list[np.ndarray],
                    cfg: MappingConfig) -> int:
    """The entry that continues mask `keys` (sorted cell keys), or -1. `entries` (n,) are the
    entries whose masks touch it (within `cfg.continuity_gap`), `sem` (n,) their cosines with it,
    `entry_keys` every entry's cell keys. The entry of largest cosine above
    `cfg.delta_sem_continuous` (ties: lower index) that does not `meet_at_corner` with the mask."""
    ok = sem > cfg.delta_sem_continuous
    e, s = np.asarray(entries)[ok], sem[ok]
    for j in e[np.lexsort((e, -s))].tolist():
        if not meet_at_corner(keys, entry_keys[j]):
            return int(j)
    return -1
