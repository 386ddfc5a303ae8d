"""Atomic file output and validated JSON input, shared by every stage.

Every file the toolkit writes goes through `atomic_write`: the content is written to a temporary
file beside the target (named `.NAME.iesm-tmp.PID.*`, with the mode the umask gives an ordinary
new file) and renamed into place, so a killed process
never leaves a half-written output; the temporary files a killed process left behind are removed
by the next write of that target (`clean_stale_temps`).

Every JSON document read from outside goes through `load_json` (size and nesting depth bounded
before parsing) and every `.npz` / `.iesm` array member through `read_npy`
(dtype, shape and size checked from the header before the data is read).
"""

from __future__ import annotations

import json
import os
import re
import shutil
import struct
import tempfile
import zipfile
import zlib
from pathlib import Path
from typing import IO, Any, Callable, Iterable, Optional, TypeVar

import numpy as np
from pydantic import BaseModel, ValidationError

from .errors import IesmError

#: infix of our temporary files (a stale one is a leftover of a killed write)
TEMP_INFIX = ".iesm-tmp."

#: largest JSON document read (bytes) and deepest nesting of arrays and objects in it
MAX_JSON_BYTES = 64 * 1024 * 1024
MAX_JSON_DEPTH = 64
#: largest array read from an `.npz` or `.iesm` member (bytes, decompressed)
MAX_ARRAY_BYTES = 1024 * 1024 * 1024

ModelT = TypeVar("ModelT", bound=BaseModel)
ErrorT = type[IesmError]


def _umask() -> int:
    """The process's file-creation mask: from /proc (Linux, no change to the process), else read
    by setting it and setting it back."""
    try:
        with open("/proc/self/status", encoding="ascii", errors="replace") as status:
            for line in status:
                if line.startswith("Umask:"):
                    return int(line.split()[1], 8)
    except (OSError, ValueError, IndexError):
        pass
    mask = os.umask(0o022)
    os.umask(mask)
    return mask


def _umask_mode(path: str | Path, mode: int) -> None:
    """Give `path` (made by mkstemp / mkdtemp, mode 0600 / 0700) the mode an ordinary `open` /
    `mkdir` would: `mode` (0666 for a file, 0777 for a directory) less the umask."""
    os.chmod(path, mode & ~_umask())


def _temp_prefix(path: Path) -> str:
    return f".{path.name}{TEMP_INFIX}{os.getpid()}."


def _pid_alive(pid: int) -> bool:
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError, ValueError, OSError):
        return True  # someone else's live process (or not ours to judge)
    return True


def clean_stale_temps(path: str | Path) -> list[Path]:
    """Remove the temporary files (or directories) a killed process left beside `path`: ours are
    named `.NAME.iesm-tmp.PID.*`, and only those whose process is gone are removed, so a write in
    progress elsewhere is left alone. Returns what was removed."""
    path = Path(path)
    removed = []
    pattern = re.compile(re.escape(f".{path.name}{TEMP_INFIX}") + r"(\d+)\.")
    try:
        siblings = list(path.parent.iterdir())
    except OSError:
        return removed
    for p in siblings:
        m = pattern.match(p.name)
        if m is None or int(m.group(1)) == os.getpid() or _pid_alive(int(m.group(1))):
            continue
        try:
            if p.is_dir() and not p.is_symlink():
                shutil.rmtree(p)
            else:
                p.unlink()
            removed.append(p)
        except OSError:
            pass
    return removed


def temp_dir(path: str | Path) -> Path:
    """A new temporary directory beside `path` named as our temporary files are (stale ones of
    the same target are cleaned first); the caller renames it into place or removes it."""
    path = Path(path)
    clean_stale_temps(path)
    stage = Path(tempfile.mkdtemp(prefix=_temp_prefix(path), dir=path.resolve().parent))
    _umask_mode(stage, 0o777)
    return stage


def atomic_write(path: str | Path, write: Callable[[Path], None]) -> None:
    """Call `write(tmp_path)` on a temporary file beside `path`, then rename it into place; the
    temporary file is removed when `write` fails (and stale ones of a killed writer first)."""
    path = Path(path)
    clean_stale_temps(path)
    fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=_temp_prefix(path), suffix=path.suffix or ".tmp")
    os.close(fd)
    try:
        _umask_mode(tmp, 0o666)  # the file a user shares is readable as the umask says, not 0600
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


def read_image(path: str | Path, color: bool, *, error: ErrorT = IesmError) -> np.ndarray:
    """RGB uint8 (H, W, 3) when `color`, else the raw single-channel image (e.g. uint16 depth);
    a missing or unreadable file is an `error` naming it."""
    import cv2

    path = Path(path)
    if not path.is_file():
        raise error("file is missing", path)
    image = cv2.imread(str(path), cv2.IMREAD_COLOR if color else cv2.IMREAD_UNCHANGED)
    if image is None:
        raise error("not a readable image", path)
    return cv2.cvtColor(image, cv2.COLOR_BGR2RGB) if color else image


def save_figure(fig, path: str | Path, dpi: int = 150, tight: bool = True) -> None:
    """Write a matplotlib figure to `path` as PNG atomically, then close it."""
    plt = pyplot()
    try:
        atomic_write(path, lambda p: fig.savefig(p, dpi=dpi, bbox_inches="tight" if tight else None, format="png"))
    finally:
        plt.close(fig)


# ------------------------------------------------------------------------------------------- JSON

_STRING = re.compile(rb'"[^"\\]*(?:\\.[^"\\]*)*"', re.DOTALL)


def json_depth(data: bytes) -> int:
    """Deepest nesting of `[` / `{` in JSON `data`, brackets inside strings not counted (a quick
    scan without recursion; an unterminated string counts its brackets, which only errs deep)."""
    stripped = np.frombuffer(_STRING.sub(b'""', data), np.uint8)
    if stripped.size == 0:
        return 0
    opens = (stripped == 0x5B) | (stripped == 0x7B)   # [ {
    closes = (stripped == 0x5D) | (stripped == 0x7D)  # ] }
    return int(np.cumsum(opens.astype(np.int32) - closes).max(initial=0))


def _reject_constant(name: str) -> Any:
    raise ValueError(f"{name} is not allowed in JSON")


def load_json(data: str | bytes | Path, source: str | Path | None = None, where: str | None = None, *,
              max_bytes: int = MAX_JSON_BYTES, max_depth: int = MAX_JSON_DEPTH, allow_nan: bool = True,
              error: ErrorT = IesmError) -> Any:
    """The parsed JSON of `data` (text, bytes, or a file path), bounded: more than `max_bytes`
    bytes or nesting deeper than `max_depth` is refused before parsing. NaN / Infinity parse as
    floats for the reader's (pydantic, `allow_inf_nan=False`) fields to refuse by name, or are
    refused here with `allow_nan=False`. Any problem is an `error` (an `IesmError` class) naming `source` (default: the
    path) and `where`, on one line."""
    if isinstance(data, Path):
        source = data if source is None else source
        try:
            size = data.stat().st_size
            if size > max_bytes:
                raise error(f"file is {size:,} bytes, more than the {max_bytes:,} a JSON input may have",
                            source, where)
            data = data.read_bytes()
        except FileNotFoundError:
            raise error("file is missing", source, where) from None
        except OSError as exc:
            raise error(f"cannot read: {exc.strerror or exc}", source, where) from None
    raw = data.encode("utf-8", "surrogatepass") if isinstance(data, str) else bytes(data)
    if len(raw) > max_bytes:
        raise error(f"JSON of {len(raw):,} bytes is more than the {max_bytes:,} allowed", source, where)
    depth = json_depth(raw)
    if depth > max_depth:
        raise error(f"JSON nested {depth} levels deep, more than the {max_depth} allowed", source, where)
    try:
        return json.loads(raw, parse_constant=None if allow_nan else _reject_constant)
    except UnicodeDecodeError as exc:
        raise error(f"invalid JSON: not UTF-8 ({exc.reason} at byte {exc.start})", source, where) from None
    except (ValueError, RecursionError) as exc:  # JSONDecodeError is a ValueError
        raise error(f"invalid JSON: {exc}", source, where) from None


def field_path(loc: Iterable[Any]) -> str:
    """Pydantic error location -> readable field path, e.g. ('objects', 3, 'size') -> 'objects[3].size'."""
    out = ""
    for part in loc:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


def validation_message(exc: ValidationError) -> tuple[str, str | None]:
    """(message, dotted field path such as `instances.2.label`) of a pydantic error's first
    problem, on one line."""
    err = exc.errors()[0]
    return " ".join(str(err["msg"]).split()), ".".join(str(p) for p in err["loc"]) or None


def read_json_model(path: str | Path, model: type[ModelT], *, error: ErrorT = IesmError) -> ModelT:
    """`model` validated from the JSON file at `path` (read with `load_json`); any problem is an
    `IesmError` naming the file and, for a validation error, the field."""
    path = Path(path)
    if not path.is_file():
        raise error("file is missing", path)
    data = load_json(path, error=error)
    try:
        return model.model_validate(data)
    except ValidationError as exc:
        message, field = validation_message(exc)
        raise error(message, path, field) from None


# ------------------------------------------------------------------------------------------ arrays

#: what can be wrong with an archive or an array stream besides a bad header
ARCHIVE_ERRORS = (zipfile.BadZipFile, zlib.error, EOFError, NotImplementedError, ValueError, struct.error,
                  OSError, OverflowError, TypeError, KeyError, RuntimeError)


def read_npy(stream: IO[bytes], source: str | Path, where: str | None = None, *, kinds: str = "biuf",
             declared_bytes: Optional[int] = None, max_bytes: int = MAX_ARRAY_BYTES,
             check: Optional[Callable[[tuple[int, ...], np.dtype], None]] = None,
             error: ErrorT = IesmError) -> np.ndarray:
    """One `.npy` array from `stream`, its header read first: a dtype kind outside `kinds` (no
    objects, strings or pickles), more than `max_bytes` of data, a size that disagrees with
    `declared_bytes` (a zip member's declared size) or a shape `check(shape, dtype)` refuses (by
    raising an `IesmError`) is refused before any data is read."""
    fmt = np.lib.format
    try:
        version = fmt.read_magic(stream)
        if version == (1, 0):
            shape, fortran, dtype = fmt.read_array_header_1_0(stream)
        elif version == (2, 0):
            shape, fortran, dtype = fmt.read_array_header_2_0(stream)
        else:
            raise ValueError(f"unsupported .npy version {version}")
    except ARCHIVE_ERRORS as exc:
        raise error(f"not a readable .npy array ({' '.join(str(exc).split())})", source, where) from None
    if dtype.hasobject:
        raise error("array of Python objects refused: pickles are never read (allow_pickle=False)", source, where)
    if dtype.kind not in kinds or dtype.fields is not None:
        raise error(f"array dtype {dtype} is not allowed here (kinds {kinds!r})", source, where)
    count = 1
    for n in shape:
        count *= int(n)
    nbytes = count * dtype.itemsize
    if nbytes > max_bytes:
        raise error(f"array {tuple(shape)} of {dtype} needs {nbytes:,} bytes, more than the {max_bytes:,} "
                    "allowed", source, where)
    if declared_bytes is not None and nbytes > declared_bytes:
        raise error(f"array {tuple(shape)} of {dtype} needs {nbytes:,} bytes but the member holds "
                    f"{declared_bytes:,}", source, where)
    if check is not None:
        check(tuple(shape), dtype)
    try:
        data = stream.read(nbytes)
        if len(data) != nbytes:
            raise EOFError(f"{len(data)} of {nbytes} bytes")
        arr = np.frombuffer(data, dtype=dtype)
        order = "F" if fortran else "C"
        return arr.reshape(shape, order=order) if shape else arr.reshape(())
    except ARCHIVE_ERRORS as exc:
        raise error(f"truncated or corrupted array ({' '.join(str(exc).split())})", source, where) from None


def read_npz(path: str | Path, names: Iterable[str], *, kinds: dict[str, str] | str = "biuf",
             max_bytes: int = MAX_ARRAY_BYTES, check: Optional[Callable[[str, tuple[int, ...], np.dtype], None]] = None,
             error: ErrorT = IesmError) -> dict[str, np.ndarray]:
    """The arrays `names` of the `.npz` at `path`, each read with `read_npy` (no pickles; kinds
    per name or for all; `check(name, shape, dtype)` before each is read). A missing, truncated,
    empty or corrupted archive, or a missing array, is an `error` naming the file, on one line."""
    path = Path(path)
    if not path.is_file():
        raise error("file is missing", path)
    out: dict[str, np.ndarray] = {}
    try:
        with zipfile.ZipFile(path) as zf:
            for name in names:
                try:
                    info = zf.getinfo(f"{name}.npy")
                except KeyError:
                    raise error(f"no array {name!r} in the archive", path) from None
                if info.file_size > max_bytes + 65536:
                    raise error(f"member {info.filename} declares {info.file_size:,} bytes, more than the "
                                f"{max_bytes:,} allowed", path)
                with zf.open(info) as stream:
                    out[name] = read_npy(
                        stream, path, name, kinds=kinds if isinstance(kinds, str) else kinds.get(name, "biuf"),
                        declared_bytes=info.file_size, max_bytes=max_bytes,
                        check=None if check is None else (lambda shape, dtype, n=name: check(n, shape, dtype)),
                        error=error)
    except IesmError:
        raise
    except ARCHIVE_ERRORS as exc:
        raise error(f"not a readable .npz archive (truncated or corrupted: {' '.join(str(exc).split())})",
                    path) from None
    return out
