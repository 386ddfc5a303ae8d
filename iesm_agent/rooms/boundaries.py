"""The structural boundary raster: line segments found in the wall/door/large-furniture mask with
OpenCV's line segment detector (LSD), short ones dropped, collinear neighbours merged, drawn,
dilated and closed.

Segments are (N, 4) float arrays of (x1, y1, x2, y2) in cell units (x = column, y = row).
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from .config import RoomConfig


@dataclass
class Boundaries:
    """`raster` (H, W) bool boundary cells (lines dilated and closed); `lines` (H, W) bool the drawn
    segments alone; `segments` (N, 4) after filtering and merging; `detector` "lsd" or "hough";
    `notes` what had to give way (e.g. the LSD fallback)."""

    raster: np.ndarray
    lines: np.ndarray
    segments: np.ndarray
    detector: str
    notes: list[str] = field(default_factory=list)


def detect_segments(mask: np.ndarray, scale: float = 0.8) -> tuple[np.ndarray, str, list[str]]:
    """Line segments of a binary (H, W) mask: LSD (Gaussian-subsampled to `scale` internally;
    coordinates stay in input pixels) when this OpenCV build has it, else
    `cv2.HoughLinesP` (with a note). Returns ((N, 4) float32, detector name, notes)."""
    import cv2

    image = np.ascontiguousarray(mask, dtype=np.uint8) * 255
    notes: list[str] = []
    try:
        detector = cv2.createLineSegmentDetector(cv2.LSD_REFINE_STD, scale)
        lines = detector.detect(image)[0]
        name = "lsd"
    except (AttributeError, cv2.error) as exc:
        notes.append(f"cv2.createLineSegmentDetector unavailable ({type(exc).__name__}); used cv2.HoughLinesP")
        lines = cv2.HoughLinesP(image, 1, np.pi / 180, threshold=10, minLineLength=3, maxLineGap=1)
        name = "hough"
    segments = np.zeros((0, 4), np.float32) if lines is None else lines.reshape(-1, 4).astype(np.float32)
    return segments, name, notes


def merge_collinear(segments: np.ndarray, angle_deg: float, offset: float, gap: float) -> np.ndarray:
    """Merge segments that are near-parallel (<= `angle_deg`), lie on nearly the same line (each
    one's midpoint within `offset` cells of the other's line) and whose extents along that line
    overlap or are at most `gap` cells apart. Each group becomes one segment along the direction of
    its longest member, spanning all members' projections."""
    n = len(segments)
    if n < 2:
        return segments
    p, q = segments[:, :2].astype(np.float64), segments[:, 2:].astype(np.float64)
    d = q - p
    length = np.linalg.norm(d, axis=1)
    u = d / np.maximum(length, 1e-9)[:, None]
    normal = np.stack([-u[:, 1], u[:, 0]], axis=1)
    mid = (p + q) / 2
    cos = np.abs(u @ u.T)
    rel = mid[None, :, :] - mid[:, None, :]                      # rel[i, j] = mid_j - mid_i
    off = np.abs(np.einsum("ijk,ik->ij", rel, normal))          # distance of mid_j from line i
    along = np.einsum("ijk,ik->ij", rel, u)                      # position of mid_j along line i
    half = length / 2
    gaps = np.abs(along) - half[:, None] - half[None, :]
    ok = ((cos >= np.cos(np.deg2rad(angle_deg))) & (np.maximum(off, off.T) <= offset)
          & (np.minimum(gaps, gaps.T) <= gap))
    pairs = np.argwhere(np.triu(ok, 1))
    from scipy.sparse import coo_matrix
    from scipy.sparse.csgraph import connected_components

    graph = coo_matrix((np.ones(len(pairs)), (pairs[:, 0], pairs[:, 1])), shape=(n, n))
    groups = connected_components(graph, directed=False)[1]
    merged = []
    for g in np.unique(groups):
        members = np.flatnonzero(groups == g)
        lead = members[np.argmax(length[members])]
        ends = np.concatenate([p[members], q[members]])
        t = (ends - p[lead]) @ u[lead]
        base = p[lead] + normal[lead] * float(np.mean((mid[members] - p[lead]) @ normal[lead]))
        merged.append(np.concatenate([base + t.min() * u[lead], base + t.max() * u[lead]]))
    return np.array(merged, np.float32)


def _disk(radius_cells: float) -> np.ndarray:
    import cv2

    r = max(int(round(radius_cells)), 0)
    return cv2.getStructuringElement(cv2.MORPH_ELLIPSE, (2 * r + 1, 2 * r + 1))


def boundary_raster(structural: np.ndarray, cell_size: float, config: RoomConfig = RoomConfig()) -> Boundaries:
    """Boundaries of a (H, W) bool structural mask at `cell_size` m per cell."""
    import cv2

    segments, detector, notes = detect_segments(structural, config.lsd_scale)
    length = np.hypot(segments[:, 2] - segments[:, 0], segments[:, 3] - segments[:, 1])
    segments = segments[length * cell_size >= config.min_segment]
    segments = merge_collinear(segments, config.merge_angle_deg, config.merge_offset / cell_size,
                               config.merge_gap / cell_size)
    raster = np.zeros(structural.shape, np.uint8)
    if len(segments):
        lines = [np.round(s).astype(np.int32).reshape(2, 2) for s in segments]
        cv2.polylines(raster, lines, isClosed=False, color=1, thickness=config.line_thickness)
    lines = raster.astype(bool)
    if config.dilate > 0:
        raster = cv2.dilate(raster, _disk(config.dilate / cell_size))
    if config.close > 0:
        raster = cv2.morphologyEx(raster, cv2.MORPH_CLOSE, _disk(config.close / cell_size))
    return Boundaries(raster=raster.astype(bool), lines=lines, segments=segments, detector=detector, notes=notes)
