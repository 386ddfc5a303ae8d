"""On-disk response cache around any `Model` (diskcache; strings only, nothing pickled).

The key is the SHA-256 of canonical JSON of the inner model's `cache_identity()`, the
messages and the options, so identical requests from any process or shard share entries.
Errors and empty replies are not stored. A cache that cannot be opened or used (a file where
the directory should be, a corrupt database, a damaged settings table, a lock held elsewhere, no
permission: any exception it raises) turns itself off with one `CacheWarning` and the calls go
straight to the inner model.
"""

from __future__ import annotations

import hashlib
import json
import sqlite3
import threading
import time
import warnings
from pathlib import Path
from typing import Any

import diskcache
from pydantic import ValidationError

from ..cachedir import default_cache_dir
from .base import ChatOptions, Completion, Message, Model, WrappedModel

#: bump when the key layout changes, so old entries are never misread
KEY_VERSION = 2


class CacheWarning(RuntimeWarning):
    """The response cache is unusable and has been turned off for this model."""


def cache_key(model: Model, messages: list[Message], options: ChatOptions) -> str:
    """Hex SHA-256 of the canonical JSON of model identity and options, then of each message: its
    role and its text as is (a message with image parts as its canonical JSON). Hashing the
    text directly spares JSON-escaping candidate blocks of many kilobytes on every call."""
    head = {"v": KEY_VERSION, "model": model.cache_identity(), "options": options.model_dump(mode="json")}
    h = hashlib.sha256(json.dumps(head, sort_keys=True, separators=(",", ":"), ensure_ascii=False).encode())
    for m in messages:
        if isinstance(m.content, str):
            body = b"t" + m.content.encode()
        else:
            body = b"j" + json.dumps(m.model_dump(mode="json")["content"], sort_keys=True,
                                     separators=(",", ":"), ensure_ascii=False).encode()
        role = m.role.encode()  # lengths first: no two message lists hash the same bytes
        h.update(len(role).to_bytes(4, "big") + role + len(body).to_bytes(8, "big") + body)
    return h.hexdigest()


class _TextDisk(diskcache.Disk):
    """diskcache serialisation limited to `str` keys and values: never pickles or unpickles,
    so a tampered cache file cannot run code."""

    def put(self, key: Any) -> Any:
        if type(key) is not str:
            raise TypeError("cache keys must be str")
        return super().put(key)

    def get(self, key: Any, raw: bool) -> Any:
        if not raw:
            raise ValueError("refusing to unpickle a cache key")
        return super().get(key, raw)

    def store(self, value: Any, read: bool, key: Any = diskcache.core.UNKNOWN) -> Any:
        if type(value) is not str:
            raise TypeError("cache values must be str")
        return super().store(value, read, key)

    def fetch(self, mode: int, filename: Any, value: Any, read: bool) -> Any:
        if mode not in (diskcache.core.MODE_RAW, diskcache.core.MODE_TEXT):
            raise ValueError(f"refusing to read cache entry of mode {mode} (only text is stored)")
        return super().fetch(mode, filename, value, read)


#: what a broken cache raises: sqlite corruption/locking, file system errors, foreign entries,
#: a damaged settings table (KeyError), diskcache's Timeout; any of them turns the cache off
_CACHE_ERRORS = (Exception,)
#: seconds a cache operation waits for a lock held elsewhere before the cache is turned off
LOCK_TIMEOUT = 1.0


def _probe(cache_dir: Path) -> None:
    """Raise at once (within `LOCK_TIMEOUT`) when the cache database is locked or unreadable:
    diskcache's own start-up runs a dozen statements, each waiting for the lock."""
    db = cache_dir / "cache.db"
    if not db.exists():
        return
    con = sqlite3.connect(str(db), timeout=LOCK_TIMEOUT, isolation_level=None)
    try:
        con.execute("BEGIN IMMEDIATE")
        con.execute("SELECT key, value FROM Settings LIMIT 1").fetchall()
        con.execute("ROLLBACK")
    finally:
        con.close()


class CachedModel(WrappedModel):
    """`inner` behind a disk cache in `cache_dir` (default: `default_cache_dir()`).

    A hit returns the stored completion with `cached=True` and `latency_ms` = lookup time.
    Counters: `hits`, `misses` (every call not answered from the cache, including while the
    cache is off). Concurrent identical requests may both miss.
    """

    def __init__(self, inner: Model, cache_dir: str | Path | None = None):
        super().__init__(inner)
        self.cache_dir = Path(cache_dir).expanduser() if cache_dir is not None else default_cache_dir()
        self.hits = self.misses = 0
        self.disabled_reason: str | None = None
        self._cache: diskcache.Cache | None = None
        self._lock = threading.Lock()

    def __repr__(self) -> str:
        return f"CachedModel({self.inner!r}, cache_dir={str(self.cache_dir)!r})"

    async def acomplete(self, messages: list[Message], options: ChatOptions | None = None) -> Completion:
        options = options or ChatOptions()
        started = time.perf_counter()
        key = cache_key(self.inner, messages, options)
        hit = self._lookup(key)
        if hit is not None:
            self.hits += 1
            return hit.model_copy(update={"cached": True,
                                          "latency_ms": (time.perf_counter() - started) * 1000.0})
        self.misses += 1
        completion = await self.inner.acomplete(messages, options)
        if completion.text.strip() and not completion.truncated:  # a reply cut at its bound is not kept
            # the notes told what this call met on the way (a refused dialect): not a replay's
            self._store(key, completion.model_copy(update={"cached": False, "notes": []}).model_dump_json())
        return completion

    async def aclose(self) -> None:
        """Close the inner model's connections and the cache's database handles."""
        try:
            await self.inner.aclose()
        finally:
            with self._lock:
                if self._cache is not None:
                    self._cache.close()

    def _open(self) -> diskcache.Cache | None:
        """The cache, opened on first use; None once it has been turned off."""
        with self._lock:
            if self._cache is None and self.disabled_reason is None:
                try:
                    _probe(self.cache_dir)
                    self._cache = diskcache.Cache(str(self.cache_dir), disk=_TextDisk, timeout=LOCK_TIMEOUT)
                except _CACHE_ERRORS as exc:
                    self._disable(exc)
            return self._cache

    def _lookup(self, key: str) -> Completion | None:
        cache = self._open()
        if cache is None:
            return None
        try:
            text = cache.get(key)
        except (ValueError, TypeError):
            return None  # one foreign entry: a miss (it is overwritten on store)
        except _CACHE_ERRORS as exc:
            self._disable(exc)
            return None
        if not isinstance(text, str):
            return None
        try:
            return Completion.model_validate_json(text)
        except ValidationError:
            return None

    def _store(self, key: str, value: str) -> None:
        cache = self._open()
        if cache is None:
            return
        try:
            cache.set(key, value)
        except _CACHE_ERRORS as exc:
            self._disable(exc)

    def _disable(self, exc: BaseException) -> None:
        """Turn the cache off for this model, with one warning."""
        if self.disabled_reason is not None:
            return
        self.disabled_reason = f"{type(exc).__name__}: {exc}"
        cache, self._cache = self._cache, None
        if cache is not None:
            try:
                cache.close()
            except _CACHE_ERRORS:
                pass
        warnings.warn(f"response cache at {self.cache_dir} is unusable ({self.disabled_reason}); "
                      "continuing without it", CacheWarning, stacklevel=3)
