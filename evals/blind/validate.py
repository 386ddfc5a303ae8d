"""Check a blind paraphrase suite: every line parses with the suite fields, ids are unique,
targets and accepted ids exist in their maps, spatial lines use maps with geometry, and each group
holds WORDINGS distinct wordings of one intent (one type, map, target and accept set). Groups that
name the exact map label in more than 2 wordings are reported (the writers' own rule).

    python evals/blind/validate.py evals/blind/round6.jsonl [--wordings 6]

Reads only the suite and its map JSON files (object lists or the paper's caption dictionaries).
"""

from __future__ import annotations

import argparse
import json
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path

FIELDS = {"id", "map", "query", "type", "target", "accept", "group"}
TYPES = {"o", "or", "od", "ord", "ard", "s"}


def load_labels(path: Path) -> tuple[dict[int, str], bool]:
    """(instance id -> label, whether the map has geometry) of an object list or a caption dictionary."""
    data = json.loads(path.read_text(encoding="utf-8"))
    if isinstance(data, dict) and "objects" in data:
        return {int(o["id"]): str(o["label"]) for o in data["objects"]}, True
    return {int(k): str(v["category"]) for k, v in data.items()}, False


def check(suite: Path, wordings: int) -> tuple[list[str], list[str], Counter, Counter]:
    """(errors, label warnings, groups per type, groups per map) of `suite`."""
    errors: list[str] = []
    maps: dict[str, tuple[dict[int, str], bool]] = {}
    groups: dict[str, list[dict]] = defaultdict(list)
    seen: set[str] = set()
    for n, line in enumerate(suite.read_text(encoding="utf-8").splitlines(), 1):
        try:
            row = json.loads(line)
        except ValueError as exc:
            errors.append(f"line {n}: does not parse ({exc})")
            continue
        if set(row) != FIELDS:
            errors.append(f"line {n}: fields {sorted(row)}")
            continue
        if row["id"] in seen:
            errors.append(f"line {n}: duplicate id {row['id']}")
        seen.add(row["id"])
        path = (suite.parent / row["map"]).resolve()
        if not path.is_file() and "/" not in row["map"]:  # a shipped map's name ("apartment")
            path = Path(__file__).resolve().parents[2] / "map_store" / f"{row['map']}.json"
        if row["map"] not in maps:
            if not path.is_file():
                errors.append(f"line {n}: no map {path}")
                continue
            maps[row["map"]] = load_labels(path)
        labels, geometry = maps[row["map"]]
        if row["type"] not in TYPES:
            errors.append(f"line {n}: type {row['type']!r}")
        if row["type"] == "s" and not geometry:
            errors.append(f"line {n}: a spatial query on a map without geometry")
        if row["target"] not in row["accept"] or any(a not in labels for a in row["accept"]):
            errors.append(f"line {n}: target or accepted ids missing from the map or the accept set")
        groups[row["group"]].append(row)
    warnings: list[str] = []
    per_type, per_map = Counter(), Counter()
    for name, rows in groups.items():
        if len(rows) != wordings or len({r["query"].lower() for r in rows}) != wordings:
            errors.append(f"group {name}: {len(rows)} lines, {len({r['query'].lower() for r in rows})} distinct")
        if len({(r["type"], r["map"], r["target"], tuple(sorted(r["accept"]))) for r in rows}) != 1:
            errors.append(f"group {name}: its lines differ in type, map, target or accept set")
        labels = maps.get(rows[0]["map"], ({}, False))[0]
        names = {labels[a].lower() for a in rows[0]["accept"] if a in labels}
        uses = sum(any(re.search(r"\b" + re.escape(lab) + r"(s|es)?\b", r["query"].lower()) for lab in names)
                   for r in rows)
        if uses > 2:
            warnings.append(f"group {name}: the map label in {uses} wordings")
        per_type[rows[0]["type"]] += 1
        per_map[Path(rows[0]["map"]).name] += 1
    return errors, warnings, per_type, per_map


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("suite", type=Path)
    parser.add_argument("--wordings", type=int, default=6)
    args = parser.parse_args(argv)
    errors, warnings, per_type, per_map = check(args.suite, args.wordings)
    for line in errors + warnings:
        print(line)
    print(f"groups per type {dict(per_type)}; per map {dict(per_map)}")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
