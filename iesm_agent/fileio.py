"""Atomic file output and validated JSON input, shared by every stage.

Every file the toolkit writes goes through `atomic_write`: the content is written to a temporary
file beside the target (named `.NAME.iesm-tmp.*`) and renamed into place, so a killed process
never leaves a half-written output.
"""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path
from typing import Callable, TypeVar

import numpy as np
from pydantic import BaseModel, ValidationError

from .errors import IesmError

#: infix of our temporary files (a stale one is a leftover of a killed write)
TEMP_INFIX = ".iesm-tmp."

ModelT = TypeVar("ModelT", bound=BaseModel)


def atomic_write(path: str | Path, write: Callable[[Path], None]) -> None:
    """Call `write(tmp_path)` on a temporary file beside `path`, then rename it into place; the
    temporary file is removed when `write` fails."""
    path = Path(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=f".{path.name}{TEMP_INFIX}", suffix=path.suffix or ".tmp")
    os.close(fd)
    try:
        write(Path(tmp))
        os.replace(tmp, path)
    except BaseException:
        Path(tmp).unlink(missing_ok=True)
        raise


def write_text(path: str | Path, text: str) -> None:
    """Write UTF-8 `text` to `path` atomically."""
    atomic_write(path, lambda p: p.write_text(text, encoding="utf-8"))


def write_png(path: str | Path, image: np.ndarray) -> None:
    """Write a uint8 (H, W) or BGR (H, W, 3) image, or a uint16 (H, W) image, as PNG atomically
    (OpenCV, fast compression)."""
    import cv2

    def write(tmp: Path) -> None:
        if not cv2.imwrite(str(tmp), image, [cv2.IMWRITE_PNG_COMPRESSION, 1]):
            raise IesmError("could not write image", path)

    atomic_write(path, write)


def pyplot(where: str | None = None):
    """matplotlib.pyplot with the Agg backend, or an `IesmError` naming the `plots` extra."""
    try:
        import matplotlib

        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        raise IesmError("drawing needs matplotlib: pip install 'iesm-agent[plots]'", None, where) from None
    return plt


def save_figure(fig, path: str | Path, dpi: int = 150, tight: bool = True) -> None:
    """Write a matplotlib figure to `path` as PNG atomically, then close it."""
    plt = pyplot()
    try:
        atomic_write(path, lambda p: fig.savefig(p, dpi=dpi, bbox_inches="tight" if tight else None, format="png"))
    finally:
        plt.close(fig)


def read_json_model(path: str | Path, model: type[ModelT]) -> ModelT:
    """`model` validated from the JSON file at `path`; any problem is an `IesmError` naming the
    file and, for a validation error, the field."""
    path = Path(path)
    if not path.is_file():
        raise IesmError("file is missing", path)
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, json.JSONDecodeError) as exc:
        raise IesmError(f"not readable JSON ({exc})", path) from None
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        err = exc.errors()[0]
        raise IesmError(err["msg"], path, ".".join(str(p) for p in err["loc"]) or None) from None
