"""A recording in any supported layout, read frame by frame into `Frame`s in our conventions:
depth (H, W) float32 metres (0 = no reading), colour (H, W, 3) uint8 RGB resized to the depth
image, pose (4, 4) camera-to-world with OpenCV camera axes (x right, y down, z forward) in the
recording's own world (gravity alignment is `gravity.py`'s job)."""

from __future__ import annotations

from collections import Counter
from dataclasses import dataclass, field
from pathlib import Path
from typing import Optional

import numpy as np
from pydantic import ValidationError

from ..errors import IesmError
from ..fileio import image_size, read_image, read_text
from .checks import BadFrame, SkipLog, check_depth_scale, check_intrinsics, check_pose, clean_depth
from .ours import Frame, Intrinsics

#: most frames one recording may list, and most lines a list or trajectory file may hold (TUM's
#: ground truth runs at 100 Hz: a few lines per frame)
MAX_FRAMES = 100_000
MAX_LIST_LINES = 4 * MAX_FRAMES
#: largest small text file read (a pose or camera matrix), bytes
MAX_MATRIX_BYTES = 64 * 1024
#: frames whose depth image sizes are compared to find the recording's size
SIZE_SAMPLE = 31
#: most pixels of a frame (its depth image: what segmentation and mapping work at) so that one
#: frame's processing stays far under 1 GB (about 64 bytes a pixel); depth sensors give at most
#: about 1 M, Replica's renders 0.8 M. Colour images (resized to the depth image) may be larger.
MAX_FRAME_PIXELS = 2048 * 2048


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

    def __post_init__(self) -> None:
        self.depth_scale = check_depth_scale(self.depth_scale, self.directory, "depth scale")
        if self.intrinsics.width * self.intrinsics.height > MAX_FRAME_PIXELS:
            raise IesmError(f"frames of {self.intrinsics.width} x {self.intrinsics.height} pixels are more than the "
                            f"{MAX_FRAME_PIXELS:,} a depth frame may have", self.directory)
        check_intrinsics(self.intrinsics, self.directory)
        if len(self.refs) > MAX_FRAMES:
            raise IesmError(f"{len(self.refs):,} frames are more than the {MAX_FRAMES:,} one recording may have "
                            "(use --every, or split it)", self.directory)

    def __len__(self) -> int:
        return len(self.refs)

    def read(self, i: int, log: SkipLog | None = None) -> Frame:
        """Frame i (index i); `BadFrame` for a missing/unreadable file or an unusable pose."""
        ref = self.refs[i]
        if ref.pose is None:
            raise BadFrame(ref.pose_error or "no pose", ref.pose_source)
        pose = check_pose(ref.pose, ref.pose_source)
        hw = (self.intrinsics.height, self.intrinsics.width)
        raw = read_image(ref.depth, color=False, error=BadFrame, max_pixels=MAX_FRAME_PIXELS)
        if raw.shape[:2] != hw:
            raise BadFrame(f"depth image is {raw.shape[:2]}, the intrinsics say {hw}", ref.depth)
        if raw.dtype not in (np.uint16, np.float32, np.float64, np.int32):
            raise BadFrame(f"depth must be 16-bit or floating point, got {raw.dtype}", ref.depth)
        depth = clean_depth(raw, self.depth_scale, self.max_depth, ref.depth, log)
        if not depth.any():
            raise BadFrame(f"depth has no reading (every pixel zero, NaN or beyond {self.max_depth:g} m)", ref.depth)
        rgb = read_image(ref.color, color=True, error=BadFrame)
        if rgb.shape[:2] != hw:
            import cv2

            rgb = cv2.resize(rgb, (hw[1], hw[0]), interpolation=cv2.INTER_AREA)
        return Frame(index=i, rgb=rgb, depth=depth, pose=pose)


def read_matrix(path: Path, shape: tuple[int, int]) -> np.ndarray:
    """A whitespace-separated numeric matrix of `shape` ("-inf" / "nan" kept as such) from a
    small regular text file (`fileio.read_text`: at most `MAX_MATRIX_BYTES`)."""
    text = read_text(path, max_bytes=MAX_MATRIX_BYTES, error=BadFrame)
    try:
        values = np.array([float(v) for v in text.split()], np.float64)
    except ValueError:
        raise BadFrame(f"must be {shape[0]} x {shape[1]} numbers", path) from None
    if values.size != shape[0] * shape[1]:
        raise BadFrame(f"must be {shape[0]} x {shape[1]} numbers, found {values.size}", path)
    return values.reshape(shape)


def read_list(path: Path) -> list[str]:
    """The lines of a recording's list or trajectory file (`fileio.read_text`: a regular UTF-8
    file, at most `MAX_LIST_LINES` lines), split on newlines only."""
    return read_text(path, max_lines=MAX_LIST_LINES).split("\n")


def intrinsics_from_matrix(k: np.ndarray, width: int, height: int, source: Path) -> Intrinsics:
    """`Intrinsics` from a 3x3 (or 4x4) camera matrix K in pixels."""
    return make_intrinsics(width, height, k[0, 0], k[1, 1], k[0, 2], k[1, 2], source)


def make_intrinsics(width, height, fx, fy, cx, cy, source) -> Intrinsics:
    """`Intrinsics` validated (finite numbers, positive sizes and focal lengths), or an `IesmError`
    naming `source` and the field."""
    values = {"width": width, "height": height, "fx": fx, "fy": fy, "cx": cx, "cy": cy}
    try:
        return Intrinsics.model_validate({k: float(v) if isinstance(v, np.floating) else v for k, v in values.items()})
    except ValidationError as exc:
        err = exc.errors()[0]
        raise IesmError(f"unusable camera parameters: {'.'.join(map(str, err['loc']))}: {err['msg']}",
                        source) from None


def frame_size(refs: list[FrameRef]) -> tuple[int, int]:
    """(width, height) of a recording's frames: the most common depth image size (from the
    headers) over up to `SIZE_SAMPLE` frames spread over it, so one odd frame (skipped later by
    --skip-bad-frames) does not set the size of all; colour images when no depth can be read."""
    picks = sorted({round(i) for i in np.linspace(0, len(refs) - 1, min(SIZE_SAMPLE, len(refs)))})
    for kind in ("depth", "color"):
        sizes = Counter()
        for i in picks:
            try:
                sizes[image_size(getattr(refs[i], kind), error=BadFrame)] += 1
            except BadFrame:
                continue
        if sizes:
            return sizes.most_common(1)[0][0]
    raise IesmError("no readable depth or colour image among the frames sampled", refs[picks[0]].depth)


def numbered(paths, pattern: str) -> list[tuple[int, Path]]:
    """(number, path) of files whose name matches regex `pattern` with one number group, sorted;
    more than `MAX_FRAMES` of them is an `IesmError` (before any of their files is read)."""
    import re

    rx = re.compile(pattern)
    out = []
    for p in paths:
        m = rx.fullmatch(p.name)
        if m:
            out.append((int(m.group(1)), p))
            if len(out) > MAX_FRAMES:
                raise IesmError(f"more than the {MAX_FRAMES:,} frames one recording may have (use a folder per "
                                "part)", p.parent)
    return sorted(out)
