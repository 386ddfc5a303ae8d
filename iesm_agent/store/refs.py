"""Map references: a `.iesm` file, an importable JSON file (object list or the paper's caption
dictionary, imported in memory), or the name of a map shipped in `map_store/`."""

from __future__ import annotations

from pathlib import Path

from ..errors import IesmError
from ..resources import shipped_map
from .model import SceneMap


def resolve_map_path(ref: str | Path, base_dir: Path | None = None) -> Path:
    """The file `ref` names: a path (relative ones against `base_dir`, default the working
    directory) or a shipped map name such as `apartment`."""
    ref = str(ref)
    path = Path(ref)
    if not path.is_absolute() and base_dir is not None:
        path = base_dir / path
    if path.is_file():
        return path.resolve()
    if "/" not in ref and "\\" not in ref:
        try:
            return shipped_map(ref.removesuffix(".iesm"))
        except FileNotFoundError:
            pass
    raise IesmError(f"unknown map {ref!r}: no file {path} and no shipped map of that name")


def open_map(ref: str | Path, base_dir: Path | None = None) -> SceneMap:
    """Load the map `ref` names; JSON inputs go through the importers (format auto-detected)."""
    path = resolve_map_path(ref, base_dir)
    if path.suffix.lower() == ".json":
        from .importers import import_map

        return import_map(path)
    from .fileformat import load_map

    return load_map(path)
