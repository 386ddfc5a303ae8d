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

#: tokens per text unit (a word or one punctuation character) assumed before the server has
#: reported usage. Units vary less with the kind of text than characters do: Gemma 3 counts
#: 0.84-1.08 tokens per unit over our prompts, 2.6-3.7 characters per token.
DEFAULT_TOKENS_PER_UNIT = 1.1
#: margin over the calibrated rate when checking that a prompt fits
ESTIMATE_MARGIN = 1.15
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
    _units: int = 0
    _tokens: int = 0
    _lock: Optional[asyncio.Lock] = None

    def lock(self) -> asyncio.Lock:
        """A lock for the one-time probe (made on first use, inside the running loop)."""
        if self._lock is None:
            self._lock = asyncio.Lock()
        return self._lock

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
