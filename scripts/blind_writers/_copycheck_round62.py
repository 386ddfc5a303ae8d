"""Report any wording of round62.jsonl that shares a run of 6 consecutive words with a caption of its map."""
import json
import re
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _maps_round62 import load, BLIND

N = 6


def tok(s):
    return re.findall(r"[a-z0-9]+", s.lower().replace("'", ""))  # hyphens split: stricter


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


rows = [json.loads(x) for x in (BLIND / "round62.jsonl").read_text(encoding="utf-8").splitlines()]
cache, hits = {}, 0
for r in rows:
    if r["map"] not in cache:
        cache[r["map"]] = [(o["id"], grams(tok(o["caption"]))) for o in load(r["map"])]
    q = grams(tok(r["query"]))
    for oid, g in cache[r["map"]]:
        for run in q & g:
            hits += 1
            print(f"{r['id']}: shares '{' '.join(run)}' with caption of object {oid}")
print(f"copycheck: {len(rows)} wordings, {hits} shared {N}-word runs")
sys.exit(1 if hits else 0)
