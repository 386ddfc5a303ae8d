"""No wording may share a run of 6 words with any caption of its own map. Exit 1 on a hit.
Captions of caption maps are read both as the raw caption string and its inner "captions" text."""
import json, re, sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SUITE = ROOT / "evals" / "blind" / "round39.jsonl"
N = 6


def words(t):
    return re.findall(r"[a-z0-9]+(?:'[a-z]+)?", t.lower())


def grams(ws, n=N):
    return {tuple(ws[i:i + n]) for i in range(len(ws) - n + 1)}


def captions(mp):
    d = json.loads((SUITE.parent / mp).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption", "") or "" for o in d["objects"]]
    return [v.get("caption", "") for v in d.values()]


cache, hits, n = {}, [], 0
for line in SUITE.read_text().splitlines():
    r = json.loads(line)
    if r["map"] not in cache:
        g = set()
        for c in captions(r["map"]):
            g |= grams(words(c))
        cache[r["map"]] = g
    n += 1
    shared = grams(words(r["query"])) & cache[r["map"]]
    if shared:
        hits.append((r["id"], [" ".join(s) for s in shared]))
for h in hits:
    print("COPY", h)
print(f"{n} wordings checked, {len(hits)} with a shared {N}-word run")
sys.exit(1 if hits else 0)
