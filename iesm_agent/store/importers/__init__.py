"""Importers that turn external map descriptions into a `SceneMap`.

* `objects`: an object list with 3D boxes (`objects.import_objects`).
* `iesm`: the paper's published instance dictionary `scene_*_caption.json`, optionally with
  the 2.5D map `*_ours_map_with_id.ply` (`iesm.import_iesm`).

`import_map(path)` detects the format from the JSON content.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any, Optional

from ...errors import MapFormatError
from ...fileio import field_path, load_json  # noqa: F401 (importers use field_path from here)
from ..model import MAX_GRID_CELLS, SceneMap, check_grid_size  # noqa: F401 (importers use them from here)

FORMATS = ("objects", "iesm")


def read_json(path: Path) -> Any:
    """The parsed JSON of `path` (`fileio.load_json`: size and depth bounded); unreadable or
    invalid files are a `MapFormatError` naming it."""
    return load_json(Path(path), error=MapFormatError)


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
