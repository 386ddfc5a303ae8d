"""Simulated per-cell room labels that behave like the paper's per-pixel CLIP baseline.

For every frame, each depth pixel (every one by default: `stride` 1) is back-projected to the world
and voted into the grid cell it lands in. Errors are correlated with the viewpoint, as a CLIP-like
feature of a whole view is: per frame, with probability `p_confuse` the camera's room is read as a
similar type (lexicon "related" pairs, else any other type in the scene) for every pixel in it;
and each other room the view sees (through a door, across an open-plan space) is recognised as its
own type with probability `p_content`, else all its pixels take the camera's room label. `p_noise`
of the pixels get a random type. Cells take the majority over all votes. Everything is seeded.
Reads the ground truth, so only for the simulator.
"""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..errors import IesmError
from ..frames import FrameSet
from ..mapping.project import world_points
from ..store.model import GridSpec
from ..rooms.labels import CellLabels, flat_cells
from .ground_truth import GroundTruth


def _similar_types(names: list[str]) -> list[np.ndarray]:
    """Per room type, the indices of the types it is confused with (lexicon relations, else all others)."""
    from ..lexicon import read_data

    related: dict[str, set[str]] = {}
    for a, b, _ in read_data("rooms.json").get("related", []):
        related.setdefault(a, set()).add(b)
        related.setdefault(b, set()).add(a)
    out = []
    for i, name in enumerate(names):
        close = [names.index(other) for other in related.get(name, ()) if other in names]
        out.append(np.array(close or [j for j in range(len(names)) if j != i] or [i]))
    return out


class ViewpointLabels:
    """`CellLabelSource` over a simulator frame directory (needs DIR/gt)."""

    def __init__(self, frames_dir: str | Path, *, seed: int = 0, stride: int = 1, p_content: float = 0.7,
                 p_confuse: float = 0.2, p_noise: float = 0.1, max_height: float = 2.0):
        self.frames = FrameSet.open(frames_dir)
        self.gt = GroundTruth.load(frames_dir)
        if not self.gt.rooms_list:
            raise IesmError("ground truth lists no rooms: no room types to label cells with", Path(frames_dir) / "gt")
        self.seed, self.stride, self.max_height = seed, stride, max_height
        self.p_content, self.p_confuse, self.p_noise = p_content, p_confuse, p_noise
        self.names = sorted({str(room["label"]) for room in self.gt.rooms_list})

    def cell_labels(self, grid: GridSpec) -> CellLabels:
        rng = np.random.default_rng(self.seed)
        index = {name: i for i, name in enumerate(self.names)}
        room_type = np.full(int(self.gt.rooms.max(initial=-1)) + 2, -1, np.int64)  # room id -> type, [-1] = none
        for room in self.gt.rooms_list:
            room_type[int(room["id"])] = index[str(room["label"])]
        gt_rooms = self.gt.rooms.ravel()
        similar = _similar_types(self.names)
        n_labels = len(self.names)
        codes = []
        k = self.frames.intrinsics
        v, u = np.mgrid[0:k.height:self.stride, 0:k.width:self.stride]
        sampled = (v * k.width + u).ravel()
        for frame in self.frames:
            pixels = sampled[frame.depth.ravel()[sampled] > 0]
            points = world_points(frame.depth, pixels, k.fx, k.fy, k.cx, k.cy, frame.pose).T  # (M, 3)
            points = points[points[:, 2] < self.max_height]
            camera_cell = flat_cells(frame.pose[None, :2, 3], self.gt.grid)[0]
            camera_type = room_type[gt_rooms[camera_cell]] if camera_cell >= 0 else -1
            if camera_type < 0 or len(points) == 0:
                continue
            camera_room = gt_rooms[camera_cell]
            read_as = int(rng.choice(similar[camera_type])) if rng.random() < self.p_confuse else camera_type
            gt_cell = flat_cells(points[:, :2], self.gt.grid)
            point_room = np.where(gt_cell >= 0, gt_rooms[np.maximum(gt_cell, 0)], -1)
            # per room seen in this view: recognised as itself, or read as the camera's room
            rooms_seen = np.unique(point_room[(point_room >= 0) & (point_room != camera_room)])
            recognised = rooms_seen[rng.random(len(rooms_seen)) < self.p_content]
            content = np.where(point_room >= 0, room_type[np.maximum(point_room, 0)], -1)
            label = np.where(np.isin(point_room, recognised) & (content >= 0), content, read_as)
            noisy = rng.random(len(points)) < self.p_noise
            label[noisy] = rng.integers(0, n_labels, int(noisy.sum()))
            cell = flat_cells(points[:, :2], grid)
            codes.append(cell[cell >= 0] * n_labels + label[cell >= 0])
        all_codes = np.concatenate(codes) if codes else np.zeros(0, np.int64)
        return CellLabels.from_votes(all_codes, (grid.height, grid.width), self.names)
