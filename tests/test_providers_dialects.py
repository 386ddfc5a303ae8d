"""Structured-output dialects and context windows against the loopback server's imitation of
each real server (vLLM, LM Studio, llama-cpp-python, llama.cpp, Ollama): what is sent, what is
remembered, what is never sent."""

import json

import httpx
import pytest

from iesm_agent.errors import ProviderError
from iesm_agent.providers import ChatOptions, FunctionModel, Message, get_model
from iesm_agent.providers.endpoint import ContextOverflowError, context_error, estimate_tokens
from loopback import LoopbackServer, count_tokens
from iesm_agent.providers.ollama import DEFAULT_NUM_CTX, OllamaModel
from iesm_agent.providers.openai_compat import OpenAICompatModel

SCHEMA = {"title": "ranking reply", "type": "object",
          "properties": {"ranked_instance_ids": {"type": "array", "items": {"type": "integer"}}}}
SHORT = [Message(role="user", content="rank the mugs")]


def long_prompt(chars: int) -> list[Message]:
    return [Message(role="system", content="rank"),
            Message(role="user", content=("{\"id\": 12, \"label\": \"mug\"}\n" * (chars // 29 + 1))[:chars])]


def schema_echo(seen):
    def answer(messages, options):
        seen.append(options.json_schema)
        return '{"ranked_instance_ids": [1]}'
    return answer


def client(server, **kw):
    kw.setdefault("timeout", 5.0)
    kw.setdefault("backoff_s", 0.001)
    return OpenAICompatModel("m", base_url=server.base_url, **kw)


def formats(server):
    return [((r.body.get("response_format") or {}).get("type"), r.status) for r in server.requests]


@pytest.mark.parametrize("flavour, first, dialect", [
    ("openai", [("json_schema", 200)], "json_schema"),
    ("vllm", [("json_schema", 200)], "json_schema"),
    ("lmstudio", [("json_schema", 200)], "json_schema"),
    ("llama.cpp", [("json_schema", 200)], "json_schema"),
    ("llama-cpp-python", [("json_schema", 500), ("json_object", 200)], "json_object"),
])
async def test_dialect_is_negotiated_and_remembered_per_endpoint(flavour, first, dialect):
    seen = []
    with LoopbackServer(FunctionModel(schema_echo(seen)), flavour=flavour) as server:
        model = client(server, max_retries=4)
        out = await model.acomplete(SHORT, ChatOptions(json_schema=SCHEMA))
        await model.acomplete(SHORT, ChatOptions(json_schema=SCHEMA))
        await model.aclose()
        again = client(server)  # a new instance for the same endpoint: no second negotiation
        await again.acomplete(SHORT, ChatOptions(json_schema=SCHEMA))
        await again.aclose()
    assert out.text == '{"ranked_instance_ids": [1]}'
    assert formats(server) == first + [(dialect, 200)] * 2
    assert model.dialect == again.dialect == dialect
    assert model.retries == 0 and model.failures == 0  # a rejection is no fault to retry
    assert seen == [SCHEMA] * 3  # the schema reached the model in either dialect


async def test_llama_cpp_python_500_names_response_format_and_is_not_retried():
    with LoopbackServer(FunctionModel(lambda m, o: "{}"), flavour="llama-cpp-python") as server:
        model = client(server, max_retries=4)
        await model.acomplete(SHORT, ChatOptions(json_schema=SCHEMA))
        await model.aclose()
    rejected = server.requests[0]
    assert rejected.status == 500 and server.request_count == 2
    assert model.facts.rejections[0].startswith("json_schema: HTTP 500")
    assert "response_format" in model.facts.rejections[0]


async def test_lm_studio_rejection_of_json_object_falls_through_to_prompted_json():
    # an endpoint already off json_schema (say a proxy rejected it) meets LM Studio's refusal
    with LoopbackServer(FunctionModel(lambda m, o: "{}"), flavour="lmstudio") as server:
        model = client(server)
        model.facts.dialect = "json_object"
        await model.acomplete(SHORT, ChatOptions(json_schema=SCHEMA))
        await model.aclose()
    assert formats(server) == [("json_object", 400), (None, 200)] and model.dialect == "prompt"


async def test_plain_http_errors_still_fail_without_changing_the_dialect():
    with LoopbackServer(FunctionModel(lambda m, o: "{}"), faults=[404]) as server:
        model = client(server)
        with pytest.raises(ProviderError, match="HTTP 404"):
            await model.acomplete(SHORT, ChatOptions(json_schema=SCHEMA))
        await model.aclose()
    assert model.dialect == "json_schema" and server.request_count == 1


@pytest.mark.parametrize("flavour, source", [("vllm", "models"), ("llama.cpp", "props")])
async def test_window_is_read_from_the_server(flavour, source):
    with LoopbackServer(FunctionModel(lambda m, o: "ok"), flavour=flavour,
                        context_window=3000) as server:
        model = client(server)
        assert await model.aprompt_limit() == 3000 - 512
        assert await model.aprompt_limit(ChatOptions(max_tokens=100)) == 2900
        await model.aclose()
    assert (model.facts.window, model.facts.window_source) == (3000, source)


async def test_unknown_window_and_user_setting():
    with LoopbackServer(FunctionModel(lambda m, o: "ok"), flavour="openai") as server:
        model = client(server)
        assert await model.aprompt_limit() is None
        await model.aclose()
        probes = len(server.probes)
        set_by_user = OpenAICompatModel("other", base_url=server.base_url, context_window=1000)
        assert await set_by_user.aprompt_limit() == 488 and set_by_user.facts.window_source == "setting"
        await set_by_user.aclose()
    # /v1/models and /props once per endpoint; a window set by the user is kept (the probe
    # still asks for the server's slots)
    assert probes == 2 and len(server.probes) == 4 and set_by_user.facts.window == 1000


async def test_prompt_over_a_known_window_is_never_sent():
    with LoopbackServer(FunctionModel(lambda m, o: "ok"), flavour="vllm", context_window=1024) as server:
        model = client(server)
        with pytest.raises(ContextOverflowError, match="does not fit the context window of 1024") as info:
            await model.acomplete(long_prompt(4000))
        ok = await model.acomplete(long_prompt(500))
        await model.aclose()
    assert info.value.estimated and not info.value.retryable and info.value.window == 1024
    assert server.request_count == 1 and ok.usage.prompt_tokens <= 1024
    assert model.failures == 1 and model.retries == 0


@pytest.mark.parametrize("flavour", ["llama-cpp-python", "llama.cpp", "lmstudio"])
async def test_server_refusal_teaches_the_window(flavour):
    with LoopbackServer(FunctionModel(lambda m, o: "ok"), flavour=flavour,
                        context_window=1500) as server:
        model = client(server, probe_window=False)
        with pytest.raises(ContextOverflowError, match="1500 tokens") as first:
            await model.acomplete(long_prompt(8000))
        with pytest.raises(ContextOverflowError, match="not sent") as second:
            await model.acomplete(long_prompt(8000))
        await model.aclose()
    assert not first.value.estimated and first.value.status == 400
    assert first.value.prompt_tokens == server.requests[0].prompt_tokens
    assert second.value.estimated and server.request_count == 1 and model.retries == 0
    assert (model.facts.window, model.facts.window_source) == (1500, "error")


async def test_estimate_is_calibrated_by_the_servers_usage():
    messages = long_prompt(6000)
    with LoopbackServer(FunctionModel(lambda m, o: "ok")) as server:
        model = client(server)
        before = model.estimate_tokens(messages)
        await model.acomplete(messages)
        after = model.estimate_tokens(messages)
        await model.aclose()
    true = count_tokens(messages)  # the loopback's tokenizer: 4 characters a token
    assert before > true * 1.2  # the uncalibrated guess errs towards shrinking
    assert true <= after <= true * 1.2


def test_context_error_wordings():
    assert context_error("Requested tokens (3012) exceed context window of 2048") == (3012, 2048)
    assert context_error("This model's maximum context length is 4096 tokens. However, you "
                         "requested 5000 tokens (4900 in the messages, 100 in the completion).") == (5000, 4096)
    assert context_error('{"error": {"n_prompt_tokens": 9000, "n_ctx": 8192}}') == (9000, 8192)
    assert context_error("HTTP 500: model failed") is None
    assert estimate_tokens([Message(role="user", content='{"id": 3} chair')], 1.0) == 8 + 6


async def test_ollama_native_api_sets_num_ctx_and_format():
    seen = []
    with LoopbackServer(FunctionModel(schema_echo(seen)), flavour="ollama",
                        model_context_length=8192) as server:
        model = get_model("ollama:gemma3", base_url=server.base_url)  # a /v1 URL works too
        out = await model.acomplete(SHORT, ChatOptions(json_schema=SCHEMA, seed=3))
        await model.aclose()
    assert isinstance(model, OllamaModel) and model.endpoint == f"{server.root_url}/api/chat"
    body = server.requests[0].body
    assert body["format"] == SCHEMA and body["stream"] is False
    assert body["options"]["num_ctx"] == 8192 < DEFAULT_NUM_CTX  # capped by /api/show
    assert body["options"]["seed"] == 3
    assert out.text == '{"ranked_instance_ids": [1]}' and seen == [SCHEMA]
    assert out.usage.prompt_tokens == server.requests[0].prompt_tokens > 0
    assert model.facts.window_source == "api/show" and "/api/show" in server.probes


async def test_ollama_never_gets_a_prompt_it_would_cut():
    with LoopbackServer(FunctionModel(lambda m, o: "ok"), flavour="ollama") as server:
        model = OllamaModel("gemma3", base_url=server.root_url, context_window=2048)
        with pytest.raises(ContextOverflowError, match="not sent"):
            await model.acomplete(long_prompt(12000))
        await model.acomplete(long_prompt(2000))
        await model.aclose()
        # the imitation does cut silently what a client sends without num_ctx
        async with httpx.AsyncClient() as raw:
            await raw.post(f"{server.root_url}/api/chat", json={
                "model": "gemma3", "stream": False,
                "messages": [{"role": "user", "content": long_prompt(12000)[1].text()}]})
    assert [(r.body["options"].get("num_ctx") if "options" in r.body else None, r.truncated)
            for r in server.requests] == [(2048, False), (None, True)]


async def test_dead_endpoint_fails_fast():
    with LoopbackServer(FunctionModel(lambda m, o: "ok")) as server:
        url = server.base_url
    model = OpenAICompatModel("m", base_url=url, max_retries=4, backoff_s=2.0)
    with pytest.raises(ProviderError, match="is the server running"):
        await model.acomplete(SHORT, ChatOptions(json_schema=SCHEMA))
    await model.aclose()
    assert model.retries == 0 and await model.aprompt_limit() is None


def test_one_query_negotiates_once_and_its_trace_says_why():
    """Five concurrent structured calls of one MTEFR query (gate and four experts: no spatial
    relation) to a server that refuses
    `json_schema`: one refusal in all (the first call negotiates while the others wait), and the
    call that met it says why in its trace and in the result's notes."""
    from iesm_agent.providers.offline import OfflineModel
    from iesm_agent.retrieval import Retriever
    from iesm_agent.store import MapStore, open_map

    with LoopbackServer(OfflineModel(use_embeddings=False), flavour="llama-cpp-python") as server:
        retriever = Retriever(MapStore(open_map("apartment")), provider=client(server))
        res = retriever.ask("the grey fabric sofa")
    assert formats(server).count(("json_schema", 500)) + formats(server).count(("json_schema", 400)) == 1
    assert [f for f, _ in formats(server)].count("json_object") == 5 and res.failed_calls == 0
    noted = [c for c in res.calls if c.notes]
    assert len(noted) == 1 and "refused structured output as json_schema" in noted[0].notes[0]
    assert "response_format" in noted[0].notes[0] or "json_schema" in noted[0].notes[0].split("(", 1)[1]
    assert any("sent again as json_object" in n for n in res.notes)
    assert all(c.max_tokens and 0 < c.max_tokens <= 300 for c in res.calls)


def test_string_lengths_bound_the_reply_but_are_not_sent():
    """`maxLength` sets the reply's `max_tokens` and the validator's cut, but is left out of the
    schema on the wire (grammar engines sample far slower inside a length-bounded string)."""
    from iesm_agent import contract

    schema = contract.ranking_schema(2)
    assert schema["properties"]["abstain"]["maxLength"] == contract.ABSTAIN_CHARS
    seen = []
    with LoopbackServer(FunctionModel(schema_echo(seen)), flavour="llama-cpp-python") as server:
        model = client(server)
        model.complete(SHORT, ChatOptions(json_schema=schema, max_tokens=contract.max_reply_tokens(schema)))
    sent = [r.body for r in server.requests if "response_format" in r.body][-1]
    assert "maxLength" not in json.dumps(sent) and sent["max_tokens"] == contract.max_reply_tokens(schema)
    assert sent["response_format"]["schema"]["properties"]["ranked_instance_ids"]["maxItems"] == 2


def test_a_dialect_set_by_the_user_is_not_negotiated():
    with LoopbackServer(FunctionModel(lambda m, o: '{"ranked_instance_ids": [1]}'), flavour="vllm") as server:
        model = client(server, dialect="prompt")
        model.complete(SHORT, ChatOptions(json_schema=SCHEMA, max_tokens=20))
    assert formats(server) == [(None, 200)] and server.requests[0].body["max_tokens"] == 20
    with pytest.raises(ProviderError.__mro__[1], match="dialect must be one of"):
        client(server, dialect="xml")
