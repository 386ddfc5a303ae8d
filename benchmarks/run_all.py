"""Run every benchmark script in this folder (`make bench`), then print the table of
`benchmarks/results.json`: one row per performance target of DESIGN.md, with its measured value
and whether it holds."""

import json
import subprocess
import sys
import time
from pathlib import Path

HERE = Path(__file__).resolve().parent
RESULTS = HERE / "results.json"


def print_table() -> None:
    results = json.loads(RESULTS.read_text()) if RESULTS.is_file() else {}
    print(f"\n{'target':<34} {'value':>12} {'unit':<10} {'target':<24} holds")
    for key, row in sorted(results.items()):
        print(f"{key:<34} {row['value']:>12.4g} {row['unit']:<10} {row['target']:<24} {'yes' if row['holds'] else 'NO'}")
        if not row["holds"] and row.get("note"):
            print(f"{'':<34} why: {row['note']}")
    print(f"\nwritten to {RESULTS.relative_to(HERE.parent)}")


if __name__ == "__main__":
    RESULTS.unlink(missing_ok=True)  # every figure comes from this run
    failed = []
    for script in sorted(HERE.glob("bench_*.py")):
        print(f"\n== {script.name}", flush=True)
        t0 = time.perf_counter()
        if subprocess.run([sys.executable, str(script)]).returncode != 0:
            failed.append(script.name)
        print(f"   ({time.perf_counter() - t0:.0f} s)", flush=True)
    print_table()
    if failed:
        print(f"\nfailed: {', '.join(failed)}")
    sys.exit(1 if failed else 0)
