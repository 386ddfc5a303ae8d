"""Client for OpenAI-compatible chat-completions servers (OpenAI, vLLM, Ollama's /v1,
llama.cpp server, LM Studio) on one `httpx.AsyncClient` per model instance.

Failure policy (each raises `ProviderError` naming the endpoint once retries are spent):
* retried with exponential backoff and full jitter (or the server's `Retry-After`, capped):
  HTTP 408, 409, 429, 5xx, connection errors, timeouts;
* not retried: 401/403 (key), 404 (model or URL), other 4xx, a body that is not JSON,
  JSON without `choices`, a choice without text content;
* HTTP 400 that mentions `response_format` while structured output was requested: the request
  is sent once more without it (the prompt already asks for JSON) and the instance stops sending
  `response_format` from then on.
"""

from __future__ import annotations

import asyncio
import email.utils
import random
import re
import ssl
import time
from typing import Any, Optional, Union

import httpx
from pydantic import BaseModel, Field, ValidationError

from ..errors import IesmError, ProviderError
from .base import Capabilities, ChatOptions, Completion, ImagePart, Message, Model, Usage

RETRYABLE_STATUS = frozenset({408, 409, 429, 500, 502, 503, 504, 520, 521, 522, 523, 524, 529})


class _ReplyMessage(BaseModel):
    content: Optional[Union[str, list[dict[str, Any]]]] = None
    refusal: Optional[str] = None


class _Choice(BaseModel):
    message: Optional[_ReplyMessage] = None
    finish_reason: Optional[str] = None


class _UsageIn(BaseModel):
    prompt_tokens: Optional[int] = None
    completion_tokens: Optional[int] = None


class _ChatReply(BaseModel):
    """The part of a chat-completions reply we read; other fields are ignored."""

    choices: list[_Choice] = Field(min_length=1)
    usage: Optional[_UsageIn] = None


class OpenAICompatModel(Model):
    """A chat model behind `{base_url}/chat/completions`.

    `timeout` (s) bounds each read/write, `connect_timeout` (s, default min(timeout, 10)) the
    connection; `max_retries` retries follow the first attempt; at most `concurrency` requests
    of this instance are in flight at once. Counters: `calls`, `retries`, `failures`,
    `prompt_tokens`, `completion_tokens`.
    """

    def __init__(self, model: str, *, base_url: str, api_key: str | None = None,
                 provider: str = "openai-compat", timeout: float = 60.0,
                 connect_timeout: float | None = None, max_retries: int = 4, concurrency: int = 8,
                 vision: bool = False, backoff_s: float = 0.5, backoff_max_s: float = 30.0,
                 retry_after_max_s: float = 60.0, key_hint: str | None = None):
        source = f"{provider}:{model}"
        if not model:
            raise IesmError("model name is empty", source)
        if not re.match(r"^https?://[^/\s]+", base_url or ""):
            raise IesmError(f"base_url must be an http(s) URL, got {base_url!r}", source, "base_url")
        if timeout <= 0:
            raise IesmError(f"timeout must be > 0 s, got {timeout}", source, "timeout")
        if max_retries < 0:
            raise IesmError(f"max_retries must be >= 0, got {max_retries}", source, "max_retries")
        if concurrency < 1:
            raise IesmError(f"concurrency must be >= 1, got {concurrency}", source, "concurrency")
        self.name = source
        self.model = model
        self.base_url = base_url.rstrip("/")
        self.endpoint = f"{self.base_url}/chat/completions"
        self.capabilities = Capabilities(vision=vision, json_schema=True)
        self.timeout = float(timeout)
        self.connect_timeout = float(connect_timeout) if connect_timeout else min(self.timeout, 10.0)
        self.max_retries = int(max_retries)
        self.concurrency = int(concurrency)
        self.backoff_s, self.backoff_max_s = float(backoff_s), float(backoff_max_s)
        self.retry_after_max_s = float(retry_after_max_s)
        self._headers = {"Authorization": f"Bearer {api_key}"} if api_key else {}
        self._key_hint = key_hint or "the API key"
        self.structured_output = True  # becomes False once the server rejects response_format
        self.calls = self.retries = self.failures = 0
        self.prompt_tokens = self.completion_tokens = 0
        self._client: httpx.AsyncClient | None = None
        self._semaphore: asyncio.Semaphore | None = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._ssl: ssl.SSLContext | None = None

    def __repr__(self) -> str:
        return f"OpenAICompatModel({self.name!r}, base_url={self.base_url!r})"

    def cache_identity(self) -> dict[str, Any]:
        return {"provider": "openai-compat", "base_url": self.base_url, "model": self.model}

    def stats(self) -> dict[str, int]:
        """The counters as a dict (for traces and reports)."""
        return {"calls": self.calls, "retries": self.retries, "failures": self.failures,
                "prompt_tokens": self.prompt_tokens, "completion_tokens": self.completion_tokens}

    async def aclose(self) -> None:
        """Close the HTTP client; the model stays usable (a new client is made on the next call).
        A client left over from an event loop that has since ended is only dropped."""
        client, loop = self._client, self._loop
        self._client = self._loop = None
        if client is not None and loop is asyncio.get_running_loop():
            await client.aclose()

    async def acomplete(self, messages: list[Message], options: ChatOptions | None = None) -> Completion:
        options = options or ChatOptions()
        self.calls += 1
        started = time.perf_counter()
        client, semaphore = self._session()
        attempt = 0
        while True:
            structured = self.structured_output and options.json_schema is not None
            try:
                async with semaphore:
                    reply = await self._post(client, self._body(messages, options, structured))
                break
            except ProviderError as exc:
                if structured and exc.status == 400 and "response_format" in exc.message:
                    self.structured_output = False
                    continue
                if not exc.retryable or attempt >= self.max_retries:
                    self.failures += 1
                    if attempt:
                        exc.message += f" (gave up after {attempt + 1} attempts)"
                    raise
                attempt += 1
                self.retries += 1
                await asyncio.sleep(self._backoff(attempt, exc.retry_after))
        text, usage = reply
        self.prompt_tokens += usage.prompt_tokens
        self.completion_tokens += usage.completion_tokens
        return Completion(text=text, model=self.name, usage=usage,
                          latency_ms=(time.perf_counter() - started) * 1000.0)

    def _session(self) -> tuple[httpx.AsyncClient, asyncio.Semaphore]:
        """The client and semaphore of the running event loop (remade when the loop changes)."""
        loop = asyncio.get_running_loop()
        if self._client is None or self._loop is not loop:
            timeout = httpx.Timeout(self.timeout, connect=self.connect_timeout)
            limits = httpx.Limits(max_connections=self.concurrency,
                                  max_keepalive_connections=self.concurrency)
            if self._ssl is None:  # made once: loading CA certificates costs ~40 ms
                self._ssl = (httpx.create_ssl_context() if self.base_url.startswith("https:")
                             else ssl.SSLContext(ssl.PROTOCOL_TLS_CLIENT))
            self._client = httpx.AsyncClient(timeout=timeout, limits=limits, headers=self._headers,
                                             verify=self._ssl)
            self._semaphore = asyncio.Semaphore(self.concurrency)
            self._loop = loop
        assert self._semaphore is not None
        return self._client, self._semaphore

    def _backoff(self, attempt: int, retry_after: float | None) -> float:
        """Seconds to wait before retry number `attempt` (1-based)."""
        if retry_after is not None:
            return max(0.0, min(retry_after, self.retry_after_max_s))
        return random.uniform(0.0, min(self.backoff_max_s, self.backoff_s * 2 ** (attempt - 1)))

    def _body(self, messages: list[Message], options: ChatOptions, structured: bool) -> dict[str, Any]:
        body: dict[str, Any] = {"model": self.model, "messages": [_wire_message(m) for m in messages],
                                "temperature": options.temperature}
        if options.max_tokens is not None:
            body["max_tokens"] = options.max_tokens
        if options.seed is not None:
            body["seed"] = options.seed
        if structured:  # only ever True with a json_schema (see `acomplete`)
            schema = options.json_schema
            name = re.sub(r"[^A-Za-z0-9_-]", "_", str(schema.get("title") or "reply"))[:64]
            body["response_format"] = {"type": "json_schema",
                                       "json_schema": {"name": name, "schema": schema}}
        return body

    async def _post(self, client: httpx.AsyncClient, body: dict[str, Any]) -> tuple[str, Usage]:
        """One HTTP attempt: the reply text and usage, or a classified `ProviderError`."""
        try:
            response = await client.post(self.endpoint, json=body)
        except httpx.TimeoutException as exc:
            raise ProviderError(f"no reply within the {self.timeout:g} s timeout "
                                f"({type(exc).__name__})", self.endpoint, retryable=True) from exc
        except httpx.TransportError as exc:
            raise ProviderError(f"connection failed: {exc or type(exc).__name__}", self.endpoint,
                                retryable=True) from exc
        if response.status_code >= 300:
            raise self._status_error(response)
        return self._parse(response)

    def _status_error(self, response: httpx.Response) -> ProviderError:
        status = response.status_code
        detail = _error_detail(response)
        if status in (401, 403):
            message = f"HTTP {status}, access refused: {detail} (check {self._key_hint})"
        elif status == 404:
            message = (f"HTTP 404, not found: {detail} (check the base URL and that model "
                       f"{self.model!r} exists there)")
        else:
            message = f"HTTP {status}: {detail}"
        retry_after = parse_retry_after(response.headers.get("retry-after"))
        return ProviderError(message, self.endpoint, retryable=status in RETRYABLE_STATUS,
                             status=status, retry_after=retry_after)

    def _parse(self, response: httpx.Response) -> tuple[str, Usage]:
        try:
            data = response.json()
        except ValueError:
            kind = response.headers.get("content-type", "no content-type")
            raise ProviderError(f"reply is not JSON ({kind}): {response.text[:80]!r}",
                                self.endpoint, status=response.status_code) from None
        if not isinstance(data, dict) or not data.get("choices"):
            detail = _error_detail(response) if isinstance(data, dict) and "error" in data else ""
            raise ProviderError(f"reply has no choices{': ' + detail if detail else ''}",
                                self.endpoint, status=response.status_code)
        try:
            reply = _ChatReply.model_validate(data)
        except ValidationError as exc:
            first = exc.errors()[0]
            where = ".".join(str(p) for p in first["loc"])
            raise ProviderError(f"malformed reply at {where}: {first['msg']}", self.endpoint,
                                status=response.status_code) from None
        choice = reply.choices[0]
        content = choice.message.content if choice.message else None
        if isinstance(content, list):
            content = "".join(str(p.get("text", "")) for p in content if p.get("type") == "text")
        if not isinstance(content, str):
            refusal = choice.message.refusal if choice.message else None
            extra = f", refusal: {refusal!r}" if refusal else ""
            raise ProviderError(f"reply has no message content (finish_reason="
                                f"{choice.finish_reason!r}{extra})", self.endpoint,
                                status=response.status_code)
        usage = reply.usage or _UsageIn()
        return content, Usage(prompt_tokens=usage.prompt_tokens or 0,
                              completion_tokens=usage.completion_tokens or 0)


def _wire_message(message: Message) -> dict[str, Any]:
    """A `Message` in the chat-completions wire format (images as data-URL `image_url` parts)."""
    if isinstance(message.content, str):
        return {"role": message.role, "content": message.content}
    parts: list[dict[str, Any]] = []
    for part in message.content:
        if isinstance(part, ImagePart):
            parts.append({"type": "image_url",
                          "image_url": {"url": f"data:{part.mime_type};base64,{part.data}"}})
        else:
            parts.append({"type": "text", "text": part.text})
    return {"role": message.role, "content": parts}


def _error_detail(response: httpx.Response) -> str:
    """The server's error message (`{"error": {"message": ...}}` or the body), shortened."""
    try:
        data = response.json()
    except ValueError:
        data = None
    if isinstance(data, dict):
        error = data.get("error", data)
        if isinstance(error, dict):
            error = error.get("message") or error.get("detail") or error
        return str(error)[:300]
    return (response.text or response.reason_phrase or "empty body").strip()[:300]


def parse_retry_after(value: str | None, now: float | None = None) -> float | None:
    """Seconds to wait from a `Retry-After` header (delta seconds or an HTTP date); None if
    absent or unreadable. `now` (epoch s) is for tests."""
    if not value:
        return None
    value = value.strip()
    try:
        return max(0.0, float(value))
    except ValueError:
        pass
    try:
        when = email.utils.parsedate_to_datetime(value)
    except (TypeError, ValueError):
        return None
    if when.tzinfo is None:
        return None
    return max(0.0, when.timestamp() - (time.time() if now is None else now))
