"""`make demo`: the toolkit end to end on the shipped apartment, with the offline model.

Each step runs the real `iesm` command line (printed first, so it can be copied) in this
process, so the embedding model loads once, and writes into `out/demo/` (override with
IESM_DEMO_DIR).
"""

from __future__ import annotations

import os
import shlex
import shutil
import sys
from pathlib import Path

from .resources import resource_dir

DEMO_QUERIES = [
    ("o", "find the sofa"),
    ("o,r", "go to the sink in the bathroom"),
    ("o,d", "take me to the red leather chair"),
    ("o,r,d", "the wooden chair in the kitchen"),
    ("a,r,d", "something soft to sit on in the living room"),
]


def _run(args: list[str]) -> int:
    from .cli import run

    print(f"\n$ iesm {shlex.join(args)}", flush=True)
    status = run(args)
    if status != 0:
        print(f"(exit status {status})", flush=True)
    return status


def main() -> int:
    out = Path(os.environ.get("IESM_DEMO_DIR", "out/demo"))
    out.mkdir(parents=True, exist_ok=True)
    source = resource_dir("map_store") / "apartment.json"
    scene = out / "apartment.iesm"
    steps = [
        ["import", str(source), "-o", str(scene)],
        ["info", str(scene)],
        ["render", str(scene), "-o", str(out / "apartment.png")],
    ]
    steps += [["ask", str(scene), query, "--explain"] for _, query in DEMO_QUERIES]
    suite = resource_dir("map_store").parent / "evals" / "apartment_suite.jsonl"
    if suite.is_file():
        shutil.rmtree(out / "eval", ignore_errors=True)  # a fresh run each time
        steps.append(["eval", str(suite), "--method", "mtefr,spr,keyword", "-o", str(out / "eval")])
    failed = [step[0] for step in steps if _run(step) != 0]
    print(f"\nDemo outputs are in {out}/" + (f"; failed steps: {', '.join(failed)}" if failed else ""))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
