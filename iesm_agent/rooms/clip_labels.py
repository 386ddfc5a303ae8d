"""Per-cell room labels from CLIP frame features (paper Sec. 3.2, semantic labelling).

`iesm segment --segmenter sam-clip` writes, beside the frames, `frame_features.npz` (`features`
(N, D) float32, one L2-normalised CLIP image embedding per frame) and `vocabulary.npz`
(`room_names` (R,), `room_embeddings` (R, D) float32: CLIP's text tower on the room types). Each
frame is scored against the room types (cosine = dot product) and read as the best one; every
grid cell the frame observes (its depth pixels back-projected with the pose, every `stride`-th
pixel in each direction, points below `max_height` m and within `max_depth` m of the camera) gets
one vote for that type, at most one per frame; each cell takes the majority over frames (ties:
the lower type index). Frames whose feature is zero (not embedded) do not vote. Like the
paper's, a frame looking through a door votes its own room into the next one; the contextual
split and object votes in `rooms.segment` deal with that.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import IesmError
from ..frames import FrameSet
from ..mapping.project import world_points
from ..store.model import GridSpec
from .labels import CellLabels, flat_cells

NEEDS = "written by `iesm segment --segmenter sam-clip`"


class ClipFrameLabels:
    """`CellLabelSource` over a frame directory with CLIP frame features and room embeddings."""

    def __init__(self, frames_dir: str | Path, *, stride: int = 4, max_height: float = 2.0, max_depth: float = 6.0):
        if stride < 1 or not max_height > 0 or not max_depth > 0:
            raise IesmError(f"stride must be >= 1 and heights/depths > 0, got {stride}, {max_height}, {max_depth}",
                            frames_dir)
        directory = Path(frames_dir)
        self.frames = FrameSet.open(directory)
        for name in ("frame_features.npz", "vocabulary.npz"):
            if not (directory / name).is_file():
                raise IesmError(f"--room-labels clip needs {name} {NEEDS}", directory / name)
        vocabulary = self.frames.vocabulary()
        features = self.frames.frame_features()
        self.names = [str(n) for n in vocabulary["room_names"]]
        rooms = np.asarray(vocabulary["room_embeddings"], np.float32)
        if not self.names:
            raise IesmError(f"no room_names to label cells with (segment with --rooms FILE or the default room list, "
                            f"{NEEDS})", directory / "vocabulary.npz")
        if rooms.ndim != 2 or rooms.shape != (len(self.names), features.shape[1]):
            raise IesmError(f"room_embeddings have shape {rooms.shape}, expected ({len(self.names)}, "
                            f"{features.shape[1]}) (one per room name, in the frame features' space)",
                            directory / "vocabulary.npz")
        if not (np.isfinite(features).all() and np.isfinite(rooms).all()):
            raise IesmError("frame features or room embeddings hold NaN or infinity", directory)
        self.stride, self.max_height, self.max_depth = stride, max_height, max_depth
        self.scores = features @ rooms.T  # (N, R) cosine of each frame with each room type
        self.frame_rooms = np.where(np.abs(features).sum(axis=1) > 0, self.scores.argmax(axis=1), -1)

    def cell_labels(self, grid: GridSpec) -> CellLabels:
        """Majority over frames of the room type each observed cell of `grid` was seen in."""
        k = self.frames.intrinsics
        v, u = np.mgrid[0:k.height:self.stride, 0:k.width:self.stride]
        sampled = (v * k.width + u).ravel()
        n_types = len(self.names)
        codes = []
        for index, room_type in enumerate(self.frame_rooms):
            if room_type < 0:
                continue
            frame = self.frames.read(index)
            depth = frame.depth.ravel()[sampled]
            pixels = sampled[(depth > 0) & (depth <= self.max_depth) & np.isfinite(depth)]
            points = world_points(frame.depth, pixels, k.fx, k.fy, k.cx, k.cy, frame.pose).T  # (M, 3) m
            cells = flat_cells(points[points[:, 2] < self.max_height, :2], grid)
            cells = np.unique(cells[cells >= 0])
            codes.append(cells * n_types + int(room_type))
        all_codes = np.concatenate(codes) if codes else np.zeros(0, np.int64)
        return CellLabels.from_votes(all_codes, (grid.height, grid.width), self.names)
