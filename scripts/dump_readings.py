"""Write every reading of the request reader to one file, to check that a change meant to leave
readings alone (a refactor of `iesm_agent/understanding/`) does: for every query of the shipped
suites, the blind rounds and the referring corpus, `analyse_query` and the spatial reading
(`spatial.parse_query`); for every label, caption and room name of the shipped and blind maps, what
`label_concepts`, `room_of` and `text_slots` read. One line each, in a fixed order; sets print in
the order of a fixed hash seed (the script restarts itself with PYTHONHASHSEED=0).

Run from the repository root on each tree and compare:
    .venv/bin/python scripts/dump_readings.py /tmp/before.txt   (on the tree before)
    .venv/bin/python scripts/dump_readings.py /tmp/after.txt    (on the tree after)
    cmp /tmp/before.txt /tmp/after.txt
About three minutes for the 18,861 texts of 61 rounds and the corpus.
"""

from __future__ import annotations

import json
import os
import sys
from pathlib import Path

from check_parse_batching import REPO, suite_queries

#: the fields of a map file that hold a label, a caption or a room name
_TEXT_FIELDS = ("label", "category", "caption", "room", "name")


def map_texts() -> list[str]:
    """The labels, captions and room names of the shipped maps, the evaluation maps and the blind
    rounds' maps, each once, sorted."""
    found: set[str] = set()

    def walk(value) -> None:
        if isinstance(value, dict):
            for key, inner in value.items():
                if key in _TEXT_FIELDS and isinstance(inner, str):
                    found.add(inner)
                else:
                    walk(inner)
        elif isinstance(value, list):
            for inner in value:
                walk(inner)

    for folder in (REPO / "map_store", REPO / "evals" / "maps", REPO / "evals" / "blind" / "maps"):
        for path in sorted(folder.glob("*.json")):
            walk(json.loads(path.read_text()))
    return sorted(found)


def main() -> None:
    if os.environ.get("PYTHONHASHSEED") != "0":  # frozensets print in hash order: fix it
        os.execve(sys.executable, [sys.executable, *sys.argv], {**os.environ, "PYTHONHASHSEED": "0"})
    if len(sys.argv) != 2:
        sys.exit("usage: dump_readings.py OUT")
    from iesm_agent.understanding import analyse_query, label_concepts, room_of, text_slots
    from iesm_agent.understanding.spatial import parse_query

    queries, labels = sorted(suite_queries()), map_texts()
    with Path(sys.argv[1]).open("w") as out:
        for text in queries:
            out.write(f"Q {analyse_query(text)!r}\nS {parse_query(text)!r}\n")
        for text in labels:
            out.write(f"L {(text, label_concepts(text), room_of(text), text_slots(text))!r}\n")
    print(f"{len(queries)} queries, {len(labels)} map texts -> {sys.argv[1]}")


if __name__ == "__main__":
    main()
