"""Report any 6-word run a wording shares with a caption of its map (lower case, words = [a-z0-9]+)."""
import json
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _common_round63 import BLIND, load, words

N = 6
rows = [json.loads(x) for x in (BLIND / "round63.jsonl").read_text().splitlines()]
grams = {}
hits = 0
longest = (0, None)
for r in rows:
    if r["map"] not in grams:
        gs = {}
        for o in load(r["map"]):
            ws = words(o["caption"])
            for k in range(1, len(ws) + 1):
                for i in range(len(ws) - k + 1):
                    gs.setdefault(k, set()).add(tuple(ws[i:i + k]))
        grams[r["map"]] = gs
    gs = grams[r["map"]]
    ws = words(r["query"])
    for k in range(len(ws), 0, -1):
        if any(tuple(ws[i:i + k]) in gs.get(k, ()) for i in range(len(ws) - k + 1)):
            if k > longest[0]:
                longest = (k, r["id"])
            if k >= N:
                hits += 1
                print("SHARED", k, r["id"], r["query"])
            break
print(f"{len(rows)} wordings checked; {hits} share a run of {N}+ words with a caption; longest shared run {longest[0]} words ({longest[1]})")
sys.exit(1 if hits else 0)
