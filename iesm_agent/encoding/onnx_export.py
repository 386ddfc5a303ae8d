"""One-time export of the bundled MiniLM to ONNX (imports torch, transformers and onnx).

The graph takes `input_ids`, `attention_mask`, `token_type_ids` (B, T) int64 and returns
`embedding` (B, 384) float32: the last hidden states mean-pooled over the attention mask and
L2-normalised, the three modules (Transformer, Pooling mean, Normalize) of the
sentence-transformers model. The file carries in its metadata the weights' fingerprint and the
torch embedding of `PROBE_TEXT`, so a load can tell a stale or corrupt export from a good one.

`export_onnx(path)` is atomic and safe when several processes start at once: an exclusive lock
file beside `path`, a re-check under the lock (another process may have finished the export),
the export written to a temporary file in the same folder, its checksum file (size and CRC-32,
which catches damage the probe cannot see, such as in the rows of rare words) written, the
export checked against torch, then renamed into place.
"""

from __future__ import annotations

import json
import os
import sys
import tempfile
from pathlib import Path

from .model_files import fingerprint, max_seq_length, model_dir

#: embedded at export time by torch; a load must reproduce it (cosine >= PROBE_MIN_COSINE)
PROBE_TEXT = "a small red wooden chair next to the kitchen table"
PROBE_MIN_COSINE = 0.9999
META_FINGERPRINT = "iesm_fingerprint"
META_PROBE = "iesm_probe"
INPUT_NAMES = ("input_ids", "attention_mask", "token_type_ids")


def export_lock(path: Path):
    """A `filelock.FileLock` on `<path>.lock`, exclusive across processes on POSIX and Windows
    alike (entering it blocks while another process exports)."""
    from filelock import FileLock

    path.parent.mkdir(parents=True, exist_ok=True)
    return FileLock(path.with_name(path.name + ".lock"))


def _pooled_module():
    """A torch module: BERT (eager attention, so the padding mask is traced as data) followed
    by mean pooling over the mask and L2 normalisation."""
    import torch
    from transformers import AutoModel

    bert = AutoModel.from_pretrained(str(model_dir()), attn_implementation="eager")
    bert.eval()

    class Pooled(torch.nn.Module):
        def __init__(self):
            super().__init__()
            self.bert = bert

        def forward(self, input_ids, attention_mask, token_type_ids):
            hidden = self.bert(input_ids=input_ids, attention_mask=attention_mask,
                               token_type_ids=token_type_ids).last_hidden_state          # (B, T, 384)
            mask = attention_mask.unsqueeze(-1).to(hidden.dtype)                         # (B, T, 1)
            mean = (hidden * mask).sum(1) / mask.sum(1).clamp(min=1e-9)                  # (B, 384)
            return mean / mean.norm(dim=1, keepdim=True).clamp(min=1e-12)

    return Pooled()


def export_onnx(path: Path, is_valid) -> None:
    """Write the ONNX export to `path` unless `is_valid(path)` already holds (checked under
    the lock). Raises RuntimeError when the export does not reproduce torch on the probe."""
    path = Path(path)
    with export_lock(path):
        if path.is_file() and is_valid(path):
            return
        print(f"iesm: exporting the sentence encoder to ONNX once ({path}); this takes a few seconds",
              file=sys.stderr, flush=True)
        os.environ.setdefault("HF_HUB_OFFLINE", "1")
        os.environ.setdefault("TRANSFORMERS_VERBOSITY", "error")
        os.environ.setdefault("HF_HUB_DISABLE_PROGRESS_BARS", "1")
        fd, tmp = tempfile.mkstemp(dir=path.parent, prefix=path.name + ".", suffix=".tmp")
        os.close(fd)
        try:
            _write(Path(tmp))
            _write_checksum(Path(tmp), checksum_path(path))
            if not is_valid(Path(tmp)):
                raise RuntimeError("the exported ONNX model does not reproduce the torch embeddings")
            os.replace(tmp, path)
        finally:
            Path(tmp).unlink(missing_ok=True)


def checksum_path(path: Path) -> Path:
    """The JSON file beside an export holding its size and CRC-32 (`file_checksum`)."""
    return path.with_name(path.name + ".json")


def file_checksum(data: bytes) -> dict:
    """{"size": bytes, "crc32": int} of a file's content (about 20 ms for the 90 MB export)."""
    import zlib

    return {"size": len(data), "crc32": zlib.crc32(data)}


def _write_checksum(onnx_file: Path, dest: Path) -> None:
    """Write `file_checksum` of `onnx_file` to `dest` atomically."""
    fd, tmp = tempfile.mkstemp(dir=dest.parent, prefix=dest.name + ".", suffix=".tmp")
    with os.fdopen(fd, "w") as fh:
        json.dump(file_checksum(onnx_file.read_bytes()), fh)
    os.chmod(tmp, 0o644)
    os.replace(tmp, dest)


def _write(tmp: Path) -> None:
    """Trace the pooled model into `tmp`, then stamp the fingerprint and the probe vector."""
    import warnings

    import onnx
    import torch
    from tokenizers import Tokenizer

    module = _pooled_module()
    tokenizer = Tokenizer.from_file(str(model_dir() / "tokenizer.json"))
    tokenizer.enable_truncation(max_seq_length())
    tokenizer.enable_padding()
    batch = tokenizer.encode_batch([PROBE_TEXT, "a chair"])  # padded: the mask path is traced
    inputs = tuple(torch.tensor([getattr(e, f) for e in batch], dtype=torch.long)
                   for f in ("ids", "attention_mask", "type_ids"))
    dynamic = {name: {0: "batch", 1: "tokens"} for name in INPUT_NAMES}
    with torch.no_grad(), warnings.catch_warnings():
        warnings.simplefilter("ignore")  # tracer and deprecation chatter
        probe = module(*inputs)[0].numpy().astype("float32")
        torch.onnx.export(module, inputs, str(tmp), dynamo=False, input_names=list(INPUT_NAMES),
                          output_names=["embedding"], dynamic_axes={**dynamic, "embedding": {0: "batch"}},
                          opset_version=17)
    proto = onnx.load(str(tmp))
    for key, value in ((META_FINGERPRINT, fingerprint()), (META_PROBE, json.dumps(probe.tolist()))):
        entry = proto.metadata_props.add()
        entry.key, entry.value = key, value
    onnx.save(proto, str(tmp))
    with open(tmp, "rb+") as fh:
        os.fsync(fh.fileno())
    os.chmod(tmp, 0o644)
