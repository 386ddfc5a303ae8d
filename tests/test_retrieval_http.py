"""MTEFR end to end over HTTP: the retriever talks to a real chat-completions server on loopback
(answering with the offline model), through retries, a garbage reply and a dead endpoint."""

import json

from iesm_agent.providers import get_model
from loopback import Fault, LoopbackServer
from iesm_agent.providers.offline import OfflineModel
from iesm_agent.retrieval import Retriever

QUERY = "the white painted wooden chair in the kitchen"


def _expert_of(body: dict) -> str | None:
    """Which expert a request is for, read from its focus line (None for the gate)."""
    text = json.dumps(body)
    for name, word in (("desc", "Description"), ("room", "Room"), ("abs", "Function")):
        if f"<focus>{word}" in text or f"\\u003cfocus\\u003e{word}" in text:
            return name
    return None


def test_same_answer_over_http_as_in_process(apartment_store):
    direct = Retriever(apartment_store, provider=OfflineModel(use_embeddings=False)).ask(QUERY)
    with LoopbackServer(OfflineModel(use_embeddings=False)) as server:
        model = get_model("openai-compat:offline", base_url=server.base_url, max_retries=2)
        remote = Retriever(apartment_store, provider=model).ask(QUERY)
        assert server.request_count == 5  # gate + four experts; the query states no spatial relation
    assert remote.instance_id == direct.instance_id and remote.failures == []
    assert remote.experts == direct.experts
    assert {c.name for c in remote.calls} == {"gate", "obj", "room", "desc", "abs"}
    assert "spatial: not asked (the query states no spatial relation, comparison, order or viewpoint)" in remote.notes


def test_retries_and_a_garbage_expert_reply_still_give_an_answer(apartment_store):
    seen: dict[str, int] = {}

    def faults(index, body):
        name = _expert_of(body)
        seen[name] = seen.get(name, 0) + 1
        if name == "room" and seen[name] == 1:
            return Fault.http(503)  # retried
        if name == "abs":
            return Fault.bad_reply("I think it is probably the chair, number twenty-four.")
        return None

    with LoopbackServer(OfflineModel(use_embeddings=False), faults=faults) as server:
        model = get_model("openai-compat:offline", base_url=server.base_url, max_retries=2)
        result = Retriever(apartment_store, provider=model).ask(QUERY)
    assert seen["room"] == 2
    assert result.instance_id is not None and result.label == "chair" and result.room == "kitchen"
    assert "abs" not in result.experts
    assert any(f.startswith("abs: unusable reply") for f in result.failures)


def test_dead_endpoint_is_recorded_not_raised(apartment_store):
    model = get_model("openai-compat:offline", base_url="http://127.0.0.1:9/v1", max_retries=0, timeout=0.5)
    result = Retriever(apartment_store, provider=model).ask(QUERY)
    assert result.instance_id is None
    assert len(result.calls) == 5 and all(c.error for c in result.calls)
    assert any("gate" in f for f in result.failures)
