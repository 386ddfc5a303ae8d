"""Checks on an output frame directory (`iesm sim --out`, `iesm segment -o`), made before any
work: the folder a command replaces must be empty, or with `--force` a frame directory of ours,
never a file, a symbolic link, the source being read or a folder holding it."""

from __future__ import annotations

from pathlib import Path

from ..errors import IesmError
from ..fileio import load_json

#: directories a frame directory of ours holds; besides them only files of these kinds
_FRAME_DIR_DIRS = {"frames", "gt"}
_FRAME_DIR_FILES = {".json", ".npz", ".iesm", ".png", ".txt", ".md"}


def check_frame_output(out: Path, force: bool, command: str, source: Path | None = None) -> None:
    """Refuse (an `IesmError` naming `out`) to write the frame directory `out` when its parent is
    missing, it is a file or a symbolic link, it is `source` or holds it or lies inside it, or it is
    a non-empty folder (`force` replaces only a frame directory of ours; `command` names the
    command that writes one)."""
    if out.is_symlink():
        raise IesmError("is a symbolic link: give the folder to write itself", out)
    if not out.parent.resolve().is_dir():
        raise IesmError("output's parent directory does not exist", out)
    if source is not None:
        target, src = out.resolve(), source.resolve()
        if target == src or target in src.parents or src in target.parents:
            raise IesmError(f"the output must not be the source {source}, hold it or lie inside it", out)
    if out.exists():
        if not out.is_dir():
            raise IesmError("exists and is not a directory", out)
        if any(out.iterdir()) and not force:
            raise IesmError("directory is not empty (use --force to replace it)", out)
        if force and any(out.iterdir()) and not looks_like_frames(out):
            raise IesmError(f"--force replaces only a frame directory made by `iesm {command}` (scene.json of "
                            "format iesm-frames, frames/, no other directories than gt/): not deleting it", out)


def looks_like_frames(out: Path) -> bool:
    """Whether `out` is a frame directory of ours: its scene.json says so and it holds nothing
    a frame directory does not."""
    try:
        scene = load_json(out / "scene.json", max_bytes=1024 * 1024)
    except IesmError:
        return False
    ours = all(p.name in _FRAME_DIR_DIRS if p.is_dir() else p.suffix.lower() in _FRAME_DIR_FILES
               for p in out.iterdir())
    return (ours and isinstance(scene, dict) and scene.get("format") == "iesm-frames"
            and (out / "frames").is_dir() and not (out / "frames").is_symlink())
