"""Importer for the IESM paper's published maps.

`scene_<s>_caption.json`: instance id -> {`category`, `room_cat`, `room_id`, `top5_categories`,
`caption`}, where `caption` is a string holding JSON (`color`, `material`, `captions`) that is
sometimes malformed; it is repaired where possible (trailing commas, then regex extraction of
"key": "value" pairs) and the outcome is counted in `meta`.

`*_ours_map_with_id.ply` (binary little-endian): per vertex `x`, `y` = grid column and row
indices, `z` = height in units of the cell size (assumption: the published files hold one value
per instance, its mean height, so per-cell top = z * cell_size m; heights are relative to the
map's vertical origin, not necessarily the floor), `red, green, blue`, `instance_id`. Grid origin
is (0, 0), so world x = (col + 0.5) * cell_size at a cell centre. Vertices whose id has no
caption entry (background) are dropped and counted. `room_map` is approximate: each occupied
cell takes the room of an instance occupying it.
"""

from __future__ import annotations

import json
import re
from pathlib import Path
from typing import Any, Optional, Union

import numpy as np
from pydantic import BaseModel, ConfigDict, ValidationError

from ...errors import MapFormatError
from ...fileio import load_json
from ..model import MAX_COORD, MAX_GRID_CELLS, MAX_ID, GridSpec, Id, Instance, InstanceGrid, Room, SceneMap
from . import field_path, read_json

_PLY_TYPES = {"char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "<i2", "int16": "<i2",
              "ushort": "<u2", "uint16": "<u2", "int": "<i4", "int32": "<i4", "uint": "<u4",
              "uint32": "<u4", "float": "<f4", "float32": "<f4", "double": "<f8", "float64": "<f8"}
_REQUIRED = ("x", "y", "z", "instance_id")
_HEADER_MAX = 65536
_PAIR = re.compile(r'"(\w+)"\s*:\s*"((?:[^"\\]|\\.)*)"')
_TRAILING_COMMA = re.compile(r",\s*([}\]])")


class _Entry(BaseModel):
    model_config = ConfigDict(extra="ignore")

    category: str
    room_cat: Optional[str] = None
    room_id: Optional[Id] = None
    top5_categories: list[str] = []
    caption: Union[str, dict[str, Any], None] = None


def parse_inner_caption(text: Union[str, dict, None]) -> tuple[dict[str, Any], str]:
    """Decode the inner caption JSON. Returns (fields, status) with status 'ok', 'repaired'
    (trailing commas stripped or pairs extracted by regex), 'plain' (free text, used as the
    caption), 'empty' or 'unrecovered'."""
    if text is None or (isinstance(text, str) and not text.strip()):
        return {}, "empty"
    if isinstance(text, dict):
        return text, "ok"
    for status, candidate in (("ok", text), ("repaired", _TRAILING_COMMA.sub(r"\1", text))):
        try:
            value = load_json(candidate, error=MapFormatError)  # bounded: a caption is data
        except MapFormatError:
            continue
        if isinstance(value, dict):
            return value, status
    if not text.lstrip().startswith("{"):
        return {"captions": text.strip()}, "plain"
    pairs = {k: _unescape(v) for k, v in _PAIR.findall(text)}
    if "captions" in pairs:
        return pairs, "repaired"
    return pairs, "unrecovered"


def _unescape(value: str) -> str:
    try:
        return json.loads(f'"{value}"')
    except json.JSONDecodeError:
        return value


def _as_text(value: Any) -> Optional[str]:
    if isinstance(value, list):
        value = ", ".join(str(v) for v in value)
    return str(value).strip() if value not in (None, "") else None


def read_ply_vertices(path: Path) -> np.ndarray:
    """Vertices of a binary little-endian PLY as a structured array (fields per the header)."""
    try:
        data = path.read_bytes()
    except OSError as exc:
        raise MapFormatError(f"cannot read: {exc.strerror or exc}", path) from exc
    end = data.find(b"end_header\n", 0, _HEADER_MAX)
    if not data.startswith(b"ply") or end < 0:
        raise MapFormatError("not a PLY file (no 'ply' magic or 'end_header')", path, "header")
    lines = data[:end].decode("ascii", "replace").splitlines()
    body = memoryview(data)[end + len("end_header\n"):]
    count, fields, element = None, [], None
    for n, line in enumerate(lines[1:], start=2):
        parts = line.split()
        if not parts or parts[0] in ("comment", "obj_info"):
            continue
        if parts[0] == "format":
            if parts[1:2] != ["binary_little_endian"]:
                raise MapFormatError(f"unsupported PLY format {' '.join(parts[1:])!r} "
                                     "(binary_little_endian expected)", path, f"header line {n}")
        elif parts[0] == "element":
            element = parts[1] if len(parts) == 3 else None
            if element == "vertex":
                count = int(parts[2]) if parts[2].isdigit() else None
            elif len(parts) != 3 or parts[2] != "0":
                raise MapFormatError(f"unsupported PLY element {line!r} (only 'vertex')", path, f"header line {n}")
        elif parts[0] == "property" and element == "vertex":
            if len(parts) != 3 or parts[1] not in _PLY_TYPES:
                raise MapFormatError(f"unsupported vertex property {line!r}", path, f"header line {n}")
            fields.append((parts[2], _PLY_TYPES[parts[1]]))
    if count is None:
        raise MapFormatError("no valid 'element vertex N' line", path, "header")
    missing = [f for f in _REQUIRED if f not in dict(fields)]
    if missing:
        raise MapFormatError(f"vertex properties {missing} missing", path, "header")
    dtype = np.dtype(fields)
    if len(body) != count * dtype.itemsize:
        raise MapFormatError(f"header declares {count} vertices ({count * dtype.itemsize} bytes) but the "
                             f"file holds {len(body)} bytes of vertex data", path, "element vertex")
    return np.frombuffer(body, dtype)


def _find_ply(caption_path: Path) -> Optional[Path]:
    prefix = caption_path.name.removesuffix(".json").removesuffix("_caption")
    candidates = sorted(caption_path.parent.glob(f"{prefix}_*.ply"))
    with_id = [p for p in candidates if p.name.endswith("_with_id.ply")]
    return (with_id or candidates or [None])[0]


def _load_entries(path: Path) -> dict[int, _Entry]:
    data = read_json(path)
    if not isinstance(data, dict):
        raise MapFormatError("expected a JSON object of instance id -> entry", path)
    entries = {}
    for key, value in data.items():
        if not key.strip().lstrip("-").isdigit() or abs(int(key)) > MAX_ID:
            raise MapFormatError("instance key is not an integer id of at most 32 bits", path, repr(key))
        if int(key) in entries:  # e.g. "7" and "07": one instance would silently replace the other
            raise MapFormatError(f"duplicate instance id {int(key)}", path, repr(key))
        try:
            entries[int(key)] = _Entry.model_validate(value)
        except ValidationError as exc:
            raise MapFormatError(exc.errors()[0]["msg"], path, field_path((key, *exc.errors()[0]["loc"]))) from exc
    return entries


def _rooms(entries: dict[int, _Entry]) -> tuple[list[Room], dict[int, Room]]:
    """Rooms from distinct (room_id, room_cat) pairs (null room_cat -> no room) and the room of
    each instance. A room_cat without room_id gets a fresh id per distinct label."""
    by_id: dict[int, Room] = {}
    by_label: dict[str, Room] = {}
    next_id = max([e.room_id for e in entries.values() if e.room_id is not None], default=0) + 1
    of_instance = {}
    for iid, e in entries.items():
        if not e.room_cat:
            continue
        if e.room_id is not None:
            room = by_id.setdefault(e.room_id, Room(id=e.room_id, label=e.room_cat))
        else:
            if e.room_cat not in by_label:
                by_label[e.room_cat] = Room(id=next_id, label=e.room_cat)
                next_id += 1
            room = by_label[e.room_cat]
        of_instance[iid] = room
    return sorted([*by_id.values(), *by_label.values()], key=lambda r: r.id), of_instance


def import_iesm(path: str | Path, ply: Optional[str | Path] = None, cell_size: float = 0.025) -> SceneMap:
    """Build a `SceneMap` from a caption dictionary and its PLY (found beside it when `ply` is None;
    without any PLY the map has instances and rooms but an empty grid)."""
    path = Path(path)
    entries = _load_entries(path)
    rooms, room_of = _rooms(entries)
    ply_path = Path(ply) if ply is not None else _find_ply(path)
    counts = {"repaired": 0, "unrecovered": 0, "plain": 0, "empty": 0}
    instances = []
    for iid, e in entries.items():
        fields, status = parse_inner_caption(e.caption)
        if status != "ok":
            counts[status] += 1
        tags = {k: v for k in ("color", "material") if (v := _as_text(fields.get(k)))}
        room = room_of.get(iid)
        instances.append(Instance(
            id=iid, label=e.category, room_id=room.id if room else None, room_label=room.label if room else None,
            caption=_as_text(fields.get("captions")) or "", tags=tags,
            alt_labels=[c for c in dict.fromkeys(e.top5_categories) if c != e.category]))
    meta = {f"captions_{k}": str(v) for k, v in counts.items()}
    scene_id = path.name.removesuffix(".json").removesuffix("_caption").removeprefix("scene_")
    source = f"iesm:{path.name}"
    if ply_path is None:
        return SceneMap(scene_id=scene_id, source=source, grid=GridSpec(cell_size=cell_size, height=0, width=0),
                        instances=instances, rooms=rooms, meta=meta)
    return _with_ply(scene_id, source + f"+{ply_path.name}", instances, rooms, meta, ply_path, cell_size)


def _with_ply(scene_id: str, source: str, instances: list[Instance], rooms: list[Room], meta: dict[str, str],
              ply_path: Path, cell_size: float) -> SceneMap:
    v = read_ply_vertices(ply_path)
    cols, rows, z = v["x"].astype(np.float64), v["y"].astype(np.float64), v["z"].astype(np.float64)
    if not (np.all(np.isfinite(cols)) and np.all(np.isfinite(rows)) and np.all(np.isfinite(z))):
        raise MapFormatError("non-finite vertex coordinates", ply_path, "vertex")
    if len(v) and max(np.abs(cols).max(), np.abs(rows).max()) > MAX_GRID_CELLS:
        raise MapFormatError(f"cell index beyond {MAX_GRID_CELLS:,} in x or y", ply_path, "vertex")
    if len(v) and np.abs(z).max() * cell_size > MAX_COORD:
        raise MapFormatError(f"vertex heights beyond {MAX_COORD:g} m", ply_path, "vertex")
    cols, rows = np.rint(cols).astype(np.int64), np.rint(rows).astype(np.int64)
    if len(v) and (cols.min() < 0 or rows.min() < 0):
        raise MapFormatError("negative cell index in x or y", ply_path, "vertex")
    height, width = (int(rows.max()) + 1, int(cols.max()) + 1) if len(v) else (0, 0)
    grid = GridSpec.checked(ply_path, "grid", cell_size=cell_size, origin=(0.0, 0.0), height=height, width=width)
    ids = v["instance_id"].astype(np.int64)
    known = np.array(sorted(inst.id for inst in instances), np.int64)
    keep = np.isin(ids, known)
    meta["background_points"] = str(int((~keep).sum()))
    meta["background_ids"] = ",".join(str(i) for i in np.unique(ids[~keep]).tolist())
    cols, rows, z, ids = cols[keep], rows[keep], z[keep] * cell_size, ids[keep]
    flat = rows * width + cols
    occupancy = InstanceGrid.from_entries(flat, ids, z.astype(np.float32))
    # per-instance statistics, vectorised over the kept points
    pos = np.searchsorted(known, ids)
    n_pts = np.bincount(pos, minlength=len(known))
    safe = np.maximum(n_pts, 1)
    mean_col = np.bincount(pos, cols, len(known)) / safe
    mean_row = np.bincount(pos, rows, len(known)) / safe
    mean_z = np.bincount(pos, z, len(known)) / safe
    occ_cells, occ_ids, _ = occupancy.entries()
    footprint = np.bincount(np.searchsorted(known, occ_ids), minlength=len(known))
    out = []
    for inst in instances:
        k = int(np.searchsorted(known, inst.id))
        if n_pts[k]:
            inst = inst.model_copy(update={
                "mean_height": float(mean_z[k]), "footprint_cells": int(footprint[k]),
                "centroid": (float((mean_col[k] + 0.5) * cell_size), float((mean_row[k] + 0.5) * cell_size),
                             float(mean_z[k]))})
        out.append(inst)
    meta["instances_without_points"] = str(int((n_pts == 0).sum()))
    room_map = np.full((height, width), -1, np.int32)
    room_id_of = {inst.id: inst.room_id for inst in out if inst.room_id is not None}
    if room_id_of:
        entry_room = np.array([room_id_of.get(i, -1) for i in known], np.int32)[np.searchsorted(known, occ_ids)]
        has = entry_room >= 0
        room_map.ravel()[occ_cells[has]] = entry_room[has]
    meta["room_map"] = "approximate: room of an instance occupying each cell"
    return SceneMap(scene_id=scene_id, source=source, grid=grid, instances=out, rooms=rooms,
                    occupancy=occupancy, room_map=room_map, meta=meta)
