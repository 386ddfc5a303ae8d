"""The encoder on sentence-transformers and torch: the reference the ONNX export must match,
and the backend when onnxruntime or tokenizers are not installed (seconds to import)."""

from __future__ import annotations

import importlib.util
import os

import numpy as np

from .model_files import model_dir


def torch_installed() -> bool:
    """Whether sentence-transformers is importable."""
    return importlib.util.find_spec("sentence_transformers") is not None


class TorchBackend:
    """`encode_batch(texts) -> (N, 384) float32` unit rows from `SentenceTransformer.encode`."""

    kind = "torch"

    def __init__(self):
        os.environ["HF_HUB_OFFLINE"] = "1"
        os.environ["TRANSFORMERS_OFFLINE"] = "1"
        os.environ.setdefault("HF_HUB_DISABLE_PROGRESS_BARS", "1")  # no "Loading weights" bars on stderr
        os.environ.setdefault("TRANSFORMERS_VERBOSITY", "error")
        from sentence_transformers import SentenceTransformer

        self.model = SentenceTransformer(str(model_dir()), device="cpu")
        dim = getattr(self.model, "get_embedding_dimension", None) or self.model.get_sentence_embedding_dimension
        self.dim = int(dim())

    def encode_batch(self, texts: list[str]) -> np.ndarray:
        """(N, dim) float32 rows, in the order of `texts`."""
        vecs = self.model.encode(list(texts), batch_size=64, convert_to_numpy=True,
                                 normalize_embeddings=True, show_progress_bar=False)
        return np.asarray(vecs, dtype=np.float32).reshape(len(texts), self.dim)
