"""The encoder on onnxruntime and `tokenizers`: no torch import on this path.

`open_onnx_backend(cache_dir)` loads `<cache_dir>/encoders/all-MiniLM-L6-v2-<fingerprint>.onnx`,
checking that it matches its checksum file, opens, was made from the installed weights and
reproduces its probe vector; a missing,
stale or corrupt file is (re)built by `onnx_export.export_onnx` when torch is installed, else
`EncoderUnavailable` says what to do.
"""

from __future__ import annotations

import importlib.util
import json
from concurrent.futures import ThreadPoolExecutor
from pathlib import Path

import numpy as np

from .model_files import MODEL_NAME, fingerprint, max_seq_length, model_dir
from .onnx_export import (INPUT_NAMES, META_FINGERPRINT, META_PROBE, PROBE_MIN_COSINE, PROBE_TEXT, checksum_path,
                          file_checksum)

#: texts per onnxruntime call; texts are sorted by length first so little is padded
BATCH = 64


class EncoderUnavailable(RuntimeError):
    """The ONNX encoder cannot be used (one line saying why and what to do)."""


def runtime_installed() -> bool:
    """Whether onnxruntime and tokenizers are importable."""
    return all(importlib.util.find_spec(m) is not None for m in ("onnxruntime", "tokenizers"))


def export_installed() -> bool:
    """Whether an export can be made here (torch, transformers and onnx importable)."""
    return all(importlib.util.find_spec(m) is not None for m in ("torch", "transformers", "onnx"))


class OnnxBackend:
    """`encode_batch(texts) -> (N, 384) float32` unit rows; thread-safe (onnxruntime sessions
    and `tokenizers` encoders may be called from several threads at once)."""

    kind = "onnx"

    def __init__(self, path: Path):
        import onnxruntime as ort
        from tokenizers import Tokenizer

        options = ort.SessionOptions()
        options.intra_op_num_threads = 1  # fastest for short texts; callers run in parallel instead
        options.log_severity_level = 3  # errors only
        self.path = Path(path)
        self.session = ort.InferenceSession(str(path), options, providers=["CPUExecutionProvider"])
        self.meta = dict(self.session.get_modelmeta().custom_metadata_map)
        self.dim = int(self.session.get_outputs()[0].shape[1])
        self.tokenizer = Tokenizer.from_file(str(model_dir() / "tokenizer.json"))
        self.tokenizer.no_padding()
        self.tokenizer.enable_truncation(max_seq_length())

    def problem(self) -> str | None:
        """Why this export must not be used (stale fingerprint, probe not reproduced), or None."""
        if self.meta.get(META_FINGERPRINT) != fingerprint():
            return "it was made from other weights or by another export version"
        try:
            probe = np.asarray(json.loads(self.meta[META_PROBE]), np.float32)
        except (KeyError, ValueError):
            return "its probe vector is missing"
        got = self.encode_batch([PROBE_TEXT])[0]
        if probe.shape != got.shape or not float(probe @ got) >= PROBE_MIN_COSINE:
            return "it does not reproduce its probe vector"
        return None

    def encode_batch(self, texts: list[str]) -> np.ndarray:
        """(N, dim) float32 rows, in the order of `texts`."""
        out = np.empty((len(texts), self.dim), np.float32)
        encoded = self.tokenizer.encode_batch(list(texts))
        order = sorted(range(len(texts)), key=lambda i: len(encoded[i].ids))
        for start in range(0, len(order), BATCH):
            rows = order[start:start + BATCH]
            width = max(len(encoded[i].ids) for i in rows)
            ids = np.zeros((len(rows), width), np.int64)
            mask = np.zeros((len(rows), width), np.int64)
            for r, i in enumerate(rows):
                n = len(encoded[i].ids)
                ids[r, :n] = encoded[i].ids
                mask[r, :n] = 1
            feed = dict(zip(INPUT_NAMES, (ids, mask, np.zeros_like(ids))))
            out[rows] = self.session.run(None, feed)[0]
        return out


def onnx_path(cache_dir: Path) -> Path:
    """Where the export for the installed weights lives."""
    return Path(cache_dir) / "encoders" / f"{MODEL_NAME}-{fingerprint()[:16]}.onnx"


def _usable(path: Path, checksum_of: Path | None = None) -> tuple[OnnxBackend | None, str]:
    """(the backend, "") when `path` is a good export, else (None, why not). `checksum_of`:
    the export whose checksum file applies (default `path` itself)."""
    if not path.is_file():
        return None, "it does not exist"
    try:
        expected = json.loads(checksum_path(checksum_of or path).read_text())
    except (OSError, ValueError):
        return None, "its checksum file is missing or unreadable"
    with ThreadPoolExecutor(1) as pool:  # the checksum (GIL released) overlaps the session load
        actual = pool.submit(lambda: file_checksum(path.read_bytes()))
        try:
            backend: OnnxBackend | None = OnnxBackend(path)
            why = ""
        except Exception as exc:  # onnxruntime refuses a truncated or garbled file with various errors
            backend, why = None, f"onnxruntime cannot read it ({str(exc).splitlines()[0][:160]})"
        if actual.result() != expected:
            return None, "its content does not match its checksum (damaged)"
    why = why or backend.problem()
    return (None, why) if why else (backend, "")


def open_onnx_backend(cache_dir: Path) -> OnnxBackend:
    """The ONNX backend, exporting (or re-exporting a bad file) first when needed."""
    from .onnx_export import export_onnx

    path = onnx_path(cache_dir)
    backend, why = _usable(path)
    if backend is not None:
        return backend
    if not export_installed():
        raise EncoderUnavailable(f"the ONNX sentence encoder {path} cannot be used ({why}) and cannot be "
                                 "rebuilt without torch: install iesm-agent[embeddings] or delete the file")
    try:
        export_onnx(path, lambda p: _usable(p, path)[0] is not None)
    except OSError as exc:
        raise EncoderUnavailable(f"cannot write the ONNX sentence encoder to {path}: {exc}") from None
    backend, why = _usable(path)
    if backend is None:
        raise EncoderUnavailable(f"the freshly exported ONNX sentence encoder {path} is unusable: {why}")
    return backend
