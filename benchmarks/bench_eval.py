"""Eval throughput: queries per second of `iesm eval` on the reference suite with the offline
provider, pinned to one CPU core, per method (model time included: the offline model is the
work). Run: HF_HUB_OFFLINE=1 python benchmarks/bench_eval.py [--embeddings]"""

from __future__ import annotations

import argparse
import asyncio
import os
import tempfile
import time
from pathlib import Path

from iesm_agent.evals.runner import make_config, make_variants, run_eval

SUITE = Path(__file__).resolve().parents[1] / "evals" / "apartment_suite.jsonl"
METHODS = ["mtefr", "spr", "keyword", "experts:obj", "experts:obj,desc", "experts:obj,room"]


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--embeddings", action="store_true", help="let the offline model use sentence embeddings")
    parser.add_argument("--concurrency", type=int, default=4)
    args = parser.parse_args()
    if not args.embeddings:
        os.environ["IESM_EMBEDDINGS"] = "0"
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {sorted(os.sched_getaffinity(0))[0]})
    n = len(SUITE.read_text().splitlines())
    print(f"suite {SUITE.name}: {n} queries, offline provider, 1 core, concurrency {args.concurrency}, "
          f"embeddings {'on' if args.embeddings else 'off'}")
    if args.embeddings:  # load the sentence encoder outside the timed runs
        from iesm_agent.embeddings import get_encoder

        started = time.perf_counter()
        get_encoder()
        print(f"  (encoder loaded in {time.perf_counter() - started:.1f} s, not counted)")
    total_queries, total_s = 0, 0.0
    for method in METHODS:
        config = make_config([SUITE], make_variants([method], []), "offline")
        with tempfile.TemporaryDirectory() as run:
            started = time.perf_counter()
            outcome = asyncio.run(run_eval(config, run, concurrency=args.concurrency))
            elapsed = time.perf_counter() - started
        total_queries, total_s = total_queries + outcome.new, total_s + elapsed
        print(f"  {method:<18} {outcome.new / elapsed:8.1f} queries/s  ({elapsed:.2f} s incl. map load)")
    print(f"  {'all methods':<18} {total_queries / total_s:8.1f} queries/s")


if __name__ == "__main__":
    main()
