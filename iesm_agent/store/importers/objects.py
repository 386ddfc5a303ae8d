"""Importer for object lists: JSON with `scene_id`, optional `rooms` and `objects` (3D boxes).

Each box footprint is rasterised into the 2.5D grid (every cell whose centre lies inside the
footprint, at least the cell holding the box centre); per-cell top = center_z + dz / 2 (m),
mean_height = center_z (m). Grid bounds = union of boxes (and room polygons) + `MARGIN`.
`room_map` comes from room polygons when any are given, else it is left at -1 everywhere.
Optional `doors` ([x, y] position and width, m) are kept in `meta["doors"]` (JSON) for the planner,
which draws walls along the room polygons with gaps at the doors (`nav.walls`).
Missing captions are built from the known attributes (see `build_caption`).
"""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional, Union

import json

import numpy as np
from pydantic import BaseModel, ConfigDict, Field, ValidationError, field_validator

from ...errors import MapFormatError
from ...colours import colour_name
from ..model import GridSpec, Id, Instance, InstanceGrid, Metres, Room, SceneMap
from . import field_path, read_json

MARGIN = 0.25  # m of free space around the union of boxes
Extent = Annotated[float, Field(gt=0, le=10_000)]
PositiveVec3 = tuple[Extent, Extent, Extent]


class RoomSpec(BaseModel):
    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    id: Id
    label: str = Field(min_length=1)
    polygon: Optional[list[tuple[Metres, Metres]]] = None

    @field_validator("polygon")
    @classmethod
    def _three_vertices(cls, v):
        if v is not None and len(v) < 3:
            raise ValueError("a polygon needs at least 3 vertices")
        return v


class ObjectSpec(BaseModel):
    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)  # NaN/inf would break the grid

    id: Id
    label: str = Field(min_length=1)
    center: tuple[Metres, Metres, Metres]
    size: PositiveVec3
    color_rgb: Optional[tuple[Annotated[int, Field(ge=0, le=255)], Annotated[int, Field(ge=0, le=255)],
                              Annotated[int, Field(ge=0, le=255)]]] = None
    room: Optional[Union[Id, str]] = None
    caption: Optional[str] = None
    tags: dict[str, str] = Field(default_factory=dict)
    alt_labels: list[str] = Field(default_factory=list)
    # written by `iesm sim` into gt/objects.json; accepted so ground truth imports as a map
    structural: bool = False  # wall, door or window: part of the building
    on: Optional[Id] = None  # id of the instance this one stands on


class DoorSpec(BaseModel):
    """A doorway in the room polygons' walls: `position` [x, y] (m) on a wall, clear `width` (m)."""

    model_config = ConfigDict(extra="forbid", allow_inf_nan=False)

    position: tuple[Metres, Metres]
    width: Annotated[float, Field(gt=0, le=100)] = 0.9


class ObjectList(BaseModel):
    model_config = ConfigDict(extra="forbid")

    scene_id: str = Field(min_length=1)
    source: str = ""
    comment: str = ""
    rooms: Optional[list[RoomSpec]] = None
    doors: Optional[list[DoorSpec]] = None
    objects: list[ObjectSpec]


_MATERIAL_ADJ = {"wood": "wooden", "wooden": "wooden", "metal": "metal", "steel": "steel", "glass": "glass",
                 "leather": "leather", "fabric": "fabric", "plastic": "plastic", "ceramic": "ceramic",
                 "porcelain": "porcelain", "stone": "stone", "marble": "marble", "wool": "wool",
                 "cotton": "cotton", "velvet": "velvet", "wicker": "wicker", "paper": "paper"}


def _length(metres: float) -> str:
    return f"{metres * 100:.0f} cm" if metres < 0.3 else f"{metres:.1f} m"


def build_caption(label: str, tags: dict[str, str], size: tuple[float, float, float],
                  bottom: float, room: Optional[str]) -> str:
    """A plain caption from known attributes, e.g. "a red wooden chair in the office, about
    0.9 m tall". `size` (dx, dy, dz) and `bottom` (height of the box base) in metres."""
    words = [w for w in (tags.get("color"), _MATERIAL_ADJ.get(tags.get("material", "").lower(),
                                                              tags.get("material"))) if w]
    noun = " ".join([*words, label])
    article = "an" if noun[:1].lower() in "aeiou" else "a"
    text = f"{article} {noun}"
    if room:
        text += f" in the {room}"
    text += f", about {_length(size[2])} tall and {_length(max(size[0], size[1]))} wide"
    if bottom >= 0.2:
        text += f", {_length(bottom)} above the floor"
    extra = {k: v for k, v in tags.items() if k not in ("color", "material")}
    if extra:
        text += "; " + ", ".join(f"{k}: {v}" for k, v in sorted(extra.items()))
    return text


def _rasterise_polygons(rooms: list[RoomSpec], grid: GridSpec) -> np.ndarray:
    """(H, W) int32 room id per cell (cell centre inside the polygon, even-odd rule), -1 elsewhere."""
    room_map = np.full((grid.height, grid.width), -1, np.int32)
    xs = grid.origin[0] + (np.arange(grid.width) + 0.5) * grid.cell_size
    ys = grid.origin[1] + (np.arange(grid.height) + 0.5) * grid.cell_size
    px, py = np.meshgrid(xs, ys)
    for room in rooms:
        if not room.polygon:
            continue
        poly = np.asarray(room.polygon, np.float64)
        inside = np.zeros(px.shape, bool)
        for (x0, y0), (x1, y1) in zip(poly, np.roll(poly, -1, axis=0)):
            if y0 == y1:
                continue
            crosses = (y0 > py) != (y1 > py)
            x_at = x0 + (py - y0) * (x1 - x0) / (y1 - y0)
            inside ^= crosses & (px < x_at)
        room_map[inside & (room_map < 0)] = room.id
    return room_map


def _box_cells(obj: ObjectSpec, grid: GridSpec) -> np.ndarray:
    """Flat indices of the cells covered by the box footprint (at least its centre cell)."""
    (cx, cy, _), (dx, dy, _) = obj.center, obj.size
    r0, c0 = grid.cell_of(cx - dx / 2, cy - dy / 2)
    r1, c1 = grid.cell_of(cx + dx / 2, cy + dy / 2)
    rows, cols = np.arange(r0, r1 + 1), np.arange(c0, c1 + 1)
    ys = grid.origin[1] + (rows + 0.5) * grid.cell_size
    xs = grid.origin[0] + (cols + 0.5) * grid.cell_size
    rows = rows[np.abs(ys - cy) <= dy / 2]
    cols = cols[np.abs(xs - cx) <= dx / 2]
    if len(rows) == 0 or len(cols) == 0:
        r, c = grid.cell_of(cx, cy)
        return np.array([r * grid.width + c], np.int64)
    return (rows[:, None] * grid.width + cols[None, :]).ravel().astype(np.int64)


def _grid_for(spec: ObjectList, cell_size: float, path: Path) -> GridSpec:
    lo = np.full(2, np.inf)
    hi = np.full(2, -np.inf)
    for obj in spec.objects:
        c, s = np.asarray(obj.center[:2]), np.asarray(obj.size[:2])
        lo, hi = np.minimum(lo, c - s / 2), np.maximum(hi, c + s / 2)
    for room in spec.rooms or []:
        if room.polygon:
            poly = np.asarray(room.polygon)
            lo, hi = np.minimum(lo, poly.min(0)), np.maximum(hi, poly.max(0))
    if not np.all(np.isfinite(lo)):
        lo = hi = np.zeros(2)
    origin = np.floor((lo - MARGIN) / cell_size) * cell_size
    shape = np.ceil((hi + MARGIN - origin) / cell_size).astype(int)
    return GridSpec.checked(path, "grid", cell_size=cell_size, origin=(float(origin[0]), float(origin[1])),
                            height=int(shape[1]), width=int(shape[0]))


def _resolve_rooms(spec: ObjectList, path: Path) -> tuple[list[Room], list[Optional[Room]]]:
    """Rooms of the map and the room of each object. Without a `rooms` list, rooms are made
    from the distinct room labels of the objects (ids 1, 2, ... in order of appearance)."""
    if spec.rooms is None:
        labels: dict[str, Room] = {}
        for i, obj in enumerate(spec.objects):
            if isinstance(obj.room, int):
                raise MapFormatError(f"room id {obj.room} given but the file has no 'rooms' list",
                                     path, f"objects[{i}].room")
            if obj.room and obj.room not in labels:
                labels[obj.room] = Room(id=len(labels) + 1, label=obj.room)
        return list(labels.values()), [labels[o.room] if o.room else None for o in spec.objects]
    rooms = [Room(id=r.id, label=r.label, polygon=r.polygon) for r in spec.rooms]
    seen: set[int] = set()
    for i, r in enumerate(rooms):
        if r.id in seen:
            raise MapFormatError(f"duplicate room id {r.id}", path, f"rooms[{i}].id")
        seen.add(r.id)
    by_id = {r.id: r for r in rooms}
    by_label = {r.label.lower(): r for r in rooms}
    resolved: list[Optional[Room]] = []
    for i, obj in enumerate(spec.objects):
        if obj.room is None:
            resolved.append(None)
            continue
        room = by_id.get(obj.room) if isinstance(obj.room, int) else by_label.get(obj.room.lower())
        if room is None:
            raise MapFormatError(f"unknown room {obj.room!r} (not in 'rooms')", path, f"objects[{i}].room")
        resolved.append(room)
    return rooms, resolved


def import_objects(path: str | Path, cell_size: float = 0.05) -> SceneMap:
    """Build a `SceneMap` from an object-list JSON file (see module docstring)."""
    path = Path(path)
    data = read_json(path)
    try:
        spec = ObjectList.model_validate(data)
    except ValidationError as exc:
        err = exc.errors()[0]
        raise MapFormatError(err["msg"], path, field_path(err["loc"])) from exc
    seen: set[int] = set()
    for i, obj in enumerate(spec.objects):
        if obj.id in seen:
            raise MapFormatError(f"duplicate object id {obj.id}", path, f"objects[{i}].id")
        seen.add(obj.id)
    rooms, obj_rooms = _resolve_rooms(spec, path)
    grid = _grid_for(spec, cell_size, path)
    room_map = _rasterise_polygons(spec.rooms or [], grid)
    instances, cells_all, ids_all, tops_all = [], [], [], []
    for obj, room in zip(spec.objects, obj_rooms):
        cells = _box_cells(obj, grid)
        if room is None and (room_map >= 0).any():  # infer the room from the polygons
            rid = int(room_map.ravel()[cells[len(cells) // 2]])
            room = next((r for r in rooms if r.id == rid), None)
        tags = dict(obj.tags)
        if obj.color_rgb is not None and "color" not in tags:
            tags["color"] = colour_name(obj.color_rgb)
        bottom = obj.center[2] - obj.size[2] / 2
        caption = obj.caption if obj.caption else build_caption(
            obj.label, tags, obj.size, bottom, room.label if room else None)
        instances.append(Instance(
            id=obj.id, label=obj.label, room_id=room.id if room else None,
            room_label=room.label if room else None, caption=caption, tags=tags,
            alt_labels=obj.alt_labels, mean_height=obj.center[2], centroid=obj.center,
            footprint_cells=len(cells)))
        cells_all.append(cells)
        ids_all.append(np.full(len(cells), obj.id, np.int64))
        tops_all.append(np.full(len(cells), obj.center[2] + obj.size[2] / 2, np.float32))
    occupancy = (InstanceGrid.from_entries(np.concatenate(cells_all), np.concatenate(ids_all),
                                           np.concatenate(tops_all)) if instances else InstanceGrid.empty())
    meta = {"comment": spec.comment} if spec.comment else {}
    if spec.doors is not None:
        if not any(room.polygon for room in spec.rooms or []):
            raise MapFormatError("doors are gaps in the walls of room polygons, but no room has a polygon",
                                 path, "doors")
        meta["doors"] = json.dumps([{"position": list(d.position), "width": d.width} for d in spec.doors])
    return SceneMap(scene_id=spec.scene_id, source=spec.source or f"objects:{path.name}", grid=grid,
                    instances=instances, rooms=rooms, occupancy=occupancy, room_map=room_map, meta=meta)
