"""The MCP server over a `MapService` (official `mcp` SDK, 2.x `MCPServer` API).

Tools are `MapService.tools()`; each served map is also a JSON resource `iesm://maps/<name>`.
A tool's listed input schema is the one `tool_specs()` gives (the same for `iesm tools` and
`MapStore.tool_specs()`); the SDK validates arguments against a pydantic model of the same
signature, and a wrong argument is a tool error in one sentence naming it
(`results.argument_problem`). `IesmError`s (unknown map or instance, over-long query) become
tool errors carrying their message. Results are one JSON text block; `find_goal` also returns
them as structured content under an output schema (`results.FindGoalResult`).

Transports: stdio (protocol only on stdout; logs go to stderr) and streamable HTTP at `/mcp`,
with DNS-rebinding protection and, when a token is given, `Authorization: Bearer <token>`
required on every request (401 otherwise).
"""

from __future__ import annotations

import asyncio
import contextlib
import functools
import gc
import hmac
import json
import logging
import re
import socket
import sys
from typing import Any, Callable, Coroutine

from mcp.server.auth.provider import AccessToken
from mcp.server.auth.settings import AuthSettings
from mcp.server.mcpserver import MCPServer
from mcp.server.mcpserver.exceptions import ToolError
from mcp.server.mcpserver.tools import Tool
from mcp.server.transport_security import TransportSecuritySettings
from mcp.types import CallToolResult, TextContent
from pydantic import ValidationError

from .. import __version__
from ..errors import IesmError
from ..store.tools import function_schema
from .results import FindGoalResult, argument_problem, output_schema
from .tools import MapService, validate_arguments

MCP_PATH = "/mcp"
#: tools whose result is also structured content, with the model giving its output schema
OUTPUT_MODELS = {"find_goal": FindGoalResult}
LOOPBACK_HOSTS = ("127.0.0.1", "localhost", "::1")
_INSTRUCTIONS = ("Goal retrieval over instance-enriched semantic maps: call find_goal with the user's sentence "
                 "to get the map instance it refers to; the other tools browse a map's rooms and instances.")


class StaticTokenVerifier:
    """Accepts exactly one bearer token (compared in constant time)."""

    def __init__(self, token: str):
        self._token = token.encode()

    async def verify_token(self, token: str) -> AccessToken | None:
        if hmac.compare_digest(token.encode(), self._token):
            return AccessToken(token=token, client_id="iesm", scopes=[])
        return None


class _Tool(Tool):
    """An SDK tool whose argument errors read as one sentence naming the argument."""

    async def run(self, arguments: dict[str, Any], context: Any, convert_result: bool = False) -> Any:
        try:
            return await super().run(arguments, context, convert_result)
        except ToolError as exc:
            if isinstance(exc.__cause__, ValidationError) and exc.__cause__.title.endswith("Arguments"):
                raise ToolError(argument_problem(self.name, exc.__cause__)) from exc.__cause__
            raise


def _as_mcp_tool(fn: Callable[..., Any]) -> Tool:
    """An SDK `Tool` for `fn`: the result as one JSON text block (and as structured content
    when `OUTPUT_MODELS` names the tool), `IesmError` -> `ToolError`, the listed input schema
    from `function_schema`."""
    spec = function_schema(fn)
    output_model = OUTPUT_MODELS.get(spec["name"])

    @functools.wraps(fn)
    async def call(**arguments: Any) -> Any:
        try:  # the SDK's own check lets NaN, 1e308 and `true` through: ours is the one for every surface
            result = await fn(**validate_arguments(fn, arguments))
        except IesmError as exc:
            raise ToolError(str(exc)) from exc
        text = [TextContent(type="text", text=json.dumps(result))]  # one block, also for lists
        return CallToolResult(content=text, structured_content=result if output_model else None)

    tool = _Tool.from_function(call, name=spec["name"], description=spec["description"], structured_output=False)
    update: dict[str, Any] = {"parameters": spec["parameters"]}
    if output_model is not None:  # the schema listed; the result is the model's dump already (validated
        # once, by the tool): with the model the SDK validated every result against it again (about 10 us)
        update["fn_metadata"] = tool.fn_metadata.model_copy(update={"output_schema": output_schema(output_model)})
    return tool.model_copy(update=update)


def build_server(service: MapService, token: str | None = None) -> MCPServer:
    """An `MCPServer` serving `service`'s tools and maps; `token` turns on bearer auth (HTTP)."""
    auth: dict[str, Any] = {}
    if token:
        # The SDK's bearer middleware needs AuthSettings; this server is its own issuer.
        auth = {"auth": AuthSettings(issuer_url="http://127.0.0.1", resource_server_url=None),
                "token_verifier": StaticTokenVerifier(token)}
    server = MCPServer("iesm-agent", version=__version__, instructions=_INSTRUCTIONS, log_level="WARNING",
                       tools=[_as_mcp_tool(fn) for fn in service.tools()], **auth)
    for name in service.maps:
        server.resource(f"iesm://maps/{name}", name=name, mime_type="application/json",
                        description=f"map {name}: rooms, categories and every instance in brief")(
            _map_reader(service, name))
    return server


def _map_reader(service: MapService, name: str) -> Callable[[], Any]:
    async def read() -> str:
        return json.dumps(service.map_summary(name))
    return read


def transport_security(host: str, port: int, extra_hosts: tuple[str, ...] = ()) -> TransportSecuritySettings:
    """DNS-rebinding protection, names compared exactly (lower case): Host must be a loopback
    name, `host` (unless a wildcard address) or one of `extra_hosts`, alone or with the port
    served (`port`); Origin, when sent, one of those names over http(s), with or without a port
    (a local page on another port may call; `checked_host_headers` refuses a port that is not a
    number)."""
    names = list(LOOPBACK_HOSTS) + [h for h in (host, *extra_hosts) if h not in ("0.0.0.0", "::", "")]
    names = list(dict.fromkeys(f"[{n}]" if _is_ipv6(n) else n for n in names))
    return TransportSecuritySettings(
        enable_dns_rebinding_protection=True, allowed_hosts=names + [f"{n}:{port}" for n in names],
        allowed_origins=[f"{scheme}://{n}{any_port}" for n in names for scheme in ("http", "https")
                         for any_port in ("", ":*")])


def _is_ipv6(name: str) -> bool:
    import ipaddress

    try:
        return isinstance(ipaddress.ip_address(name), ipaddress.IPv6Address)
    except ValueError:
        return False


def http_app(server: MCPServer, host: str, port: int, extra_hosts: tuple[str, ...] = ()):
    """The Starlette app: streamable HTTP at `/mcp` (JSON responses, per-client sessions) for a
    server listening on `host`:`port`, the Host and Origin headers checked (`checked_host_headers`)."""
    extra_hosts = tuple(h.lower() for h in extra_hosts)
    return checked_host_headers(server.streamable_http_app(
        streamable_http_path=MCP_PATH, json_response=True,
        transport_security=transport_security(host.lower(), port, extra_hosts), host=host))


#: an Origin header as browsers send it: scheme, host (name or [IPv6]) and an optional numeric port
_ORIGIN = re.compile(r"https?://(?:[a-z0-9.-]+|\[[0-9a-f:.]+\])(?::[0-9]{1,5})?")


class checked_host_headers:  # noqa: N801 (an ASGI wrapper used like a function)
    """ASGI wrapper lower-casing the `host` and `origin` request headers, so that the SDK's
    DNS-rebinding check (which compares exactly) accepts `LOCALHOST:port` as `localhost:port`, and
    refusing (403) an Origin that is not scheme://host[:port] with a numeric port, which the SDK's
    `host:*` pattern would let through (`http://localhost:1@evil.example`)."""

    def __init__(self, app):
        self.app = app

    def __getattr__(self, name: str) -> Any:  # the Starlette app's router, state, ...
        return getattr(self.app, name)

    async def __call__(self, scope, receive, send) -> None:
        if scope.get("type") in ("http", "websocket"):
            scope = dict(scope)
            scope["headers"] = [(k, v.lower()) if k in (b"host", b"origin") else (k, v)
                                for k, v in scope.get("headers", [])]
            origin = next((v for k, v in scope["headers"] if k == b"origin"), None)
            if origin is not None and not _ORIGIN.fullmatch(origin.decode("latin-1")):
                from starlette.responses import Response

                await Response("Invalid Origin header", status_code=403)(scope, receive, send)
                return
        await self.app(scope, receive, send)


def is_loopback(host: str) -> bool:
    """Whether `host` (a name or address to bind) only listens on this machine."""
    import ipaddress

    name = host.strip("[]").lower()
    if name == "localhost":
        return True
    try:
        return ipaddress.ip_address(name).is_loopback
    except ValueError:
        return False


def check_exposure(host: str, token: str | None, insecure_no_token: bool) -> None:
    """Refuse to serve a non-loopback address without a bearer token, unless told explicitly."""
    if token or insecure_no_token or is_loopback(host):
        return
    raise IesmError(f"refusing to serve {host} (reachable from other machines) without a token: set "
                    "IESM_TOKEN, bind 127.0.0.1, or pass --insecure-no-token", None, "--http")


def bind(host: str, port: int) -> socket.socket:
    """A listening TCP socket on (host, port); port 0 picks a free one."""
    family = socket.AF_INET6 if ":" in host else socket.AF_INET
    # proto IPPROTO_TCP: asyncio then sets TCP_NODELAY on accepted connections (without it every
    # response waits ~40 ms for the client's delayed ACK)
    sock = socket.socket(family, socket.SOCK_STREAM, socket.IPPROTO_TCP)
    sock.setsockopt(socket.SOL_SOCKET, socket.SO_REUSEADDR, 1)
    try:
        sock.bind((host, port))
    except OSError as exc:
        sock.close()
        raise IesmError(f"cannot listen on {host}:{port}: {exc.strerror or exc}", None, "--http") from None
    sock.listen(128)
    return sock


def uvicorn_server(app, log_level: str = "warning"):
    """A uvicorn server for `app` (logs to stderr); run it with `await s.serve(sockets=[bind(...)])`."""
    import uvicorn

    config = uvicorn.Config(app, log_level=log_level, access_log=False, lifespan="on")
    return uvicorn.Server(config)


def quiet_sdk_logging() -> None:
    """SDK loggers to stderr at WARNING (stdout carries only protocol on stdio)."""
    handler = logging.StreamHandler()  # stderr
    for name in ("mcp", "uvicorn"):
        logger = logging.getLogger(name)
        logger.handlers[:] = [handler]
        logger.setLevel(logging.WARNING)
        logger.propagate = False


def parse_listen(spec: str) -> tuple[str, int]:
    """(host, port) from "HOST:PORT", "[::1]:PORT", ":PORT" or "PORT" (host defaults to 127.0.0.1)."""
    host, sep, port = spec.strip().rpartition(":")
    if not sep:
        host, port = "", spec.strip()
    host = host.strip("[]") or "127.0.0.1"
    if not port.isdigit() or not 0 <= int(port) <= 65535:
        raise IesmError(f"expected HOST:PORT, got {spec!r}", None, "--http")
    return host, int(port)


def freeze_start_up_heap() -> None:
    """Collect, then move everything start-up built (maps, parser, encoder, warm caches: about
    250,000 objects) out of the cyclic garbage collector's sight (`gc.freeze`): its full passes,
    about 100 ms of CPU each with them, come every few hundred queries and land on one burst of
    calls. Frozen objects are still freed by reference counting."""
    gc.collect()
    gc.freeze()


def event_loop_factory() -> Callable[[], asyncio.AbstractEventLoop] | None:
    """uvloop's event loop when it is installed (the `mcp` extra installs it where it builds: not on
    Windows), else None for asyncio's own. With uvicorn's httptools parser it took a no-op MCP tool's
    server CPU per call over HTTP from 1.41 ms (asyncio, h11) to 0.90 ms (`benchmarks/sdk_loop_ab.py`,
    docs/performance.md, "Fifth round")."""
    try:
        import uvloop
    except ImportError:
        return None
    return uvloop.new_event_loop


def run(main: Coroutine[Any, Any, None]) -> None:
    """Run `main` (`serve_stdio(...)` or `serve_http(...)`) to completion on `event_loop_factory()`'s loop."""
    with asyncio.Runner(loop_factory=event_loop_factory()) as runner:
        runner.run(main)


async def serve_stdio(service: MapService) -> None:
    """Warm the service up, then speak MCP on stdin/stdout until stdin closes."""
    quiet_sdk_logging()
    with contextlib.redirect_stdout(sys.stderr):  # nothing but protocol on stdout
        await service.warm_up()
    freeze_start_up_heap()
    try:
        await build_server(service).run_stdio_async()
    finally:
        await service.aclose()


async def serve_http(service: MapService, host: str, port: int, token: str | None,
                     extra_hosts: tuple[str, ...] = ()) -> None:
    """Warm the service up, then serve streamable HTTP on host:port until interrupted."""
    quiet_sdk_logging()
    sock = bind(host, port)
    await service.warm_up()
    server = uvicorn_server(http_app(build_server(service, token), host, sock.getsockname()[1], extra_hosts))
    freeze_start_up_heap()
    bound = sock.getsockname()
    shown = f"[{bound[0]}]" if ":" in bound[0] else bound[0]
    print(f"iesm serve: MCP on http://{shown}:{bound[1]}{MCP_PATH} ({', '.join(service.maps)}; "
          f"{'bearer token required' if token else 'no token: set IESM_TOKEN to require one'})",
          file=sys.stderr, flush=True)
    try:
        await server.serve(sockets=[sock])
    finally:
        sock.close()
        await service.aclose()
