"""Open-vocabulary categorisation (paper Sec. 3.1): Z = F E^T, label = argmax_j Z_nj."""

from __future__ import annotations

import numpy as np


def category_scores(f: np.ndarray, e: np.ndarray) -> np.ndarray:
    """Z (N, J) = F (N, D) E^T for instance embeddings F and category text embeddings E (J, D)."""
    return np.asarray(f, np.float64) @ np.asarray(e, np.float64).T


def category_ranking(z: np.ndarray) -> np.ndarray:
    """(N, J) category indices per instance, best first (ties: lower category index first)."""
    return np.argsort(-z, axis=1, kind="stable")


def ranked_labels(z: np.ndarray, categories: list[str], n_alt: int = 4) -> list[tuple[str, list[str]]]:
    """(label, next `n_alt` labels) per instance from its category scores Z (N, J)."""
    if z.shape[1] != len(categories):
        raise ValueError(f"{len(categories)} categories but {z.shape[1]} category embeddings")
    return [(categories[row[0]], [categories[j] for j in row[1:1 + n_alt]]) for row in category_ranking(z)]
