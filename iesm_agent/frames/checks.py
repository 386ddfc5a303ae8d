"""Checks on real sensor input: depth readings, depth units and camera poses.

Depth: readings of 0, NaN or beyond the range are no reading (set to 0 and counted); a recording
whose typical reading is not a plausible indoor distance is in the wrong unit (one error for the
whole recording). Poses: finite, last row 0 0 0 1, a rotation block within `RIGID_TOL` of a rotation
(re-orthonormalised); ScanNet writes "-inf" rows where tracking was lost: that frame has no pose.
"""

from __future__ import annotations

import math
from collections import Counter
from pathlib import Path

import numpy as np

from ..errors import IesmError
from .ours import MAX_TRANSLATION_M, Intrinsics

RIGID_TOL = 0.02          # max |R^T R - I| entry of a usable pose
UNIT_RANGE_M = (0.2, 15.0)  # a recording's median depth reading must lie here (indoor sensors)
#: focal lengths (pixels) a camera may have, as multiples of the image's longer side: a
#: 170-degree fisheye is about 0.1, a strong telephoto 20
FOCAL_RANGE = (0.05, 100.0)


class BadFrame(IesmError):
    """One frame is unusable (missing file, bad pose); `iesm segment --skip-bad-frames` skips it."""


class SkipLog:
    """Frames skipped and why (frame name -> reason), plus invalid depth readings counted."""

    def __init__(self) -> None:
        self.skipped: list[tuple[str, str]] = []
        self.invalid_depth = Counter()   # reason -> pixels
        self.depth_pixels = 0

    def skip(self, name: str, reason: str) -> None:
        self.skipped.append((name, reason))

    def summary(self) -> str:
        """One line: skipped frames by reason and the share of depth pixels without a reading."""
        parts = []
        if self.skipped:
            reasons = Counter(r for _, r in self.skipped)
            parts.append(f"{len(self.skipped)} frames skipped (" +
                         "; ".join(f"{n} {r}" for r, n in reasons.most_common()) + ")")
        else:
            parts.append("no frame skipped")
        if self.depth_pixels:
            bad = ", ".join(f"{reason} {100 * n / self.depth_pixels:.1f}%" for reason, n in
                            sorted(self.invalid_depth.items()))
            parts.append(f"depth pixels without a reading: {bad or 'none'}")
        return "; ".join(parts)

    def as_meta(self) -> dict[str, str]:
        return {"frames_skipped": str(len(self.skipped)),
                "skipped": "; ".join(f"{n}: {r}" for n, r in self.skipped)[:2000]}


def clean_depth(raw: np.ndarray, scale: float, max_depth: float, path: Path, log: SkipLog | None = None) -> np.ndarray:
    """Depth (H, W) float32 metres from raw sensor values (`scale` raw units per metre): zero,
    NaN / inf and readings beyond `max_depth` m become 0 (no reading) and are counted in `log`."""
    if raw.ndim != 2:
        raise BadFrame(f"depth must be a single-channel image, got shape {raw.shape}", path)
    depth = raw.astype(np.float32) / np.float32(scale)
    finite = np.isfinite(depth)
    zero = finite & (depth <= 0)
    far = finite & (depth > max_depth)
    if log is not None:
        log.depth_pixels += depth.size
        log.invalid_depth["zero"] += int(zero.sum())
        log.invalid_depth["NaN"] += int((~finite).sum())
        log.invalid_depth[f"beyond {max_depth:g} m"] += int(far.sum())
    depth[~finite | zero | far] = 0.0
    return depth


def check_depth_scale(scale: float, source, where: str | None = None) -> float:
    """`scale` (raw depth units per metre) when it is a finite number > 0, else an `IesmError`
    (NaN, infinity, zero or a negative scale would lose every reading)."""
    try:
        value = float(scale)
    except (TypeError, ValueError, OverflowError):
        value = math.nan
    if not (math.isfinite(value) and value > 0):
        raise IesmError(f"depth scale must be a finite number > 0 (raw units per metre), got {scale!r}", source, where)
    return value


def check_intrinsics(k: Intrinsics, source) -> Intrinsics:
    """`k` when a camera could have it: focal lengths within `FOCAL_RANGE` times the image's
    longer side and the principal point within one image size of the image; else an `IesmError`."""
    side = max(k.width, k.height)
    lo, hi = FOCAL_RANGE[0] * side, FOCAL_RANGE[1] * side
    for name, f in (("fx", k.fx), ("fy", k.fy)):
        if not lo <= f <= hi:
            raise IesmError(f"camera intrinsics: {name} = {f:g} px is not a focal length for a {k.width} x "
                            f"{k.height} image (expected {lo:g}-{hi:g} px)", source)
    for name, c, size in (("cx", k.cx, k.width), ("cy", k.cy, k.height)):
        if not -size <= c <= 2 * size:
            raise IesmError(f"camera intrinsics: {name} = {c:g} px lies far outside the {k.width} x {k.height} "
                            f"image", source)
    return k


def check_depth_unit(depth_m: np.ndarray, scale: float, path: Path, layout: str) -> None:
    """Refuse a recording whose median reading (m) is not a plausible indoor distance."""
    valid = depth_m[depth_m > 0]
    if valid.size < 100:
        return
    median = float(np.median(valid))
    lo, hi = UNIT_RANGE_M
    if not lo <= median <= hi:
        raise IesmError(f"depth looks like it is in the wrong unit: median reading {median:.3g} m with "
                        f"{layout}'s scale of {scale:g} per metre (expected {lo}-{hi} m); "
                        f"pass --depth-scale with the raw units per metre", path)


def check_pose(pose: np.ndarray, source: str) -> np.ndarray:
    """A usable camera-to-world pose (4, 4) float64 (rotation re-orthonormalised), or `BadFrame`."""
    pose = np.asarray(pose, np.float64)
    if pose.shape != (4, 4):
        raise BadFrame(f"pose must be 4x4, got {pose.shape}", source)
    if np.isneginf(pose).any() or np.isposinf(pose).any():
        raise BadFrame("pose has infinite entries (tracking lost)", source)
    if np.isnan(pose).any():
        raise BadFrame("pose has NaN entries", source)
    if not np.allclose(pose[3], [0, 0, 0, 1], atol=1e-6):
        raise BadFrame(f"pose's last row must be 0 0 0 1, got {pose[3].tolist()}", source)
    if np.abs(pose[:3, 3]).max() > MAX_TRANSLATION_M:
        raise BadFrame(f"pose translation of {np.abs(pose[:3, 3]).max():.3g} m is too far (a corrupt pose: "
                       f"at most +-{MAX_TRANSLATION_M:g} m)", source)
    r = pose[:3, :3]
    if np.abs(r).max() > 1.0 + RIGID_TOL:  # a rotation's entries lie in [-1, 1] (and R^T R cannot overflow)
        raise BadFrame(f"pose is not rigid (rotation entry {np.abs(r).max():.3g} outside [-1, 1])", source)
    err = float(np.abs(r.T @ r - np.eye(3)).max())
    if err > RIGID_TOL or np.linalg.det(r) <= 0:
        raise BadFrame(f"pose is not rigid (|R^T R - I| = {err:.3g}, det {np.linalg.det(r):.3g})", source)
    u, _s, vt = np.linalg.svd(r)
    out = pose.copy()
    out[:3, :3] = u @ vt
    return out


def pose_reason(exc: BadFrame) -> str:
    """The short reason of a pose error for the skip summary."""
    msg = exc.message
    return ("invalid pose (-inf: tracking lost)" if "infinite" in msg else
            "invalid pose (NaN)" if "NaN" in msg else "invalid pose (too far)" if "too far" in msg else
            "invalid pose (not rigid)" if "rigid" in msg else "no depth reading" if "no reading" in msg else
            "missing file" if "missing" in msg else msg.split(" (")[0])
