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
import stat
import struct
import tempfile
import zipfile
import zlib
from contextlib import contextmanager
from pathlib import Path
from typing import IO, Any, Callable, Iterable, Iterator, Optional, TypeVar

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


def utf8_text(text: str) -> str:
    """`text` as valid UTF-8 text: a path's undecodable bytes (Python's surrogate escapes) and
    other lone surrogates become U+FFFD, so the text can be written to JSON or a page."""
    return text.encode("utf-8", "surrogatepass").decode("utf-8", "replace")


def recordable_path(path: str | Path, where: str | None = None) -> str:
    """`str(path)` when it is valid UTF-8 text, as a path written into a JSON file and read back
    must be; else an `IesmError` (a name with undecodable bytes: rename it)."""
    text = str(path)
    try:
        text.encode("utf-8")
    except UnicodeEncodeError:
        raise IesmError("path is not valid UTF-8 text and is recorded in the run's files: rename it", text,
                        where) from None
    return text


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
    temporary file is removed when `write` fails (and stale ones of a killed writer first). A
    target that is a directory or whose folder does not exist is an `IesmError` before anything
    is written."""
    path = Path(path)
    if path.is_dir():
        raise IesmError("is a directory: give a file name to write", path)
    if not path.parent.is_dir():
        raise IesmError("cannot write: the folder does not exist", path.parent)
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

    def write(tmp: Path) -> None:  # encoded in memory: OpenCV never sees the path (any bytes)
        ok, encoded = cv2.imencode(".png", image, [cv2.IMWRITE_PNG_COMPRESSION, 1])
        if not ok:
            raise IesmError("could not write image", path)
        tmp.write_bytes(encoded.tobytes())

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


#: largest image file read (bytes) and most pixels an image may declare in its header
MAX_IMAGE_BYTES = 128 * 1024 * 1024
MAX_IMAGE_PIXELS = 4096 * 4096
#: largest text file read (bytes)
MAX_TEXT_BYTES = 64 * 1024 * 1024


def read_bytes(path: str | Path, max_bytes: int, *, error: ErrorT = IesmError, where: str | None = None) -> bytes:
    """The bytes of the regular file `path`, refused (an `error` on one line) when it is missing,
    not a regular file (a FIFO that would block, a device such as /dev/zero that never ends) or
    larger than `max_bytes`, before more than `max_bytes` + 1 bytes are read. Any path Python
    can name works, one that is not valid UTF-8 included (the OS gets `os.fsencode` bytes)."""
    path = Path(path)
    try:
        info = path.stat()
    except FileNotFoundError:
        raise error("file is missing", path, where) from None
    except (OSError, ValueError) as exc:  # ValueError: an embedded NUL
        raise error(f"cannot read: {getattr(exc, 'strerror', None) or exc}", path, where) from None
    if not stat.S_ISREG(info.st_mode):
        raise error("not a regular file (a directory, FIFO or device is not read)", path, where)
    if info.st_size > max_bytes:
        raise error(f"file is {info.st_size:,} bytes, more than the {max_bytes:,} allowed", path, where)
    try:
        with open(path, "rb") as handle:
            data = handle.read(max_bytes + 1)
    except OSError as exc:
        raise error(f"cannot read: {exc.strerror or exc}", path, where) from None
    if len(data) > max_bytes:
        raise error(f"file grew past the {max_bytes:,} bytes allowed while read", path, where)
    return data


def read_text(path: str | Path, *, max_bytes: int = MAX_TEXT_BYTES, max_lines: int | None = None,
              error: ErrorT = IesmError, where: str | None = None) -> str:
    """The UTF-8 text of the regular file `path` (`read_bytes`' checks), with at most `max_lines`
    lines when given; anything else is an `error` naming the file, on one line."""
    data = read_bytes(path, max_bytes, error=error, where=where)
    if max_lines is not None and data.count(b"\n") > max_lines:
        raise error(f"file has more than the {max_lines:,} lines allowed", path, where)
    try:
        return data.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise error(f"not UTF-8 text ({exc.reason} at byte {exc.start})", path, where) from None


def image_header(data: bytes) -> tuple[str, int, int]:
    """(kind "png" / "jpeg", width, height) read from the header of encoded image `data`, without
    decoding it; `ValueError` for anything else (or a header without a size)."""
    if data[:8] == b"\x89PNG\r\n\x1a\n":
        if len(data) < 24 or data[12:16] != b"IHDR":
            raise ValueError("PNG without an IHDR header")
        width, height = struct.unpack(">II", data[16:24])
        return "png", width, height
    if data[:2] == b"\xff\xd8":
        at = 2
        while at + 4 <= len(data):
            if data[at] != 0xFF:
                raise ValueError("damaged JPEG marker")
            marker = data[at + 1]
            if marker == 0xFF:  # fill byte
                at += 1
                continue
            if marker in (0xD8, 0x01) or 0xD0 <= marker <= 0xD7:  # markers without a length
                at += 2
                continue
            (length,) = struct.unpack(">H", data[at + 2:at + 4])
            if 0xC0 <= marker <= 0xCF and marker not in (0xC4, 0xC8, 0xCC):  # start of frame
                if at + 9 > len(data):
                    break
                height, width = struct.unpack(">HH", data[at + 5:at + 9])
                return "jpeg", width, height
            if marker == 0xD9 or length < 2:
                break
            at += 2 + length
        raise ValueError("JPEG without a frame header")
    raise ValueError("not a PNG or JPEG image")


def read_image(path: str | Path, color: bool, *, error: ErrorT = IesmError,
               max_pixels: int = MAX_IMAGE_PIXELS) -> np.ndarray:
    """RGB uint8 (H, W, 3) when `color`, else the raw single-channel image (e.g. uint16 depth),
    from a PNG or JPEG file. The file is read by Python (`read_bytes`: regular file, at most
    `MAX_IMAGE_BYTES`; any path, one that is not UTF-8 included), its header checked (format, at
    most `max_pixels` pixels) before OpenCV decodes it from memory. Any problem is an `error`
    naming the file, on one line."""
    import cv2

    data = read_bytes(path, MAX_IMAGE_BYTES, error=error)
    kind, width, height = _checked_header(data, path, error)
    if width * height > max_pixels or not width or not height:
        raise error(f"{kind.upper()} declares {width} x {height} pixels (at most {max_pixels:,} are read)", path)
    image = cv2.imdecode(np.frombuffer(data, np.uint8), cv2.IMREAD_COLOR if color else cv2.IMREAD_UNCHANGED)
    if image is None or image.shape[:2] not in ((height, width), (width, height)):  # EXIF may turn a JPEG
        raise error("not a readable image (damaged data)", path)
    return cv2.cvtColor(image, cv2.COLOR_BGR2RGB) if color else image


def image_size(path: str | Path, *, error: ErrorT = IesmError) -> tuple[int, int]:
    """(width, height) of a PNG or JPEG file from its header alone."""
    _kind, width, height = _checked_header(read_bytes(path, MAX_IMAGE_BYTES, error=error), path, error)
    return width, height


def _checked_header(data: bytes, path: str | Path, error: ErrorT) -> tuple[str, int, int]:
    """`image_header(data)`, or an `error` naming `path`."""
    try:
        return image_header(data)
    except (ValueError, struct.error) as exc:
        raise error(f"not a readable image ({exc})", path) from None


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
        data = read_bytes(data, max_bytes, error=error, where=where)
    raw = data.encode("utf-8", "surrogatepass") if isinstance(data, str) else bytes(data)
    if len(raw) > max_bytes:
        raise error(f"JSON of {len(raw):,} bytes is more than the {max_bytes:,} allowed", source, where)
    # nesting cannot exceed the number of opening brackets: short replies skip the scan
    depth = json_depth(raw) if raw.count(b"[") + raw.count(b"{") > max_depth else 0
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


@contextmanager
def staged_directory(target: Path) -> Iterator[Path]:
    """A fresh directory beside `target` (`.NAME.iesm-tmp.PID.*`, so that a later run removes it
    when this process was killed) that replaces `target` when the block succeeds and is removed
    when it fails."""
    target = Path(target)
    if not target.parent.resolve().is_dir():
        raise IesmError("output directory's parent does not exist", target)
    stage = temp_dir(target)
    try:
        yield stage
        if target.exists():  # the caller checked it may be replaced (cli.outputs.check_frame_output)
            old = stage.with_name(stage.name + ".old")
            os.replace(target, old)
            os.replace(stage, target)
            shutil.rmtree(old)
        else:
            os.replace(stage, target)
    except BaseException:
        shutil.rmtree(stage, ignore_errors=True)
        raise
