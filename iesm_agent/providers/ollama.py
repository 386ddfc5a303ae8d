"""Ollama's native chat API (`POST /api/chat`), used by `ollama:<model>`.

The native API is used rather than Ollama's /v1 because only it takes `options.num_ctx`:
Ollama's default window is a few thousand tokens and it drops the start of a longer prompt
without a word. This client asks for `num_ctx` = the `context_window` setting, else
`DEFAULT_NUM_CTX` capped by the model's own length (`/api/show` `model_info.*.context_length`),
and never sends a prompt estimated longer than that.

Structured output: `format: <schema>` (dialect `json_schema`), then `format: "json"`
(`json_object`, Ollama before 0.5), then prompted JSON.
"""

from __future__ import annotations

import re
import time
from typing import Any, Optional

import httpx
from pydantic import BaseModel, ValidationError

from ..errors import ProviderError
from .base import ChatOptions, ImagePart, Message, Usage, clean_text
from .endpoint import Dialect, wire_schema
from .openai_compat import HttpReply, OpenAICompatModel, Reply, _request

OLLAMA_ROOT = "http://localhost:11434"
#: tokens of context asked for when neither the user nor the model's length says less
DEFAULT_NUM_CTX = 16384


class _OllamaMessage(BaseModel):
    content: Optional[str] = None


class _OllamaReply(BaseModel):
    message: _OllamaMessage
    done_reason: Optional[str] = None
    prompt_eval_count: Optional[int] = None
    eval_count: Optional[int] = None


class OllamaModel(OpenAICompatModel):
    """`ollama:<model>` at `base_url` (the server root; a trailing `/v1` is dropped).
    `context_window` (tokens) is sent as `num_ctx`; other arguments as `OpenAICompatModel`."""

    def __init__(self, model: str, *, base_url: str = OLLAMA_ROOT, **kwargs: Any):
        root = re.sub(r"/v1/?$", "", (base_url or OLLAMA_ROOT).rstrip("/"))
        kwargs.setdefault("provider", "ollama")
        self.requested_ctx: int | None = kwargs.get("context_window")
        super().__init__(model, base_url=root, **kwargs)
        self.endpoint = f"{self.base_url}/api/chat"
        self.probe_window = True  # the model's own length still caps a requested num_ctx

    def cache_identity(self) -> dict[str, Any]:
        return {"provider": "ollama", "base_url": self.base_url, "model": self.model}

    async def _probe_window(self, client: httpx.AsyncClient) -> None:
        """Window = the requested num_ctx (or `DEFAULT_NUM_CTX`) capped by `/api/show`'s
        context length; always known, since this client sets it."""
        wanted = self.requested_ctx or DEFAULT_NUM_CTX
        length = None
        try:
            answer = await _request(client, "POST", f"{self.base_url}/api/show",
                                    time.monotonic() + self.connect_timeout, json={"model": self.model})
            info = answer.json().get("model_info") if answer.status == 200 else None
        except (ProviderError, ValueError, AttributeError):
            info = None
        if isinstance(info, dict):
            lengths = [v for k, v in info.items() if k.endswith(".context_length") and isinstance(v, int)]
            length = min(lengths) if lengths else None
        self.facts.learn_window(min(wanted, length) if length else wanted,
                                "api/show" if length and length < wanted else "setting")

    def _body(self, messages: list[Message], options: ChatOptions, dialect: Dialect) -> dict[str, Any]:
        body: dict[str, Any] = {"model": self.model, "messages": [_ollama_message(m) for m in messages],
                                "stream": False,
                                "options": {"temperature": options.temperature,
                                            "num_ctx": self.facts.window or DEFAULT_NUM_CTX}}
        if options.max_tokens is not None:
            body["options"]["num_predict"] = options.max_tokens
        if options.seed is not None:
            body["options"]["seed"] = options.seed
        if options.json_schema is not None and dialect != "prompt":
            body["format"] = wire_schema(options.json_schema) if dialect == "json_schema" else "json"
        return body

    def _parse(self, answer: HttpReply) -> Reply:
        try:
            reply = _OllamaReply.model_validate_json(answer.body)
        except ValidationError as exc:
            first = exc.errors()[0]
            where = ".".join(str(p) for p in first["loc"]) or "body"
            raise ProviderError(f"malformed reply at {where}: {clean_text(first['msg'])}", self.endpoint,
                                status=answer.status) from None
        if reply.message.content is None:
            raise ProviderError(f"reply has no message content (done_reason="
                                f"{clean_text(str(reply.done_reason))[:40]!r})", self.endpoint, status=answer.status)
        return Reply(clean_text(reply.message.content),
                     Usage(prompt_tokens=reply.prompt_eval_count or 0, completion_tokens=reply.eval_count or 0),
                     truncated=reply.done_reason == "length")


def _ollama_message(message: Message) -> dict[str, Any]:
    """A `Message` in Ollama's format (images as a list of base64 strings)."""
    if isinstance(message.content, str):
        return {"role": message.role, "content": message.content}
    images = [p.data for p in message.content if isinstance(p, ImagePart)]
    return {"role": message.role, "content": message.text(), **({"images": images} if images else {})}
