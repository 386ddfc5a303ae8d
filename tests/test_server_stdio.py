"""`iesm serve --stdio` as a subprocess: a tool call over real stdio, and nothing but protocol on stdout."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import pytest

pytest.importorskip("mcp")

from mcp import Client, StdioServerParameters  # noqa: E402
from mcp_types.version import LATEST_HANDSHAKE_VERSION  # noqa: E402

SERVE = [sys.executable, "-m", "iesm_agent.cli", "serve", "apartment", "--stdio"]


def _env() -> dict[str, str]:
    return {**os.environ, "HF_HUB_OFFLINE": "1", "IESM_EMBEDDINGS": "0"}


async def test_tool_call_over_stdio_with_the_sdk_client():
    params = StdioServerParameters(command=SERVE[0], args=SERVE[1:], env=_env())
    async with Client(params, read_timeout_seconds=60) as client:
        assert "find_goal" in {t.name for t in (await client.list_tools()).tools}
        result = await client.call_tool("find_goal", {"query": "something to sit on in the living room"})
        assert not result.is_error, result.content[0].text
        found = json.loads(result.content[0].text)
        assert found["room"] == "living room" and found["label"] in ("sofa", "armchair")
        bad = await client.call_tool("get_instance", {"instance_id": -5})
        assert bad.is_error and "unknown instance id -5" in bad.content[0].text


def test_stdout_carries_only_json_rpc():
    messages = [
        {"jsonrpc": "2.0", "id": 1, "method": "initialize",
         "params": {"protocolVersion": LATEST_HANDSHAKE_VERSION, "capabilities": {},
                    "clientInfo": {"name": "raw", "version": "0"}}},
        {"jsonrpc": "2.0", "method": "notifications/initialized"},
        {"jsonrpc": "2.0", "id": 2, "method": "tools/call",
         "params": {"name": "find_goal", "arguments": {"query": "the lamp next to the bed"}}},
        {"jsonrpc": "2.0", "id": 3, "method": "tools/call",
         "params": {"name": "find_goal", "arguments": {"query": "z" * 100_000}}},
    ]
    proc = subprocess.Popen(SERVE, stdin=subprocess.PIPE, stdout=subprocess.PIPE, stderr=subprocess.PIPE,
                            text=True, env=_env())
    replies = []
    try:
        for message in messages:
            proc.stdin.write(json.dumps(message) + "\n")
            proc.stdin.flush()
            if "id" in message:  # every line on stdout is a JSON-RPC message
                replies.append(json.loads(proc.stdout.readline()))
        proc.stdin.close()
        rest, err = proc.stdout.read(), proc.stderr.read()
        assert proc.wait(timeout=60) == 0, err
    finally:
        if proc.poll() is None:
            proc.kill()
    replies += [json.loads(line) for line in rest.splitlines()]
    by_id = {r["id"]: r for r in replies if "id" in r}
    assert set(by_id) == {1, 2, 3} and all(r["jsonrpc"] == "2.0" for r in replies)
    found = json.loads(by_id[2]["result"]["content"][0]["text"])
    assert (found["label"], found["room"]) == ("lamp", "bedroom")
    too_long = by_id[3]["result"]
    assert too_long["isError"] and "at most" in too_long["content"][0]["text"]
