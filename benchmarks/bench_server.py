"""`iesm serve` over HTTP with the offline model: find_goal latency on a warm server, bursts of 40
concurrent calls against the MCP SDK's own floor, and one call against `iesm ask` in a fresh process.

The server runs as its own process (`iesm serve apartment --http 127.0.0.1:0`, embeddings as
installed); the client is the MCP SDK's. Queries come from the shipped suites on the apartment map
(208, shuffled with a fixed seed): 40 are asked one by one, each for the first time (per-query
caches cold, the server warm), then asked again (repeats); then come three bursts of 40 others at
once, each query asked for the first time: every request of a burst is distinct and new to the
server, so no memo answers its parse (the server parses the queries waiting together,
`server/batching.py`, which is what the bursts measure).

The SDK's floor is an MCP server with the same transport settings whose only tool returns "ok"
(no iesm code), running beside ours for the whole run: each find_goal burst is followed by a burst
of 40 calls to it, so that both see the same load on the shared machine, and the ratio of their
p50s is taken per round.

Targets: find_goal on a warm server p50 <= 20 ms; 40 concurrent calls with p50 <= 30 ms and no
failure (DESIGN.md, issue 23); the server's CPU per find_goal call in the bursts <= 3 ms and the
bursts' p50 within 2x the SDK floor's (issue 33). For scale, a burst of `list_maps` (no
retrieval) is measured too.

The client is this process and the servers others, all sharing the machine's cores: the CPU each
spends during the bursts (servers: all their threads, from /proc/<pid>/task/*/schedstat in
nanoseconds, Linux only; client: this process's `time.process_time()`) is reported per call, so a
burst's latency can be read against the work it took on each side.

Run: .venv/bin/python benchmarks/bench_server.py [--concurrent 40] [--rounds 3]
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
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
#: the interpreter the servers and `iesm ask` run with (`server_ab.py` sets it per tree)
PYTHON = sys.executable
SUITES = ("evals/apartment_suite.jsonl", "evals/apartment_human_suite.jsonl", "evals/conflict_suite.jsonl",
          "evals/spatial_suite.jsonl")
ASK_QUERY = "the red leather chair in the office"


def queries(seed: int = 7) -> list[str]:
    lines = [json.loads(line) for s in SUITES for line in (REPO / s).read_text().splitlines() if line.strip()]
    out = list(dict.fromkeys(q["query"] for q in lines))
    random.Random(seed).shuffle(out)
    return out


def percentile(values: list[float], q: float) -> float:
    ordered = sorted(values)
    return ordered[min(len(ordered) - 1, round(q * (len(ordered) - 1)))]


#: `iesm serve` over HTTP on a free port
SERVE = ("-m", "iesm_agent.cli", "serve", "apartment", "--http", "127.0.0.1:0")


def start_server(env: dict[str, str], command: tuple[str, ...] = SERVE) -> tuple[subprocess.Popen, str, float]:
    """The server process (`python command`), its /mcp URL and its start-up time in s (maps +
    model loaded, warm-up query done)."""
    started = time.perf_counter()
    proc = subprocess.Popen([PYTHON, *command], stderr=subprocess.PIPE, stdout=subprocess.DEVNULL, text=True,
                            env=env, cwd=REPO)
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
    """CPU seconds process `pid` has used so far, all its live threads (Linux: /proc schedstat in
    ns; else user + system ticks of /proc/<pid>/stat; None without /proc)."""
    try:
        return sum(int((task / "schedstat").read_text().split()[0])
                   for task in Path(f"/proc/{pid}/task").iterdir()) / 1e9
    except (OSError, ValueError, IndexError):
        pass
    try:
        fields = Path(f"/proc/{pid}/stat").read_text().rpartition(")")[2].split()
    except OSError:
        return None
    return (int(fields[11]) + int(fields[12])) / os.sysconf("SC_CLK_TCK")  # utime, stime (ticks)


async def timed_ping(client) -> tuple[float, bool]:
    """(wall ms, failed) of one call to the no-op server's tool."""
    t0 = time.perf_counter()
    await client.call_tool("ping", {})
    return (time.perf_counter() - t0) * 1000.0, False


async def burst(client, pid: int, calls) -> dict[str, object]:
    """Run the coroutines `calls` at once: their (ms, failed), the wall s and the CPU s of the
    server (process `pid`) and of this client."""
    server0, client0, t0 = process_cpu_s(pid), time.process_time(), time.perf_counter()
    done = await asyncio.gather(*calls)
    wall = time.perf_counter() - t0
    server1, client1 = process_cpu_s(pid), time.process_time()
    return {"calls": done, "wall_s": wall, "client_cpu_s": client1 - client0,
            "server_cpu_s": None if server0 is None or server1 is None else server1 - server0}


async def measure(url: str, server_pid: int, sequential: list[str], bursts: list[list[str]],
                  floor: tuple[str, int]) -> dict[str, object]:
    """Sequential, repeated and warm calls, then per round a find_goal burst and a burst of the
    same size to the no-op server at `floor` (url, pid), then one burst of list_maps."""
    from mcp import Client

    async with Client(url) as client, Client(floor[0]) as noop:
        for _ in range(len(bursts[0])):
            await timed_ping(noop)  # the no-op server's own warm-up
        first = [await timed_call(client, q) for q in sequential]
        repeat = [await timed_call(client, q) for q in sequential]
        ask_warm = statistics.median([(await timed_call(client, ASK_QUERY))[0] for _ in range(5)])
        rounds = []
        for queries_ in bursts:
            ours = await burst(client, server_pid, [timed_call(client, q) for q in queries_])
            sdk = await burst(noop, floor[1], [timed_ping(noop) for _ in queries_])
            rounds.append((ours, sdk))
        maps = await asyncio.gather(*(timed_list_maps(client) for _ in bursts[0]))
    return {"first": first, "repeat": repeat, "ask_warm_ms": ask_warm, "rounds": rounds, "list_maps": maps}


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
        subprocess.run([PYTHON, "-m", "iesm_agent.cli", "ask", "apartment", ASK_QUERY], env=env, cwd=REPO,
                       check=True, capture_output=True)
        times.append(time.perf_counter() - t0)
    return statistics.median(times)


def _per_call_ms(rounds: list[dict[str, object]], key: str) -> float | None:
    """CPU ms per call over `rounds` (bursts) for `key` (server_cpu_s or client_cpu_s)."""
    if any(r[key] is None for r in rounds):
        return None
    return sum(r[key] for r in rounds) * 1000 / sum(len(r["calls"]) for r in rounds)


def _ms(value: float | None) -> str:
    """A per-call CPU figure in ms for a note ("?" when the process could not be measured)."""
    return "?" if value is None else f"{value:.2f}"


def run_config(env: dict[str, str], sequential: list[str], bursts: list[list[str]],
               floor: tuple[str, int], command: tuple[str, ...] = SERVE, cold: bool = True) -> dict[str, float]:
    """Start a server (`command`) with `env`, measure, stop it, time `iesm ask` cold (unless not
    `cold`); the figures, printed too."""
    proc, url, startup_s = start_server(env, command)
    try:
        m = asyncio.run(measure(url, proc.pid, sequential, bursts, floor))
    finally:
        proc.terminate()
        proc.wait(timeout=30)
    cold_ms = ask_cold_s(env) * 1000 if cold else float("nan")
    first_ms = [t for t, _ in m["first"]]
    repeat_ms = [t for t, _ in m["repeat"]]
    ours, sdk = [o for o, _ in m["rounds"]], [f for _, f in m["rounds"]]
    p50s = [statistics.median(t for t, _ in r["calls"]) for r in ours]
    floor_p50s = [statistics.median(t for t, _ in r["calls"]) for r in sdk]
    all_ms = [t for r in ours for t, _ in r["calls"]]
    out = {"startup_s": startup_s, "p50_first": statistics.median(first_ms), "p95_first": percentile(first_ms, 0.95),
           "p50_repeat": statistics.median(repeat_ms), "p95_repeat": percentile(repeat_ms, 0.95),
           "throughput": len(all_ms) / sum(r["wall_s"] for r in ours), "burst_n": len(bursts[0]),
           "burst_p50": statistics.median(p50s), "burst_p50s": p50s, "burst_p95": percentile(all_ms, 0.95),
           "burst_failures": sum(failed for r in ours for _, failed in r["calls"]), "calls": len(all_ms),
           "floor_p50": statistics.median(floor_p50s), "floor_p50s": floor_p50s,
           "floor_ratio": statistics.median(p / f for p, f in zip(p50s, floor_p50s)),
           "warm_ms": m["ask_warm_ms"], "cold_ms": cold_ms, "list_maps_p50": statistics.median(m["list_maps"]),
           "burst_server_cpu_ms": _per_call_ms(ours, "server_cpu_s"),
           "burst_client_cpu_ms": _per_call_ms(ours, "client_cpu_s"),
           "floor_server_cpu_ms": _per_call_ms(sdk, "server_cpu_s"),
           "floor_client_cpu_ms": _per_call_ms(sdk, "client_cpu_s")}
    cpu = "?" if out["burst_server_cpu_ms"] is None else f"{out['burst_server_cpu_ms']:.2f}"
    floor_cpu = "?" if out["floor_server_cpu_ms"] is None else f"{out['floor_server_cpu_ms']:.2f}"
    print(f"  server start-up (maps, model, warm-up query): {out['startup_s']:.2f} s")
    print(f"  find_goal, {len(first_ms)} queries one by one, first time: p50 {out['p50_first']:.1f} ms, "
          f"p95 {out['p95_first']:.1f} ms")
    print(f"  find_goal, the same queries again: p50 {out['p50_repeat']:.1f} ms, p95 {out['p95_repeat']:.1f} ms")
    print(f"  {len(bursts)} bursts of {out['burst_n']} concurrent find_goal calls (first-time queries): "
          f"p50 {', '.join(f'{p:.0f}' for p in p50s)} ms, p95 {out['burst_p95']:.0f} ms, "
          f"{out['throughput']:.1f} calls/s, {out['burst_failures']} failures")
    print(f"  the SDK floor right after each (a tool returning 'ok'): p50 "
          f"{', '.join(f'{p:.0f}' for p in floor_p50s)} ms; ratio (median of rounds) {out['floor_ratio']:.2f}x; "
          f"a burst of list_maps: p50 {out['list_maps_p50']:.0f} ms")
    print(f"  CPU per call in the bursts: server {cpu} ms, client {out['burst_client_cpu_ms']:.2f} ms "
          f"(SDK floor: server {floor_cpu} ms, client {out['floor_client_cpu_ms']:.2f} ms)")
    if cold:
        print(f"  '{ASK_QUERY}': warm server {out['warm_ms']:.1f} ms vs iesm ask in a fresh process "
              f"{cold_ms:.0f} ms ({cold_ms / out['warm_ms']:.0f}x)")
    return out


def serve_noop(port_file: str, loop: str = "served", http: str = "auto") -> None:
    """The SDK's floor: an MCP server with one tool that returns "ok", the same transport settings
    as `iesm serve` (streamable HTTP, JSON responses, loggers at WARNING, its event loop: uvloop's
    when installed, `loop` "asyncio" for asyncio's; `http` uvicorn's parser: auto (httptools when
    installed), h11 or httptools); writes its port to `port_file`."""
    import logging
    import socket

    import uvicorn
    from mcp.server.mcpserver import MCPServer

    from iesm_agent.server.app import event_loop_factory

    logging.disable(logging.INFO)
    server = MCPServer("noop")

    @server.tool()
    def ping() -> str:
        """Return ok."""
        return "ok"

    config = uvicorn.Config(server.streamable_http_app(streamable_http_path="/mcp", json_response=True,
                                                      host="127.0.0.1"), log_level="warning", access_log=False,
                            http=http)
    sock = socket.socket(socket.AF_INET, socket.SOCK_STREAM, socket.IPPROTO_TCP)  # TCP_NODELAY, as `iesm serve`
    sock.bind(("127.0.0.1", 0))
    sock.listen(128)
    Path(port_file).write_text(str(sock.getsockname()[1]))
    with asyncio.Runner(loop_factory=event_loop_factory() if loop == "served" else None) as runner:
        runner.run(uvicorn.Server(config).serve(sockets=[sock]))


def serve_canned() -> None:
    """`iesm serve apartment --http` whose find_goal answers every benchmark query from answers
    computed at start-up: the MCP SDK's and the server wrapper's cost for find_goal's own result
    (text block, structured content under the output schema), without retrieval."""
    from iesm_agent.server import MapService, app

    async def main() -> None:
        service = MapService.open(["apartment"])
        await service.warm_up()
        answers = {q: await service.find_goal(q) for q in [*queries(), ASK_QUERY]}

        async def find_goal(query: str, map: str | None = None, method: str = "mtefr",
                            provider: str | None = None) -> dict:
            return answers[query]

        find_goal.__doc__ = MapService.find_goal.__doc__
        service.find_goal = find_goal
        service.warm_up = lambda: asyncio.sleep(0)
        await app.serve_http(service, "127.0.0.1", 0, None)

    app.run(main())


@contextlib.contextmanager
def noop_server(loop: str = "served", http: str = "auto"):
    """The SDK's floor server (this script with --noop-server; `serve_noop`'s `loop` and `http`) in
    its own process: (url, pid)."""
    with tempfile.TemporaryDirectory() as tmp:
        port_file = Path(tmp) / "port"
        proc = subprocess.Popen([sys.executable, __file__, "--noop-server", str(port_file), "--noop-loop", loop,
                                 "--noop-http", http],
                                stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        try:
            for _ in range(200):
                if port_file.is_file() and port_file.read_text():
                    break
                time.sleep(0.05)
            else:
                raise SystemExit("the no-op MCP server did not start")
            yield f"http://127.0.0.1:{port_file.read_text()}/mcp", proc.pid
        finally:
            proc.terminate()
            proc.wait(timeout=30)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--concurrent", type=int, default=40)
    parser.add_argument("--rounds", type=int, default=3, help="bursts per configuration")
    parser.add_argument("--noop-server", metavar="PORT_FILE", help=argparse.SUPPRESS)
    parser.add_argument("--noop-loop", choices=("served", "asyncio"), default="served", help=argparse.SUPPRESS)
    parser.add_argument("--noop-http", choices=("auto", "h11", "httptools"), default="auto", help=argparse.SUPPRESS)
    parser.add_argument("--canned-server", action="store_true", help=argparse.SUPPRESS)
    args = parser.parse_args()
    if args.noop_server:
        serve_noop(args.noop_server, args.noop_loop, args.noop_http)
        return
    if args.canned_server:
        serve_canned()
        return
    env = {**os.environ, "HF_HUB_OFFLINE": "1"}
    env.pop("IESM_TOKEN", None)
    env.pop("IESM_EMBEDDINGS", None)
    pool = queries()
    sequential, rest = pool[:40], pool[40:]
    n = args.concurrent
    bursts = [(rest[i * n:(i + 1) * n] + pool)[:n] for i in range(args.rounds)]  # unseen queries first

    with noop_server() as floor:
        print("offline model, embeddings as installed:")
        full = run_config(env, sequential, bursts, floor)
        print("offline model on lexicons only (IESM_EMBEDDINGS=0):")
        lex = run_config({**env, "IESM_EMBEDDINGS": "0"}, sequential, bursts, floor)
        print("find_goal answered from answers computed at start-up (the SDK and the server wrapper alone):")
        canned = run_config(env, sequential, bursts, floor, (__file__, "--canned-server"), cold=False)

    cpu = full["burst_server_cpu_ms"]
    bursts_text = f"{args.rounds} bursts of {n} first-time queries"
    record("serve_find_goal_p50_ms", full["p50_first"], "ms", "<= 20 ms", full["p50_first"] <= 20,
           note=f"warm server over HTTP, each query asked for the first time; p95 {full['p95_first']:.1f} ms; "
                f"repeated queries p50 {full['p50_repeat']:.1f} ms; lexicons only p50 {lex['p50_first']:.1f} ms")
    record("serve_40_concurrent_failures", full["burst_failures"], "calls", "0", full["burst_failures"] == 0,
           note=f"{full['calls']} calls in {bursts_text}: {full['throughput']:.1f} calls/s, p95 "
                f"{full['burst_p95']:.0f} ms (lexicons only: {lex['throughput']:.0f} calls/s, "
                f"{lex['burst_failures']} failures)")
    record("serve_40_concurrent_p50_ms", full["burst_p50"], "ms", "<= 30 ms", full["burst_p50"] <= 30,
           note=f"median over {bursts_text} (p50s {', '.join(f'{p:.0f}' for p in full['burst_p50s'])} ms), client "
                f"and servers on this machine's cores; a burst of list_maps (no retrieval) p50 "
                f"{full['list_maps_p50']:.0f} ms; lexicons only p50 {lex['burst_p50']:.0f} ms; the SDK alone p50 "
                f"{full['floor_p50']:.0f} ms")
    record("serve_40_concurrent_over_sdk_floor", full["floor_ratio"], "x", "<= 2 x", full["floor_ratio"] <= 2,
           note=f"burst p50 over the p50 of the same burst to a tool returning 'ok' right after it, median over "
                f"{args.rounds} rounds (find_goal {', '.join(f'{p:.0f}' for p in full['burst_p50s'])} ms, SDK "
                f"{', '.join(f'{p:.0f}' for p in full['floor_p50s'])} ms); lexicons only {lex['floor_ratio']:.2f}x")
    record("serve_find_goal_server_cpu_ms", -1 if cpu is None else cpu, "ms", "<= 3 ms",
           cpu is not None and cpu <= 3,
           note=f"server CPU (all threads) per find_goal call over MCP HTTP in {bursts_text}; client "
                f"{full['burst_client_cpu_ms']:.2f} ms; lexicons only: server "
                f"{_ms(lex['burst_server_cpu_ms'])} ms; "
                f"the SDK floor's server {_ms(full['floor_server_cpu_ms'])} "
                f"ms, client {full['floor_client_cpu_ms']:.2f} ms per call")
    record("serve_canned_find_goal_over_sdk_floor", canned["floor_ratio"], "x", "reported", True,
           note=f"find_goal answered from answers computed at start-up (no retrieval): burst p50 over the SDK "
                f"floor's, median of {args.rounds} rounds (p50s {', '.join(f'{p:.0f}' for p in canned['burst_p50s'])} "
                f"vs {', '.join(f'{p:.0f}' for p in canned['floor_p50s'])} ms); CPU per call server "
                f"{_ms(canned['burst_server_cpu_ms'])} ms, "
                f"client {canned['burst_client_cpu_ms']:.2f} ms")
    record("mcp_sdk_floor_40_concurrent_p50_ms", full["floor_p50"], "ms", "reported", True,
           note=f"{n} calls at once to an MCP server whose only tool returns 'ok' (no iesm code), right after each "
                f"find_goal burst, median of {args.rounds}; CPU per call: server "
                f"{_ms(full['floor_server_cpu_ms'])} ms, "
                f"client {full['floor_client_cpu_ms']:.2f} ms")
    record("serve_vs_ask_cold_speedup", full["cold_ms"] / full["warm_ms"], "x", "reported", True,
           note=f"warm find_goal {full['warm_ms']:.1f} ms vs fresh iesm ask {full['cold_ms']:.0f} ms; lexicons only "
                f"{lex['warm_ms']:.1f} ms vs {lex['cold_ms']:.0f} ms")


if __name__ == "__main__":
    main()
