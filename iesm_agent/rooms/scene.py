"""Room segmentation of a built `SceneMap`: structural and known masks from its instances, rooms
with polygons and each instance's room written back into the map."""

from __future__ import annotations

import numpy as np

from ..errors import IesmError
from ..store.model import Room, SceneMap
from .config import RoomConfig
from .labels import CellLabels, object_votes
from .outline import cells_polygon
from .segment import RoomSegmentation, nearest_room, segment_room_map


def structural_masks(scene: SceneMap, config: RoomConfig = RoomConfig()) -> tuple[np.ndarray, np.ndarray]:
    """Two (H, W) bool masks: cells of walls, doors, windows (`structural_labels`), and cells of large
    fixed furniture (`large_fixed_labels` with a footprint of at least `large_fixed_min_area` m^2)."""
    structural = {s.lower() for s in config.structural_labels}
    large = {s.lower() for s in config.large_fixed_labels}
    min_cells = config.large_fixed_min_area / scene.grid.cell_size ** 2
    walls = [inst.id for inst in scene.instances if inst.label.lower() in structural]
    furniture = [inst.id for inst in scene.instances
                 if inst.label.lower() in large and inst.footprint_cells >= min_cells]
    return scene.cells_of(walls), scene.cells_of(furniture)


def room_polygon(mask: np.ndarray, scene: SceneMap) -> list[tuple[float, float]] | None:
    """Outline (x, y) in metres of the largest blob of a (H, W) bool room mask (through cell
    corners, `outline.cells_polygon`, simplified to within one cell by `cv2.approxPolyDP`)."""
    import cv2

    corners = cells_polygon(mask, 1.0)
    if not corners:
        return None
    outline = cv2.approxPolyDP(np.asarray(corners, np.float32).reshape(-1, 1, 2), 1.0, True).reshape(-1, 2)
    s, (ox, oy) = scene.grid.cell_size, scene.grid.origin
    return [(round(ox + float(x) * s, 3), round(oy + float(y) * s, 3)) for x, y in outline.tolist()]


def instance_rooms(scene: SceneMap, room_map: np.ndarray, reach: float = 0.0) -> dict[int, int]:
    """Instance id -> room id holding most of its footprint cells; an instance with no cell in a
    room takes the room nearest to its footprint when that is within `reach` cells (else omitted)."""
    flat, ids, _ = scene.occupancy.entries()
    rooms = room_map.ravel()[flat]
    inside = rooms >= 0
    if not (room_map >= 0).any():
        return {}
    pairs, counts = np.unique(np.stack([ids[inside], rooms[inside]]), axis=1, return_counts=True)
    best = pairs[:, _first_of_each(pairs[0], -counts)]
    found = dict(zip(best[0].tolist(), best[1].tolist()))
    outside = ~np.isin(ids, best[0])
    if reach > 0 and outside.any():
        distance, nearest = (a.ravel()[flat[outside]] for a in nearest_room(room_map))
        closest = _first_of_each(ids[outside], distance)
        within = distance[closest] <= reach
        found.update(zip(ids[outside][closest][within].tolist(), nearest[closest][within].tolist()))
    return found


def _first_of_each(ids: np.ndarray, key: np.ndarray) -> np.ndarray:
    """Indices of the entry with the smallest `key` for each distinct value of `ids`."""
    order = np.lexsort((key, ids))
    first = np.ones(len(order), bool)
    first[1:] = ids[order][1:] != ids[order][:-1]
    return order[first]


def segment_scene(scene: SceneMap, cell_labels: CellLabels,
                  config: RoomConfig = RoomConfig()) -> RoomSegmentation:
    """Room segmentation of `scene` from its instances and the per-cell labels (same grid)."""
    hw = (scene.grid.height, scene.grid.width)
    if cell_labels.labels.shape != hw:
        raise IesmError(f"per-cell labels are {cell_labels.labels.shape}, the map grid is {hw}", scene.scene_id)
    if hw[0] == 0 or hw[1] == 0:
        raise IesmError("the map has an empty grid: no rooms to segment", scene.scene_id)
    occupied = np.zeros(hw[0] * hw[1], bool)
    occupied[scene.occupancy.cells] = True
    known = occupied.reshape(hw) | (cell_labels.labels >= 0)
    evidence = object_votes(scene, cell_labels.names) if config.split and config.object_vote_weight > 0 else None
    walls, furniture = structural_masks(scene, config)
    return segment_room_map(walls, known, cell_labels, scene.grid.cell_size, config, evidence, furniture)


def segment_rooms(scene: SceneMap, cell_labels: CellLabels, config: RoomConfig = RoomConfig()) -> SceneMap:
    """A copy of `scene` with rooms (id, label, polygon), `room_map` and each instance's room;
    `meta["room_segmentation"]` records the detector and the contextual splits."""
    seg = segment_scene(scene, cell_labels, config)
    rooms = [Room(id=i, label=label, polygon=room_polygon(seg.room_map == i, scene))
             for i, label in enumerate(seg.labels)]
    room_of = instance_rooms(scene, seg.room_map, config.instance_reach / scene.grid.cell_size)
    instances = [inst.model_copy(update={"room_id": room_of.get(inst.id),
                                         "room_label": seg.labels[room_of[inst.id]] if inst.id in room_of else None})
                 for inst in scene.instances]
    note = f"{seg.boundaries.detector}; {seg.components} components, {seg.splits} contextual splits"
    meta = {**scene.meta, "room_segmentation": "; ".join([note, *seg.notes])}
    return scene.model_copy(update={"rooms": rooms, "room_map": seg.room_map.astype(np.int32),
                                    "instances": instances, "meta": meta})
