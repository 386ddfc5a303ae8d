"""`embeddings.held_only`: within it the encoder answers from the rows it holds (memory or its
vector store) and refuses to embed a new text; outside it, it embeds as always."""

from __future__ import annotations

import asyncio
import threading

import numpy as np
import pytest

from iesm_agent.embeddings import HASH_SPACE, Encoder, EncodingNeeded, held_only, text_vectors
from iesm_agent.encoding.vector_store import VectorStore


class HashBackend:
    """An encoder backend over the hash space that records the thread of each batch it embeds."""

    kind, dim = "hash", 384

    def __init__(self) -> None:
        self.batches: list[tuple[str, list[str]]] = []

    def encode_batch(self, texts: list[str]) -> np.ndarray:
        self.batches.append((threading.current_thread().name, list(texts)))
        return text_vectors(list(texts), HASH_SPACE)[0]


def test_held_rows_are_answered_and_a_new_text_is_refused(tmp_path):
    backend = HashBackend()
    stored = Encoder(backend, VectorStore(tmp_path / "vectors.sqlite", HashBackend.dim))
    first = stored.encode(["a red chair", "a blue sofa"])
    assert len(backend.batches) == 1
    with held_only():
        again = stored.encode(["a blue sofa", "a red chair"])  # from memory
        with pytest.raises(EncodingNeeded, match="1 text"):
            stored.encode(["a red chair", "a green lamp"])
    assert np.array_equal(again, first[::-1])
    assert len(backend.batches) == 1  # nothing was embedded within held_only
    # a fresh encoder over the same store holds the stored rows, not the refused text
    fresh = Encoder(backend, VectorStore(tmp_path / "vectors.sqlite", HashBackend.dim))
    with held_only():
        assert np.array_equal(fresh.encode(["a red chair"]), first[:1])
    assert np.array_equal(fresh.encode(["a green lamp"]), text_vectors(["a green lamp"], HASH_SPACE)[0])
    assert backend.batches[-1][1] == ["a green lamp"]  # embedded once held_only was left


def test_held_only_holds_in_its_own_context_alone():
    """Tasks started within it inherit it; a task started outside it and the server's worker
    threads (`WorkerPool.run`: the executor does not copy the context) do not."""
    from iesm_agent.server.workers import WorkerPool

    encoder = Encoder(HashBackend())
    pool = WorkerPool(1)

    async def embed(text: str) -> str:
        try:
            encoder.encode([text])
            return "embedded"
        except EncodingNeeded:
            return "refused"

    async def run() -> tuple[str, str, str]:
        outside = asyncio.get_running_loop().create_task(embed("made outside"))
        with held_only():
            inside = await asyncio.gather(embed("made inside"))
            on_pool = await pool.run(asyncio.run, embed("on a worker"))
        return inside[0], on_pool, await outside

    try:
        assert asyncio.run(run()) == ("refused", "embedded", "embedded")
    finally:
        pool.shutdown()
