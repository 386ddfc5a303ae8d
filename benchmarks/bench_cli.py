"""`iesm ask` cold start: wall time of a fresh process answering one query on the shipped map.

Targets (DESIGN.md): <= 1 s with the offline model on lexicons alone (IESM_EMBEDDINGS=0). With the
embedding model installed it is only loaded when a query needs it (descriptions, or nothing the
lexicon recognises); those starts are reported, not targeted.

Run: .venv/bin/python benchmarks/bench_cli.py [--repeat N]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import time

CASES = [
    ("lexicons only, (o) query", "0", "find the sofa", 1.0),
    ("embeddings installed, (o) query", "1", "find the sofa", None),
    ("embeddings installed, (o,d) query", "1", "the yellow photo book", None),
]


def cold_start_s(embeddings: str, query: str) -> float:
    env = {**os.environ, "IESM_EMBEDDINGS": embeddings, "HF_HUB_OFFLINE": "1"}
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "iesm_agent.cli", "ask", "apartment", query],
                   env=env, check=True, capture_output=True)
    return time.perf_counter() - start


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--repeat", type=int, default=5)
    args = parser.parse_args()
    print(f"{'iesm ask cold start (median of %d)' % args.repeat:<44} {'value':>8} {'target':>8}  ok")
    for name, embeddings, query, target in CASES:
        value = statistics.median(cold_start_s(embeddings, query) for _ in range(args.repeat))
        ok = "-" if target is None else ("yes" if value <= target else "NO")
        print(f"{name:<44} {value:>7.2f}s {'' if target is None else f'{target:.1f}s':>8}  {ok}")


if __name__ == "__main__":
    main()
