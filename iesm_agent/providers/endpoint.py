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
import re
import time
from dataclasses import dataclass, field
from typing import Any, Literal, Optional

from ..errors import ProviderError
from .base import (DEFAULT_TOKENS_PER_UNIT, ESTIMATE_MARGIN, MESSAGE_OVERHEAD_TOKENS, Message, estimate_tokens,
                   text_units)

Dialect = Literal["json_schema", "json_object", "prompt"]
DIALECTS: tuple[Dialect, ...] = ("json_schema", "json_object", "prompt")

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
    """`dialect` in use and whether it is settled (`negotiated`: a structured request got an
    answer that was not a refusal); `window` (tokens) and where it came from (`window_source`:
    "props", "models", "api/show", "setting", "error"); `slots`, requests the server serves in
    parallel (llama.cpp `/props` `total_slots`; None: unknown); token calibration from the
    server's usage; `stalled_until` (monotonic s), before which calls are not sent because one
    ran out of time."""

    dialect: Dialect = "json_schema"
    negotiated: bool = False
    window: Optional[int] = None
    window_source: Optional[str] = None
    slots: Optional[int] = None
    probed: bool = False
    rejections: list[str] = field(default_factory=list)
    stalled_until: float = 0.0
    stall_reason: str = ""
    _units: int = 0
    _tokens: int = 0
    _lock: Optional[asyncio.Lock] = None
    _lock_loop: Optional[asyncio.AbstractEventLoop] = None

    def lock(self) -> asyncio.Lock:
        """The lock of the one-time probe and negotiation, made per event loop (a process may
        run several loops one after another)."""
        loop = asyncio.get_running_loop()
        if self._lock is None or self._lock_loop is not loop:
            self._lock, self._lock_loop = asyncio.Lock(), loop
        return self._lock

    def stall(self, reason: str, seconds: float) -> None:
        """Send nothing to this endpoint for `seconds`: a call ran out of time (`reason`)."""
        self.stalled_until = time.monotonic() + seconds
        self.stall_reason = reason

    def stalled_reason(self) -> str:
        """Why calls are not sent now ("" when they are)."""
        left = self.stalled_until - time.monotonic()
        if left <= 0:
            return ""
        return f"{self.stall_reason}; the endpoint is not asked again for {left:.0f} s"

    @property
    def tokens_per_unit(self) -> float:
        """Tokens per text unit measured from the server's usage (total over prompts of 200+
        units), else `DEFAULT_TOKENS_PER_UNIT`."""
        return self._tokens / self._units if self._units else DEFAULT_TOKENS_PER_UNIT

    def observe(self, messages: list[Message], prompt_tokens: int) -> None:
        """Calibrate from one prompt the server counted as `prompt_tokens`."""
        units, tokens = text_units(messages), prompt_tokens - MESSAGE_OVERHEAD_TOKENS * len(messages)
        if units >= 200 and tokens > 0:
            self._units += units
            self._tokens += tokens

    def estimate(self, messages: list[Message]) -> int:
        """Tokens `messages` will take at this endpoint (`ESTIMATE_MARGIN` over the calibration)."""
        return estimate_tokens(messages, self.tokens_per_unit * ESTIMATE_MARGIN)

    def demote(self, rejected: Dialect, reason: str) -> bool:
        """Move on from dialect `rejected` after the server refused it (a no-op when a
        concurrent call already did); False when no dialect is left."""
        if self.dialect != rejected:
            return True
        index = DIALECTS.index(rejected)
        self.rejections.append(f"{self.dialect}: {reason[:200]}")
        if index + 1 >= len(DIALECTS):
            return False
        self.dialect = DIALECTS[index + 1]
        return True

    def learn_window(self, window: int, source: str) -> None:
        if window > 0:
            self.window, self.window_source = int(window), source


_FACTS: dict[tuple[str, str], EndpointFacts] = {}


def facts_for(base_url: str, model: str) -> EndpointFacts:
    """The shared facts of endpoint `base_url` serving `model` (made on first use)."""
    return _FACTS.setdefault((base_url.rstrip("/"), model), EndpointFacts())


def wire_schema(schema: Any) -> Any:
    """`schema` as sent to a server: without `maxLength` (the call's `max_tokens` bounds the
    reply instead). Grammar engines expand `maxLength: n` into n nested optional rules, and
    llama-cpp-python then samples about 40x slower inside such a string (Gemma 3 270M: 1.8 s
    instead of 41 ms per token); OpenAI's strict mode does not take it at all."""
    if isinstance(schema, dict):
        return {k: wire_schema(v) for k, v in schema.items() if k != "maxLength"}
    if isinstance(schema, list):
        return [wire_schema(v) for v in schema]
    return schema


def response_format(dialect: Dialect, schema: dict[str, Any]) -> dict[str, Any] | None:
    """The `response_format` field for `dialect` (None for `prompt`), with `wire_schema`."""
    schema = wire_schema(schema)
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
