"""Text -> embedding rows kept on disk (one SQLite file per model fingerprint and backend), so
texts embedded once (instance labels and captions, room and lexicon labels, frequent queries)
are read back by later processes instead of being embedded again.

Several processes and threads may read and write at once (WAL journal, one connection per
thread, `INSERT OR IGNORE`). A store that cannot be opened or written (no permission, a corrupt
file) switches itself off for the process with one warning: embeddings are then computed as
if it were empty. Rows of the wrong length are ignored. Values are raw float32 bytes (no pickle).
"""

from __future__ import annotations

import sqlite3
import threading
import warnings
from pathlib import Path

import numpy as np

#: texts per SELECT (below SQLite's bound-parameter limit)
_CHUNK = 500


class VectorStore:
    """`get(texts) -> {text: (dim,) float32}` for the stored ones; `put(texts, rows)`."""

    def __init__(self, path: Path, dim: int):
        self.path = Path(path)
        self.dim = dim
        self._local = threading.local()
        self._off = False

    def _db(self) -> sqlite3.Connection | None:
        if self._off:
            return None
        db = getattr(self._local, "db", None)
        if db is None:
            try:
                self.path.parent.mkdir(parents=True, exist_ok=True)
                db = sqlite3.connect(self.path, timeout=10.0)
                db.execute("PRAGMA journal_mode=WAL")
                db.execute("CREATE TABLE IF NOT EXISTS vectors (text TEXT PRIMARY KEY, vec BLOB NOT NULL)")
                db.commit()
            except (sqlite3.Error, OSError) as exc:
                self._switch_off(exc)
                return None
            self._local.db = db
        return db

    def _switch_off(self, exc: Exception) -> None:
        if not self._off:
            self._off = True
            warnings.warn(f"embedding store {self.path} unusable, embedding without it: {exc}",
                          RuntimeWarning, stacklevel=4)

    def get(self, texts: list[str]) -> dict[str, np.ndarray]:
        """The stored rows among `texts` (read-only float32 arrays of length `dim`)."""
        db = self._db()
        found: dict[str, np.ndarray] = {}
        if db is None or not texts:
            return found
        unique = list(dict.fromkeys(texts))
        try:
            for start in range(0, len(unique), _CHUNK):
                chunk = unique[start:start + _CHUNK]
                rows = db.execute(f"SELECT text, vec FROM vectors WHERE text IN ({','.join('?' * len(chunk))})",
                                  chunk).fetchall()
                for text, blob in rows:
                    if isinstance(blob, bytes) and len(blob) == 4 * self.dim:
                        found[text] = np.frombuffer(blob, np.float32)
        except sqlite3.Error as exc:
            self._switch_off(exc)
        return found

    def put(self, texts: list[str], rows: np.ndarray) -> None:
        """Store `rows` (N, dim) float32 under `texts` (existing entries are kept)."""
        db = self._db()
        if db is None or not len(texts):
            return
        data = [(t, np.ascontiguousarray(r, np.float32).tobytes()) for t, r in zip(texts, rows)]
        try:
            db.executemany("INSERT OR IGNORE INTO vectors (text, vec) VALUES (?, ?)", data)
            db.commit()
        except sqlite3.Error as exc:
            self._switch_off(exc)
