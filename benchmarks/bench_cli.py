"""`iesm ask` cold start: wall time of a fresh process answering one query on the shipped map.

Targets (DESIGN.md, issues 23 and 32): <= 3 s with the offline model on lexicons and the English
parser (IESM_EMBEDDINGS=0; importing spaCy and loading its pipeline is most of it), and <= 3 s for an
(o,d) query that needs the sentence encoder too (onnxruntime over the ONNX export in the user cache;
the encoder is only loaded when a query needs it). Each case runs once unmeasured
first, so the user cache holds the export and the vectors of the map's texts, as after any first use;
the first use ever (export included) is measured apart, in an empty cache, and reported.

Run: .venv/bin/python benchmarks/bench_cli.py [--repeat N]
"""

from __future__ import annotations

import argparse
import os
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from results_io import record  # noqa: E402

#: (name, IESM_EMBEDDINGS, query, target s or None, results.json key)
CASES = [
    ("lexicons + parser, (o) query", "0", "find the sofa", 3.0, "ask_cold_start_s"),
    ("embeddings installed, (o) query", "1", "find the sofa", None, "ask_cold_start_embeddings_o_s"),
    ("embeddings installed, (o,d) query", "1", "the yellow photo book", 3.0, "ask_cold_start_embeddings_od_s"),
]


def cold_start_s(embeddings: str, query: str, **extra_env: str) -> float:
    env = {**os.environ, "IESM_EMBEDDINGS": embeddings, "HF_HUB_OFFLINE": "1", **extra_env}
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
        cold_start_s(embeddings, query)  # unmeasured: fills the user cache as any first use does
        value = statistics.median(cold_start_s(embeddings, query) for _ in range(args.repeat))
        ok = "-" if target is None else ("yes" if value <= target else "NO")
        print(f"{name:<44} {value:>7.2f}s {'' if target is None else f'{target:.1f}s':>8}  {ok}")
        record(key, value, "s", "reported" if target is None else f"<= {target:g} s",
               target is None or value <= target, note=f"median of {args.repeat}: {name}")
    with tempfile.TemporaryDirectory() as empty:
        first = cold_start_s("1", CASES[-1][2], IESM_CACHE_DIR=empty)
    print(f"{'first use ever, (o,d) query (ONNX export)':<44} {first:>7.2f}s {'':>8}  -")
    record("ask_first_use_embeddings_s", first, "s", "reported", True,
           note="empty user cache: the one-time ONNX export from the torch weights, then the query")


if __name__ == "__main__":
    main()
