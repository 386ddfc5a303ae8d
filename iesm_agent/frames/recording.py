"""A recording in any supported layout, read frame by frame into `Frame`s in our conventions:
depth (H, W) float32 metres (0 = no reading), colour (H, W, 3) uint8 RGB resized to the depth
image, pose (4, 4) camera-to-world with OpenCV camera axes (x right, y down, z forward) in the
recording's own world (gravity alignment is `gravity.py`'s job)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

import numpy as np

from ..errors import IesmError
from ..fileio import read_image
from .checks import BadFrame, SkipLog, check_pose, clean_depth
from .ours import Frame, Intrinsics


@dataclass
class FrameRef:
    """Where one frame lives: `name` for messages, colour and depth files, and its pose (4, 4)
    (None: the format says there is none, with `pose_error` saying why) from `pose_source`."""

    name: str
    color: Path
    depth: Path
    pose: Optional[np.ndarray]
    pose_source: str
    pose_error: str = ""


@dataclass
class Recording:
    """Frames of one recording: `intrinsics` of the depth camera (pixels), `depth_scale` raw depth
    units per metre, `max_depth` m beyond which readings are dropped, `notes` on the conventions
    applied (shown to the user and stored in scene.json's `source`)."""

    layout: str
    directory: Path
    intrinsics: Intrinsics
    depth_scale: float
    refs: list[FrameRef]
    max_depth: float = 10.0
    notes: list[str] = field(default_factory=list)
    up: Optional[tuple[float, float, float]] = None   # the format's known world up, if any

    def __len__(self) -> int:
        return len(self.refs)

    def read(self, i: int, log: SkipLog | None = None) -> Frame:
        """Frame i (index i); `BadFrame` for a missing/unreadable file or an unusable pose."""
        ref = self.refs[i]
        if ref.pose is None:
            raise BadFrame(ref.pose_error or "no pose", ref.pose_source)
        pose = check_pose(ref.pose, ref.pose_source)
        hw = (self.intrinsics.height, self.intrinsics.width)
        raw = read_image(ref.depth, color=False, error=BadFrame)
        if raw.shape[:2] != hw:
            raise BadFrame(f"depth image is {raw.shape[:2]}, the intrinsics say {hw}", ref.depth)
        if raw.dtype not in (np.uint16, np.float32, np.float64, np.int32):
            raise BadFrame(f"depth must be 16-bit or floating point, got {raw.dtype}", ref.depth)
        depth = clean_depth(raw, self.depth_scale, self.max_depth, ref.depth, log)
        rgb = read_image(ref.color, color=True, error=BadFrame)
        if rgb.shape[:2] != hw:
            import cv2

            rgb = cv2.resize(rgb, (hw[1], hw[0]), interpolation=cv2.INTER_AREA)
        return Frame(index=i, rgb=rgb, depth=depth, pose=pose)


def read_matrix(path: Path, shape: tuple[int, int]) -> np.ndarray:
    """A whitespace-separated numeric matrix of `shape` ("-inf" / "nan" kept as such)."""
    try:
        text = path.read_text(encoding="utf-8")
        values = np.array([float(v) for v in text.split()], np.float64)
    except FileNotFoundError:
        raise BadFrame("file is missing", path) from None
    except (OSError, UnicodeDecodeError, ValueError):
        raise BadFrame(f"must be {shape[0]} x {shape[1]} numbers", path) from None
    if values.size != shape[0] * shape[1]:
        raise BadFrame(f"must be {shape[0]} x {shape[1]} numbers, found {values.size}", path)
    return values.reshape(shape)


def intrinsics_from_matrix(k: np.ndarray, width: int, height: int, source: Path) -> Intrinsics:
    """`Intrinsics` from a 3x3 (or 4x4) camera matrix K in pixels."""
    try:
        return Intrinsics(width=width, height=height, fx=float(k[0, 0]), fy=float(k[1, 1]),
                          cx=float(k[0, 2]), cy=float(k[1, 2]))
    except ValueError as exc:
        raise IesmError(f"unusable camera matrix ({exc.errors()[0]['msg'] if hasattr(exc, 'errors') else exc})",
                        source) from None


def image_size(path: Path) -> tuple[int, int]:
    """(width, height) of an image file."""
    image = read_image(path, color=False, error=BadFrame)
    return image.shape[1], image.shape[0]


def numbered(paths, pattern: str) -> list[tuple[int, Path]]:
    """(number, path) of files whose name matches regex `pattern` with one number group, sorted."""
    import re

    rx = re.compile(pattern)
    out = []
    for p in paths:
        m = rx.fullmatch(p.name)
        if m:
            out.append((int(m.group(1)), p))
    return sorted(out)
