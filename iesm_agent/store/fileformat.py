"""The `.iesm` single-file map format.

A ZIP archive (deflate; members that barely compress, e.g. embeddings, are stored) holding `manifest.json` and one `.npy` member per array:

* `manifest.json`: `schema_version`, `scene_id`, `source`, `grid`, `instances`, `rooms`, `meta`,
  `embedding_model`, and `arrays`: one entry per stored array with `name`, `member`, `dtype`
  and `shape` (as in memory), `disk_dtype`, `encoding` (`raw` or `delta`) and `base`.
* Arrays: `occupancy.cells|indptr|ids|top`, `room_map`, `obstacles`, `embeddings`, and
  `observations` (maps built from frames; files without it load with `observations=None`).

On disk, integer arrays use the smallest integer dtype that holds their values; sorted ones
(occupancy cells and indptr) are delta-encoded (first value in `base`). Loading restores the
in-memory dtype and values exactly. Embeddings are stored in their own dtype unless the caller
asks for float16 on disk (`embeddings_dtype="float16"`, lossy, about half the size); they are
loaded back in their original dtype.

Loading is bounded before anything large is allocated: the manifest is read with
`fileio.load_json` (size and depth), the grid it declares must be within `MAX_GRID_CELLS`, and
each `.npy` member's header (dtype kind, shape) is checked against the manifest, the grid and the
member's declared size by `fileio.read_npy` before its data is read (never with pickles).
"""

from __future__ import annotations

import io
import json
import zipfile
import zlib
from pathlib import Path
from typing import Any, Optional

import numpy as np
from pydantic import ValidationError

from ..errors import IesmError, MapFormatError
from ..fileio import ARCHIVE_ERRORS, MAX_ARRAY_BYTES, atomic_write, load_json, read_npy, validation_message
from .model import SCHEMA_VERSION, GridSpec, InstanceGrid, SceneMap

MANIFEST = "manifest.json"
_ARRAYS = ("occupancy.cells", "occupancy.indptr", "occupancy.ids", "occupancy.top",
           "room_map", "obstacles", "embeddings", "observations")
_ARRAY_KINDS = "biuf"  # bool, signed and unsigned integers, floats
_INT_DTYPES = [np.dtype(t) for t in ("uint8", "int8", "uint16", "int16", "uint32", "int32", "int64")]


def _smallest_int_dtype(values: np.ndarray) -> np.dtype:
    """Smallest integer dtype holding every value of `values` (uint8 for empty arrays)."""
    if values.size == 0:
        return np.dtype(np.uint8)
    lo, hi = int(values.min()), int(values.max())
    for dt in _INT_DTYPES:
        info = np.iinfo(dt)
        if info.min <= lo and hi <= info.max:
            return dt
    return np.dtype(np.int64)


def _encode(name: str, arr: np.ndarray, embeddings_dtype: Optional[str]) -> tuple[dict, np.ndarray]:
    """Manifest entry and the on-disk array for one in-memory array."""
    entry: dict[str, Any] = {"name": name, "member": f"{name}.npy", "dtype": arr.dtype.str,
                             "shape": list(arr.shape), "encoding": "raw", "base": 0}
    disk = arr
    if arr.dtype.kind in "iu":
        if name in ("occupancy.cells", "occupancy.indptr") and arr.size:
            entry["encoding"], entry["base"] = "delta", int(arr[0])
            disk = np.diff(arr)
        disk = disk.astype(_smallest_int_dtype(disk), copy=False)
    elif name == "embeddings" and embeddings_dtype is not None:
        disk = arr.astype(np.dtype(embeddings_dtype))
    entry["disk_dtype"] = disk.dtype.str
    return entry, np.ascontiguousarray(disk)


def _decode(entry: dict, disk: np.ndarray) -> np.ndarray:
    """Inverse of `_encode`: the array with its in-memory dtype and shape."""
    dtype = np.dtype(entry["dtype"])
    if entry["encoding"] == "delta":
        out = np.empty(len(disk) + 1, dtype)
        out[0] = entry["base"]
        np.cumsum(disk, dtype=dtype, out=out[1:])
        out[1:] += out[0]
        return out
    return disk.astype(dtype, copy=False)


def _scene_arrays(scene: SceneMap) -> dict[str, np.ndarray]:
    occ = scene.occupancy
    arrays = {"occupancy.cells": occ.cells, "occupancy.indptr": occ.indptr,
              "occupancy.ids": occ.ids, "occupancy.top": occ.top,
              "room_map": scene.room_map, "obstacles": scene.obstacles, "embeddings": scene.embeddings,
              "observations": scene.observations}
    return {k: np.asarray(v) for k, v in arrays.items() if v is not None}


def save_map(scene: SceneMap, path: str | Path, *, embeddings_dtype: Optional[str] = None) -> int:
    """Write `scene` to `path` atomically (temp file + rename); returns the file size in bytes.

    `embeddings_dtype="float16"` stores embeddings as float16 on disk (lossy; restored as the
    original dtype on load). Everything else round-trips exactly.
    """
    path = Path(path)
    if embeddings_dtype not in (None, "float16", "float32"):
        raise ValueError(f"embeddings_dtype must be None, 'float16' or 'float32', got {embeddings_dtype!r}")
    entries, blobs = [], []
    for name, arr in _scene_arrays(scene).items():
        entry, disk = _encode(name, arr, embeddings_dtype)
        buf = io.BytesIO()
        np.save(buf, disk, allow_pickle=False)
        entries.append(entry)
        blobs.append((entry["member"], buf.getvalue()))
    manifest = scene.model_dump(include={"schema_version", "scene_id", "source", "grid", "instances",
                                         "rooms", "meta", "embedding_model"})
    manifest["arrays"] = entries
    manifest_bytes = json.dumps(manifest, ensure_ascii=False, separators=(",", ":")).encode()
    def write(tmp: Path) -> None:
        with zipfile.ZipFile(tmp, "w", zipfile.ZIP_DEFLATED, compresslevel=6) as zf:
            zf.writestr(MANIFEST, manifest_bytes)
            for member, data in blobs:
                # float payloads such as embeddings barely deflate: store them when it saves < 10 %
                packed = len(zlib.compress(data[:65536], 1)) < 0.9 * min(len(data), 65536)
                zf.writestr(member, data, zipfile.ZIP_DEFLATED if packed else zipfile.ZIP_STORED)

    atomic_write(path, write)
    return path.stat().st_size


#: largest manifest.json (bytes)
MAX_MANIFEST_BYTES = 64 * 1024 * 1024


def load_map(path: str | Path) -> SceneMap:
    """Read and validate a `.iesm` file. Any problem raises `MapFormatError` naming the file
    and the field (or member) at fault, on one line."""
    path = Path(path)
    if not path.is_file():
        raise MapFormatError("no such map file", path)
    try:
        with zipfile.ZipFile(path) as zf:
            manifest = _read_manifest(zf, path)
            grid = _read_grid(manifest, path)
            arrays = {entry["name"]: _read_array(zf, entry, path, grid) for entry in manifest.pop("arrays")}
    except IesmError:
        raise
    except ARCHIVE_ERRORS as exc:
        # corrupted headers surface as any of these (e.g. "zip file version 23.8"), or an OSError
        # for a corrupted offset that seeks out of the file
        raise MapFormatError(f"not a valid .iesm archive (truncated or corrupted): {' '.join(str(exc).split())}",
                             path) from None
    occ = None
    if any(name.startswith("occupancy.") for name in arrays):
        try:
            occ = InstanceGrid(cells=arrays.pop("occupancy.cells"), indptr=arrays.pop("occupancy.indptr"),
                               ids=arrays.pop("occupancy.ids"), top=arrays.pop("occupancy.top"))
        except KeyError as exc:
            raise MapFormatError("occupancy arrays incomplete", path, f"arrays.{exc.args[0]}") from None
        except ValidationError as exc:
            raise MapFormatError(validation_message(exc)[0], path, "occupancy") from None
    try:
        return SceneMap.model_validate({**manifest, **arrays, **({"occupancy": occ} if occ is not None else {})})
    except ValidationError as exc:
        message, field = validation_message(exc)
        raise MapFormatError(message, path, field or "manifest") from None


def _read_grid(manifest: dict, path: Path) -> GridSpec:
    """The grid the manifest declares, validated (within `MAX_GRID_CELLS`) before any array is read."""
    try:
        return GridSpec.model_validate(manifest.get("grid"))
    except ValidationError as exc:
        message, field = validation_message(exc)
        raise MapFormatError(message, path, f"grid.{field}" if field else "grid") from None


def _read_manifest(zf: zipfile.ZipFile, path: Path) -> dict:
    try:
        info = zf.getinfo(MANIFEST)
    except KeyError:
        raise MapFormatError("archive has no manifest.json", path, MANIFEST) from None
    if info.file_size > MAX_MANIFEST_BYTES:
        raise MapFormatError(f"manifest declares {info.file_size:,} bytes, more than the {MAX_MANIFEST_BYTES:,} "
                             "allowed", path, MANIFEST)
    with zf.open(info) as stream:
        raw = stream.read(MAX_MANIFEST_BYTES + 1)
    manifest = load_json(raw, path, MANIFEST, max_bytes=MAX_MANIFEST_BYTES, error=MapFormatError)
    if not isinstance(manifest, dict):
        raise MapFormatError("manifest must be a JSON object", path, MANIFEST)
    version = manifest.get("schema_version")
    if not isinstance(version, int):
        raise MapFormatError("missing or non-integer schema_version", path, "schema_version")
    if version > SCHEMA_VERSION:
        raise MapFormatError(f"schema_version {version} is newer than this iesm-agent supports "
                             f"({SCHEMA_VERSION}); upgrade iesm-agent", path, "schema_version")
    arrays = manifest.get("arrays")
    if not isinstance(arrays, list):
        raise MapFormatError("missing array list", path, "arrays")
    for i, entry in enumerate(arrays):
        where = f"arrays[{i}]"
        if not isinstance(entry, dict) or entry.get("name") not in _ARRAYS:
            raise MapFormatError(f"unknown or missing array name (expected one of {', '.join(_ARRAYS)})", path, where)
        for key, kind in (("member", str), ("dtype", str), ("disk_dtype", str), ("shape", list),
                          ("encoding", str), ("base", int)):
            if not isinstance(entry.get(key), kind) or isinstance(entry.get(key), bool):
                raise MapFormatError(f"missing or invalid {key!r}", path, f"{where}.{key}")
        if not all(isinstance(n, int) and not isinstance(n, bool) and 0 <= n < 2**40 for n in entry["shape"]) \
                or len(entry["shape"]) > 2:
            raise MapFormatError("shape must be at most 2 non-negative integers", path, f"{where}.shape")
        if entry["encoding"] not in ("raw", "delta"):
            raise MapFormatError(f"unknown encoding {entry['encoding']!r}", path, f"{where}.encoding")
        for key in ("dtype", "disk_dtype"):  # only the numeric and bool arrays `save_map` writes
            try:
                kind = np.dtype(entry[key]).kind
            except (TypeError, ValueError, OverflowError):
                kind = None
            if kind is None or kind not in _ARRAY_KINDS:
                raise MapFormatError(f"unsupported array dtype {entry[key]!r}", path, f"{where}.{key}")
    return manifest


#: arrays laid over the grid: their shape must be the grid's
_GRID_LAYERS = ("room_map", "obstacles")


def _read_array(zf: zipfile.ZipFile, entry: dict, path: Path, grid: GridSpec) -> np.ndarray:
    member = entry["member"]
    shape = entry["shape"]
    if entry["name"] in _GRID_LAYERS and shape != [grid.height, grid.width]:
        raise MapFormatError(f"shape {shape} does not match the grid ({grid.height} x {grid.width})", path, member)
    try:
        info = zf.getinfo(member)
    except KeyError:
        raise MapFormatError("member missing from archive", path, member) from None
    disk_shape = [max(shape[0] - 1, 0)] if entry["encoding"] == "delta" and shape else shape

    def check(found: tuple[int, ...], dtype: np.dtype) -> None:
        if dtype != np.dtype(entry["disk_dtype"]):
            raise MapFormatError(f"dtype {dtype} does not match manifest {entry['disk_dtype']}", path, member)
        if list(found) != disk_shape:
            raise MapFormatError(f"shape {list(found)} does not match manifest {shape}", path, member)

    with zf.open(info) as stream:
        disk = read_npy(stream, path, member, declared_bytes=info.file_size, max_bytes=MAX_ARRAY_BYTES,
                        check=check, error=MapFormatError)
    try:
        arr = _decode(entry, disk)
    except (ValueError, TypeError, OverflowError) as exc:  # OverflowError: a `base` out of range
        raise MapFormatError(f"unreadable array: {exc}", path, member) from None
    if list(arr.shape) != entry["shape"]:
        raise MapFormatError(f"shape {list(arr.shape)} does not match manifest {entry['shape']}", path, member)
    return arr
