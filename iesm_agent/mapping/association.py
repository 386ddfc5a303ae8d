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
