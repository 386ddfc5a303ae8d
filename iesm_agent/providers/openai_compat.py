"""Client for OpenAI-compatible chat-completions servers (OpenAI, vLLM, Ollama's /v1,
llama.cpp server, LM Studio) on one `httpx.AsyncClient` per model instance.

Bounds (a misbehaving server costs at most these): every call ends within its `deadline`
(default `DEFAULT_DEADLINE_S`, or `timeout` when longer), retries, waits for a free slot and
`Retry-After` included; a reply body is read up to `MAX_REPLY_BYTES` as sent and as inflated;
after a call ran out of time the endpoint is not asked again for one `deadline` (later calls
fail at once), so a stalled server ends a run of calls one at a time within one deadline too.
Reply text is cleaned of lone surrogates.

Failure policy (each raises `ProviderError` naming the endpoint once retries are spent):
* retried with exponential backoff and full jitter (or the server's `Retry-After`, capped and
  only when it ends before the call's deadline): HTTP 408, 409, 429, 5xx, connection errors,
  timeouts;
* not retried: 401/403 (key), 404 (model or URL), other 4xx, a body that is not JSON,
  JSON without `choices`, a choice without text content, a refused connection (nothing listens
  there: retrying cannot help);
* structured output is negotiated (`endpoint.py`) by the first call of the process to the
  endpoint while the others wait: an HTTP error naming `response_format` or the schema moves
  the endpoint to the next dialect (json_schema -> json_object -> prompted JSON) and the request
  is sent again at once, for every later call too; the call's `notes` say why;
* at most `concurrency` requests are in flight, fewer when the server reports fewer parallel
  slots (llama.cpp `/props` `total_slots`);
* a prompt that would not fit the context window is never sent (`ContextOverflowError`): the
  window comes from the user (`context_window=`), the server (`/v1/models` `max_model_len`,
  llama.cpp `/props`), or the server's own context error, which teaches it for later calls.
"""

from __future__ import annotations

import asyncio
import email.utils
import json
import random
import re
import ssl
import time
from dataclasses import dataclass
from typing import Any, Optional, Union

import httpx
from pydantic import BaseModel, Field, ValidationError

from ..errors import IesmError, ProviderError
from .base import LLM_CANDIDATES, Capabilities, ChatOptions, Completion, ImagePart, Message, Model, Usage, clean_text
from .endpoint import (DIALECTS, REPLY_RESERVE_TOKENS, ContextOverflowError, Dialect, context_error,
                       facts_for, is_rejection, response_format)

RETRYABLE_STATUS = frozenset({408, 409, 429, 500, 502, 503, 504, 520, 521, 522, 523, 524, 529})
#: largest reply body read (bytes), as sent and after decompression
MAX_REPLY_BYTES = 8 * 1024 * 1024
#: seconds within which a call ends, whatever the server does (unless `timeout` is longer)
DEFAULT_DEADLINE_S = 60.0


class DialectRejected(ProviderError):
    """The server refused the structured-output dialect of the request (see `endpoint.py`)."""


class DeadlineExceeded(ProviderError):
    """A request's answer was not complete by its deadline (a trickling or stalled server)."""


class _ReplyMessage(BaseModel):
    content: Optional[Union[str, list[dict[str, Any]]]] = None
    refusal: Optional[str] = None


class _Choice(BaseModel):
    message: Optional[_ReplyMessage] = None
    finish_reason: Optional[str] = None


class _TokenDetails(BaseModel):
    cached_tokens: Optional[int] = None


class _UsageIn(BaseModel):
    prompt_tokens: Optional[int] = None
    completion_tokens: Optional[int] = None
    prompt_tokens_details: Optional[_TokenDetails] = None


class _Timings(BaseModel):
    """llama.cpp server's `timings`: `cache_n` prompt tokens came from its cache."""

    cache_n: Optional[int] = None


class _ChatReply(BaseModel):
    """The part of a chat-completions reply we read; other fields are ignored."""

    choices: list[_Choice] = Field(min_length=1)
    usage: Optional[_UsageIn] = None
    timings: Optional[_Timings] = None


@dataclass
class HttpReply:
    """One HTTP answer, its body read within `MAX_REPLY_BYTES`."""

    status: int
    headers: httpx.Headers
    body: bytes

    @property
    def text(self) -> str:
        return clean_text(self.body.decode("utf-8", "replace"))

    def json(self) -> Any:
        """The body as JSON; `ValueError` when it is not (or nests deeper than Python recurses)."""
        try:
            return json.loads(self.body)
        except RecursionError:
            raise ValueError("JSON nested too deep") from None


@dataclass
class Reply:
    """A parsed chat reply: text, usage, and whether it stopped at `max_tokens`."""

    text: str
    usage: Usage
    truncated: bool = False


class OpenAICompatModel(Model):
    """A chat model behind `{base_url}/chat/completions` (`candidate_budget`: `LLM_CANDIDATES`).

    `timeout` (s) bounds each read/write, `deadline` (s) each call as a whole (retries, waits
    and slots included); `connect_timeout` (s, default min(timeout, 10)) the connection;
    `max_retries` retries follow the first attempt; at most `concurrency` requests of this
    instance are in flight at once (fewer when the server has fewer slots). `context_window`
    (tokens) overrides what the server says; `probe_window=False` skips asking it (window and
    slots); `dialect` fixes the structured-output dialect instead of negotiating it (`prompt`:
    no grammar; llama-cpp-python samples a grammar over Gemma 3's 262k-token vocabulary at
    0.3-1.8 s a token on two loaded cores). Counters: `calls`, `retries`, `failures`,
    `prompt_tokens`, `cached_tokens`, `completion_tokens`.
    """

    def __init__(self, model: str, *, base_url: str, api_key: str | None = None,
                 provider: str = "openai-compat", timeout: float = 60.0,
                 connect_timeout: float | None = None, max_retries: int = 4, concurrency: int = 8,
                 vision: bool = False, backoff_s: float = 0.5, backoff_max_s: float = 30.0,
                 retry_after_max_s: float = 60.0, key_hint: str | None = None,
                 context_window: int | None = None, probe_window: bool = True,
                 deadline: float | None = None, dialect: Dialect | None = None):
        source = f"{provider}:{model}"
        if not model:
            raise IesmError("model name is empty", source)
        if not re.match(r"^https?://[^/\s]+", base_url or ""):
            raise IesmError(f"base_url must be an http(s) URL, got {base_url!r}", source, "base_url")
        if not timeout > 0:
            raise IesmError(f"timeout must be > 0 s, got {timeout}", source, "timeout")
        if deadline is not None and not deadline > 0:
            raise IesmError(f"deadline must be > 0 s, got {deadline}", source, "deadline")
        if max_retries < 0:
            raise IesmError(f"max_retries must be >= 0, got {max_retries}", source, "max_retries")
        if concurrency < 1:
            raise IesmError(f"concurrency must be >= 1, got {concurrency}", source, "concurrency")
        if dialect is not None and dialect not in DIALECTS:
            raise IesmError(f"dialect must be one of {', '.join(DIALECTS)}, got {dialect!r}", source, "dialect")
        if context_window is not None and context_window < 1:
            raise IesmError(f"context_window must be >= 1 token, got {context_window}", source,
                            "context_window")
        self.name = source
        self.model = model
        self.base_url = base_url.rstrip("/")
        self.endpoint = f"{self.base_url}/chat/completions"
        self.capabilities = Capabilities(vision=vision, json_schema=True)
        self.timeout = float(timeout)
        self.deadline = float(deadline) if deadline else max(DEFAULT_DEADLINE_S, self.timeout)
        self.connect_timeout = float(connect_timeout) if connect_timeout else min(self.timeout, 10.0)
        self.max_retries = int(max_retries)
        self.concurrency = int(concurrency)
        self.backoff_s, self.backoff_max_s = float(backoff_s), float(backoff_max_s)
        self.retry_after_max_s = float(retry_after_max_s)
        self._headers = {"Authorization": f"Bearer {api_key}"} if api_key else {}
        self._key_hint = key_hint or "the API key"
        self.facts = facts_for(self.base_url, model)  # dialect, window, slots: shared per endpoint
        if context_window:
            self.facts.learn_window(context_window, "setting")
        if dialect is not None:  # set by the user: not negotiated
            self.facts.dialect = dialect
        self.probe_window = probe_window
        self.calls = self.retries = self.failures = 0
        self.prompt_tokens = self.cached_tokens = self.completion_tokens = 0
        self._client: httpx.AsyncClient | None = None
        self._semaphore: asyncio.Semaphore | None = None
        self._loop: asyncio.AbstractEventLoop | None = None
        self._ssl: ssl.SSLContext | None = None

    candidate_budget = LLM_CANDIDATES

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
                "prompt_tokens": self.prompt_tokens, "cached_tokens": self.cached_tokens,
                "completion_tokens": self.completion_tokens}

    def estimate_tokens(self, messages: list[Message]) -> int:
        return self.facts.estimate(messages)

    async def aprompt_limit(self, options: ChatOptions | None = None) -> int | None:
        """Tokens a prompt may take: the window (asked of the server once) less the reply's
        `max_tokens` (`REPLY_RESERVE_TOKENS` when unset); None when the window is unknown."""
        await self._probe_once()
        return self._limit(options)

    async def aparallel_calls(self) -> int | None:
        """Requests in flight at most: `concurrency`, or the server's slots when fewer (asked of the
        server once)."""
        await self._probe_once()
        return min(self.concurrency, self.facts.slots or self.concurrency)

    def _limit(self, options: ChatOptions | None) -> int | None:
        """`aprompt_limit` from what is known now (no probe)."""
        if self.facts.window is None:
            return None
        reserve = (options.max_tokens if options and options.max_tokens else REPLY_RESERVE_TOKENS)
        return max(self.facts.window - reserve, 0)

    async def _probe_once(self) -> None:
        """Ask the server for its window and slots, once per endpoint and process (the other
        calls wait for it); within the call's deadline."""
        if not self.probe_window or self.facts.probed:
            return
        client, _ = self._session()
        async with self.facts.lock():
            if not self.facts.probed:
                try:
                    async with asyncio.timeout(self.deadline):
                        await self._probe_window(client)
                except TimeoutError:
                    pass
                self.facts.probed = True

    async def _probe_window(self, client: httpx.AsyncClient) -> None:
        """Learn the window from vLLM's `/v1/models` (`max_model_len`) or llama.cpp's `/props`
        (`default_generation_settings.n_ctx`, and `total_slots`); a server with neither leaves
        them unknown. A window set by the user is kept."""
        models = await _get_json(client, f"{self.base_url}/models", self.connect_timeout)
        data = models.get("data") if isinstance(models, dict) else None
        entries = [e for e in data if isinstance(e, dict)] if isinstance(data, list) else []
        mine = [e for e in entries if e.get("id") == self.model] or entries[:1] * (len(entries) == 1)
        root = re.sub(r"/v1$", "", self.base_url)
        props = await _get_json(client, f"{root}/props", self.connect_timeout)
        if isinstance(props, dict) and _positive_int(props.get("total_slots")):
            self.facts.slots = props["total_slots"]
        if self.facts.window_source == "setting":
            return
        for entry in mine:
            if _positive_int(entry.get("max_model_len")):
                self.facts.learn_window(entry["max_model_len"], "models")
                return
        if isinstance(props, dict):
            settings = props.get("default_generation_settings")
            n_ctx = settings.get("n_ctx") if isinstance(settings, dict) else props.get("n_ctx")
            if _positive_int(n_ctx):
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
        deadline = time.monotonic() + self.deadline
        notes: list[str] = []
        try:
            stalled = self.facts.stalled_reason()
            if stalled:
                raise ProviderError(f"not sent: {stalled}", self.endpoint)
            try:
                async with asyncio.timeout(self.deadline):
                    await self._probe_once()
                    reply = None
                    if not self.facts.negotiated:
                        # the first call negotiates dialect and window; the others wait for it,
                        # then go at once, checked against what it learnt
                        async with self.facts.lock():
                            if not self.facts.negotiated:
                                self._check_fits(messages, options, self._limit(options))
                                reply = await self._attempts(messages, options, deadline, notes)
                    if reply is None:
                        self._check_fits(messages, options, self._limit(options))
                        reply = await self._attempts(messages, options, deadline, notes)
            except (TimeoutError, DeadlineExceeded):
                self.facts.stall(f"a call got no reply within its {self.deadline:g} s deadline", self.deadline)
                raise ProviderError(f"no complete reply within the {self.deadline:g} s deadline of a "
                                    f"call (waits and retries included)", self.endpoint) from None
        except ProviderError:
            self.failures += 1
            raise
        self.facts.observe(messages, reply.usage.prompt_tokens)
        self.prompt_tokens += reply.usage.prompt_tokens
        self.cached_tokens += reply.usage.cached_tokens
        self.completion_tokens += reply.usage.completion_tokens
        return Completion(text=reply.text, model=self.name, usage=reply.usage, truncated=reply.truncated,
                          notes=notes, latency_ms=(time.perf_counter() - started) * 1000.0)

    async def _attempts(self, messages: list[Message], options: ChatOptions, deadline: float,
                        notes: list[str]) -> Reply:
        """Send until a reply, retrying what may pass and moving on from a refused dialect (each
        refusal noted in `notes`); the endpoint counts as negotiated once a structured request
        got a reply or an error that is not a refusal."""
        client, _ = self._session()
        semaphore = self._slots()
        attempt = 0
        while True:
            dialect = self.facts.dialect if options.json_schema is not None else "prompt"
            try:
                async with semaphore:
                    reply = await self._post(client, self._body(messages, options, dialect),
                                             structured=dialect != "prompt", deadline=deadline)
                self.facts.negotiated = True
                return reply
            except DialectRejected as exc:
                moved = self.facts.demote(dialect, exc.message)
                notes.append(f"the server refused structured output as {dialect} ({exc.message[:160]}); "
                             + (f"sent again as {self.facts.dialect}" if moved else "no dialect left"))
                if moved:
                    continue
                raise
            except ContextOverflowError as exc:  # the window is learnt, the dialect not yet
                self.facts.observe(messages, exc.prompt_tokens)
                raise
            except ProviderError as exc:
                self.facts.negotiated |= exc.status is not None  # answered: not a refusal of the dialect
                if not exc.retryable or attempt >= self.max_retries:
                    if attempt:
                        exc.message += f" (gave up after {attempt + 1} attempts)"
                    raise
                wait = self._backoff(attempt + 1, exc.retry_after)
                if time.monotonic() + wait >= deadline:
                    exc.message += (f" (a retry after {wait:.3g} s would end past the call's "
                                    f"{self.deadline:g} s deadline; not retried)")
                    raise
                attempt += 1
                self.retries += 1
                await asyncio.sleep(wait)

    def _session(self) -> tuple[httpx.AsyncClient, asyncio.Semaphore | None]:
        """The client of the running event loop (remade when the loop changes) and its slot
        semaphore (None until `_slots` makes it)."""
        loop = asyncio.get_running_loop()
        if self._client is None or self._loop is not loop:
            timeout = httpx.Timeout(self.timeout, connect=self.connect_timeout)
            limits = httpx.Limits(max_connections=self.concurrency,
                                  max_keepalive_connections=self.concurrency)
            if self._ssl is None:  # made once: loading CA certificates costs ~40 ms
                self._ssl = (httpx.create_ssl_context() if self.base_url.startswith("https:")
                             else ssl.SSLContext(ssl.PROTOCOL_TLS_CLIENT))
            self._client = httpx.AsyncClient(timeout=timeout, limits=limits, headers=self._headers,
                                             verify=self._ssl, follow_redirects=False)
            self._semaphore = None
            self._loop = loop
        return self._client, self._semaphore

    def _slots(self) -> asyncio.Semaphore:
        """The semaphore bounding requests in flight: `concurrency`, or the server's slots when
        fewer (made after the probe, once per event loop)."""
        self._session()
        if self._semaphore is None:
            self._semaphore = asyncio.Semaphore(min(self.concurrency, self.facts.slots or self.concurrency))
        return self._semaphore

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

    async def _post(self, client: httpx.AsyncClient, body: dict[str, Any], structured: bool,
                    deadline: float) -> Reply:
        """One HTTP attempt (`structured`: the body asks for a structured-output dialect): the
        parsed reply, or a classified `ProviderError`."""
        answer = await _request(client, "POST", self.endpoint, deadline, json=body)
        if answer.status >= 300:
            raise self._status_error(answer, structured)
        return self._parse(answer)

    def _status_error(self, answer: HttpReply, structured: bool) -> ProviderError:
        """The error for an HTTP status >= 300; a request with `response_format` that the body
        blames on it is a `DialectRejected`, a context error a `ContextOverflowError`."""
        status, text = answer.status, answer.text
        detail = _error_detail(answer)
        overflow = context_error(text) if status >= 400 else None
        if overflow is not None:
            tokens, window = overflow
            self.facts.learn_window(window, "error")
            return ContextOverflowError(
                f"HTTP {status}: the server's context window of {window} tokens is too small for "
                f"this prompt of {tokens} tokens: {detail}", self.endpoint,
                prompt_tokens=tokens, window=window, estimated=False, status=status)
        if structured and is_rejection(status, text):
            return DialectRejected(f"HTTP {status}: {detail}", self.endpoint, status=status)
        if status in (401, 403):
            message = f"HTTP {status}, access refused: {detail} (check {self._key_hint})"
        elif status == 404:
            message = (f"HTTP 404, not found: {detail} (check the base URL and that model "
                       f"{self.model!r} exists there)")
        else:
            message = f"HTTP {status}: {detail}"
        retry_after = parse_retry_after(answer.headers.get("retry-after"))
        return ProviderError(message, self.endpoint, retryable=status in RETRYABLE_STATUS,
                             status=status, retry_after=retry_after)

    def _parse(self, answer: HttpReply) -> Reply:
        try:
            data = answer.json()
        except ValueError as exc:
            kind = answer.headers.get("content-type", "no content-type")
            raise ProviderError(f"reply is not JSON ({kind}, {exc}): {answer.text[:80]!r}",
                                self.endpoint, status=answer.status) from None
        if not isinstance(data, dict) or not data.get("choices"):
            detail = _error_detail(answer) if isinstance(data, dict) and "error" in data else ""
            raise ProviderError(f"reply has no choices{': ' + detail if detail else ''}",
                                self.endpoint, status=answer.status)
        try:
            reply = _ChatReply.model_validate(data)
        except ValidationError as exc:
            first = exc.errors()[0]
            where = ".".join(str(p) for p in first["loc"])
            raise ProviderError(f"malformed reply at {where}: {clean_text(first['msg'])}", self.endpoint,
                                status=answer.status) from None
        choice = reply.choices[0]
        content = choice.message.content if choice.message else None
        if isinstance(content, list):
            content = "".join(str(p.get("text", "")) for p in content if p.get("type") == "text")
        if not isinstance(content, str):
            refusal = choice.message.refusal if choice.message else None
            extra = f", refusal: {clean_text(refusal)[:200]!r}" if refusal else ""
            raise ProviderError(f"reply has no message content (finish_reason="
                                f"{clean_text(str(choice.finish_reason))[:40]!r}{extra})", self.endpoint,
                                status=answer.status)
        usage = reply.usage or _UsageIn()
        cached = (usage.prompt_tokens_details.cached_tokens if usage.prompt_tokens_details else None)
        if cached is None and reply.timings is not None:
            cached = reply.timings.cache_n
        return Reply(clean_text(content),
                     Usage(prompt_tokens=max(usage.prompt_tokens or 0, 0), cached_tokens=max(cached or 0, 0),
                           completion_tokens=max(usage.completion_tokens or 0, 0)),
                     truncated=choice.finish_reason == "length")


def _positive_int(value: Any) -> bool:
    return isinstance(value, int) and not isinstance(value, bool) and value > 0


async def _request(client: httpx.AsyncClient, method: str, url: str, deadline: float,
                   **kwargs: Any) -> HttpReply:
    """One request whose body is read within `MAX_REPLY_BYTES` (as sent and inflated) and the
    time left before `deadline` (monotonic s); transport failures as `ProviderError`."""
    left = deadline - time.monotonic()
    if left <= 0:
        raise ProviderError("no time left before the call's deadline; not sent", url)
    timeout = client.timeout
    kwargs.setdefault("timeout", httpx.Timeout(min(timeout.read or left, left),
                                               connect=min(timeout.connect or left, left)))
    try:
        async with asyncio.timeout(left), client.stream(method, url, **kwargs) as response:
            declared = response.headers.get("content-length", "")
            if declared.isdigit() and int(declared) > MAX_REPLY_BYTES:
                raise ProviderError(f"reply of {int(declared)} bytes refused (at most {MAX_REPLY_BYTES})",
                                    url, status=response.status_code)
            chunks, size = [], 0
            async for chunk in response.aiter_bytes():
                size += len(chunk)
                if size > MAX_REPLY_BYTES or response.num_bytes_downloaded > MAX_REPLY_BYTES:
                    raise ProviderError(f"reply longer than {MAX_REPLY_BYTES} bytes (as sent or inflated); "
                                        "not read further", url, status=response.status_code)
                chunks.append(chunk)
            return HttpReply(response.status_code, response.headers, b"".join(chunks))
    except TimeoutError:
        raise DeadlineExceeded(f"no complete answer within {left:.3g} s", url) from None
    except httpx.TimeoutException as exc:
        raise ProviderError(f"no reply within the {min(timeout.read or left, left):.3g} s timeout "
                            f"({type(exc).__name__})", url, retryable=True) from exc
    except httpx.ConnectError as exc:
        raise ProviderError(f"connection failed: {exc or type(exc).__name__} (is the server "
                            f"running at {url}?)", url) from exc
    except (httpx.TransportError, httpx.DecodingError) as exc:
        raise ProviderError(f"connection failed: {exc or type(exc).__name__}", url,
                            retryable=isinstance(exc, httpx.TransportError)) from exc


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
    """GET `url` as JSON within `timeout` s and `MAX_REPLY_BYTES`; None on any failure (probes
    are best effort)."""
    try:
        answer = await _request(client, "GET", url, time.monotonic() + timeout)
        return answer.json() if answer.status == 200 else None
    except (ProviderError, ValueError):
        return None


def _error_detail(answer: HttpReply) -> str:
    """The server's error message (`{"error": {"message": ...}}` or the body), shortened."""
    try:
        data = answer.json()
    except ValueError:
        data = None
    if isinstance(data, dict):
        error = data.get("error", data)
        if isinstance(error, dict):
            error = error.get("message") or error.get("detail") or error
        return clean_text(str(error)[:300])
    return (answer.text or f"HTTP {answer.status}, empty body").strip()[:300]


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
