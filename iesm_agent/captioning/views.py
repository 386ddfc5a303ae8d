"""What a captioner sees of one instance: keyframe crops with their masks, room and geometry."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Callable, Iterable, Optional

import numpy as np

from ..errors import IesmError
from ..store.model import Instance, SceneMap
from .keyframes import Keyframe, crop_box

#: masks smaller than this (pixels) give no crop: too little to describe or measure
MIN_MASK_PX = 20


@dataclass
class Crop:
    """A keyframe crop: `rgb` (h, w, 3) uint8 and the instance's `mask` (h, w) bool inside it;
    `gain` (3,) per-channel factor that brings the keyframe to the scene's white balance
    (`colours.constancy`; ones when not estimated)."""

    frame: int
    rgb: np.ndarray
    mask: np.ndarray
    gain: np.ndarray = field(default_factory=lambda: np.ones(3))

    def balanced_rgb(self) -> np.ndarray:
        """(h, w, 3) float64 sRGB 0-255: `rgb` times `gain`, clipped."""
        return np.clip(self.rgb * self.gain, 0.0, 255.0)


@dataclass
class Geometry:
    """From the map: `footprint_m2` top-down area (m^2), `top_m` highest top (m above the floor,
    None if unknown), `mean_height_m` (m, None if unknown)."""

    footprint_m2: float
    top_m: Optional[float]
    mean_height_m: Optional[float]


@dataclass
class InstanceView:
    """One instance as handed to a captioner."""

    instance: Instance
    room: Optional[str]
    geometry: Geometry
    room_id: Optional[int] = None
    crops: list[Crop] = field(default_factory=list)
    observed_frames: int = 0


def instance_geometry(scene: SceneMap) -> dict[int, Geometry]:
    """Instance id -> `Geometry` from the instance fields and the CSR map's top heights."""
    _, ids, top = scene.occupancy.entries()
    tops: dict[int, float] = {}
    if len(ids):
        order = np.argsort(ids, kind="stable")
        sorted_ids, sorted_top = ids[order], np.nan_to_num(top[order].astype(np.float64), nan=-np.inf)
        uniq, starts = np.unique(sorted_ids, return_index=True)
        best = np.maximum.reduceat(sorted_top, starts)
        tops = {int(i): float(t) for i, t in zip(uniq, best) if np.isfinite(t)}
    area = scene.grid.cell_size ** 2
    return {inst.id: Geometry(inst.footprint_cells * area, tops.get(inst.id), inst.mean_height)
            for inst in scene.instances}


def room_of_instances(scene: SceneMap) -> dict[int, tuple[Optional[int], str]]:
    """Instance id -> (room id, room label): the instance's own room, else the most common room
    of its cells in `scene.room_map` (instances outside every room are left out)."""
    labels = {room.id: room.label for room in scene.rooms}
    out = {i.id: (i.room_id, i.room_label) for i in scene.instances if i.room_label}
    if scene.room_map is None or not labels:
        return out
    flat, ids, _ = scene.occupancy.entries()
    rooms = scene.room_map.ravel()[flat]
    inside = rooms >= 0
    if not inside.any():
        return out
    pairs, counts = np.unique(np.stack([ids[inside], rooms[inside]], axis=1), axis=0, return_counts=True)
    order = np.lexsort((-counts, pairs[:, 0]))  # per instance, the most common room first
    pairs = pairs[order]
    first = np.ones(len(pairs), bool)
    first[1:] = pairs[1:, 0] != pairs[:-1, 0]
    for inst_id, room_id in pairs[first]:
        if int(inst_id) not in out and int(room_id) in labels:
            out[int(inst_id)] = (int(room_id), labels[int(room_id)])
    return out


def build_views(scene: SceneMap, keyframes: dict[int, list[Keyframe]], read_frame: Callable[[int], object],
                observed: dict[int, int], progress: Callable[[int], None] | None = None) -> list[InstanceView]:
    """One `InstanceView` per instance of `scene`, with crops cut from the keyframes.

    `read_frame(i)` returns a `frames.Frame` with a segmentation; each frame is read once.
    `observed` maps instance id -> number of distinct frames it was seen in. `progress(n)` is
    called after each frame read with the number of frames read so far. Each crop's `gain` brings
    its keyframe to the white balance of the keyframes read (`colours.constancy`)."""
    from ..colours.constancy import relative_gains, white_patch

    geometry = instance_geometry(scene)
    rooms = room_of_instances(scene)
    views = {i.id: InstanceView(i, rooms.get(i.id, (None, None))[1], geometry[i.id],
                                room_id=rooms.get(i.id, (None, None))[0], observed_frames=observed.get(i.id, 0))
             for i in scene.instances}
    by_frame: dict[int, list[tuple[int, Keyframe]]] = {}
    for inst_id, frames in keyframes.items():
        if inst_id in views:
            for kf in frames:
                by_frame.setdefault(kf.frame, []).append((inst_id, kf))
    patches = {}
    for n, index in enumerate(sorted(by_frame), start=1):
        frame = read_frame(index)
        patches[index] = white_patch(frame.rgb)
        seg = getattr(frame, "segmentation", None)
        if seg is None:
            raise IesmError("frame has no segmentation (seg.npz) but the map's observations refer to it",
                            f"frame {index}")
        for inst_id, kf in by_frame[index]:
            crop = _cut(frame.rgb, seg.masks, kf, index)
            if crop is not None:
                views[inst_id].crops.append(crop)
        if progress is not None:
            progress(n)
    gains = relative_gains(patches)
    for view in views.values():  # best keyframe first, as selected
        for crop in view.crops:
            crop.gain = gains[crop.frame]
        order = {kf.frame: r for r, kf in enumerate(keyframes.get(view.instance.id, ()))}
        view.crops.sort(key=lambda c: order.get(c.frame, 0))
    return list(views.values())


def _cut(rgb: np.ndarray, masks: np.ndarray, kf: Keyframe, index: int) -> Crop | None:
    if any(m < 0 or m >= len(masks) for m in kf.masks):
        raise IesmError(f"the map's observations name mask {max(kf.masks)} but the frame has {len(masks)}",
                        f"frame {index}")
    mask = np.any(masks[list(kf.masks)], axis=0)
    if int(mask.sum()) < MIN_MASK_PX:
        return None
    box = crop_box(mask)
    if box is None:
        return None
    y0, y1, x0, x1 = box
    return Crop(index, rgb[y0:y1, x0:x1].copy(), mask[y0:y1, x0:x1].copy())


def frames_seen(observations: Iterable) -> dict[int, int]:
    """Instance id -> number of distinct frames with an observation of it."""
    obs = np.asarray(observations, np.float64)
    if obs.size == 0:
        return {}
    pairs = np.unique(obs[:, :2].astype(np.int64), axis=0)
    ids, counts = np.unique(pairs[:, 0], return_counts=True)
    return {int(i): int(c) for i, c in zip(ids, counts)}
