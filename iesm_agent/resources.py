"""Locate the shipped resource folders (`prompts/`, `experts/`, `map_store/`).

From an installed wheel they live in `iesm_agent/_data/<name>`; from a checkout
(editable install) they are the top-level folders of the repository.
"""

from __future__ import annotations

from pathlib import Path

_PKG = Path(__file__).resolve().parent


def resource_dir(name: str) -> Path:
    """Return the shipped folder `name` (one of prompts, experts, map_store)."""
    for candidate in (_PKG / "_data" / name, _PKG.parent / name):
        if candidate.is_dir():
            return candidate
    raise FileNotFoundError(f"shipped resource folder {name!r} not found under {_PKG}")


def shipped_map(name: str = "apartment") -> Path:
    """Path of a map shipped in `map_store/` (`name` without the `.iesm` suffix)."""
    path = resource_dir("map_store") / f"{name}.iesm"
    if not path.is_file():
        raise FileNotFoundError(f"no shipped map {name!r} in {path.parent}")
    return path
