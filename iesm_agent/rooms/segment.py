"""Room segmentation (paper Sec. 3.2) with a contextual split for open-plan space.

Free space = cells near observed space that are neither structural nor boundary (the LSD raster);
its 4-connected components, large and observed enough, are room instances; rooms grow
geodesically over the boundary margin and the rest of the sealed building (the drawn lines stop
them); a large room whose smoothed per-cell labels (plus room-typical objects) form separate
label-coherent parts is cut into them (open plan, and narrow rooms such as a hallway whose own free
space was too small to be a room and that a neighbour grew into), except a part that is a room
behind its wall seen through the door; rooms then take large furniture and share the walls
between them; each room takes the label with the most evidence (its per-cell
labels plus the votes of room-typical objects, as in the split).
"""

from __future__ import annotations

import functools
from dataclasses import dataclass, field
from typing import Callable, NamedTuple, Optional

import numpy as np

from .boundaries import Boundaries, boundary_raster
from .config import RoomConfig
from .labels import CellLabels


@dataclass
class RoomSegmentation:
    """`room_map` (H, W) int32 room id per cell (0..R-1), -1 none; `labels` the room type per id;
    `components` free components kept before splitting; `splits` cuts made by the contextual split."""

    room_map: np.ndarray
    labels: list[str]
    components: int
    splits: int
    boundaries: Boundaries
    notes: list[str] = field(default_factory=list)


def _label_parts(mask: np.ndarray, labels: np.ndarray, objects: Optional[np.ndarray], n_labels: int,
                 cell_size: float, config: RoomConfig,
                 beside: Optional[Callable[[], Optional[Neighbours]]] = None,
                 voted: Optional[np.ndarray] = None) -> list[np.ndarray]:
    """Cut a room `mask` (h, w) into label-coherent parts; returns disjoint masks (just `mask` when
    no cut pays). Each cell takes the label with the most evidence (per-cell `labels` (h, w), plus
    `object_vote_weight` x the object evidence `objects` (L, h, w)) within a Gaussian of
    `split_smoothing` m; equal-label connected cells form a part; parts under `min_room_area` m^2,
    and cells without evidence nearby, join the neighbouring part they share the longest border with.
    The parts are kept when their own majorities explain `split_gain` more of the evidence than the
    room's single majority; failing that, a part alone is cut out when its label beats the room's
    majority inside it by `split_gain` of its evidence and room-typical objects of its label stand
    in it (a bathroom off a large hallway)."""
    import cv2

    inside = mask & (labels >= 0)
    evidence = np.stack([(inside & (labels == label)).astype(np.float32) for label in range(n_labels)])
    if objects is not None:
        rows, cols = np.nonzero(mask & (objects.any(axis=0) if voted is None else voted))  # elsewhere they add nothing
        evidence[:, rows, cols] += config.object_vote_weight * objects[:, rows, cols]
    total = evidence.sum(axis=(1, 2))
    if np.count_nonzero(total) < 2:
        return [mask]
    choice = _smoothed_choice(evidence, mask, config.split_smoothing / cell_size)
    parts = np.full(mask.shape, -1, np.int32)
    count = 0
    for label in _present(choice).tolist():  # -1 off the mask
        n, comp = cv2.connectedComponents((choice == label).astype(np.uint8), connectivity=4)
        found = comp > 0
        parts[found] = comp[found] + (count - 1)
        count += n - 1
    parts = _absorb_small(parts, mask, config.min_room_area / cell_size ** 2)
    ids = _present(parts)  # -1 off the mask
    if len(ids) < 2:
        return [mask]
    part_masks = [parts == part for part in ids.tolist()]
    part_evidence = np.stack([evidence[:, part].sum(axis=1) for part in part_masks])  # (P, L)
    major, own = int(total.argmax()), part_evidence.argmax(axis=1)
    near = beside() if beside is not None and (own != major).any() else None
    if near is not None:
        # a part labelled as a room behind the wall it borders, a room with more evidence of that
        # label than the part has, is most likely that room seen through the opening between them
        # (a view's label spills over what it sees): it joins its own room's part it shares the
        # longest border with. A part touching that room, nothing between them, is a piece of it.
        seen = []
        for k, part in enumerate(part_masks):
            same = part & (near.label == own[k])
            if (own[k] != major and same.any() and not (near.distance[same] <= 1).any()
                    and near.evidence[same].max() > part_evidence[k, own[k]]):
                seen.append(k)
        if seen:
            parts = _join_neighbours(parts, mask, [int(ids[k]) for k in seen])
            ids = _present(parts)  # -1 off the mask
            if len(ids) < 2:
                return [mask]
            part_masks = [parts == part for part in ids.tolist()]
            part_evidence = np.stack([evidence[:, part].sum(axis=1) for part in part_masks])
    if (part_evidence.max(axis=1).sum() - total.max()) / total.sum() >= config.split_gain:
        return part_masks
    # a small room inside a large one holds too little of the evidence for that test; it stands
    # alone when its own label beats the room's majority inside it by `split_gain` of its evidence
    # and objects typical of its label stand in it
    own = part_evidence.argmax(axis=1)
    margin = (part_evidence.max(axis=1) - part_evidence[:, major]) / np.maximum(part_evidence.sum(axis=1), 1e-9)
    alone = [part for k, part in enumerate(part_masks)
             if own[k] != major and margin[k] >= config.split_gain and objects is not None
             and float(objects[own[k]][part].sum()) > 0]
    if not alone:
        return [mask]
    rest = mask & ~np.logical_or.reduce(alone)
    return ([rest] if rest.any() else []) + alone


def _smoothed_choice(evidence: np.ndarray, mask: np.ndarray, sigma: float) -> np.ndarray:
    """(h, w) int32: per cell of `mask`, the label whose (L, h, w) float32 `evidence` is largest
    after a Gaussian of `sigma` cells (OpenCV's, over the box), the lower label on ties; -1 where
    no label has any (and off `mask`). Labels without evidence are not smoothed (they stay zero)."""
    import cv2

    best, choice = np.zeros(mask.shape, np.float32), np.full(mask.shape, -1, np.int32)
    for label in np.flatnonzero(evidence.any(axis=(1, 2))).tolist():
        smooth = cv2.GaussianBlur(evidence[label], (0, 0), sigma) if sigma > 0 else evidence[label]
        choice[smooth > best] = label  # strictly: a tie keeps the lower label
        np.maximum(best, smooth, out=best)
    choice[~mask] = -1
    return choice


def _join_neighbours(parts: np.ndarray, mask: np.ndarray, joining: list[int]) -> np.ndarray:
    """`parts` (h, w) int32 part id per cell of `mask` with each part in `joining` given to the
    neighbouring part outside `joining` it shares the longest border with (kept when it has none)."""
    import cv2

    cross = cv2.getStructuringElement(cv2.MORPH_CROSS, (3, 3))
    parts = parts.copy()
    staying = mask & ~np.isin(parts, joining)
    for part in joining:
        own = mask & (parts == part)
        ring = cv2.dilate(own.astype(np.uint8), cross).astype(bool) & staying
        if ring.any():
            neighbours, border = np.unique(parts[ring], return_counts=True)
            parts[own] = neighbours[np.argmax(border)]
    return parts


def _present(ids: np.ndarray) -> np.ndarray:
    """The distinct values >= 0 of an int array of ids >= -1, ascending (np.unique without the sort)."""
    return np.flatnonzero(np.bincount(ids.ravel() + 1)[1:]) if ids.size else np.zeros(0, np.int64)


def _absorb_small(parts: np.ndarray, mask: np.ndarray, min_cells: float) -> np.ndarray:
    """`parts` (h, w) int32 part id per cell of `mask` (-1: no part) with every part smaller than
    `min_cells`, and every unassigned cell, joined to the neighbouring part with the longest shared
    border (smallest first); a part with no neighbour stays."""
    import cv2

    cross = cv2.getStructuringElement(cv2.MORPH_CROSS, (3, 3))
    parts = parts.copy()
    stuck: set[int] = set()
    while True:
        counts = np.bincount(parts[mask] + 1)
        ids = np.flatnonzero(counts) - 1  # part ids present, ascending, -1 (no part) first
        sizes = counts[ids + 1]
        small = [(size, part) for part, size in zip(ids.tolist(), sizes.tolist())
                 if (part < 0 or size < min_cells) and part not in stuck]
        if not small or len(ids) < 2:
            return parts
        part = min(small)[1]
        own = mask & (parts == part)
        ring = cv2.dilate(own.astype(np.uint8), cross).astype(bool) & mask & ~own & (parts >= 0)
        if not ring.any():
            stuck.add(part)
            continue
        neighbours, border = np.unique(parts[ring], return_counts=True)
        parts[own] = neighbours[np.argmax(border)]


def segment_room_map(walls: np.ndarray, known: np.ndarray, cell_labels: CellLabels, cell_size: float,
                     config: RoomConfig = RoomConfig(), object_evidence: Optional[np.ndarray] = None,
                     furniture: Optional[np.ndarray] = None) -> RoomSegmentation:
    """Rooms of a grid from (H, W) bool masks `walls` (walls, doors, windows), `known` (observed or
    occupied) and optional `furniture` (large fixed furniture: part of the boundary mask, but its
    cells are then given to the room around them), per-cell labels and optional (L, H, W) object
    evidence for the split. Cells are `cell_size` m wide."""
    import cv2

    labels, names = cell_labels.labels, cell_labels.names
    n_labels = len(names)
    cell_area = cell_size * cell_size
    furniture = np.zeros_like(walls) if furniture is None else furniture
    structural = walls | furniture
    boundaries = boundary_raster(structural, cell_size, config)
    pad = int(round(0.5 / cell_size))  # close 0.5 m holes of the observed area (square kernel: fast),
    # with unobserved space around the grid so the closing cannot spill over its border
    padded = cv2.copyMakeBorder(known.astype(np.uint8), pad, pad, pad, pad, cv2.BORDER_CONSTANT, value=0)
    near_known = cv2.morphologyEx(padded, cv2.MORPH_CLOSE, cv2.getStructuringElement(
        cv2.MORPH_RECT, (2 * pad + 1, 2 * pad + 1)))[pad:pad + known.shape[0], pad:pad + known.shape[1]].astype(bool)
    free = near_known & ~boundaries.raster & ~structural
    n, comp, stats, _ = cv2.connectedComponentsWithStats(free.astype(np.uint8), connectivity=4)
    comp = comp.astype(np.int32)
    area = stats[:, cv2.CC_STAT_AREA]
    observed = np.bincount(comp[labels >= 0], minlength=n)
    keep = (area * cell_area >= config.min_room_area) & (observed >= config.min_observed * area)
    keep[0] = False
    lut = np.full(n, -1, np.int32)
    lut[keep] = np.arange(int(keep.sum()), dtype=np.int32)
    room_map = lut[comp]
    n_rooms = int(keep.sum())
    margin = int(np.ceil((config.dilate + config.close) / cell_size)) + config.line_thickness + 2
    open_cells = ~walls & ~boundaries.lines
    room_map = _grow(room_map, near_known & open_cells, margin)
    building = _enclosed(walls | boundaries.raster)
    room_map = _grow(room_map, building & open_cells, max(walls.shape))  # the rest of a sealed building
    parent = list(range(n_rooms))  # the free component each room comes from
    voted = None if object_evidence is None else object_evidence.any(axis=0)  # cells with object votes
    if config.split and n_labels >= 2:
        boxes = _room_boxes(room_map, n_rooms)
        around = RoomsAround(room_map.copy(), boxes, labels, n_labels, object_evidence, voted,
                             config.object_vote_weight, margin)
        for room, (size, r0, r1, c0, c1) in enumerate(boxes):
            if size * cell_area < config.split_min_area:
                continue
            beside = functools.partial(around.near, room)
            crop = room_map[r0:r1, c0:c1]
            objects = None if voted is None or not voted[r0:r1, c0:c1].any() else object_evidence[:, r0:r1, c0:c1]
            for part in _label_parts(crop == room, labels[r0:r1, c0:c1], objects, n_labels, cell_size, config,
                                     beside, None if voted is None else voted[r0:r1, c0:c1])[1:]:
                crop[part] = n_rooms
                parent.append(room)
                n_rooms += 1
    room_map = _fill_nearest(room_map, furniture, walls | boundaries.raster, config.wall_share / cell_size)
    room_labels = _majority_labels(room_map, labels, n_rooms, n_labels, object_evidence, config.object_vote_weight,
                                   voted)
    room_map, room_labels = _merge_alike_parts(room_map, room_labels, parent)
    return RoomSegmentation(room_map=room_map, labels=[names[i] if i >= 0 else "unknown" for i in room_labels],
                            components=int(keep.sum()), splits=len(room_labels) - int(keep.sum()),
                            boundaries=boundaries, notes=list(boundaries.notes))


def _room_boxes(room_map: np.ndarray, n_rooms: int) -> list[tuple[int, int, int, int, int]]:
    """(cells, row0, row1, col0, col1) of each room 0..n_rooms-1 of `room_map` (h, w), one pass
    over the map; (0, 0, 0, 0, 0) for a room without cells."""
    from scipy import ndimage

    shifted = room_map + 1  # 0: no room
    counts = np.bincount(shifted.ravel(), minlength=n_rooms + 1)[1:]
    boxes = ndimage.find_objects(shifted, max_label=n_rooms)
    return [(int(size), box[0].start, box[0].stop, box[1].start, box[1].stop) if box is not None else (0, 0, 0, 0, 0)
            for size, box in zip(counts.tolist(), boxes)]


class Neighbours(NamedTuple):
    """Around one room, per cell of its box (h, w): `label` (int32) the label index of the nearest
    other room, -1 where none is within reach; `distance` (float32) to it in cells (1: the rooms
    touch, nothing between them); `evidence` (float64) that room's evidence for its label."""

    label: np.ndarray
    distance: np.ndarray
    evidence: np.ndarray


class RoomsAround:
    """The rooms before any cut (`room_map` (H, W) ids 0..R-1, `boxes` from `_room_boxes`), asked
    for the other rooms within `reach` cells of one of them. A room's evidence (`_room_evidence` of
    the per-cell `labels` and object `votes`) is summed over its box when first asked for (the split
    asks only when a part takes a label other than its room's)."""

    def __init__(self, room_map: np.ndarray, boxes: list[tuple[int, int, int, int, int]], labels: np.ndarray,
                 n_labels: int, votes: Optional[np.ndarray], voted: Optional[np.ndarray], vote_weight: float,
                 reach: int):
        self.room_map, self.boxes, self.labels, self.n_labels = room_map, boxes, labels, n_labels
        self.votes, self.voted, self.vote_weight, self.reach = votes, voted, vote_weight, reach
        self._evidence: dict[int, np.ndarray] = {}

    def evidence(self, room: int) -> np.ndarray:
        """(L,) float64 evidence of each label in `room`."""
        if room not in self._evidence:
            _, r0, r1, c0, c1 = self.boxes[room]
            own = np.where(self.room_map[r0:r1, c0:c1] == room, 0, -1)
            votes, voted = (None, None) if self.votes is None else (self.votes[:, r0:r1, c0:c1], self.voted[r0:r1, c0:c1])
            self._evidence[room] = _room_evidence(own, self.labels[r0:r1, c0:c1], 1, self.n_labels, votes,
                                                  self.vote_weight, voted)[0]
        return self._evidence[room]

    def near(self, room: int) -> Optional[Neighbours]:
        """The other rooms within `reach` of `room`, over its box, each labelled by its largest
        evidence; None when none is that near."""
        _, r0, r1, c0, c1 = self.boxes[room]
        reach, (height, width) = self.reach, self.room_map.shape
        w0, w1, v0, v1 = max(r0 - reach, 0), min(r1 + reach, height), max(c0 - reach, 0), min(c1 + reach, width)
        window = self.room_map[w0:w1, v0:v1]
        others = np.where(window == room, -1, window)
        if not (others >= 0).any():
            return None
        distance, nearest = nearest_room(others)
        crop = (slice(r0 - w0, r1 - w0), slice(c0 - v0, c1 - v0))
        distance, nearest = distance[crop], nearest[crop]
        rooms = _present(np.where(distance <= reach, nearest, -1))
        label, evidence = np.full(len(self.boxes), -1, np.int64), np.zeros(len(self.boxes))
        for other in rooms.tolist():
            counts = self.evidence(other)
            label[other], evidence[other] = (int(counts.argmax()), counts.max()) if counts.any() else (-1, 0.0)
        return Neighbours(np.where(distance <= reach, label[nearest], -1), distance, evidence[nearest])


def _merge_alike_parts(room_map: np.ndarray, room_labels: np.ndarray, parent: list[int]) -> tuple[np.ndarray, np.ndarray]:
    """Rejoin split parts of one component that ended up with the same label; ids renumbered 0..R-1.
    Returns (room_map, label index per room)."""
    first: dict[tuple[int, int], int] = {}
    target = np.array([first.setdefault((parent[room], int(label)), room) for room, label in enumerate(room_labels)],
                      np.int64)
    kept, dense = np.unique(target, return_inverse=True)
    lut = np.append(dense, -1).astype(np.int32)  # room id -1 -> index -1 -> stays -1
    return lut[room_map], room_labels[kept]


def _enclosed(barrier: np.ndarray) -> np.ndarray:
    """(H, W) bool: cells not reachable from the grid border without crossing `barrier` (the
    building, its walls included, when the barrier seals it)."""
    import cv2

    n, comp = cv2.connectedComponents((~barrier).astype(np.uint8), connectivity=4)
    outside = np.zeros(n, bool)
    outside[np.concatenate([comp[0], comp[-1], comp[:, 0], comp[:, -1]])] = True
    outside[0] = False  # barrier cells
    return ~outside[comp]


def _grow(room_map: np.ndarray, allowed: np.ndarray, steps: int) -> np.ndarray:
    """Grow rooms into unassigned `allowed` cells one 4-neighbour step at a time, `steps` times
    (geodesic: the drawn boundary lines, left out of `allowed`, stop it at closed doors)."""
    import cv2

    dtype = np.uint16 if room_map.max(initial=0) < np.iinfo(np.uint16).max - 1 else np.float32
    shifted = (room_map + 1).astype(dtype)  # 0 = no room, so a dilation takes a neighbour's id
    cross = cv2.getStructuringElement(cv2.MORPH_CROSS, (3, 3))
    todo = allowed & (shifted == 0)
    for _ in range(steps):
        grown = cv2.dilate(shifted, cross)
        take = todo & (grown > 0)
        if not take.any():
            break
        np.copyto(shifted, grown, where=take)
        todo &= ~take
    out = shifted.astype(np.int32)
    out -= 1
    return out


def _fill_nearest(room_map: np.ndarray, anywhere: np.ndarray, near: np.ndarray, max_cells: float) -> np.ndarray:
    """Give unassigned cells the id of the nearest room (Euclidean): `anywhere` cells at any
    distance, `near` cells within `max_cells`."""
    unassigned = room_map < 0
    if unassigned.all() or not unassigned.any():
        return room_map
    distance, nearest = nearest_room(room_map)
    fill = unassigned & (anywhere | (near & (distance <= max_cells)))
    out = room_map.copy()
    out[fill] = nearest[fill]
    return out


def nearest_room(room_map: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """(distance in cells, id) of the nearest cell with a room (id >= 0) of `room_map` (h, w), for
    every cell (Euclidean, OpenCV's 5x5 mask; a room's own cells: 0 and their id). Needs a room cell."""
    import cv2

    inside = room_map >= 0
    distance, nearest = cv2.distanceTransformWithLabels((~inside).astype(np.uint8), cv2.DIST_L2, 5,
                                                        labelType=cv2.DIST_LABEL_PIXEL)
    lut = np.full(int(nearest.max()) + 1, -1, np.int32)
    lut[nearest[inside]] = room_map[inside]
    return distance, lut[nearest]


def _room_evidence(room_map: np.ndarray, labels: np.ndarray, n_rooms: int, n_labels: int,
                   votes: Optional[np.ndarray] = None, vote_weight: float = 1.0,
                   voted: Optional[np.ndarray] = None) -> np.ndarray:
    """(R, L) float64 evidence of each label in each room: its per-cell labels, plus `vote_weight`
    x the (L, H, W) object `votes` summed over its cells when given (the split's evidence; `voted`
    (H, W) bool: the cells with any vote, found when not given)."""
    code = room_map * n_labels + labels
    code[(room_map < 0) | (labels < 0)] = n_rooms * n_labels  # one bin past the rooms' for unlabelled cells
    counts = np.bincount(code.ravel(), minlength=n_rooms * n_labels + 1)[:-1].reshape(n_rooms, n_labels).astype(np.float64)
    if votes is not None:  # cells without votes add nothing
        rows, cols = np.nonzero((room_map >= 0) & (votes.any(axis=0) if voted is None else voted))
        ids = room_map[rows, cols]
        counts += np.stack([np.bincount(ids, weights=vote_weight * v[rows, cols], minlength=n_rooms) for v in votes],
                           axis=1)
    return counts


def _majority_labels(room_map: np.ndarray, labels: np.ndarray, n_rooms: int, n_labels: int,
                     votes: Optional[np.ndarray] = None, vote_weight: float = 1.0,
                     voted: Optional[np.ndarray] = None) -> np.ndarray:
    """(R,) label index with the most evidence (`_room_evidence`) in each room; -1 for a room with none."""
    counts = _room_evidence(room_map, labels, n_rooms, n_labels, votes, vote_weight, voted)
    return np.where(counts.any(axis=1), counts.argmax(axis=1), -1)
