"""Realistic mask boundaries: a segmenter's boundary follows strong colour and depth edges and
wanders where they are weak, so a mask leaks into (or gives up pixels to) a neighbour that looks
like it.

Per frame, `weakness` (H, W) in [0, 1] is exp(-edge strength), edge strength being the colour
gradient (Sobel on the grey image, per 64 grey levels) plus the relative depth gradient (per 5 %),
blurred over the wander distance. Per mask, the signed distance to its boundary (pixels, positive
inside) plus `wander_px` x weakness x a smooth random field in [-1, 1] decides the new mask.
"""

from __future__ import annotations

import numpy as np


def weakness(rgb: np.ndarray, depth: np.ndarray, wander_px: float) -> np.ndarray:
    """(H, W) float32 in [0, 1]: 1 where neither colour nor depth has an edge nearby."""
    import cv2

    grey = cv2.cvtColor(rgb, cv2.COLOR_RGB2GRAY).astype(np.float32)
    colour = np.hypot(cv2.Sobel(grey, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(grey, cv2.CV_32F, 0, 1, ksize=3)) / 8.0
    valid = depth > 0
    safe = np.where(valid, depth, 1.0).astype(np.float32)
    log_d = np.log(safe)
    grad = np.hypot(cv2.Sobel(log_d, cv2.CV_32F, 1, 0, ksize=3), cv2.Sobel(log_d, cv2.CV_32F, 0, 1, ksize=3)) / 8.0
    grad[~valid] = 0.0
    strength = colour / 64.0 + grad / 0.05
    sigma = max(wander_px / 2.0, 0.5)
    return cv2.GaussianBlur(np.exp(-strength).astype(np.float32), (0, 0), sigma)


def smooth_field(shape: tuple[int, int], rng: np.random.Generator, scale_px: float = 12.0) -> np.ndarray:
    """(H, W) float32 smooth random values in about [-1, 1] (features ~`scale_px` wide)."""
    import cv2

    h, w = shape
    coarse = rng.uniform(-1, 1, (max(2, int(h / scale_px) + 2), max(2, int(w / scale_px) + 2))).astype(np.float32)
    return cv2.resize(coarse, (w, h), interpolation=cv2.INTER_CUBIC).clip(-1, 1)


def wander(mask: np.ndarray, weak: np.ndarray, wander_px: float, rng: np.random.Generator) -> np.ndarray:
    """`mask` (H, W) bool with its boundary moved by up to `wander_px` where `weak` is high."""
    import cv2

    if wander_px <= 0 or not mask.any():
        return mask
    rows, cols = np.nonzero(mask)
    pad = int(np.ceil(wander_px)) + 2
    r0, r1 = max(rows.min() - pad, 0), min(rows.max() + pad + 1, mask.shape[0])
    c0, c1 = max(cols.min() - pad, 0), min(cols.max() + pad + 1, mask.shape[1])
    crop = mask[r0:r1, c0:c1].astype(np.uint8)
    inside = cv2.distanceTransform(crop, cv2.DIST_L2, 3)
    outside = cv2.distanceTransform(1 - crop, cv2.DIST_L2, 3)
    signed = np.where(crop > 0, inside, -outside + 1.0)  # boundary pixels inside at 1, just outside at 0
    field = smooth_field(signed.shape, rng)
    moved = signed + wander_px * weak[r0:r1, c0:c1] * field > 0.5
    out = np.zeros_like(mask)
    out[r0:r1, c0:c1] = moved
    return out


def leak_shares(new: np.ndarray, old: np.ndarray, inst: np.ndarray) -> dict[int, float]:
    """Instance id -> share of `new` mask pixels that belong to that other instance (leaked in)."""
    gained = new & ~old
    total = int(new.sum())
    if not total or not gained.any():
        return {}
    ids, counts = np.unique(inst[gained], return_counts=True)
    return {int(i): c / total for i, c in zip(ids.tolist(), counts.tolist()) if i > 0}
