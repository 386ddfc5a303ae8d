"""A segmenter that needs no weights: colour-and-depth superpixels (scikit-image SLIC on Lab
colour plus scaled inverse depth, at half resolution), merged across boundaries where colour
is close and depth continuous (union-find over neighbouring superpixel pairs). Each region is a
mask; its embedding is a 4 x 4 x 4 CIELAB histogram, square-rooted and L2-normalised (so the
cosine of two embeddings is their Bhattacharyya coefficient); its score is its share of pixels with
depth. The instances carry no category (embedding space `SPACE`, no text tower)."""

from __future__ import annotations

import numpy as np

from ..frames import Frame, Segmentation

SPACE = "lab-hist-64"
BINS = 4


class GeometricSegmenter:
    """`segment(frame) -> Segmentation`; all thresholds in the constructor.

    `n_segments` SLIC superpixels per frame; `colour_merge` max CIELAB distance of neighbours'
    means to merge; `depth_jump` max relative depth step (|dz| / z) across a shared boundary;
    `min_area` smallest mask as a share of the image; `min_depth_share` smallest share of mask
    pixels with depth."""

    name = "geometric"
    space = SPACE

    def __init__(self, n_segments: int = 300, colour_merge: float = 12.0, depth_jump: float = 0.04,
                 min_area: float = 0.002, min_depth_share: float = 0.5, depth_weight: float = 60.0):
        self.n_segments = n_segments
        self.colour_merge = colour_merge
        self.depth_jump = depth_jump
        self.min_area = min_area
        self.min_depth_share = min_depth_share
        self.depth_weight = depth_weight

    def segment(self, frame: Frame) -> Segmentation:
        import cv2
        from skimage.segmentation import slic

        h, w = frame.depth.shape
        small_rgb = cv2.resize(frame.rgb, (w // 2, h // 2), interpolation=cv2.INTER_AREA)
        small_d = cv2.resize(frame.depth, (w // 2, h // 2), interpolation=cv2.INTER_NEAREST)
        lab = cv2.cvtColor(small_rgb, cv2.COLOR_RGB2LAB).astype(np.float32)
        lab[..., 0] *= 100.0 / 255.0
        lab[..., 1:] -= 128.0
        inv = np.where(small_d > 0, 1.0 / np.maximum(small_d, 1e-3), 0.0).astype(np.float32)
        features = np.dstack([lab, inv * self.depth_weight])
        labels = slic(features, n_segments=self.n_segments, compactness=10.0, channel_axis=-1,
                      convert2lab=False, start_label=0, enforce_connectivity=True)
        labels = self._merge(labels, lab, small_d)
        labels = cv2.resize(labels.astype(np.int32), (w, h), interpolation=cv2.INTER_NEAREST)
        return self._masks(labels, frame)

    def _merge(self, labels: np.ndarray, lab: np.ndarray, depth: np.ndarray) -> np.ndarray:
        """Union superpixels whose mean colours are within `colour_merge` and whose shared
        boundary has a median relative depth step below `depth_jump`."""
        n = int(labels.max()) + 1
        flat = labels.ravel()
        counts = np.bincount(flat, minlength=n).astype(np.float64)
        mean_lab = np.stack([np.bincount(flat, lab[..., c].ravel(), n) for c in range(3)], 1) / counts[:, None]
        pairs, steps = [], []
        for a, b, da, db in ((labels[:, :-1], labels[:, 1:], depth[:, :-1], depth[:, 1:]),
                             (labels[:-1], labels[1:], depth[:-1], depth[1:])):
            edge = (a != b) & (da > 0) & (db > 0)
            lo, hi = np.minimum(a[edge], b[edge]), np.maximum(a[edge], b[edge])
            pairs.append(lo.astype(np.int64) * n + hi)
            steps.append(np.abs(da[edge] - db[edge]) / np.minimum(da[edge], db[edge]))
        pairs, steps = np.concatenate(pairs), np.concatenate(steps)
        if len(pairs) == 0:
            return labels
        order = np.argsort(pairs, kind="stable")
        pairs, steps = pairs[order], steps[order]
        uniq, start = np.unique(pairs, return_index=True)
        sizes = np.diff(np.append(start, len(pairs)))
        med = np.array([np.median(steps[s:s + k]) for s, k in zip(start, sizes)])
        a, b = uniq // n, uniq % n
        close = (np.linalg.norm(mean_lab[a] - mean_lab[b], axis=1) < self.colour_merge) & (med < self.depth_jump)
        from scipy.sparse import coo_matrix
        from scipy.sparse.csgraph import connected_components

        graph = coo_matrix((np.ones(int(close.sum())), (a[close], b[close])), shape=(n, n))
        return connected_components(graph, directed=False)[1][labels]

    def _masks(self, labels: np.ndarray, frame: Frame) -> Segmentation:
        import cv2

        h, w = labels.shape
        flat = labels.ravel()
        n = int(flat.max()) + 1
        area = np.bincount(flat, minlength=n)
        with_depth = np.bincount(flat, (frame.depth.ravel() > 0).astype(np.float64), minlength=n)
        share = with_depth / np.maximum(area, 1)
        keep = np.flatnonzero((area >= self.min_area * h * w) & (share >= self.min_depth_share))
        keep = keep[np.argsort(-area[keep], kind="stable")]
        lab = cv2.cvtColor(frame.rgb, cv2.COLOR_RGB2LAB)
        bins = (lab[..., 0] // (256 // BINS)).astype(np.int64) * BINS * BINS + \
            (lab[..., 1] // (256 // BINS)).astype(np.int64) * BINS + (lab[..., 2] // (256 // BINS)).astype(np.int64)
        remap = np.full(n, -1, np.int64)
        remap[keep] = np.arange(len(keep))
        k = remap[flat]
        sel = k >= 0
        hist = np.bincount(k[sel] * BINS ** 3 + bins.ravel()[sel], minlength=len(keep) * BINS ** 3)
        hist = np.sqrt(hist.reshape(len(keep), BINS ** 3).astype(np.float64))
        hist /= np.maximum(np.linalg.norm(hist, axis=1, keepdims=True), 1e-12)
        masks = labels[None] == keep[:, None, None]
        return Segmentation(masks, hist.astype(np.float32), share[keep].astype(np.float32))
