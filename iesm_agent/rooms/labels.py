"""Per-cell room labels: the pluggable source (a CLIP-like per-pixel classifier projected to the
top-down grid in real use) and the object evidence used by the contextual split."""

from __future__ import annotations

import json
from dataclasses import dataclass
from functools import lru_cache
from pathlib import Path
from typing import Protocol

import numpy as np

from ..store.model import GridSpec, SceneMap


@dataclass
class CellLabels:
    """`labels` (H, W) int32: index into `names` of the room type voted for each cell, -1 where
    nothing was observed; `names` the room-type vocabulary."""

    labels: np.ndarray
    names: list[str]

    @classmethod
    def from_votes(cls, codes: np.ndarray, shape: tuple[int, int], names: list[str]) -> "CellLabels":
        """Majority vote per cell of (M,) codes `flat_cell * len(names) + label` (ties -> lower
        label index); cells without votes get -1."""
        n_labels = len(names)
        counts = np.bincount(codes, minlength=shape[0] * shape[1] * n_labels).reshape(-1, n_labels)
        labels = np.where(counts.any(axis=1), counts.argmax(axis=1), -1).astype(np.int32)
        return cls(labels.reshape(shape), list(names))


def flat_cells(points_xy: np.ndarray, grid: GridSpec) -> np.ndarray:
    """(M,) flat cell index (row * width + col) of each (x, y) point in metres of (M, 2)
    `points_xy`, -1 for points outside the grid."""
    col = np.floor((points_xy[:, 0] - grid.origin[0]) / grid.cell_size).astype(np.int64)
    row = np.floor((points_xy[:, 1] - grid.origin[1]) / grid.cell_size).astype(np.int64)
    inside = (row >= 0) & (row < grid.height) & (col >= 0) & (col < grid.width)
    return np.where(inside, row * grid.width + col, -1)


class CellLabelSource(Protocol):
    """Gives each observed cell of `grid` a room type (e.g. CLIP similarity of the pixels that
    project there against room-type prompts, majority-voted over frames)."""

    def cell_labels(self, grid: GridSpec) -> CellLabels: ...


@lru_cache(maxsize=1)
def room_objects() -> dict[str, tuple[str, ...]]:
    """Room type -> categories typical of it (rooms/room_objects.json)."""
    data = json.loads((Path(__file__).parent / "room_objects.json").read_text(encoding="utf-8"))
    return {room: tuple(objects) for room, objects in data["rooms"].items()}


def object_votes(scene: SceneMap, names: list[str]) -> np.ndarray:
    """(L, H, W) float32 room-type evidence from room-typical objects: each footprint cell of an
    instance whose label is typical of k room types in `names` adds 1/k to each of them."""
    index = {name: i for i, name in enumerate(names)}
    typical: dict[str, list[int]] = {}
    for room, objects in room_objects().items():
        if room in index:
            for obj in objects:
                typical.setdefault(obj, []).append(index[room])
    h, w, n_labels = scene.grid.height, scene.grid.width, len(names)
    weight = np.zeros((len(scene.instances), n_labels), np.float32)
    for row, inst in enumerate(scene.instances):
        rooms = typical.get(inst.label.lower())
        if rooms:
            weight[row, rooms] = 1.0 / len(rooms)
    votes = np.zeros((n_labels, h * w), np.float32)
    flat, ids, _ = scene.occupancy.entries()
    if weight.any() and len(ids):
        inst_ids = np.array([inst.id for inst in scene.instances], np.int64)
        order = np.argsort(inst_ids)
        rows = order[np.searchsorted(inst_ids[order], ids)]
        typical_cell = weight[rows].any(axis=1)  # cells of other instances vote nothing
        cells, at = np.unique(flat[typical_cell], return_inverse=True)
        rows = rows[typical_cell]
        for label in np.flatnonzero(weight.any(axis=0)):
            votes[label, cells] = np.bincount(at, weights=weight[rows, label], minlength=len(cells))
    return votes.reshape(n_labels, h, w)
