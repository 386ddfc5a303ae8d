"""The user cache folder shared by the response cache and the sentence encoder's files."""

from __future__ import annotations

import os
from pathlib import Path


def default_cache_dir() -> Path:
    """`$IESM_CACHE_DIR`, else the platform's user cache dir for `iesm-agent`."""
    env = os.environ.get("IESM_CACHE_DIR")
    if env:
        return Path(env).expanduser()
    import platformdirs  # deferred: only needed when no directory is given

    return Path(platformdirs.user_cache_dir("iesm-agent", appauthor=False))
