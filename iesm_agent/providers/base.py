"""The provider protocol: chat messages in, one completion out, sync and async.

A `Model` is named by a string such as `offline`, `openai:gpt-4o-mini` or
`ollama:llama3.1`; see `iesm_agent.providers.get_model`.
"""

from __future__ import annotations

import asyncio
from abc import ABC, abstractmethod
from typing import Any, Literal, Optional, Union

from pydantic import BaseModel, ConfigDict, Field


class TextPart(BaseModel):
    type: Literal["text"] = "text"
    text: str


class ImagePart(BaseModel):
    """An image given inline: base64 `data` with its `mime_type` (e.g. image/png)."""

    type: Literal["image"] = "image"
    data: str
    mime_type: str = "image/png"


class Message(BaseModel):
    role: Literal["system", "user", "assistant"]
    content: Union[str, list[Union[TextPart, ImagePart]]]

    def text(self) -> str:
        """The message's text, image parts left out."""
        if isinstance(self.content, str):
            return self.content
        return "\n".join(part.text for part in self.content if isinstance(part, TextPart))


class Usage(BaseModel):
    prompt_tokens: int = 0
    completion_tokens: int = 0

    @property
    def total_tokens(self) -> int:
        return self.prompt_tokens + self.completion_tokens


class Completion(BaseModel):
    """A model's reply. `latency_ms` is wall time of the call; `cached` is True when served by the cache."""

    text: str
    model: str
    usage: Usage = Field(default_factory=Usage)
    latency_ms: float = 0.0
    cached: bool = False


class Capabilities(BaseModel):
    vision: bool = False
    json_schema: bool = False
    tools: bool = False


class ChatOptions(BaseModel):
    """Per-call parameters. `json_schema` asks for structured output when the model supports it
    (the prompt must still say what JSON to return, for models that do not)."""

    model_config = ConfigDict(extra="forbid")

    temperature: float = 0.0
    max_tokens: Optional[int] = None
    json_schema: Optional[dict[str, Any]] = None
    seed: Optional[int] = None


class Model(ABC):
    """One chat model. Subclasses implement `acomplete`; `complete` is its sync twin."""

    #: the string naming this model, e.g. "offline" or "openai:gpt-4o-mini"
    name: str = "model"
    capabilities: Capabilities = Capabilities()
    #: whether a response cache pays off (False for models that answer locally faster than a
    #: cache lookup, such as the offline model); `get_model` never wraps those in a cache
    cacheable: bool = True

    @abstractmethod
    async def acomplete(self, messages: list[Message], options: ChatOptions | None = None) -> Completion:
        """Answer `messages`; raise `iesm_agent.errors.ProviderError` on failure."""

    def complete(self, messages: list[Message], options: ChatOptions | None = None) -> Completion:
        """Synchronous `acomplete` in a fresh event loop, with `aclose` before returning so no
        connection outlives its loop (must not be called from a running event loop)."""
        async def once() -> Completion:
            try:
                return await self.acomplete(messages, options)
            finally:
                await self.aclose()
        return asyncio.run(once())

    def cache_identity(self) -> dict[str, Any]:
        """What, besides messages and options, determines this model's replies (for cache keys)."""
        return {"model": self.name}

    async def aprompt_limit(self, options: ChatOptions | None = None) -> int | None:
        """Tokens a prompt may take (context window less room for the reply), None when there
        is no known limit (the default)."""
        return None

    def estimate_tokens(self, messages: list[Message]) -> int:
        """Tokens `messages` will take (an estimate, rounded up, for `aprompt_limit`)."""
        from .endpoint import estimate_tokens  # endpoint imports this module

        return estimate_tokens(messages)

    async def aclose(self) -> None:
        """Release connections (the model stays usable and reconnects lazily); a no-op by default."""


class WrappedModel(Model):
    """A model that adds something around `inner` (a response cache, a prompt recorder, a worker
    pool): name, capabilities, cacheability, cache identity, prompt limit, token estimate and
    closing are the inner model's. Subclasses implement `acomplete`."""

    def __init__(self, inner: Model):
        self.inner = inner
        self.name = inner.name
        self.capabilities = inner.capabilities
        self.cacheable = inner.cacheable

    def cache_identity(self) -> dict[str, Any]:
        return self.inner.cache_identity()

    async def aprompt_limit(self, options: ChatOptions | None = None) -> int | None:
        return await self.inner.aprompt_limit(options)

    def estimate_tokens(self, messages: list[Message]) -> int:
        return self.inner.estimate_tokens(messages)

    async def aclose(self) -> None:
        await self.inner.aclose()
