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
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from results_io import record  # noqa: E402

#: (name, IESM_EMBEDDINGS, query, target s or None, results.json key)
CASES = [
    ("lexicons only, (o) query", "0", "find the sofa", 1.0, "ask_cold_start_s"),
    ("embeddings installed, (o) query", "1", "find the sofa", None, "ask_cold_start_embeddings_o_s"),
    ("embeddings installed, (o,d) query", "1", "the yellow photo book", None, "ask_cold_start_embeddings_od_s"),
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
    for name, embeddings, query, target, key in CASES:
        value = statistics.median(cold_start_s(embeddings, query) for _ in range(args.repeat))
        ok = "-" if target is None else ("yes" if value <= target else "NO")
        print(f"{name:<44} {value:>7.2f}s {'' if target is None else f'{target:.1f}s':>8}  {ok}")
        record(key, value, "s", "reported" if target is None else f"<= {target:g} s",
               target is None or value <= target, note=f"median of {args.repeat}: {name}")


if __name__ == "__main__":
    main()
