"""What a client learns about one inference endpoint, kept for the process per (base URL, model):
the structured-output dialect it accepts, its context window and how many characters make one
of its tokens. Every model instance for the same endpoint negotiates once.

Dialects, tried in this order (the first a server rejects is never sent to it again):

* `json_schema`: `response_format: {"type": "json_schema", "json_schema": {"name", "schema"}}`
  (OpenAI, vLLM, LM Studio, recent llama.cpp and Ollama /v1);
* `json_object`: `response_format: {"type": "json_object", "schema": ...}` (llama-cpp-python,
  llama.cpp's server);
* `prompt`: no `response_format`; the prompt alone asks for the JSON.

A rejection is an HTTP error (4xx or 5xx) to a request that carried `response_format`, whose
body names `response_format` or the schema. A context error is an error body saying the prompt
is longer than the window (llama-cpp-python, llama.cpp, vLLM and OpenAI wordings).
"""

from __future__ import annotations

import asyncio
import math
import re
from dataclasses import dataclass, field
from typing import Any, Literal, Optional

from ..errors import ProviderError
from .base import ImagePart, Message

Dialect = Literal["json_schema", "json_object", "prompt"]
DIALECTS: tuple[Dialect, ...] = ("json_schema", "json_object", "prompt")

#: characters per token assumed before the server has reported any usage (JSON-heavy prompts
#: run at 3-4 characters per token; the lower figure errs towards shrinking)
DEFAULT_CHARS_PER_TOKEN = 3.0
#: tokens added per message (role markers of chat templates) and per image part
MESSAGE_OVERHEAD_TOKENS = 6
IMAGE_TOKENS = 768
#: tokens kept free for the reply when checking that a prompt fits (unless max_tokens is set)
REPLY_RESERVE_TOKENS = 512

_REJECTION = re.compile(r"response_format|json_schema|\bschema\b", re.IGNORECASE)
_CONTEXT_ERRORS = (
    # llama-cpp-python: "Requested tokens (3012) exceed context window of 2048"
    (re.compile(r"Requested tokens \((\d+)\) exceed context window of (\d+)"), 1, 2),
    # vLLM / OpenAI: "maximum context length is 2048 tokens. However, you requested 3000 tokens"
    (re.compile(r"maximum context length is (\d+) tokens.*?(?:requested|resulted in) (\d+) tokens",
                re.IGNORECASE | re.DOTALL), 2, 1),
    # llama.cpp server: {"type": "exceed_context_size_error", "n_prompt_tokens": N, "n_ctx": M}
    (re.compile(r'"n_prompt_tokens"\s*:\s*(\d+).*?"n_ctx"\s*:\s*(\d+)', re.DOTALL), 1, 2),
    (re.compile(r'"n_ctx"\s*:\s*(\d+).*?"n_prompt_tokens"\s*:\s*(\d+)', re.DOTALL), 2, 1),
)


class ContextOverflowError(ProviderError):
    """A prompt longer than the model's context window: refused before sending (`estimated`
    True) or by the server. `prompt_tokens` and `window` in tokens. Never retried."""

    def __init__(self, message: str, source: str | None = None, *, prompt_tokens: int,
                 window: int, estimated: bool, status: int | None = None):
        super().__init__(message, source, retryable=False, status=status)
        self.prompt_tokens = prompt_tokens
        self.window = window
        self.estimated = estimated


@dataclass
class EndpointFacts:
    """`dialect` in use; `window` (tokens) and where it came from (`window_source`: "props",
    "models", "api/show", "setting", "error"); token calibration from the server's usage."""

    dialect: Dialect = "json_schema"
    window: Optional[int] = None
    window_source: Optional[str] = None
    probed: bool = False
    rejections: list[str] = field(default_factory=list)
    _ratio: Optional[float] = None
    _lock: Optional[asyncio.Lock] = None

    def lock(self) -> asyncio.Lock:
        """A lock for the one-time probe (made on first use, inside the running loop)."""
        if self._lock is None:
            self._lock = asyncio.Lock()
        return self._lock

    @property
    def chars_per_token(self) -> float:
        """Characters per token measured from the server's usage: the fewest seen in any prompt
        of 500+ characters (texts differ: the densest one errs towards shrinking), else
        `DEFAULT_CHARS_PER_TOKEN`."""
        return self._ratio or DEFAULT_CHARS_PER_TOKEN

    def observe(self, messages: list[Message], prompt_tokens: int) -> None:
        """Calibrate from one prompt the server counted as `prompt_tokens`."""
        chars, tokens = text_chars(messages), prompt_tokens - MESSAGE_OVERHEAD_TOKENS * len(messages)
        if chars >= 500 and tokens > 0:
            self._ratio = min(self._ratio or chars / tokens, chars / tokens)

    def estimate(self, messages: list[Message]) -> int:
        """Tokens `messages` will take at this endpoint (10 % margin over the calibration)."""
        return estimate_tokens(messages, self.chars_per_token / 1.1)

    def demote(self, rejected: Dialect, reason: str) -> bool:
        """Move on from dialect `rejected` after the server refused it (a no-op when a
        concurrent call already did); False when no dialect is left."""
        if self.dialect != rejected:
            return True
        index = DIALECTS.index(rejected)
        if index + 1 >= len(DIALECTS):
            return False
        self.rejections.append(f"{self.dialect}: {reason[:200]}")
        self.dialect = DIALECTS[index + 1]
        return True

    def learn_window(self, window: int, source: str) -> None:
        if window > 0:
            self.window, self.window_source = int(window), source


_FACTS: dict[tuple[str, str], EndpointFacts] = {}


def facts_for(base_url: str, model: str) -> EndpointFacts:
    """The shared facts of endpoint `base_url` serving `model` (made on first use)."""
    return _FACTS.setdefault((base_url.rstrip("/"), model), EndpointFacts())


def text_chars(messages: list[Message]) -> int:
    return sum(len(m.text()) for m in messages)


def estimate_tokens(messages: list[Message], chars_per_token: float = DEFAULT_CHARS_PER_TOKEN) -> int:
    """Tokens of `messages`: text length / `chars_per_token`, plus per-message and per-image
    overheads (rounded up)."""
    images = sum(isinstance(p, ImagePart) for m in messages if not isinstance(m.content, str)
                 for p in m.content)
    return (math.ceil(text_chars(messages) / chars_per_token)
            + MESSAGE_OVERHEAD_TOKENS * len(messages) + IMAGE_TOKENS * images)


def response_format(dialect: Dialect, schema: dict[str, Any]) -> dict[str, Any] | None:
    """The `response_format` field for `dialect` (None for `prompt`)."""
    if dialect == "json_schema":
        name = re.sub(r"[^A-Za-z0-9_-]", "_", str(schema.get("title") or "reply"))[:64]
        return {"type": "json_schema", "json_schema": {"name": name, "schema": schema}}
    if dialect == "json_object":
        return {"type": "json_object", "schema": schema}
    return None


def is_rejection(status: int, body: str) -> bool:
    """An HTTP error to a structured-output request that names the format or the schema."""
    return status >= 400 and bool(_REJECTION.search(body))


def context_error(body: str) -> tuple[int, int] | None:
    """(prompt tokens, window tokens) from an error body saying the prompt is too long; None
    when the body says nothing of the kind."""
    for pattern, tokens_group, window_group in _CONTEXT_ERRORS:
        match = pattern.search(body)
        if match:
            return int(match.group(tokens_group)), int(match.group(window_group))
    return None
