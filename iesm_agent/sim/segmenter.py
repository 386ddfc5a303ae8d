"""The synthetic segmenter: ground-truth instance ids -> candidate masks + embeddings with
seeded, configurable faults (misses, splits, merges, eroded boundaries, embedding noise,
confusable labels). Embeddings live in a `text_vectors` space, so categorising them against
category text embeddings (Z = F E^T) is meaningful."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
from pydantic import BaseModel, ConfigDict, Field

from ..embeddings import text_vectors
from ..errors import IesmError
from ..frames import Frame, Segmentation
from .realism import EASY, Realism

DEFAULT_CONFUSABLES: dict[str, list[str]] = {
    "stool": ["chair"], "office chair": ["chair"], "armchair": ["sofa"], "bench": ["sofa"],
    "nightstand": ["dresser"], "sideboard": ["dresser"], "cabinet": ["wardrobe"], "mug": ["cup"],
    "cup": ["mug"], "coffee table": ["dining table"], "console table": ["desk"], "bookshelf": ["shelf"],
    "shelf": ["bookshelf"], "monitor": ["television"], "basket": ["storage box"], "bowl": ["plate"],
    "towel": ["pillow"], "dryer": ["washing machine"], "laundry basket": ["trash can"],
}


class FaultConfig(BaseModel):
    """Segmenter faults; every rate is a per-mask probability in [0, 1].

    - `min_area_px`: instances with fewer visible pixels are not proposed at all.
    - `miss_rate`: a mask is dropped.
    - `split_rate`: a mask is cut in two across its longer side (both halves keep the label).
    - `merge_rate`: a pair of touching instances becomes one mask with the larger one's label.
    - `erode_rate`, `erode_px`: the mask boundary is eroded by `erode_px` pixels (cv2.erode).
    - `embedding_noise`: norm of the random direction added to the unit label vector
      (cosine to the clean vector ~ 1 / sqrt(1 + noise^2)).
    - `confusion_rate`, `confusion_strength`: the label vector is pulled towards a confusable
      label from `confusables` (strength > 0.5 puts it nearer the wrong label).
    - `seed`: faults for frame i are drawn from `default_rng([seed, i])`.
    """

    model_config = ConfigDict(extra="forbid")

    min_area_px: int = Field(default=40, ge=1)
    miss_rate: float = Field(default=0.05, ge=0, le=1)
    split_rate: float = Field(default=0.05, ge=0, le=1)
    merge_rate: float = Field(default=0.03, ge=0, le=1)
    erode_rate: float = Field(default=0.3, ge=0, le=1)
    erode_px: int = Field(default=2, ge=1, le=20)
    embedding_noise: float = Field(default=0.4, ge=0)
    confusion_rate: float = Field(default=0.1, ge=0, le=1)
    confusion_strength: float = Field(default=0.6, ge=0, le=1)
    confusables: dict[str, list[str]] = Field(default_factory=lambda: dict(DEFAULT_CONFUSABLES))
    seed: int = 0


@dataclass
class FaultLog:
    """What happened to one frame's masks: counts of proposed instances and of each fault."""

    proposed: int = 0
    missed: int = 0
    split: int = 0
    merged: int = 0
    eroded: int = 0
    confused: int = 0


class SyntheticSegmenter:
    """Implements the `Segmenter` protocol from ground-truth instance ids. `labels` maps
    instance id -> category label; `space` the embedding space (None: the best available);
    `realism` the profile (sim/realism.py; default easy: masks are the instance pixels with the
    `config` faults, embeddings the label vector plus isotropic noise); `vocabulary` the
    categories whose similarities realistic embedding errors follow (default: the labels)."""

    def __init__(self, labels: dict[int, str], config: FaultConfig | None = None, space: str | None = None,
                 realism: Realism | None = None, vocabulary: list[str] | None = None):
        from .embedding_noise import EmbeddingNoise

        self.labels = labels
        self.config = config or FaultConfig()
        self.realism = realism or EASY
        names = sorted(set(labels.values()) | {c for cs in self.config.confusables.values() for c in cs}
                       | set(vocabulary or ()))
        vectors, self.space = text_vectors(names, space)
        self.vectors = dict(zip(names, vectors))
        self.noise = None if self.realism.easy else EmbeddingNoise(
            self.vectors, self.realism, self.config.seed)

    def segment(self, frame: Frame) -> Segmentation:
        return self.segment_with_log(frame)[0]

    def _embed(self, label: str, rng: np.random.Generator, log: FaultLog) -> np.ndarray:
        cfg = self.config
        vec = self.vectors[label].astype(np.float64)
        confusers = cfg.confusables.get(label)
        if confusers and rng.random() < cfg.confusion_rate:
            other = self.vectors[confusers[int(rng.integers(len(confusers)))]]
            vec = (1 - cfg.confusion_strength) * vec + cfg.confusion_strength * other
            vec /= np.linalg.norm(vec)
            log.confused += 1
        if cfg.embedding_noise > 0:
            noise = rng.standard_normal(vec.shape)
            vec = vec + cfg.embedding_noise * noise / np.linalg.norm(noise)
        return (vec / np.linalg.norm(vec)).astype(np.float32)

    def _embed_realistic(self, instance: int, label: str, piece: np.ndarray, true_mask: np.ndarray, frame: Frame,
                         rng: np.random.Generator) -> tuple[np.ndarray, float]:
        """Embedding of one realistic mask and a score penalty for its leaked share."""
        from .mask_noise import leak_shares

        leaks = leak_shares(piece, true_mask, frame.instance_ids)
        depth = frame.depth[piece]
        depth = depth[depth > 0]
        median = float(np.median(depth)) if len(depth) else self.realism.depth_max
        vec = self.noise.embed(instance, label, leaks, self.labels, int(piece.sum()), median, rng)
        return vec, 0.3 * sum(leaks.values())

    def segment_with_log(self, frame: Frame) -> tuple[Segmentation, FaultLog]:
        """Masks (K, H, W), embeddings (K, D), scores (K,) for frame.instance_ids, plus the fault log."""
        import cv2

        if frame.instance_ids is None:
            raise IesmError(f"frame {frame.index} has no instance ids; the synthetic segmenter needs inst.png")
        cfg, inst = self.config, frame.instance_ids
        rng = np.random.default_rng([cfg.seed, frame.index])
        ids, areas = np.unique(inst[inst > 0], return_counts=True)
        big = areas >= cfg.min_area_px
        ids, area_of = ids[big], dict(zip(ids[big].tolist(), areas[big].tolist()))
        log = FaultLog(proposed=len(ids))
        groups = {int(i): [int(i)] for i in ids}  # mask key -> instance ids it covers
        for a, b in _touching_pairs(inst, set(groups)):
            if a in groups and b in groups and rng.random() < cfg.merge_rate:
                groups[a] += groups.pop(b)
                log.merged += 1
        masks, vecs, scores = [], [], []
        realistic = self.noise is not None
        if realistic:
            from .mask_noise import weakness

            weak = weakness(frame.rgb, frame.depth, self.realism.boundary_wander_px)
        for key in sorted(groups):
            if rng.random() < cfg.miss_rate:
                log.missed += 1
                continue
            members = groups[key]
            mask = np.isin(inst, members)
            main = max(members, key=lambda m: area_of[m])
            label = self.labels[main]
            faults = len(members) - 1
            if rng.random() < cfg.erode_rate:
                kernel = np.ones((2 * cfg.erode_px + 1,) * 2, np.uint8)
                eroded = cv2.erode(mask.astype(np.uint8), kernel).astype(bool)
                if eroded.sum() >= cfg.min_area_px:
                    mask, faults = eroded, faults + 1
                    log.eroded += 1
            true_mask = np.isin(inst, members)
            if realistic:
                from .mask_noise import wander

                moved = wander(mask, weak, self.realism.boundary_wander_px, rng)
                if moved.sum() >= cfg.min_area_px:
                    mask = moved
            pieces = [mask]
            if rng.random() < cfg.split_rate and mask.sum() >= 2 * cfg.min_area_px:
                pieces = _split(mask)
                faults += 1
                log.split += 1
            for piece in pieces:
                masks.append(piece)
                penalty = 0.0
                if realistic:
                    vec, penalty = self._embed_realistic(main, label, piece, true_mask, frame, rng)
                    vecs.append(vec)
                else:
                    vecs.append(self._embed(label, rng, log))
                scores.append(np.clip(0.95 - 0.15 * faults - penalty - rng.uniform(0, 0.1), 0.05, 1.0))
        h, w = inst.shape
        dim = len(next(iter(self.vectors.values())))
        seg = Segmentation(np.array(masks, bool).reshape(-1, h, w), np.array(vecs, np.float32).reshape(-1, dim),
                           np.array(scores, np.float32))
        return seg, log


def _touching_pairs(inst: np.ndarray, keep: set[int]) -> list[tuple[int, int]]:
    """Sorted unique (a, b), a < b, of proposed instances with 4-adjacent pixels."""
    pairs = []
    for a, b in ((inst[:, :-1], inst[:, 1:]), (inst[:-1], inst[1:])):
        edge = (a != b) & (a > 0) & (b > 0)
        pairs.append(np.stack([np.minimum(a[edge], b[edge]), np.maximum(a[edge], b[edge])], 1))
    uniq = np.unique(np.concatenate(pairs), axis=0) if pairs else np.zeros((0, 2), int)
    return [(int(a), int(b)) for a, b in uniq if a in keep and b in keep]


def _split(mask: np.ndarray) -> list[np.ndarray]:
    """Cut a mask in two at the median pixel coordinate across its longer side."""
    rows, cols = np.nonzero(mask)
    axis_cols = (cols.max() - cols.min()) >= (rows.max() - rows.min())
    coords = cols if axis_cols else rows
    cut = int(np.median(coords))
    first = np.zeros_like(mask)
    sel = coords <= cut
    first[rows[sel], cols[sel]] = True
    second = mask & ~first
    return [first, second] if second.any() and first.any() else [mask]
