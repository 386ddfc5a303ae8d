"""Hand-made walled layouts for tests and benchmarks: a rectangle cut into a grid of rooms by
interior walls with door gaps; any interior wall can be left out (open plan)."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..store.model import GridSpec, Instance, InstanceGrid, SceneMap
from ..rooms.labels import CellLabels


@dataclass
class Layout:
    """`scene` with wall and furniture instances; `rooms` (H, W) int32 ground-truth room id
    (-1 in walls); `room_labels` the room type of each id."""

    scene: SceneMap
    rooms: np.ndarray
    room_labels: list[str]


def grid_layout(nx: int, ny: int, room_size: float = 4.0, cell_size: float = 0.05, wall: float = 0.1,
                door: float = 0.9, open_walls: tuple[tuple[str, int, int], ...] = (),
                labels: tuple[str, ...] = ("living room", "bedroom", "kitchen", "bathroom", "office", "hallway"),
                furniture: bool = True) -> Layout:
    """`nx` x `ny` rooms of `room_size` m; an interior wall is ("v", i, j) between columns i, i+1 in
    row j or ("h", i, j) between rows j, j+1 in column i; those listed in `open_walls` are left out.
    Room (i, j) is labelled `labels[(j * nx + i) % len(labels)]`; with `furniture` a typical object
    (bed, sofa, ...) stands in each room."""
    n = int(round(room_size / cell_size))
    t = max(int(round(wall / cell_size)), 1)
    h, w = ny * n + t, nx * n + t
    instances: list[Instance] = []
    entries: list[np.ndarray] = []
    ids: list[np.ndarray] = []

    def add(label: str, rows: slice, cols: slice, height: float) -> None:
        mask = np.zeros((h, w), bool)
        mask[rows, cols] = True
        flat = np.flatnonzero(mask)
        inst_id = len(instances) + 1
        r, c = np.divmod(flat, w)
        instances.append(Instance(id=inst_id, label=label, mean_height=height, footprint_cells=len(flat),
                                  centroid=(float((c.mean() + 0.5) * cell_size), float((r.mean() + 0.5) * cell_size),
                                            height)))
        entries.append(flat)
        ids.append(np.full(len(flat), inst_id))

    gap = int(round(door / cell_size))
    add("wall", slice(0, t), slice(0, w), 1.25)
    add("wall", slice(h - t, h), slice(0, w), 1.25)
    add("wall", slice(0, h), slice(0, t), 1.25)
    add("wall", slice(0, h), slice(w - t, w), 1.25)
    for j in range(ny):
        for i in range(nx - 1):
            if ("v", i, j) not in open_walls:
                c0, r0 = (i + 1) * n, j * n
                add("wall", slice(r0, r0 + n // 2 - gap // 2), slice(c0, c0 + t), 1.25)
                add("wall", slice(r0 + n // 2 + gap - gap // 2, r0 + n + t), slice(c0, c0 + t), 1.25)
    for j in range(ny - 1):
        for i in range(nx):
            if ("h", i, j) not in open_walls:
                r0, c0 = (j + 1) * n, i * n
                add("wall", slice(r0, r0 + t), slice(c0, c0 + n // 2 - gap // 2), 1.25)
                add("wall", slice(r0, r0 + t), slice(c0 + n // 2 + gap - gap // 2, c0 + n + t), 1.25)
    typical = {"living room": "sofa", "bedroom": "bed", "kitchen": "refrigerator", "bathroom": "toilet",
               "office": "desk", "hallway": "shoe rack", "dining room": "dining table"}
    room_labels = [labels[(j * nx + i) % len(labels)] for j in range(ny) for i in range(nx)]
    rooms = np.full((h, w), -1, np.int32)
    for j in range(ny):
        for i in range(nx):
            rooms[j * n + t:(j + 1) * n, i * n + t:(i + 1) * n] = j * nx + i
            label = room_labels[j * nx + i]
            if furniture and label in typical:
                r0, c0 = j * n + n // 4, i * n + n // 4
                add(typical[label], slice(r0, r0 + n // 5), slice(c0, c0 + n // 4), 0.5)
    for kind, i, j in open_walls:  # the cells of a left-out wall belong to the room before it
        if kind == "v":
            rooms[j * n + t:(j + 1) * n, (i + 1) * n:(i + 1) * n + t] = j * nx + i
        else:
            rooms[(j + 1) * n:(j + 1) * n + t, i * n + t:(i + 1) * n] = j * nx + i
    occupancy = InstanceGrid.from_entries(np.concatenate(entries), np.concatenate(ids))
    scene = SceneMap(scene_id=f"grid{nx}x{ny}", grid=GridSpec(cell_size=cell_size, height=h, width=w),
                     instances=instances, occupancy=occupancy)
    return Layout(scene=scene, rooms=rooms, room_labels=room_labels)


def noisy_labels(layout: Layout, accuracy: float = 0.7, seed: int = 0, blob: int = 8) -> CellLabels:
    """Per-cell labels like a noisy per-pixel classifier: each `blob` x `blob` block of a room keeps
    its true type with probability `accuracy`, else takes another type of the layout."""
    names = sorted(set(layout.room_labels))
    rng = np.random.default_rng(seed)
    truth = np.array([names.index(lab) for lab in layout.room_labels])
    h, w = layout.rooms.shape
    bh, bw = -(-h // blob), -(-w // blob)
    wrong = rng.random((bh, bw)) > accuracy
    shift = rng.integers(1, max(len(names), 2), size=(bh, bw))
    wrong = np.kron(wrong, np.ones((blob, blob), bool))[:h, :w]
    shift = np.kron(shift, np.ones((blob, blob), np.int64))[:h, :w]
    inside = layout.rooms >= 0
    labels = np.full((h, w), -1, np.int32)
    true_label = truth[layout.rooms[inside]]
    labels[inside] = np.where(wrong[inside], (true_label + shift[inside]) % len(names), true_label)
    return CellLabels(labels=labels, names=names)
