"""`FunctionModel`: a `Model` whose replies come from a Python function (tests of callers)."""

from __future__ import annotations

import inspect
import time
from typing import Any, Awaitable, Callable, Union

from .base import Capabilities, ChatOptions, Completion, Message, Model

Reply = Union[str, Completion]
ReplyFn = Callable[[list[Message], ChatOptions], Union[Reply, Awaitable[Reply]]]


class FunctionModel(Model):
    """Answers with `fn(messages, options)`, a sync or async function returning the reply text
    or a full `Completion`. Exceptions from `fn` propagate unchanged, so a test can raise
    `ProviderError` to play a failing endpoint. `calls` counts invocations."""

    def __init__(self, fn: ReplyFn, name: str = "function", *,
                 capabilities: Capabilities | None = None):
        self.fn = fn
        self.name = name
        self.capabilities = capabilities or Capabilities(vision=True, json_schema=True)
        self.calls = 0

    async def acomplete(self, messages: list[Message], options: ChatOptions | None = None) -> Completion:
        options = options or ChatOptions()
        self.calls += 1
        started = time.perf_counter()
        reply = self.fn(messages, options)
        if inspect.isawaitable(reply):
            reply = await reply
        latency_ms = (time.perf_counter() - started) * 1000.0
        if isinstance(reply, Completion):
            return reply if reply.latency_ms else reply.model_copy(update={"latency_ms": latency_ms})
        if isinstance(reply, str):
            return Completion(text=reply, model=self.name, latency_ms=latency_ms)
        raise TypeError(f"FunctionModel {self.name!r}: fn returned {type(reply).__name__}, "
                        "expected str or Completion")

    def cache_identity(self) -> dict[str, Any]:
        fn = self.fn
        return {"model": self.name,
                "function": f"{getattr(fn, '__module__', '?')}.{getattr(fn, '__qualname__', repr(fn))}"}
