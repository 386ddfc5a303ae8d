import asyncio

import pytest

from iesm_agent.errors import ProviderError
from iesm_agent.providers import ChatOptions, Completion, FunctionModel, Message, Usage

ASK = [Message(role="user", content="the lamp")]


def test_sync_function_gets_messages_and_options():
    seen = []

    def fn(messages, options):
        seen.append((messages, options))
        return f"{messages[0].text()} @ {options.temperature}"

    model = FunctionModel(fn, name="lamp-fn")
    out = model.complete(ASK, ChatOptions(temperature=0.3))
    assert out.text == "the lamp @ 0.3" and out.model == "lamp-fn" and out.latency_ms >= 0
    assert seen[0][0] == ASK and model.calls == 1
    assert model.complete(ASK).text == "the lamp @ 0.0"  # options default to ChatOptions()


async def test_async_function_and_full_completion():
    async def fn(messages, options):
        await asyncio.sleep(0.01)
        return Completion(text="x", model="custom", usage=Usage(prompt_tokens=4, completion_tokens=1))

    out = await FunctionModel(fn).acomplete(ASK)
    assert out.model == "custom" and out.usage.total_tokens == 5 and out.latency_ms >= 10


async def test_errors_propagate_and_bad_returns_are_type_errors():
    def fail(messages, options):
        raise ProviderError("down", "fn", retryable=True)

    with pytest.raises(ProviderError, match="down"):
        await FunctionModel(fail).acomplete(ASK)
    with pytest.raises(TypeError, match="expected str or Completion"):
        await FunctionModel(lambda m, o: 42).acomplete(ASK)


def test_cache_identity_distinguishes_functions():
    def a(messages, options):
        return "a"

    def b(messages, options):
        return "b"

    assert FunctionModel(a).cache_identity() != FunctionModel(b).cache_identity()
    assert FunctionModel(a).cache_identity() == FunctionModel(a).cache_identity()
