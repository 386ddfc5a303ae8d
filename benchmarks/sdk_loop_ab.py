"""What the event loop and uvicorn's HTTP parser cost the MCP SDK per call: `bench_server.py`'s no-op
server (one tool returning "ok") under asyncio's loop with h11, asyncio's with httptools, and uvloop's
with httptools (as `iesm serve` runs when they are installed), its bursts of 40 calls interleaved
round by round so that all three see the same load. Prints the server's CPU per call (all threads,
/proc schedstat) and the bursts' p50 per variant, then the medians.

Run from the repository root (not part of `make bench`: it reports differences, no target):
.venv/bin/python benchmarks/sdk_loop_ab.py --rounds 6
"""

from __future__ import annotations

import argparse
import asyncio
import contextlib
import statistics
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
import bench_server  # noqa: E402

VARIANTS = (("asyncio", "h11"), ("asyncio", "httptools"), ("served", "httptools"))


async def measure(servers: dict[tuple[str, str], tuple[str, int]], rounds: int, n: int) -> dict:
    from mcp import Client

    cpu: dict[tuple[str, str], list[float]] = {v: [] for v in servers}
    p50: dict[tuple[str, str], list[float]] = {v: [] for v in servers}
    async with contextlib.AsyncExitStack() as stack:
        clients = {v: await stack.enter_async_context(Client(url)) for v, (url, _) in servers.items()}
        for v, client in clients.items():
            for _ in range(n):
                await bench_server.timed_ping(client)  # warm-up
        for _ in range(rounds):
            for v, client in clients.items():
                out = await bench_server.burst(client, servers[v][1], [bench_server.timed_ping(client) for _ in range(n)])
                cpu[v].append(out["server_cpu_s"] * 1000 / n)
                p50[v].append(statistics.median(t for t, _ in out["calls"]))
    return {v: (cpu[v], p50[v]) for v in servers}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=6)
    parser.add_argument("--concurrent", type=int, default=40)
    args = parser.parse_args()
    with contextlib.ExitStack() as stack:
        servers = {v: stack.enter_context(bench_server.noop_server(*v)) for v in VARIANTS}
        figures = asyncio.run(measure(servers, args.rounds, args.concurrent))
    for (loop, http), (cpu, p50) in figures.items():
        name = f"{'uvloop (as served)' if loop == 'served' else loop} + {http}"
        print(f"{name:<30} server CPU per call {statistics.median(cpu):.2f} ms "
              f"({', '.join(f'{c:.2f}' for c in cpu)}), burst p50 {statistics.median(p50):.0f} ms")


if __name__ == "__main__":
    main()
