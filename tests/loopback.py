"""A real chat-completions HTTP server on 127.0.0.1 that answers with any `Model`.

For tests and benchmarks of HTTP clients and of everything built on them::

    with LoopbackServer(FunctionModel(lambda m, o: "hi"), delay_s=0.2,
                        faults=["500", Fault.rate_limited(0.1), None]) as server:
        model = get_model("openai-compat:any", base_url=server.base_url)
        ...
        server.request_count, server.max_in_flight, server.requests[0].fault

Each request takes the next fault from `faults` (a list, consumed in order; `None` = serve
normally) or asks `faults(index, body)` when it is a callable. Requests run on their own
threads, so concurrent requests overlap (`delay_s` is slept per request, outside any lock).

`flavour` imitates a real server's structured-output dialect and context window (the table in
docs/providers.md); `context_window` (tokens, counted as 4 characters + 4 per message) turns
on its over-long-prompt behaviour: an error in that server's wording, or for `ollama` the
silent cut of the prompt's start (`RequestRecord.truncated`).
"""

from __future__ import annotations

import json
import threading
import time
from collections import deque
from dataclasses import dataclass, field
from http.server import BaseHTTPRequestHandler, ThreadingHTTPServer
from typing import Any, Callable, Iterable, Literal, Optional, Union, get_args

from pydantic import ValidationError

from iesm_agent.providers import endpoint
from iesm_agent.providers.base import ChatOptions, ImagePart, Message, Model, TextPart

Flavour = Literal["openai", "vllm", "lmstudio", "llama-cpp-python", "llama.cpp", "ollama"]
#: response_format types each flavour accepts on /v1/chat/completions
_ACCEPTS: dict[str, tuple[str, ...]] = {
    "openai": ("json_schema", "json_object"), "vllm": ("json_schema", "json_object"),
    "lmstudio": ("json_schema",), "llama-cpp-python": ("json_object",),
    "llama.cpp": ("json_schema", "json_object"), "ollama": ("json_schema", "json_object")}
#: Ollama's own default num_ctx when a request does not set one
OLLAMA_DEFAULT_CTX = 2048

FaultKind = Literal["slow", "status", "non_json", "no_choices", "no_content", "bad_reply",
                    "reject_response_format"]


@dataclass(frozen=True)
class Fault:
    """One misbehaviour of the server for one request.

    * `slow`: sleep `seconds` before answering (set it past the client's timeout);
    * `status`: answer HTTP `status` with an OpenAI-style error body (and `Retry-After:
      retry_after` when given) - e.g. 500, 429, 401, 404;
    * `non_json`: HTTP 200 with an HTML body;
    * `no_choices`: HTTP 200 with JSON lacking `choices`;
    * `no_content`: HTTP 200 with a choice whose message content is null;
    * `bad_reply`: a normal completion whose text is `text` (not the JSON the prompt asked for);
    * `reject_response_format`: HTTP 400 naming `response_format` if the request carries one,
      otherwise served normally (a server without structured output).
    """

    kind: FaultKind
    status: int = 500
    retry_after: Optional[str] = None
    seconds: float = 1.0
    text: str = "Sorry, I cannot help with that."

    @classmethod
    def slow(cls, seconds: float) -> "Fault":
        return cls("slow", seconds=seconds)

    @classmethod
    def http(cls, status: int, retry_after: float | str | None = None) -> "Fault":
        return cls("status", status=status,
                   retry_after=None if retry_after is None else str(retry_after))

    @classmethod
    def rate_limited(cls, retry_after: float | str = 1) -> "Fault":
        return cls.http(429, retry_after)

    @classmethod
    def bad_reply(cls, text: str = "Sorry, I cannot help with that.") -> "Fault":
        return cls("bad_reply", text=text)

    @classmethod
    def parse(cls, spec: Union["Fault", str, int, None]) -> Optional["Fault"]:
        """A `Fault` from a shorthand: an HTTP status (`500`, `"429"`), or a kind name
        (`"slow"`, `"non_json"`, `"no_choices"`, `"no_content"`, `"bad_reply"`,
        `"reject_response_format"`); `None` and `Fault` pass through."""
        if spec is None or isinstance(spec, Fault):
            return spec
        if isinstance(spec, int) or str(spec).isdigit():
            return cls.http(int(spec))
        if spec in get_args(FaultKind) and spec != "status":
            return cls(spec)  # type: ignore[arg-type]
        raise ValueError(f"unknown fault {spec!r}")


FaultSource = Union[Iterable[Union[Fault, str, int, None]],
                    Callable[[int, dict[str, Any]], Union[Fault, str, int, None]]]


@dataclass
class RequestRecord:
    """One request the server received (`headers` with lower-case names, `body` parsed JSON or
    text). `status` is what it answered (0 while in flight or when the client hung up first)."""

    index: int
    path: str
    headers: dict[str, str]
    body: Any
    fault: Optional[Fault]
    status: int = 0
    prompt_tokens: int = 0
    truncated: bool = False
    started: float = field(default_factory=time.perf_counter)
    finished: float = 0.0


class LoopbackServer:
    """Chat-completions server on 127.0.0.1 with an ephemeral port, run in a background thread.

    `base_url` (`http://127.0.0.1:<port>/v1`) is what clients use; `requests` logs every
    chat request; `probes` every other path asked (GET /v1/models, /props, POST /api/show);
    `max_in_flight` is the most requests seen at once. Use as a context manager or call
    `start()` / `close()`.
    """

    def __init__(self, model: Model, *, delay_s: float = 0.0, faults: FaultSource | None = None,
                 flavour: Flavour = "openai", context_window: int | None = None,
                 model_context_length: int = 32768):
        self.model = model
        self.delay_s = float(delay_s)
        self.flavour = flavour
        self.context_window = context_window
        self.model_context_length = model_context_length
        self.probes: list[str] = []
        if callable(faults):
            self._fault_fn: Callable[[int, dict[str, Any]], Any] | None = faults
            self._fault_queue: deque[Any] = deque()
        else:
            self._fault_fn = None
            self._fault_queue = deque(Fault.parse(f) for f in (faults or ()))
        self.requests: list[RequestRecord] = []
        self.max_in_flight = 0
        self._in_flight = 0
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._httpd: ThreadingHTTPServer | None = None
        self._thread: threading.Thread | None = None
        self._port: int | None = None

    # lifecycle -----------------------------------------------------------------
    def start(self) -> "LoopbackServer":
        handler = type("_Handler", (_Handler,), {"owner": self})
        httpd = ThreadingHTTPServer(("127.0.0.1", 0), handler, bind_and_activate=False)
        httpd.daemon_threads = True
        httpd.request_queue_size = 128
        httpd.server_bind()
        httpd.server_activate()
        self._httpd = httpd
        self._port = httpd.server_address[1]
        # a new server, even on a port an earlier test's server had: what the process learnt
        # about that address (dialect, window) is not this server's
        for key in [k for k in endpoint._FACTS if k[0] == f"http://127.0.0.1:{self._port}" or
                    k[0].startswith(f"http://127.0.0.1:{self._port}/")]:
            del endpoint._FACTS[key]
        self._thread = threading.Thread(target=httpd.serve_forever, kwargs={"poll_interval": 0.05},
                                        name="iesm-loopback", daemon=True)
        self._thread.start()
        return self

    def close(self) -> None:
        """Stop serving; requests still sleeping in a `slow` fault are abandoned."""
        self._stop.set()
        if self._httpd is not None:
            self._httpd.shutdown()
            self._httpd.server_close()
            self._httpd = None
        if self._thread is not None:
            self._thread.join()
            self._thread = None

    def __enter__(self) -> "LoopbackServer":
        return self.start()

    def __exit__(self, *exc: Any) -> None:
        self.close()

    @property
    def port(self) -> int:
        """The bound port (kept after `close`, so logs and errors can still be matched)."""
        if self._port is None:
            raise RuntimeError("LoopbackServer was never started")
        return self._port

    @property
    def base_url(self) -> str:
        return f"http://127.0.0.1:{self.port}/v1"

    @property
    def root_url(self) -> str:
        """The server root (Ollama's native API and llama.cpp's /props live here)."""
        return f"http://127.0.0.1:{self.port}"

    def info(self, path: str) -> tuple[int, bytes]:
        """Answer a GET (or Ollama's POST /api/show) the way this flavour does."""
        self.probes.append(path)
        path = path.rstrip("/")
        if path.endswith("/v1/models"):
            entry: dict[str, Any] = {"id": "loopback", "object": "model"}
            if self.flavour == "vllm" and self.context_window:
                entry["max_model_len"] = self.context_window
            return 200, _json({"object": "list", "data": [entry]})
        if path == "/props" and self.flavour == "llama.cpp":
            return 200, _json({"default_generation_settings": {"n_ctx": self.context_window or 4096}})
        if path == "/api/show" and self.flavour == "ollama":
            return 200, _json({"model_info": {"general.architecture": "gemma3",
                                              "gemma3.context_length": self.model_context_length},
                               "parameters": "stop \"<end_of_turn>\""})
        return 404, _json({"error": {"message": f"no route {path}"}})

    @property
    def request_count(self) -> int:
        return len(self.requests)

    # per-request bookkeeping (called from handler threads) ---------------------
    def _begin(self, path: str, headers: dict[str, str], body: Any) -> RequestRecord:
        with self._lock:
            index = len(self.requests)
            if self._fault_fn is not None:
                fault = Fault.parse(self._fault_fn(index, body if isinstance(body, dict) else {}))
            else:
                fault = self._fault_queue.popleft() if self._fault_queue else None
            record = RequestRecord(index, path, headers, body, fault)
            self.requests.append(record)
            self._in_flight += 1
            self.max_in_flight = max(self.max_in_flight, self._in_flight)
        return record

    def _end(self, record: RequestRecord, status: int) -> None:
        with self._lock:
            self._in_flight -= 1
            record.status = status
            record.finished = time.perf_counter()

    def _answer(self, record: RequestRecord) -> tuple[int, dict[str, str], bytes]:
        """Status, extra headers and body for one request."""
        if self.delay_s:
            self._stop.wait(self.delay_s)
        fault, body = record.fault, record.body
        kind = fault.kind if fault is not None else None
        if kind == "slow":
            if self._stop.wait(fault.seconds):
                return 503, {}, _json({"error": {"message": "server shutting down"}})
        if kind == "status":
            headers = {"Retry-After": fault.retry_after} if fault.retry_after else {}
            return fault.status, headers, _json({"error": {"message": f"injected HTTP {fault.status}",
                                                           "code": fault.status}})
        if kind == "non_json":
            return 200, {"Content-Type": "text/html"}, b"<html><body>502 Bad Gateway</body></html>"
        if kind == "no_choices":
            return 200, {}, _json({"id": "x", "object": "chat.completion", "model": "loopback"})
        if kind == "reject_response_format" and isinstance(body, dict) and "response_format" in body:
            return 400, {}, _json({"error": {"message": "response_format is not supported by "
                                             "this server", "param": "response_format"}})
        native = record.path.rstrip("/") == "/api/chat"
        rejected = None if native else self._rejection(body)
        if rejected is not None:
            return rejected
        try:
            messages, options = (_parse_ollama if native else _parse_request)(body)
        except (ValueError, ValidationError) as exc:
            return 400, {}, _json({"error": {"message": f"bad request: {exc}"}})
        record.prompt_tokens = count_tokens(messages)
        too_long = self._context(record, messages, body if native else None)
        if too_long is not None:
            return too_long
        if kind == "bad_reply":
            text, usage = fault.text, {"prompt_tokens": 0, "completion_tokens": 0}
        else:
            try:
                completion = self.model.complete(messages, options)
            except Exception as exc:  # the served model failed: a server answers 500
                return 500, {}, _json({"error": {"message": f"model failed: {exc}"}})
            text, usage = completion.text, completion.usage.model_dump()
        usage["prompt_tokens"] = usage["prompt_tokens"] or record.prompt_tokens
        content = None if kind == "no_content" else text
        if native:
            return 200, {}, _json({"model": body.get("model"), "created_at": "2026-01-01T00:00:00Z",
                                   "message": {"role": "assistant", "content": content},
                                   "done": True, "done_reason": "stop",
                                   "prompt_eval_count": usage["prompt_tokens"],
                                   "eval_count": usage["completion_tokens"]})
        return 200, {}, _json({
            "id": f"chatcmpl-{record.index}", "object": "chat.completion",
            "created": int(time.time()), "model": body.get("model", "loopback"),
            "choices": [{"index": 0, "finish_reason": "stop",
                         "message": {"role": "assistant", "content": content}}],
            "usage": {**usage, "total_tokens": sum(usage.values())}})


    def _rejection(self, body: Any) -> tuple[int, dict[str, str], bytes] | None:
        """This flavour's answer to a response_format type it does not take (None if taken)."""
        fmt = body.get("response_format") if isinstance(body, dict) else None
        kind = fmt.get("type") if isinstance(fmt, dict) else None
        if kind in (None, "text") or kind in _ACCEPTS[self.flavour]:
            return None
        if self.flavour == "llama-cpp-python":  # its pydantic validation error, as HTTP 500
            return 500, {}, _json({"error": {"message": (
                "1 validation error for CreateChatCompletionRequest\nresponse_format.type\n  "
                f"Input should be 'text' or 'json_object' [type=literal_error, input_value='{kind}']"),
                "type": "internal_server_error"}})
        return 400, {}, _json({"error": {"message": (
            f"'response_format.type' must be one of {list(_ACCEPTS[self.flavour])}, got {kind!r}")}})

    def _context(self, record: RequestRecord, messages: list[Message],
                 native: dict[str, Any] | None) -> tuple[int, dict[str, str], bytes] | None:
        """A prompt over the window: this flavour's error, or for Ollama's native API the
        silent cut of the prompt's start (`messages` edited in place, `record.truncated`)."""
        tokens = record.prompt_tokens
        if native is not None:
            options = native.get("options") if isinstance(native.get("options"), dict) else {}
            window = int(options.get("num_ctx") or OLLAMA_DEFAULT_CTX)
            if tokens > window:
                record.truncated = True
                last = messages[-1]
                keep = max(0, len(last.text()) - 4 * (tokens - window))
                messages[-1] = Message(role=last.role, content=last.text()[-keep:] if keep else "")
            return None
        window = self.context_window
        if window is None or tokens <= window:
            return None
        if self.flavour == "llama-cpp-python":
            message = f"Requested tokens ({tokens}) exceed context window of {window}"
            return 400, {}, _json({"error": {"message": message, "type": "invalid_request_error",
                                             "code": "context_length_exceeded"}})
        if self.flavour == "llama.cpp":
            return 400, {}, _json({"error": {
                "code": 400, "message": "the request exceeds the available context size, try "
                "increasing it", "type": "exceed_context_size_error",
                "n_prompt_tokens": tokens, "n_ctx": window}})
        return 400, {}, _json({"error": {"message": (
            f"This model's maximum context length is {window} tokens. However, you requested "
            f"{tokens} tokens ({tokens} in the messages, 0 in the completion)."),
            "type": "BadRequestError", "code": 400}})


def count_tokens(messages: list[Message]) -> int:
    """The loopback server's token count: 4 characters a token plus 4 per message."""
    return sum(-(-len(m.text()) // 4) + 4 for m in messages)


class _Handler(BaseHTTPRequestHandler):
    protocol_version = "HTTP/1.1"
    disable_nagle_algorithm = True  # headers and body go out in two writes: avoid 40 ms ACK stalls
    owner: LoopbackServer

    def log_message(self, format: str, *args: Any) -> None:  # noqa: A002 - stdlib signature
        """Silence the default per-request stderr log (the owner keeps `requests`)."""

    def do_GET(self) -> None:  # noqa: N802 - stdlib naming
        self._send(*_with_headers(self.owner.info(self.path)))

    def do_POST(self) -> None:  # noqa: N802 - stdlib naming
        raw = self.rfile.read(int(self.headers.get("Content-Length") or 0))
        path = self.path.rstrip("/")
        native = self.owner.flavour == "ollama" and path == "/api/chat"
        if not (path.endswith("/chat/completions") or native):
            self._send(*_with_headers(self.owner.info(path)))
            return
        try:
            body: Any = json.loads(raw)
        except ValueError:
            body = raw.decode("utf-8", "replace")
        headers = {k.lower(): v for k, v in self.headers.items()}
        record = self.owner._begin(self.path, headers, body)
        try:
            status, reply_headers, payload = self.owner._answer(record)
        except BaseException:
            self.owner._end(record, 0)
            raise
        # counted out before replying: a client that sends its next request as soon as this
        # reply arrives must not find this one still in flight
        self.owner._end(record, status)
        try:
            self._send(status, reply_headers, payload)
        except (BrokenPipeError, ConnectionResetError):
            record.status = 0  # the client gave up (e.g. its timeout fired during a slow fault)

    def _send(self, status: int, headers: dict[str, str], payload: bytes) -> None:
        self.send_response(status)
        headers = {"Content-Type": "application/json", **headers}
        for name, value in headers.items():
            self.send_header(name, value)
        self.send_header("Content-Length", str(len(payload)))
        self.end_headers()
        self.wfile.write(payload)


def _json(data: Any) -> bytes:
    return json.dumps(data).encode()


def _with_headers(answer: tuple[int, bytes]) -> tuple[int, dict[str, str], bytes]:
    return answer[0], {}, answer[1]


def _parse_request(body: Any) -> tuple[list[Message], ChatOptions]:
    """Chat-completions request JSON -> messages and options (raises ValueError if malformed)."""
    if not isinstance(body, dict) or not isinstance(body.get("messages"), list):
        raise ValueError("body must be a JSON object with a 'messages' list")
    messages = []
    for raw in body["messages"]:
        content = raw.get("content") if isinstance(raw, dict) else None
        if isinstance(content, list):
            content = [_parse_part(p) for p in content]
        messages.append(Message.model_validate({"role": raw.get("role") if isinstance(raw, dict)
                                                else None, "content": content}))
    schema = None
    fmt = body.get("response_format")
    if isinstance(fmt, dict) and fmt.get("type") == "json_schema":
        spec = fmt.get("json_schema")
        schema = spec.get("schema") if isinstance(spec, dict) else None
    elif isinstance(fmt, dict) and fmt.get("type") == "json_object":
        schema = fmt.get("schema") if isinstance(fmt.get("schema"), dict) else {"type": "object"}
    options = ChatOptions(temperature=body.get("temperature", 0.0),
                          max_tokens=body.get("max_tokens"), seed=body.get("seed"),
                          json_schema=schema)
    return messages, options


def _parse_ollama(body: Any) -> tuple[list[Message], ChatOptions]:
    """Ollama /api/chat request JSON -> messages and options (`format` a schema or "json")."""
    if not isinstance(body, dict) or not isinstance(body.get("messages"), list):
        raise ValueError("body must be a JSON object with a 'messages' list")
    messages = []
    for raw in body["messages"]:
        if not isinstance(raw, dict):
            raise ValueError("each message must be an object")
        parts: list[TextPart | ImagePart] = [TextPart(text=str(raw.get("content", "")))]
        parts += [ImagePart(data=str(i)) for i in raw.get("images") or []]
        messages.append(Message(role=raw.get("role"), content=parts if len(parts) > 1 else parts[0].text))
    fmt = body.get("format")
    options = body.get("options") if isinstance(body.get("options"), dict) else {}
    return messages, ChatOptions(temperature=options.get("temperature", 0.0),
                                 max_tokens=options.get("num_predict"), seed=options.get("seed"),
                                 json_schema=fmt if isinstance(fmt, dict) else
                                 {"type": "object"} if fmt == "json" else None)


def _parse_part(part: Any) -> TextPart | ImagePart:
    if isinstance(part, dict) and part.get("type") == "image_url":
        image = part.get("image_url")
        url = str(image.get("url", "")) if isinstance(image, dict) else ""
        head, _, data = url.partition(",")
        if not head.startswith("data:") or not head.endswith(";base64"):
            raise ValueError("image_url must be a base64 data URL")
        return ImagePart(data=data, mime_type=head[5:-7] or "image/png")
    return TextPart.model_validate(part)
