"""`iesm serve` over HTTP with the offline model: find_goal latency on a warm server, 40 concurrent
calls, and one call against `iesm ask` in a fresh process.

The server runs as its own process (`iesm serve apartment --http 127.0.0.1:0`, embeddings as
installed); the client is the MCP SDK's. Queries come from the shipped apartment suites (96,
shuffled with a fixed seed): 40 are asked one by one, each for the first time (per-query caches
cold, the server warm), then asked again (repeats); 40 others are sent at once.

Targets (DESIGN.md, issue 23): find_goal on a warm server p50 <= 20 ms; 40 concurrent calls with
p50 <= 30 ms and no failure. For scale, the same burst of `list_maps` (no retrieval: the MCP
transport, client and server alone on the same cores) is measured too.

The client is this process and the server another, but both share the machine's cores: the
CPU each spends during a burst (server: user + system time from /proc/<pid>/stat, Linux only;
client: this process's `time.process_time()`) is reported per call, so a burst's latency can be
read against the work it took on each side.

Run: .venv/bin/python benchmarks/bench_server.py [--concurrent 40]
"""

from __future__ import annotations

import argparse
import asyncio
import json
import os
import random
import re
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from results_io import record  # noqa: E402

REPO = Path(__file__).resolve().parents[1]
SUITES = ("evals/apartment_suite.jsonl", "evals/apartment_human_suite.jsonl")
ASK_QUERY = "the red leather chair in the office"


def queries(seed: int = 7) -> list[str]:
    lines = [json.loads(line) for s in SUITES for line in (REPO / s).read_text().splitlines() if line.strip()]
    out = list(dict.fromkeys(q["query"] for q in lines))
    random.Random(seed).shuffle(out)
    return out


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(q * (len(ordered) - 1)))]


def start_server(env: dict[str, str]) -> tuple[subprocess.Popen, str, float]:
    """The server process, its /mcp URL and its start-up time in s (maps + model loaded, warm-up query done)."""
    started = time.perf_counter()
    proc = subprocess.Popen([sys.executable, "-m", "iesm_agent.cli", "serve", "apartment", "--http", "127.0.0.1:0"],
                            stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True, env=env, cwd=REPO)
    seen = []
    for line in proc.stderr:  # progress lines (encoder loading), then the URL
        seen.append(line)
        match = re.search(r"http://127\.0\.0\.1:\d+/mcp", line)
        if match:
            return proc, match.group(0), time.perf_counter() - started
    proc.kill()
    raise SystemExit(f"server did not start: {''.join(seen)}")


async def timed_call(client, query: str) -> tuple[float, bool]:
    """(wall ms, failed) of one find_goal call."""
    t0 = time.perf_counter()
    try:
        result = await client.call_tool("find_goal", {"query": query})
        failed = result.is_error or not (result.structured_content or {}).get("found")
    except Exception:  # a transport failure counts as a failure, the benchmark goes on
        failed = True
    return (time.perf_counter() - t0) * 1000.0, failed


def process_cpu_s(pid: int) -> float | None:
    """User + system CPU seconds process `pid` has used so far (Linux /proc; None elsewhere)."""
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()
    except OSError:
        return None
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime, stime (ticks)


async def measure(url: str, server_pid: int, sequential: list[str], concurrent: list[str]) -> dict[str, object]:
    from mcp import Client

    async with Client(url) as client:
        first = [await timed_call(client, q) for q in sequential]
        repeat = [await timed_call(client, q) for q in sequential]
        ask_warm = statistics.median([(await timed_call(client, ASK_QUERY))[0] for _ in range(5)])
        server0, client0, t0 = process_cpu_s(server_pid), time.process_time(), time.perf_counter()
        burst = await asyncio.gather(*(timed_call(client, q) for q in concurrent))
        wall = time.perf_counter() - t0
        server1, client1 = process_cpu_s(server_pid), time.process_time()
        floor = await asyncio.gather(*(timed_list_maps(client) for _ in concurrent))
    server_cpu = None if server0 is None or server1 is None else server1 - server0
    return {"first": first, "repeat": repeat, "burst": burst, "burst_wall_s": wall, "ask_warm_ms": ask_warm,
            "floor": floor, "burst_server_cpu_s": server_cpu, "burst_client_cpu_s": client1 - client0}


async def timed_list_maps(client) -> float:
    """Wall ms of one `list_maps` call (transport and protocol cost alone)."""
    t0 = time.perf_counter()
    await client.call_tool("list_maps", {})
    return (time.perf_counter() - t0) * 1000.0


def ask_cold_s(env: dict[str, str], repeat: int = 3) -> float:
    """Median wall time of `iesm ask apartment ASK_QUERY` in a fresh process."""
    times = []
    for _ in range(repeat):
        t0 = time.perf_counter()
        subprocess.run([sys.executable, "-m", "iesm_agent.cli", "ask", "apartment", ASK_QUERY], env=env, cwd=REPO,
                       check=True, capture_output=True)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def run_config(env: dict[str, str], sequential: list[str], concurrent: list[str]) -> dict[str, float]:
    """Start a server with `env`, measure, stop it, time `iesm ask` cold; the figures, printed too."""
    proc, url, startup_s = start_server(env)
    try:
        m = asyncio.run(measure(url, proc.pid, sequential, concurrent))
    finally:
        proc.terminate()
        proc.wait(timeout=30)
    cold_ms = ask_cold_s(env) * 1000
    first_ms = [t for t, _ in m["first"]]
    repeat_ms = [t for t, _ in m["repeat"]]
    burst_ms = [t for t, _ in m["burst"]]
    out = {"startup_s": startup_s, "p50_first": statistics.median(first_ms), "p95_first": percentile(first_ms, 0.95),
           "p50_repeat": statistics.median(repeat_ms), "p95_repeat": percentile(repeat_ms, 0.95),
           "burst_wall_s": m["burst_wall_s"], "throughput": len(burst_ms) / m["burst_wall_s"],
           "burst_p50": statistics.median(burst_ms), "burst_p95": percentile(burst_ms, 0.95),
           "burst_failures": sum(failed for _, failed in m["burst"]), "burst_n": len(burst_ms),
           "warm_ms": m["ask_warm_ms"], "cold_ms": cold_ms, "floor_p50": statistics.median(m["floor"]),
           "burst_client_cpu_ms": m["burst_client_cpu_s"] * 1000 / len(burst_ms),
           "burst_server_cpu_ms": (None if m["burst_server_cpu_s"] is None
                                   else m["burst_server_cpu_s"] * 1000 / len(burst_ms))}
    print(f"  server start-up (maps, model, warm-up query): {out['startup_s']:.2f} s")
    print(f"  find_goal, {len(first_ms)} queries one by one, first time: p50 {out['p50_first']:.1f} ms, "
          f"p95 {out['p95_first']:.1f} ms")
    print(f"  find_goal, the same queries again: p50 {out['p50_repeat']:.1f} ms, p95 {out['p95_repeat']:.1f} ms")
    print(f"  {out['burst_n']} concurrent find_goal calls: {out['burst_wall_s']:.2f} s wall, "
          f"{out['throughput']:.1f} calls/s, p50 {out['burst_p50']:.1f} ms, p95 {out['burst_p95']:.1f} ms, "
          f"{out['burst_failures']} failures (the same burst of list_maps: p50 {out['floor_p50']:.1f} ms)")
    server_cpu = "?" if out["burst_server_cpu_ms"] is None else f"{out['burst_server_cpu_ms']:.1f}"
    print(f"  CPU per call during that burst: server {server_cpu} ms, client {out['burst_client_cpu_ms']:.1f} ms")
    print(f"  '{ASK_QUERY}': warm server {out['warm_ms']:.1f} ms vs iesm ask in a fresh process "
          f"{cold_ms:.0f} ms ({cold_ms / out['warm_ms']:.0f}x)")
    return out


def serve_noop(port_file: str) -> None:
    """The SDK's floor: an MCP server with one tool that returns "ok", the same transport settings
    as `iesm serve` (streamable HTTP, JSON responses, loggers at WARNING); writes its port to `port_file`."""
    import logging
    import socket

    import uvicorn
    from mcp.server.mcpserver import MCPServer

    logging.disable(logging.INFO)
    server = MCPServer("noop")

    @server.tool()
    def ping() -> str:
        """Return ok."""
        return "ok"

    config = uvicorn.Config(server.streamable_http_app(streamable_http_path="/mcp", json_response=True,
                                                      host="127.0.0.1"), log_level="warning", access_log=False)
    sock = socket.socket()
    sock.bind(("127.0.0.1", 0))
    sock.listen(128)
    Path(port_file).write_text(str(sock.getsockname()[1]))
    asyncio.run(uvicorn.Server(config).serve(sockets=[sock]))


async def noop_bursts(url: str, pid: int, n: int, rounds: int = 5) -> dict[str, float]:
    """Median over `rounds` bursts of `n` concurrent no-op calls: p50 ms, server and client CPU ms per call."""
    from mcp import Client

    async def one(client) -> float:
        t0 = time.perf_counter()
        await client.call_tool("ping", {})
        return (time.perf_counter() - t0) * 1000.0

    p50s, server_ms, client_ms = [], [], []
    async with Client(url) as client:
        for _ in range(n):
            await one(client)  # warm-up
        for _ in range(rounds):
            s0, c0 = process_cpu_s(pid), time.process_time()
            p50s.append(statistics.median(await asyncio.gather(*(one(client) for _ in range(n)))))
            s1 = process_cpu_s(pid)
            client_ms.append((time.process_time() - c0) * 1000 / n)
            server_ms.append(float("nan") if s0 is None or s1 is None else (s1 - s0) * 1000 / n)
    return {"p50": statistics.median(p50s), "server_cpu_ms": statistics.median(server_ms),
            "client_cpu_ms": statistics.median(client_ms)}


def sdk_floor(n: int) -> dict[str, float]:
    """Bursts of `n` calls to the no-op server in its own process (this script with --noop-server)."""
    with tempfile.TemporaryDirectory() as tmp:
        port_file = Path(tmp) / "port"
        proc = subprocess.Popen([sys.executable, __file__, "--noop-server", str(port_file)],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            for _ in range(200):
                if port_file.is_file() and port_file.read_text():
                    break
                time.sleep(0.05)
            else:
                raise SystemExit("the no-op MCP server did not start")
            url = f"http://127.0.0.1:{port_file.read_text()}/mcp"
            out = asyncio.run(noop_bursts(url, proc.pid, n))
        finally:
            proc.terminate()
            proc.wait(timeout=30)
    print(f"MCP SDK floor (a tool that returns 'ok'): {n} concurrent calls p50 {out['p50']:.1f} ms; CPU per call: "
          f"server {out['server_cpu_ms']:.2f} ms, client {out['client_cpu_ms']:.2f} ms")
    return out


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--concurrent", type=int, default=40)
    parser.add_argument("--noop-server", metavar="PORT_FILE", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.noop_server:
        serve_noop(args.noop_server)
        return
    env = {**os.environ, "HF_HUB_OFFLINE": "1"}
    env.pop("IESM_TOKEN", None)
    env.pop("IESM_EMBEDDINGS", None)
    pool = queries()
    sequential, concurrent = pool[:40], pool[40:40 + args.concurrent]
    concurrent += pool[:args.concurrent - len(concurrent)]  # fewer unseen queries than asked for: reuse

    print("offline model, embeddings as installed:")
    full = run_config(env, sequential, concurrent)
    print("offline model on lexicons only (IESM_EMBEDDINGS=0):")
    lex = run_config({**env, "IESM_EMBEDDINGS": "0"}, sequential, concurrent)
    floor = sdk_floor(args.concurrent)

    record("serve_find_goal_p50_ms", full["p50_first"], "ms", "<= 20 ms", full["p50_first"] <= 20,
           note=f"warm server over HTTP, each query asked for the first time; p95 {full['p95_first']:.1f} ms; "
                f"repeated queries p50 {full['p50_repeat']:.1f} ms; lexicons only p50 {lex['p50_first']:.1f} ms")
    record("serve_40_concurrent_failures", full["burst_failures"], "calls", "0", full["burst_failures"] == 0,
           note=f"{full['burst_n']} calls at once: {full['throughput']:.1f} calls/s, p50 {full['burst_p50']:.0f} ms, "
                f"p95 {full['burst_p95']:.0f} ms (lexicons only: {lex['throughput']:.0f} calls/s, "
                f"{lex['burst_failures']} failures)")
    record("serve_40_concurrent_p50_ms", full["burst_p50"], "ms", "<= 30 ms", full["burst_p50"] <= 30,
           note=f"{full['burst_n']} find_goal calls at once, client and server on this machine's cores; the same "
                f"burst of list_maps (no retrieval) p50 {full['floor_p50']:.0f} ms; lexicons only p50 "
                f"{lex['burst_p50']:.0f} ms; CPU per call: server "
                f"{'?' if full['burst_server_cpu_ms'] is None else format(full['burst_server_cpu_ms'], '.1f')} ms, "
                f"client {full['burst_client_cpu_ms']:.1f} ms; the SDK alone (a tool returning 'ok') p50 "
                f"{floor['p50']:.0f} ms")
    record("mcp_sdk_floor_40_concurrent_p50_ms", floor["p50"], "ms", "reported", True,
           note=f"{args.concurrent} calls at once to an MCP server whose only tool returns 'ok' (no iesm code), "
                f"median of 5 bursts; CPU per call: server {floor['server_cpu_ms']:.2f} ms, "
                f"client {floor['client_cpu_ms']:.2f} ms")
    record("serve_vs_ask_cold_speedup", full["cold_ms"] / full["warm_ms"], "x", "reported", True,
           note=f"warm find_goal {full['warm_ms']:.1f} ms vs fresh iesm ask {full['cold_ms']:.0f} ms; lexicons only "
                f"{lex['warm_ms']:.1f} ms vs {lex['cold_ms']:.0f} ms")


if __name__ == "__main__":
    main()
