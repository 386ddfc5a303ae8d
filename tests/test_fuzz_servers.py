"""Model servers that misbehave (issue #31, defects 3 and 4): every call ends within its
deadline with a one-line `ProviderError` (or a clean reply), reads at most `MAX_REPLY_BYTES`,
and never raises anything else. The deadlines here are short so the suite stays fast; the
defaults (60 s) are the same code."""

from __future__ import annotations

import time
import tracemalloc

import pytest
from hostile import SCENARIOS, HostileServer, bomb, normal, trickle

from iesm_agent.config import RetrievalConfig
from iesm_agent.errors import ProviderError
from iesm_agent.providers import ChatOptions, Message
from iesm_agent.providers.openai_compat import DEFAULT_DEADLINE_S, OpenAICompatModel
from iesm_agent.retrieval import Retriever
from iesm_agent.store import MapStore, open_map

DEADLINE = 2.0
PROMPT = [Message(role="user", content="where is the mug?")]
#: what each scenario must end in: an error matching the pattern, or None for a usable reply
EXPECTED = {
    "endless body": "longer than", "gzip bomb": "longer than", "trickle": "deadline",
    "huge length": "refused", "503 retry-after 9999": "not retried", "429 retry-after 999999": "not retried",
    "deep /models": None, "deep reply": "too deep", "endless /models": None, "lone surrogates": None,
}


def model_for(base_url: str, **kw) -> OpenAICompatModel:
    kw = {"timeout": 1.0, "deadline": DEADLINE, "max_retries": 2, **kw}
    return OpenAICompatModel("hostile", base_url=base_url, **kw)


@pytest.mark.parametrize("name", sorted(SCENARIOS))
async def test_a_misbehaving_server_costs_one_deadline_and_bounded_memory(name):
    bomb()  # made before the clock starts
    with HostileServer(SCENARIOS[name]) as base_url:
        model = model_for(base_url)
        tracemalloc.start()
        started = time.monotonic()
        try:
            out = await model.acomplete(PROMPT, ChatOptions(max_tokens=32))
            error = None
        except ProviderError as exc:
            error, out = exc, None
        finally:
            took = time.monotonic() - started
            peak = tracemalloc.get_traced_memory()[1]
            tracemalloc.stop()
            await model.aclose()
    assert took < DEADLINE + 1.5, f"{name}: {took:.1f} s"
    # bounded by the cap plus one raw chunk inflated (gzip inflates at most ~1032x: 64 KiB ->
    # 66 MiB), whatever the body's size; the bound is 1 GB
    assert peak < 256 * 2**20, f"{name}: {peak / 2**20:.0f} MiB"
    if EXPECTED[name] is None:
        assert error is None and out is not None
        out.model_dump_json()  # lone surrogates would fail here
        assert "\ud800" not in out.text
    else:
        assert error is not None and EXPECTED[name] in str(error) and "\n" not in str(error)


async def test_after_a_stall_the_endpoint_is_not_asked_again_for_one_deadline():
    with HostileServer(trickle) as base_url:
        model = model_for(base_url)
        with pytest.raises(ProviderError, match="deadline"):
            await model.acomplete(PROMPT)
        started = time.monotonic()
        with pytest.raises(ProviderError, match="not sent"):
            await model.acomplete(PROMPT)
        assert time.monotonic() - started < 0.5
        await model.aclose()


def test_a_query_against_a_stalled_server_ends_by_its_deadline_with_recorded_failures():
    with HostileServer(trickle) as base_url:
        model = model_for(base_url, deadline=30.0)
        retriever = Retriever(MapStore(open_map("apartment")), provider=model,
                              config=RetrievalConfig(deadline_s=DEADLINE))
        started = time.monotonic()
        res = retriever.ask("the sofa")
    assert time.monotonic() - started < DEADLINE + 1.5
    assert res.failed_calls == len(res.calls) == 5 and res.instance_id is None  # gate + four experts
    assert all("deadline" in c.error for c in res.calls)


def test_the_default_deadline_is_one_minute():
    with HostileServer(normal) as base_url:
        assert OpenAICompatModel("m", base_url=base_url).deadline == DEFAULT_DEADLINE_S == 60.0
        assert OpenAICompatModel("m", base_url=base_url, timeout=600).deadline == 600.0
