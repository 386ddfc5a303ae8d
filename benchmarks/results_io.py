"""Shared by the benchmark scripts: record one figure per DESIGN.md performance target into
`benchmarks/results.json` (merged, so scripts can run one by one or all through `run_all.py`)."""

from __future__ import annotations

import json
import os
import tempfile
from pathlib import Path

RESULTS = Path(__file__).resolve().parent / "results.json"


def record(key: str, value: float, unit: str, target: str, holds: bool, note: str = "") -> None:
    """Store `value` (in `unit`) for target `key` ("<= 2 ms", ">= 30 frames/s", ...) and whether it holds."""
    try:
        results = json.loads(RESULTS.read_text())
    except (OSError, ValueError):
        results = {}
    results[key] = {"value": round(float(value), 4), "unit": unit, "target": target, "holds": bool(holds)}
    if note:
        results[key]["note"] = note
    fd, tmp = tempfile.mkstemp(dir=RESULTS.parent, suffix=".json")
    with os.fdopen(fd, "w") as fh:
        json.dump(results, fh, indent=2, sort_keys=True)
        fh.write("\n")
    os.replace(tmp, RESULTS)
