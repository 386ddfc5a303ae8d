"""`iesm serve`: the MCP server over maps; `iesm tools`: the same tools as JSON schemas."""

from __future__ import annotations

import json
import os
from typing import Optional

import typer

from ..errors import IesmError


def serve_command(
    maps: list[str] = typer.Argument(..., metavar="MAP",
                                     help="Maps to serve: .iesm files, importable JSON maps or shipped names."),
    stdio: bool = typer.Option(False, "--stdio", help="Speak MCP on stdin/stdout (the default)."),
    http: Optional[str] = typer.Option(None, "--http", metavar="HOST:PORT",
                                       help="Serve streamable HTTP at /mcp (host defaults to 127.0.0.1)."),
    providers: list[str] = typer.Option(["offline"], "--provider", "-p",
                                        help="Model spec callers may use (repeatable; the first is the default)."),
    allowed_hosts: list[str] = typer.Option([], "--allowed-host",
                                            help="Extra Host header accepted over HTTP: NAME (alone or with the port served) or "
                                                 "NAME:PORT as sent (repeatable)."),
    insecure_no_token: bool = typer.Option(False, "--insecure-no-token",
                                           help="Serve a non-loopback address without IESM_TOKEN (anyone who "
                                                "reaches it may call the tools)."),
) -> None:
    """Serve goal retrieval and map tools to assistants over the Model Context Protocol.

    Over HTTP, when IESM_TOKEN is set every request must carry `Authorization: Bearer <token>`;
    a non-loopback address needs IESM_TOKEN (or --insecure-no-token)."""
    if stdio and http:
        raise IesmError("choose one of --stdio and --http", None, "transport")
    try:
        from ..server import app
    except ModuleNotFoundError as exc:
        if exc.name and exc.name.split(".")[0] == "mcp":
            raise IesmError("the MCP SDK is missing: install iesm-agent[mcp]", None, "serve") from None
        raise
    from ..server import MapService

    listen = app.parse_listen(http) if http is not None else None
    token = os.environ.get("IESM_TOKEN") or None
    if listen is not None:
        app.check_exposure(listen[0], token, insecure_no_token)
    service = MapService.open(maps, tuple(dict.fromkeys(providers)))
    if listen is None:
        app.run(app.serve_stdio(service))
        return
    host, port = listen
    try:
        app.run(app.serve_http(service, host, port, token, tuple(allowed_hosts)))
    except KeyboardInterrupt:
        pass


def tools_command(
    fmt: str = typer.Option("openai", "--format", "-f", help="openai (function-calling `tools`), mcp or json."),
) -> None:
    """Print the assistant tools (the ones `iesm serve` offers) as JSON schemas."""
    from ..server import format_specs, tool_specs

    print(json.dumps(format_specs(tool_specs(), fmt), indent=2))


def register(app: typer.Typer) -> None:
    app.command("serve")(serve_command)
    app.command("tools")(tools_command)
