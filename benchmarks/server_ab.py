"""Interleaved A/B of `bench_server.py`'s measurement on two or more source trees: each round starts
each tree's `iesm serve` in turn (the tree as working directory, so its `iesm_agent` is the one
imported) and measures 40 first-time calls one by one and three bursts of 40 first-time queries
against the SDK floor, embeddings as installed (`--lexicons-only`: switched off). Per round and
tree it prints the server's and the client's CPU per call in the bursts, the bursts' p50 over the
floor's, and the one-by-one p50; then the medians.
On a shared machine only figures from the same rounds compare.

`--new-embeddings`: each server starts with a cache folder of its own holding the encoder's model
files but no stored sentence vectors, so every query's embedding is computed in the run, as for a
user's new queries (without it the bench queries' vectors come back from the on-disk store that
earlier runs filled).

A tree of an older commit: `git archive <commit> | tar -x -C DIR`. `DIR=PYTHON` runs that tree's
server with another interpreter (another venv: installed packages such as uvloop and httptools
differ); the SDK floor and the client stay this one's.

Run from the repository root (not part of `make bench`: it reports differences, no target):
HF_HUB_OFFLINE=1 .venv/bin/python benchmarks/server_ab.py --rounds 4 DIR_BEFORE .
"""

from __future__ import annotations

import argparse
import contextlib
import io
import os
import statistics
import sys
import tempfile
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
import bench_server  # noqa: E402


@contextlib.contextmanager
def without_stored_vectors(env: dict[str, str]):
    """`env` with IESM_CACHE_DIR a new folder whose encoders/ links the encoder's model files of
    the cache in use (the ONNX export and its checksum) and holds no vector store."""
    from iesm_agent.cachedir import default_cache_dir

    with tempfile.TemporaryDirectory() as tmp:
        encoders = Path(tmp) / "encoders"
        encoders.mkdir()
        for f in (default_cache_dir() / "encoders").glob("*.onnx*"):
            if f.suffix in (".onnx", ".json"):
                (encoders / f.name).symlink_to(f)
        yield {**env, "IESM_CACHE_DIR": tmp}


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("trees", nargs="+", help="DIR or DIR=PYTHON")
    parser.add_argument("--rounds", type=int, default=4)
    parser.add_argument("--new-embeddings", action="store_true",
                        help="no stored sentence vectors: every query is embedded in the run")
    parser.add_argument("--lexicons-only", action="store_true", help="the offline model without embeddings "
                        "(IESM_EMBEDDINGS=0)")
    args = parser.parse_args()
    env = {**os.environ, "HF_HUB_OFFLINE": "1"}
    env.pop("IESM_EMBEDDINGS", None)
    if args.lexicons_only:
        env["IESM_EMBEDDINGS"] = "0"
    pool = bench_server.queries()
    sequential, rest = pool[:40], pool[40:]
    bursts = [rest[i * 40:(i + 1) * 40] for i in range(3)]
    figures: dict[str, list[dict]] = {tree: [] for tree in args.trees}
    with bench_server.noop_server() as floor:
        for r in range(args.rounds):
            for tree in args.trees:
                path, _, python = tree.partition("=")
                bench_server.REPO, bench_server.PYTHON = Path(path).resolve(), python or sys.executable
                fresh = without_stored_vectors(env) if args.new_embeddings else contextlib.nullcontext(env)
                with fresh as run_env, contextlib.redirect_stdout(io.StringIO()):
                    out = bench_server.run_config(run_env, sequential, bursts, floor, cold=False)
                figures[tree].append(out)
                print(f"round {r} {tree}: server CPU per call {out['burst_server_cpu_ms']:.2f} ms (client "
                      f"{out['burst_client_cpu_ms']:.2f}), burst p50 "
                      f"{out['burst_p50']:.0f} ms / floor {out['floor_p50']:.0f} ms = {out['floor_ratio']:.2f}x, "
                      f"one by one p50 {out['p50_first']:.1f} ms", flush=True)
    for tree, outs in figures.items():
        print(f"{tree}: medians over {args.rounds} rounds: server CPU per call "
              f"{statistics.median(o['burst_server_cpu_ms'] for o in outs):.2f} ms (client "
              f"{statistics.median(o['burst_client_cpu_ms'] for o in outs):.2f} ms), burst p50 "
              f"{statistics.median(o['burst_p50'] for o in outs):.0f} ms, ratio "
              f"{statistics.median(o['floor_ratio'] for o in outs):.2f}x, one by one p50 "
              f"{statistics.median(o['p50_first'] for o in outs):.1f} ms")


if __name__ == "__main__":
    main()
