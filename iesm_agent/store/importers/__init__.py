"""Importers that turn external map descriptions into a `SceneMap`.

* `objects`: an object list with 3D boxes (`objects.import_objects`).
* `iesm`: the paper's published instance dictionary `scene_*_caption.json`, optionally with
  the 2.5D map `*_ours_map_with_id.ply` (`iesm.import_iesm`).

`import_map(path)` detects the format from the JSON content.
"""

from __future__ import annotations

import json
from pathlib import Path
from typing import Any, Optional

from ...errors import MapFormatError
from ..model import SceneMap

FORMATS = ("objects", "iesm")
#: largest grid an importer builds (cells); 5000 x 5000 is 125 m square at 2.5 cm
MAX_GRID_CELLS = 25_000_000


def field_path(loc: tuple[Any, ...]) -> str:
    """Pydantic error location -> readable field path, e.g. ('objects', 3, 'size') -> 'objects[3].size'."""
    out = ""
    for part in loc:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


def check_grid_size(height: int, width: int, path: Path) -> None:
    """Refuse a grid too large to hold in memory (far-apart objects, a corrupted PLY, a tiny
    cell size) with a `MapFormatError` instead of exhausting memory."""
    if height * width > MAX_GRID_CELLS:
        raise MapFormatError(f"the map would need a grid of {height} x {width} cells (more than "
                             f"{MAX_GRID_CELLS:,}): check the coordinates or use a larger --cell-size",
                             path, "grid")


def read_json(path: Path) -> Any:
    """The parsed JSON of `path`; unreadable or invalid files are a `MapFormatError` naming it."""
    try:
        return json.loads(path.read_bytes())
    except OSError as exc:
        raise MapFormatError(f"cannot read: {exc.strerror or exc}", path) from exc
    except (UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise MapFormatError(f"invalid JSON: {exc}", path) from exc


def detect_format(path: str | Path) -> str:
    """'objects' for a JSON object with an `objects` list, 'iesm' for a dictionary of instance
    entries with `category` and `caption`; anything else is a `MapFormatError`."""
    path = Path(path)
    if path.suffix.lower() == ".ply":
        raise MapFormatError("a PLY file is imported together with its caption JSON: "
                             "pass the scene_*_caption.json (and --ply for this file)", path)
    data = read_json(path)
    if isinstance(data, dict):
        if "objects" in data:
            return "objects"
        first = next(iter(data.values()), None)
        if isinstance(first, dict) and "category" in first:
            return "iesm"
    raise MapFormatError("unrecognised input: expected an object list (with 'objects') or an IESM "
                         "caption dictionary (entries with 'category' and 'caption')", path)


def import_map(path: str | Path, fmt: Optional[str] = None, *, cell_size: Optional[float] = None,
               ply: Optional[str | Path] = None) -> SceneMap:
    """Import `path` as `fmt` ('objects' | 'iesm' | None = detect). `cell_size` in metres
    (default 0.05 for object lists, 0.025 for IESM PLY maps); `ply` only for 'iesm'."""
    fmt = fmt or detect_format(path)
    if fmt not in FORMATS:
        raise MapFormatError(f"unknown format {fmt!r} (expected one of {', '.join(FORMATS)})", path)
    if cell_size is not None and not cell_size > 0:
        raise MapFormatError(f"cell size must be > 0, got {cell_size}", path, "cell_size")
    if fmt == "objects":
        if ply is not None:
            raise MapFormatError("--ply only applies to the 'iesm' format", path)
        from .objects import import_objects

        return import_objects(path, cell_size=cell_size or 0.05)
    from .iesm import import_iesm

    return import_iesm(path, ply=ply, cell_size=cell_size or 0.025)


def attach_embeddings(scene: SceneMap, encoder) -> SceneMap:
    """A copy of `scene` with one `encoder` embedding per instance (text from
    `mapstore.embedding_text`) and `embedding_model = encoder.name`."""
    import numpy as np

    from ..mapstore import embedding_text

    texts = [embedding_text(inst.label, inst.room_label, inst.caption, inst.tags) for inst in scene.instances]
    emb = np.asarray(encoder.encode(texts), np.float32) if texts else np.zeros((0, encoder.dim), np.float32)
    return scene.model_copy(update={"embeddings": emb, "embedding_model": encoder.name})
