"""Keyframe selection per instance and crops around an instance's mask.

Observations are rows [instance_id, frame_index, mask_index, mask_area_px, mask_score] (the
built map's `SceneMap.observations`, (M, 5)). Rows of one instance in one frame (a split mask)
are merged: masks united, areas summed, the best score kept. The keyframe score of instance n
in frame f is

    s(n, f) = c(n, f) * nu(n, f) * sqrt(a(n, f) / max_f' a(n, f'))

with c the mask confidence, nu the observation frequency around f (the fraction of the frames
f - w .. f + w in which n is observed: a steady view, not a glimpse) and a the mask area in
pixels (a larger view shows more of the object). The K frames with the highest s are the
keyframes (ties: larger area, then earlier frame).
"""

from __future__ import annotations

import base64
from dataclasses import dataclass

import numpy as np

from ..errors import IesmError

#: half-width w (frames) of the window in which observation frequency is counted
FREQUENCY_WINDOW = 5


@dataclass(frozen=True)
class Keyframe:
    """One keyframe of an instance: `frame` index, the instance's `masks` (indices into that
    frame's segmentation), `score` s(n, f) and merged mask `area` (pixels)."""

    frame: int
    masks: tuple[int, ...]
    score: float
    area: float


def select_keyframes(observations: np.ndarray, k: int = 3,
                     window: int = FREQUENCY_WINDOW) -> dict[int, list[Keyframe]]:
    """Instance id -> its at most `k` keyframes, best first (see the module docstring)."""
    if k < 1:
        raise IesmError(f"the number of keyframes must be >= 1, got {k}", "keyframes")
    obs = np.asarray(observations, np.float64)
    if obs.ndim != 2 or obs.shape[1] != 5:
        raise IesmError(f"observations must be (M, 5), got {obs.shape}", "keyframes")
    if len(obs) == 0:
        return {}
    inst, frame, mask = obs[:, 0].astype(np.int64), obs[:, 1].astype(np.int64), obs[:, 2].astype(np.int64)
    order = np.lexsort((mask, frame, inst))
    inst, frame, mask, area, conf = inst[order], frame[order], mask[order], obs[order, 3], obs[order, 4]
    # one row per (instance, frame)
    new_pair = np.ones(len(inst), bool)
    new_pair[1:] = (inst[1:] != inst[:-1]) | (frame[1:] != frame[:-1])
    starts = np.flatnonzero(new_pair)
    p_inst, p_frame = inst[starts], frame[starts]
    p_area = np.add.reduceat(area, starts)
    p_conf = np.maximum.reduceat(conf, starts)
    # observation frequency: observed frames of the same instance within +-window
    key = p_inst * (int(frame.max()) + 2 * window + 2) + p_frame
    count = np.searchsorted(key, key + window, "right") - np.searchsorted(key, key - window, "left")
    freq = count / (2 * window + 1)
    new_inst = np.ones(len(p_inst), bool)
    new_inst[1:] = p_inst[1:] != p_inst[:-1]
    inst_starts = np.flatnonzero(new_inst)
    group = np.cumsum(new_inst) - 1
    max_area = np.maximum.reduceat(p_area, inst_starts)[group]
    score = p_conf * freq * np.sqrt(p_area / np.maximum(max_area, 1e-9))
    ranked = np.lexsort((p_frame, -p_area, -score, p_inst))
    rank = np.arange(len(ranked)) - inst_starts[group[ranked]]
    chosen = ranked[rank < k]
    masks_of = np.split(mask, starts[1:])
    out: dict[int, list[Keyframe]] = {}
    for i in chosen:  # at most k per instance
        out.setdefault(int(p_inst[i]), []).append(
            Keyframe(int(p_frame[i]), tuple(int(m) for m in masks_of[i]), float(score[i]), float(p_area[i])))
    return out


def crop_box(mask: np.ndarray, margin: float = 0.15, min_margin: int = 8) -> tuple[int, int, int, int] | None:
    """(y0, y1, x0, x1) of the mask's bounding box grown by `margin` of its size (at least
    `min_margin` pixels) and clipped to the image; None for an empty mask."""
    rows, cols = np.flatnonzero(mask.any(axis=1)), np.flatnonzero(mask.any(axis=0))
    if len(rows) == 0:
        return None
    y0, y1, x0, x1 = rows[0], rows[-1] + 1, cols[0], cols[-1] + 1
    my = max(min_margin, int(round((y1 - y0) * margin)))
    mx = max(min_margin, int(round((x1 - x0) * margin)))
    h, w = mask.shape
    return max(0, y0 - my), min(h, y1 + my), max(0, x0 - mx), min(w, x1 + mx)


def outlined_png(rgb: np.ndarray, mask: np.ndarray) -> str:
    """Base64 PNG of `rgb` (H, W, 3) uint8 with the mask's outline drawn in green (what the
    vision prompt calls "outlined")."""
    import cv2

    contours, _ = cv2.findContours(mask.astype(np.uint8), cv2.RETR_EXTERNAL, cv2.CHAIN_APPROX_SIMPLE)
    bgr = cv2.cvtColor(rgb, cv2.COLOR_RGB2BGR)
    cv2.drawContours(bgr, contours, -1, (0, 255, 0), max(1, min(rgb.shape[:2]) // 120))
    ok, buf = cv2.imencode(".png", bgr)
    if not ok:
        raise IesmError("cannot encode the crop as PNG", "captioning")
    return base64.b64encode(buf.tobytes()).decode("ascii")
