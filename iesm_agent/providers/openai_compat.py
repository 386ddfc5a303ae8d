"""Client for OpenAI-compatible chat-completions servers (OpenAI, vLLM, Ollama's /v1,
llama.cpp server, LM Studio) on one `httpx.AsyncClient` per model instance.

Failure policy (each raises `ProviderError` naming the endpoint once retries are spent):
* retried with exponential backoff and full jitter (or the server's `Retry-After`, capped):
  HTTP 408, 409, 429, 5xx, connection errors, timeouts;
* not retried: 401/403 (key), 404 (model or URL), other 4xx, a body that is not JSON,
  JSON without `choices`, a choice without text content, a refused connection (nothing listens
  there: retrying cannot help);
* structured output is negotiated (`endpoint.py`): an HTTP error naming `response_format` or the
  schema moves the endpoint to the next dialect (json_schema -> json_object -> prompted JSON)
  and the request is sent again at once, for every later call too;
* a prompt that would not fit the context window is never sent (`ContextOverflowError`): the
  window comes from the user (`context_window=`), the server (`/v1/models` `max_model_len`,
  llama.cpp `/props`), or the server's own context error, which teaches it for later calls.
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
from .endpoint import (REPLY_RESERVE_TOKENS, ContextOverflowError, Dialect, context_error,
                       facts_for, is_rejection, response_format)

RETRYABLE_STATUS = frozenset({408, 409, 429, 500, 502, 503, 504, 520, 521, 522, 523, 524, 529})


class DialectRejected(ProviderError):
    """The server refused the structured-output dialect of the request (see `endpoint.py`)."""


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
    of this instance are in flight at once. `context_window` (tokens) overrides what the server
    says; `probe_window=False` skips asking it. Counters: `calls`, `retries`, `failures`,
    `prompt_tokens`, `completion_tokens`.
    """

    def __init__(self, model: str, *, base_url: str, api_key: str | None = None,
                 provider: str = "openai-compat", timeout: float = 60.0,
                 connect_timeout: float | None = None, max_retries: int = 4, concurrency: int = 8,
                 vision: bool = False, backoff_s: float = 0.5, backoff_max_s: float = 30.0,
                 retry_after_max_s: float = 60.0, key_hint: str | None = None,
                 context_window: int | None = None, probe_window: bool = True):
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
        if context_window is not None and context_window < 1:
            raise IesmError(f"context_window must be >= 1 token, got {context_window}", source,
                            "context_window")
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
        self.facts = facts_for(self.base_url, model)  # dialect and window, shared per endpoint
        if context_window:
            self.facts.learn_window(context_window, "setting")
        self.probe_window = probe_window and not context_window
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

    @property
    def dialect(self) -> Dialect:
        """The structured-output dialect this endpoint is spoken to in now."""
        return self.facts.dialect

    def stats(self) -> dict[str, int]:
        """The counters as a dict (for traces and reports)."""
        return {"calls": self.calls, "retries": self.retries, "failures": self.failures,
                "prompt_tokens": self.prompt_tokens, "completion_tokens": self.completion_tokens}

    def estimate_tokens(self, messages: list[Message]) -> int:
        return self.facts.estimate(messages)

    async def aprompt_limit(self, options: ChatOptions | None = None) -> int | None:
        """Tokens a prompt may take: the window (asked of the server once) less the reply's
        `max_tokens` (`REPLY_RESERVE_TOKENS` when unset); None when the window is unknown."""
        if self.probe_window and not self.facts.probed:
            client, _ = self._session()
            async with self.facts.lock():
                if not self.facts.probed:
                    await self._probe_window(client)
                    self.facts.probed = True
        if self.facts.window is None:
            return None
        reserve = (options.max_tokens if options and options.max_tokens else REPLY_RESERVE_TOKENS)
        return max(self.facts.window - reserve, 0)

    async def _probe_window(self, client: httpx.AsyncClient) -> None:
        """Learn the window from vLLM's `/v1/models` (`max_model_len`) or llama.cpp's `/props`
        (`default_generation_settings.n_ctx`); a server with neither leaves it unknown."""
        models = await _get_json(client, f"{self.base_url}/models", self.connect_timeout)
        data = models.get("data") if isinstance(models, dict) else None
        entries = [e for e in data if isinstance(e, dict)] if isinstance(data, list) else []
        mine = [e for e in entries if e.get("id") == self.model] or entries[:1] * (len(entries) == 1)
        for entry in mine:
            if isinstance(entry.get("max_model_len"), int):
                self.facts.learn_window(entry["max_model_len"], "models")
                return
        root = re.sub(r"/v1$", "", self.base_url)
        props = await _get_json(client, f"{root}/props", self.connect_timeout)
        if isinstance(props, dict):
            settings = props.get("default_generation_settings")
            n_ctx = settings.get("n_ctx") if isinstance(settings, dict) else props.get("n_ctx")
            if isinstance(n_ctx, int):
                self.facts.learn_window(n_ctx, "props")

    def _check_fits(self, messages: list[Message], options: ChatOptions, limit: int | None) -> None:
        """Refuse, before sending, a prompt whose estimate exceeds `limit` tokens."""
        if limit is None:
            return
        need = self.facts.estimate(messages)
        if need > limit:
            raise ContextOverflowError(
                f"prompt of about {need} tokens does not fit the context window of "
                f"{self.facts.window} tokens ({self.facts.window_source}) with "
                f"{self.facts.window - limit} kept for the reply; not sent",
                self.endpoint, prompt_tokens=need, window=self.facts.window or 0, estimated=True)

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
        try:
            self._check_fits(messages, options, await self.aprompt_limit(options))
            while True:
                dialect = self.facts.dialect if options.json_schema is not None else "prompt"
                try:
                    async with semaphore:
                        text, usage = await self._post(client, self._body(messages, options, dialect),
                                                       structured=dialect != "prompt")
                    break
                except DialectRejected as exc:
                    if self.facts.demote(dialect, exc.message):
                        continue
                    raise
                except ContextOverflowError as exc:
                    self.facts.observe(messages, exc.prompt_tokens)
                    raise
                except ProviderError as exc:
                    if not exc.retryable or attempt >= self.max_retries:
                        if attempt:
                            exc.message += f" (gave up after {attempt + 1} attempts)"
                        raise
                    attempt += 1
                    self.retries += 1
                    await asyncio.sleep(self._backoff(attempt, exc.retry_after))
        except ProviderError:
            self.failures += 1
            raise
        self.facts.observe(messages, usage.prompt_tokens)
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

    def _body(self, messages: list[Message], options: ChatOptions, dialect: Dialect) -> dict[str, Any]:
        body: dict[str, Any] = {"model": self.model, "messages": [_wire_message(m) for m in messages],
                                "temperature": options.temperature}
        if options.max_tokens is not None:
            body["max_tokens"] = options.max_tokens
        if options.seed is not None:
            body["seed"] = options.seed
        fmt = response_format(dialect, options.json_schema) if options.json_schema else None
        if fmt is not None:
            body["response_format"] = fmt
        return body

    async def _post(self, client: httpx.AsyncClient, body: dict[str, Any],
                    structured: bool) -> tuple[str, Usage]:
        """One HTTP attempt (`structured`: the body asks for a structured-output dialect): the
        reply text and usage, or a classified `ProviderError`."""
        try:
            response = await client.post(self.endpoint, json=body)
        except httpx.TimeoutException as exc:
            raise ProviderError(f"no reply within the {self.timeout:g} s timeout "
                                f"({type(exc).__name__})", self.endpoint, retryable=True) from exc
        except httpx.ConnectError as exc:
            raise ProviderError(f"connection failed: {exc or type(exc).__name__} (is the server "
                                f"running at {self.base_url}?)", self.endpoint) from exc
        except httpx.TransportError as exc:
            raise ProviderError(f"connection failed: {exc or type(exc).__name__}", self.endpoint,
                                retryable=True) from exc
        if response.status_code >= 300:
            raise self._status_error(response, structured)
        return self._parse(response)

    def _status_error(self, response: httpx.Response, structured: bool) -> ProviderError:
        """The error for an HTTP status >= 300; a request with `response_format` that the body
        blames on it is a `DialectRejected`, a context error a `ContextOverflowError`."""
        status = response.status_code
        detail = _error_detail(response)
        overflow = context_error(response.text) if status >= 400 else None
        if overflow is not None:
            tokens, window = overflow
            self.facts.learn_window(window, "error")
            return ContextOverflowError(
                f"HTTP {status}: the server's context window of {window} tokens is too small for "
                f"this prompt of {tokens} tokens: {detail}", self.endpoint,
                prompt_tokens=tokens, window=window, estimated=False, status=status)
        if structured and is_rejection(status, response.text):
            return DialectRejected(f"HTTP {status}: {detail}", self.endpoint, status=status)
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


async def _get_json(client: httpx.AsyncClient, url: str, timeout: float) -> Any:
    """GET `url` as JSON; None on any failure (probes are best effort)."""
    try:
        response = await client.get(url, timeout=timeout)
        return response.json() if response.status_code == 200 else None
    except (httpx.HTTPError, ValueError):
        return None


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
