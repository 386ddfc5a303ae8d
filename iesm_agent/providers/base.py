"""The provider protocol: chat messages in, one completion out, sync and async.

A `Model` is named by a string such as `offline`, `openai:gpt-4o-mini` or
`ollama:llama3.1`; see `iesm_agent.providers.get_model`.
"""

from __future__ import annotations

import asyncio
import math
import re
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
    """Tokens of one call: `prompt_tokens` the prompt as counted by the server, `cached_tokens`
    the part of it read from the server's prompt cache (not evaluated again; 0 when the server
    does not say), `completion_tokens` the reply."""

    prompt_tokens: int = 0
    cached_tokens: int = 0
    completion_tokens: int = 0

    @property
    def total_tokens(self) -> int:
        return self.prompt_tokens + self.completion_tokens


class Completion(BaseModel):
    """A model's reply. `latency_ms` is wall time of the call; `cached` is True when served by
    the cache; `truncated` when the reply stopped at the call's `max_tokens` (finish_reason
    "length"), so it is incomplete."""

    text: str
    model: str
    usage: Usage = Field(default_factory=Usage)
    latency_ms: float = 0.0
    cached: bool = False
    truncated: bool = False
    #: what the client did on the way that the trace should say (e.g. a refused dialect)
    notes: list[str] = Field(default_factory=list)


def clean_text(text: str) -> str:
    """`text` with lone surrogates (from JSON escapes such as "\\ud800") replaced by "?", so
    it can be encoded, printed and serialised."""
    try:
        text.encode("utf-8")
        return text
    except UnicodeEncodeError:
        return text.encode("utf-8", "replace").decode("utf-8")


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


#: tokens per text unit (a word or one punctuation character) assumed before a server has
#: reported usage. Units vary less with the kind of text than characters do: Gemma 3 counts
#: 0.84-1.08 tokens per unit over our prompts, 2.6-3.7 characters per token.
DEFAULT_TOKENS_PER_UNIT = 1.1
#: margin over the calibrated rate when checking that a prompt fits
ESTIMATE_MARGIN = 1.15
#: tokens added per message (role markers of chat templates) and per image part
MESSAGE_OVERHEAD_TOKENS = 6
IMAGE_TOKENS = 768

_UNIT = re.compile(r"\w+|[^\w\s]")


def text_units(messages: list[Message]) -> int:
    """Words and punctuation characters in the messages' text."""
    return sum(len(_UNIT.findall(m.text())) for m in messages)


def estimate_tokens(messages: list[Message],
                    tokens_per_unit: float = DEFAULT_TOKENS_PER_UNIT * ESTIMATE_MARGIN) -> int:
    """Tokens of `messages`: text units x `tokens_per_unit`, plus per-message and per-image
    overheads (rounded up)."""
    images = sum(isinstance(p, ImagePart) for m in messages if not isinstance(m.content, str)
                 for p in m.content)
    return (math.ceil(text_units(messages) * tokens_per_unit)
            + MESSAGE_OVERHEAD_TOKENS * len(messages) + IMAGE_TOKENS * images)


#: candidates sent to a model that reads prompts for nothing (the offline model): the paper's G
PAPER_CANDIDATES = 100
#: candidates sent to an LLM endpoint, whose prompt tokens cost time: the cheap pre-ranking
#: (`retrieval.candidates`) keeps an accepted instance among its first 15 for all 620 queries of
#: the shipped suites (0.990 at 10; `python benchmarks/candidate_budget.py`), and the offline
#: model predicts the same instance for each of them at 20 as at 100 (`iesm eval evals/*.jsonl
#: -m mtefr,spr --max-candidates 20`); Gemma 3 270M on two loaded cores read a 56-candidate MTEFR
#: prefix (8,172 tokens) in 264 s
LLM_CANDIDATES = 20


class Model(ABC):
    """One chat model. Subclasses implement `acomplete`; `complete` is its sync twin."""

    #: the string naming this model, e.g. "offline" or "openai:gpt-4o-mini"
    name: str = "model"
    capabilities: Capabilities = Capabilities()
    #: whether a response cache pays off (False for models that answer locally faster than a
    #: cache lookup, such as the offline model); `get_model` never wraps those in a cache
    cacheable: bool = True
    #: candidates a query sends to this model unless the user sets `max_candidates`
    candidate_budget: int = PAPER_CANDIDATES

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
        return estimate_tokens(messages)

    async def aparallel_calls(self) -> int | None:
        """Calls this model serves at once, None when not bounded or not known (the default). With
        1, a query's calls queue anyway, so MTEFR asks the gate first and uses its weights."""
        return None

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
        self.candidate_budget = inner.candidate_budget

    def cache_identity(self) -> dict[str, Any]:
        return self.inner.cache_identity()

    async def aprompt_limit(self, options: ChatOptions | None = None) -> int | None:
        return await self.inner.aprompt_limit(options)

    def estimate_tokens(self, messages: list[Message]) -> int:
        return self.inner.estimate_tokens(messages)

    async def aparallel_calls(self) -> int | None:
        return await self.inner.aparallel_calls()

    async def aclose(self) -> None:
        await self.inner.aclose()
