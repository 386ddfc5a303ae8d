"""`iesm serve --http`: streamable HTTP at /mcp, bearer token, DNS-rebinding protection."""

from __future__ import annotations

import asyncio
import json
import os
import re
import signal
import subprocess
import sys
from contextlib import asynccontextmanager

import pytest

pytest.importorskip("mcp")

import httpx2  # noqa: E402
from mcp import Client  # noqa: E402
from mcp.client.streamable_http import streamable_http_client  # noqa: E402

from iesm_agent.server import MapService  # noqa: E402
from iesm_agent.server.app import bind, build_server, http_app, uvicorn_server  # noqa: E402

INIT = {"jsonrpc": "2.0", "id": 1, "method": "initialize",
        "params": {"protocolVersion": "2025-06-18", "capabilities": {}, "clientInfo": {"name": "t", "version": "0"}}}
HEADERS = {"Accept": "application/json, text/event-stream", "Content-Type": "application/json"}


@pytest.fixture(autouse=True)
def _no_embeddings(monkeypatch):
    monkeypatch.setenv("IESM_EMBEDDINGS", "0")


@asynccontextmanager
async def serving(service: MapService, token: str | None):
    """The HTTP server on a free 127.0.0.1 port for the duration of the block; yields its /mcp URL."""
    sock = bind("127.0.0.1", 0)
    server = uvicorn_server(http_app(build_server(service, token), "127.0.0.1", sock.getsockname()[1]))
    task = asyncio.create_task(server.serve(sockets=[sock]))
    try:
        while not server.started:
            assert not task.done(), task.exception()
            await asyncio.sleep(0.01)
        yield f"http://127.0.0.1:{sock.getsockname()[1]}/mcp"
    finally:
        server.should_exit = True
        await asyncio.wait_for(task, 10)
        sock.close()


async def test_token_required_and_checked(apartment_store):
    async with serving(MapService({"apartment": apartment_store}), token="s3cret") as url:
        async with httpx2.AsyncClient() as http:
            missing = await http.post(url, json=INIT, headers=HEADERS)
            wrong = await http.post(url, json=INIT, headers={**HEADERS, "Authorization": "Bearer nope"})
            right = await http.post(url, json=INIT, headers={**HEADERS, "Authorization": "Bearer s3cret"})
        assert missing.status_code == 401 and wrong.status_code == 401
        assert right.status_code == 200 and right.json()["result"]["serverInfo"]["name"] == "iesm-agent"

        authed = httpx2.AsyncClient(headers={"Authorization": "Bearer s3cret"})
        async with authed, Client(streamable_http_client(url, http_client=authed)) as client:
            result = await client.call_tool("find_goal", {"query": "the red chair in the office"})
            found = json.loads(result.content[0].text)
            assert (found["label"], found["room"]) == ("chair", "office")


async def test_dns_rebinding_and_concurrent_calls_without_token(apartment_store):
    async with serving(MapService({"apartment": apartment_store}), token=None) as url:
        async with httpx2.AsyncClient() as http:
            rebound = await http.post(url, json=INIT, headers={**HEADERS, "Host": "evil.example:80"})
            foreign = await http.post(url, json=INIT, headers={**HEADERS, "Origin": "http://evil.example"})
        assert rebound.status_code == 421 and foreign.status_code == 403
        async with Client(url) as client:
            queries = ["the red chair in the office", "the lamp next to the bed", "the fridge"] * 4
            results = await asyncio.gather(*(client.call_tool("find_goal", {"query": q}) for q in queries))
        labels = [json.loads(r.content[0].text)["label"] for r in results]
        assert not any(r.is_error for r in results)
        assert labels[:3] == ["chair", "lamp", "refrigerator"] and labels == labels[:3] * 4


def test_cli_serves_http_and_reads_the_token_from_the_environment():
    env = {**os.environ, "HF_HUB_OFFLINE": "1", "IESM_EMBEDDINGS": "0", "IESM_TOKEN": "t0k"}
    proc = subprocess.Popen([sys.executable, "-m", "iesm_agent.cli", "serve", "apartment", "--http", "127.0.0.1:0"],
                            stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True, env=env)
    try:
        line = proc.stderr.readline()
        match = re.search(r"http://127\.0\.0\.1:(\d+)/mcp", line)
        assert match and "bearer token required" in line, line + proc.stderr.read()
        url = match.group(0)
        assert httpx2.post(url, json=INIT, headers=HEADERS).status_code == 401
        ok = httpx2.post(url, json=INIT, headers={**HEADERS, "Authorization": "Bearer t0k"})
        assert ok.status_code == 200
    finally:
        proc.send_signal(signal.SIGINT)
        code = proc.wait(timeout=20)
    assert code == 0 and proc.stdout.read() == ""


def test_the_start_up_heap_is_frozen_after_warm_up_before_serving(apartment_store, monkeypatch):
    """The cyclic collector's full passes do not walk what start-up built: `serve_http` freezes
    the heap after the warm-up query and before the first request."""
    import gc

    from iesm_agent.server import app

    events: list[str] = []
    service = MapService({"apartment": apartment_store})
    warm_up = service.warm_up

    async def recorded_warm_up():
        await warm_up()
        events.append("warm-up")

    class NoServer:
        async def serve(self, sockets):
            events.append(f"serve (frozen objects: {gc.get_freeze_count() > 0})")

    monkeypatch.setattr(service, "warm_up", recorded_warm_up)
    monkeypatch.setattr(app, "uvicorn_server", lambda _app: NoServer())
    try:
        asyncio.run(app.serve_http(service, "127.0.0.1", 0, None))
    finally:
        gc.unfreeze()  # the test process's heap back to normal
    assert events == ["warm-up", "serve (frozen objects: True)"]


def test_the_server_runs_on_uvloop_when_installed(monkeypatch):
    """`app.run` (what `iesm serve` runs) uses uvloop's event loop when it is importable and
    asyncio's own when it is not."""
    from iesm_agent.server import app

    async def loop_module() -> str:
        return type(asyncio.get_running_loop()).__module__

    def run_and_see() -> str:
        seen: list[str] = []

        async def main() -> None:
            seen.append(await loop_module())

        app.run(main())
        return seen[0]

    try:
        import uvloop  # noqa: F401
    except ImportError:
        pass
    else:
        assert run_and_see().startswith("uvloop")
    monkeypatch.setitem(sys.modules, "uvloop", None)  # not installed
    assert run_and_see().startswith("asyncio")
