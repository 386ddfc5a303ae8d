"""OpenAI-compatible client against a real HTTP server on loopback (no mocks).

Fault outcomes: 5xx / 429 / slow -> retried (request counts asserted); 401, 404, non-JSON body,
no choices, no content -> ProviderError at once; a reply that is not the requested JSON -> the
text comes back unchanged for the caller's parser; 400 on response_format -> one resend without it.
"""

import asyncio
import base64
import gc
import time

import pytest

from iesm_agent.errors import ProviderError
from iesm_agent.providers import ChatOptions, FunctionModel, ImagePart, Message, TextPart
from iesm_agent.providers.jsonreply import JsonReplyError, parse_json_reply
from loopback import Fault, LoopbackServer
from iesm_agent.providers.openai_compat import OpenAICompatModel, parse_retry_after

USER = [Message(role="system", content="be brief"), Message(role="user", content="where is the mug?")]


def echo(messages, options):
    return f"echo: {messages[-1].text()}"


def client(server, **kw):
    kw.setdefault("timeout", 2.0)
    kw.setdefault("backoff_s", 0.001)
    return OpenAICompatModel("test-model", base_url=server.base_url, **kw)


async def test_round_trip_body_usage_and_counters():
    def answer(messages, options):
        from iesm_agent.providers import Completion, Usage
        return Completion(text=echo(messages, options), model="inner",
                          usage=Usage(prompt_tokens=11, completion_tokens=3))

    with LoopbackServer(FunctionModel(answer)) as server:
        model = client(server, api_key="sk-test")
        out = await model.acomplete(USER, ChatOptions(temperature=0.2, max_tokens=50, seed=7))
        await model.acomplete(USER)
        await model.aclose()
    assert out.text == "echo: where is the mug?"
    assert out.model == "openai-compat:test-model" and not out.cached and out.latency_ms > 0
    assert (out.usage.prompt_tokens, out.usage.completion_tokens) == (11, 3)
    body = server.requests[0].body
    assert body["model"] == "test-model" and body["temperature"] == 0.2
    assert body["max_tokens"] == 50 and body["seed"] == 7 and "response_format" not in body
    assert body["messages"] == [{"role": "system", "content": "be brief"},
                                {"role": "user", "content": "where is the mug?"}]
    assert server.requests[0].headers["authorization"] == "Bearer sk-test"
    assert "max_tokens" not in server.requests[1].body
    assert model.stats() == {"calls": 2, "retries": 0, "failures": 0,
                             "prompt_tokens": 22, "cached_tokens": 0, "completion_tokens": 6}


async def test_images_travel_as_data_urls():
    seen = {}

    def look(messages, options):
        seen["parts"] = messages[0].content
        return "a red mug"

    png = base64.b64encode(b"\x89PNG fake").decode()
    msg = Message(role="user", content=[TextPart(text="what colour?"),
                                        ImagePart(data=png, mime_type="image/png")])
    with LoopbackServer(FunctionModel(look)) as server:
        model = client(server)
        assert (await model.acomplete([msg])).text == "a red mug"
        await model.aclose()
    wire = server.requests[0].body["messages"][0]["content"]
    assert wire[1] == {"type": "image_url", "image_url": {"url": f"data:image/png;base64,{png}"}}
    assert seen["parts"][1] == ImagePart(data=png, mime_type="image/png")


async def test_json_schema_sent_as_response_format():
    schema = {"title": "ranking reply", "type": "object",
              "properties": {"ranked_instance_ids": {"type": "array"}}}
    seen = {}

    def reply(messages, options):
        seen["schema"] = options.json_schema
        return '{"ranked_instance_ids": [1]}'

    with LoopbackServer(FunctionModel(reply)) as server:
        model = client(server)
        await model.acomplete(USER, ChatOptions(json_schema=schema))
        await model.aclose()
    fmt = server.requests[0].body["response_format"]
    assert fmt == {"type": "json_schema", "json_schema": {"name": "ranking_reply", "schema": schema}}
    assert seen["schema"] == schema


async def test_5xx_is_retried_then_succeeds():
    with LoopbackServer(FunctionModel(echo), faults=[500, 503]) as server:
        model = client(server)
        out = await model.acomplete(USER)
        await model.aclose()
    assert out.text == "echo: where is the mug?"
    assert [r.status for r in server.requests] == [500, 503, 200]
    assert (model.retries, model.failures) == (2, 0)


async def test_persistent_5xx_gives_up_after_max_retries():
    with LoopbackServer(FunctionModel(echo), faults=[500] * 10) as server:
        model = client(server, max_retries=2)
        with pytest.raises(ProviderError) as info:
            await model.acomplete(USER)
        await model.aclose()
    err = info.value
    assert server.request_count == 3
    assert err.status == 500 and err.retryable
    assert server.base_url in str(err) and "gave up after 3 attempts" in str(err)
    assert (model.retries, model.failures) == (2, 1)


async def test_429_retry_after_is_honoured():
    with LoopbackServer(FunctionModel(echo), faults=[Fault.rate_limited(0.3)]) as server:
        model = client(server, backoff_s=0.0)
        started = time.perf_counter()
        out = await model.acomplete(USER)
        waited = server.requests[1].started - server.requests[0].finished
        await model.aclose()
    assert out.text.startswith("echo")
    assert server.request_count == 2 and waited >= 0.29
    assert time.perf_counter() - started >= 0.3


async def test_retry_after_is_capped():
    with LoopbackServer(FunctionModel(echo), faults=[Fault.rate_limited(3600)]) as server:
        model = client(server, retry_after_max_s=0.05)
        await model.acomplete(USER)
        await model.aclose()
    assert server.requests[1].started - server.requests[0].finished < 1.0


async def test_slow_reply_times_out_and_is_retried():
    with LoopbackServer(FunctionModel(echo), faults=[Fault.slow(1.0)]) as server:
        model = client(server, timeout=0.3)
        out = await model.acomplete(USER)
        await model.aclose()
    assert out.text.startswith("echo") and server.request_count == 2 and model.retries == 1


async def test_always_slow_raises_timeout_error():
    with LoopbackServer(FunctionModel(echo), faults=[Fault.slow(1.0)] * 3) as server:
        model = client(server, timeout=0.2, max_retries=1)
        with pytest.raises(ProviderError, match="timeout") as info:
            await model.acomplete(USER)
        await model.aclose()
    assert info.value.retryable and server.request_count == 2


@pytest.mark.parametrize("fault, phrase", [
    ("non_json", "not JSON"),
    ("no_choices", "no choices"),
    ("no_content", "no message content"),
    (Fault.http(401), "access refused"),
    (Fault.http(404), "'test-model'"),
    (Fault.http(422), "HTTP 422"),
])
async def test_unretryable_faults_raise_at_once(fault, phrase):
    with LoopbackServer(FunctionModel(echo), faults=[fault]) as server:
        model = client(server, api_key="sk-x", key_hint="$MY_KEY")
        with pytest.raises(ProviderError) as info:
            await model.acomplete(USER)
        await model.aclose()
    assert server.request_count == 1 and not info.value.retryable
    assert phrase in str(info.value) and server.base_url + "/chat/completions" in str(info.value)
    if "refused" in phrase:
        assert "$MY_KEY" in str(info.value) and "sk-x" not in str(info.value)


async def test_reply_that_is_not_json_is_returned_unchanged():
    with LoopbackServer(FunctionModel(echo), faults=[Fault.bad_reply("I think it's the mug.")]) as server:
        model = client(server)
        out = await model.acomplete(USER, ChatOptions(json_schema={"type": "object"}))
        await model.aclose()
    assert out.text == "I think it's the mug." and server.request_count == 1
    with pytest.raises(JsonReplyError):
        parse_json_reply(out.text)


async def test_rejected_response_format_falls_back_to_prompted_json():
    opts = ChatOptions(json_schema={"type": "object"})
    with LoopbackServer(FunctionModel(echo),
                        faults=lambda i, body: "reject_response_format") as server:
        model = client(server)
        first = await model.acomplete(USER, opts)
        second = await model.acomplete(USER, opts)
        await model.aclose()
    assert first.text == second.text == "echo: where is the mug?"
    assert [(r.body.get("response_format", {}).get("type"), r.status) for r in server.requests] == [
        ("json_schema", 400), ("json_object", 400), (None, 200), (None, 200)]
    assert model.dialect == "prompt" and model.retries == 0


async def test_400_without_response_format_is_not_retried():
    with LoopbackServer(FunctionModel(echo), faults=[Fault.http(400)]) as server:
        model = client(server)
        with pytest.raises(ProviderError, match="HTTP 400"):
            await model.acomplete(USER, ChatOptions(json_schema={"type": "object"}))
        await model.aclose()
    assert server.request_count == 1 and model.dialect == "json_schema"


async def test_connection_refused_is_reported_at_once():
    with LoopbackServer(FunctionModel(echo)) as server:
        url = server.base_url
    model = OpenAICompatModel("m", base_url=url, timeout=1.0, max_retries=2, backoff_s=1.0)
    with pytest.raises(ProviderError, match="connection failed.*is the server running") as info:
        await model.acomplete(USER)
    await model.aclose()
    assert not info.value.retryable and model.retries == 0 and model.failures == 1
    assert url in str(info.value)


async def test_concurrency_limit_is_honoured():
    with LoopbackServer(FunctionModel(echo), delay_s=0.1) as server:
        model = client(server, concurrency=2)
        outs = await asyncio.gather(*(model.acomplete(USER) for _ in range(6)))
        await model.aclose()
    assert len(outs) == 6 and server.request_count == 6
    assert server.max_in_flight == 2


async def test_requests_overlap_up_to_the_limit():
    with LoopbackServer(FunctionModel(echo), delay_s=0.2) as server:
        model = client(server, concurrency=8)
        await asyncio.gather(*(model.acomplete(USER) for _ in range(5)))
        first = server.max_in_flight
        await asyncio.gather(*(model.acomplete(USER) for _ in range(5)))
        await model.aclose()
    # the first call of a new endpoint goes alone (it negotiates), the four others overlap; once
    # the endpoint is known, all five do
    assert first == 4 and server.max_in_flight == 5


def test_sync_calls_each_get_a_working_client():
    with LoopbackServer(FunctionModel(echo)) as server:
        model = client(server)
        assert model.complete(USER).text == model.complete(USER).text == "echo: where is the mug?"
    assert server.request_count == 2 and model._client is None


def test_parse_retry_after():
    assert parse_retry_after("7") == 7.0
    assert parse_retry_after(" 0.5 ") == 0.5
    assert parse_retry_after("-3") == 0.0
    now = 1_700_000_000.0
    assert parse_retry_after("Tue, 14 Nov 2023 22:13:40 GMT", now=now) == pytest.approx(20.0)
    assert parse_retry_after("Tue, 14 Nov 2023 22:00:00 GMT", now=now) == 0.0
    assert parse_retry_after(None) is None and parse_retry_after("soon") is None


def test_bad_construction_names_the_field():
    from iesm_agent.errors import IesmError
    with pytest.raises(IesmError, match="base_url"):
        OpenAICompatModel("m", base_url="localhost:8000")
    with pytest.raises(IesmError, match="concurrency"):
        OpenAICompatModel("m", base_url="http://x", concurrency=0)
    with pytest.raises(IesmError, match="timeout"):
        OpenAICompatModel("m", base_url="http://x", timeout=0)


@pytest.mark.filterwarnings("ignore::pytest.PytestUnraisableExceptionWarning")
def test_client_from_an_ended_event_loop_is_replaced():
    """Without `aclose` the first loop's sockets leak until garbage collection (warned
    about, collected here); the model itself keeps working."""
    with LoopbackServer(FunctionModel(echo)) as server:
        model = client(server)
        first = asyncio.run(model.acomplete(USER))  # no aclose: the client outlives its loop
        stale = model._client

        async def again():
            try:
                return await model.acomplete(USER)
            finally:
                await model.aclose()

        second = asyncio.run(again())
    assert first.text == second.text and stale is not None and model._client is None
    assert server.request_count == 2
    del stale
    gc.collect()
