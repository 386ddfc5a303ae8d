"""The retriever against servers with small context windows (loopback imitations): the
candidate set is cut, best first, until every prompt fits; no prompt over the window is sent;
candidate recall is recorded for the cut set."""

import pytest

from iesm_agent.config import RetrievalConfig
from iesm_agent.providers import get_model
from loopback import LoopbackServer
from iesm_agent.providers.offline import OfflineModel
from iesm_agent.retrieval import Retriever

QUERY = "the white painted wooden chair in the kitchen"
#: every instance of the apartment map is a candidate (an HTTP model's own budget is smaller):
#: these tests are about the window
ALL = RetrievalConfig(max_candidates=100)


def offline_server(**kw):
    return LoopbackServer(OfflineModel(use_embeddings=False), **kw)


def full_prompt_tokens(apartment_store):
    """The largest prompt of an uncut MTEFR query, in the loopback's own tokens."""
    with offline_server() as server:
        model = get_model("openai-compat:m", base_url=server.base_url)
        result = Retriever(apartment_store, provider=model, config=ALL).ask(QUERY)
    assert result.failures == [] and result.candidates_before_fit is None
    return max(r.prompt_tokens for r in server.requests), len(result.candidate_ids)


@pytest.mark.parametrize("flavour", ["vllm", "llama.cpp"])
def test_known_window_cuts_the_candidate_set_before_sending(apartment_store, flavour):
    biggest, n_all = full_prompt_tokens(apartment_store)
    window = biggest // 2 + 512
    with offline_server(flavour=flavour, context_window=window) as server:
        model = get_model("openai-compat:m", base_url=server.base_url)
        result = Retriever(apartment_store, provider=model, config=ALL).ask(QUERY, target=result_target(apartment_store))
    assert result.failures == [] and all(c.error is None for c in result.calls)
    assert 1 <= len(result.candidate_ids) < n_all and result.candidates_before_fit == n_all
    assert result.candidate_recall is (result.target in result.candidate_ids)
    assert server.request_count == 5 and max(r.prompt_tokens for r in server.requests) <= window - 512
    assert result.instance_id in result.candidate_ids


def test_window_learnt_from_a_refusal_reruns_the_query_cut(apartment_store):
    biggest, n_all = full_prompt_tokens(apartment_store)
    window = biggest // 2 + 512
    with offline_server(flavour="llama-cpp-python", context_window=window) as server:
        model = get_model("openai-compat:m", base_url=server.base_url)
        retriever = Retriever(apartment_store, provider=model, config=ALL)
        first = retriever.ask(QUERY)
        sent_first = server.request_count
        second = retriever.ask(QUERY)
    refused = [r for r in server.requests if r.status == 400]
    assert refused and all(r.prompt_tokens > window for r in refused)
    assert first.failures == [] and first.candidates_before_fit == n_all
    assert second.failures == [] and second.candidates_before_fit == n_all
    assert server.request_count - sent_first == 5  # learnt: the second query is cut at once
    assert all(r.status == 200 for r in server.requests[sent_first:])


def test_a_window_too_small_for_one_candidate_fails_each_call_clearly(apartment_store):
    with offline_server(flavour="vllm", context_window=600) as server:
        model = get_model("openai-compat:m", base_url=server.base_url)
        result = Retriever(apartment_store, provider=model, config=ALL).ask(QUERY)
    assert server.request_count == 0 and result.instance_id is None
    assert len(result.candidate_ids) == 1
    assert all("does not fit the context window of 600 tokens" in c.error for c in result.calls)


def test_offline_and_unknown_windows_leave_the_set_alone(apartment_store):
    config = RetrievalConfig(max_candidates=10)
    with offline_server(flavour="openai") as server:
        model = get_model("openai-compat:m", base_url=server.base_url)
        result = Retriever(apartment_store, provider=model, config=config).ask(QUERY)
    offline = Retriever(apartment_store, provider=OfflineModel(use_embeddings=False), config=config).ask(QUERY)
    assert len(result.candidate_ids) == len(offline.candidate_ids) == 10
    assert result.candidates_before_fit is None and offline.candidates_before_fit is None


def result_target(store):
    """The instance the query means (the kitchen's chair)."""
    hits = [i for i in store.scene.instances if i.label == "chair" and (i.room_label or "") == "kitchen"]
    return hits[0].id if hits else None


def test_an_llm_endpoint_gets_its_candidate_budget_and_the_cut_is_reported(apartment_store):
    from iesm_agent.providers.base import LLM_CANDIDATES

    n_all = len(apartment_store.scene.instances)
    with offline_server() as server:
        model = get_model("openai-compat:m", base_url=server.base_url)
        res = Retriever(apartment_store, provider=model).ask("somewhere to sleep")
    assert len(res.candidate_ids) == LLM_CANDIDATES < n_all and res.candidates_cut == n_all - LLM_CANDIDATES
    assert f"{n_all - LLM_CANDIDATES} of {n_all} instances cut" in res.explain()
    offline = Retriever(apartment_store).ask("somewhere to sleep")  # reads prompts for nothing: all
    assert len(offline.candidate_ids) == n_all and offline.candidates_cut == 0
    assert res.instance_id == offline.instance_id
