"""No wording of round41.jsonl may share a run of 6 words with any caption of its map."""
import json, re, sys
from pathlib import Path

SUITE = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round41.jsonl"
N = 6
tok = lambda s: re.findall(r"[a-z0-9]+", (s or "").lower())

def captions(mp):
    d = json.loads((SUITE.parent / mp).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption") or "" for o in d["objects"]]
    return [v.get("caption", "") for v in d.values()]  # full caption string incl. the captions sentence

cache, bad, total = {}, 0, 0
for line in SUITE.read_text().splitlines():
    r = json.loads(line); total += 1
    if r["map"] not in cache:
        grams = set()
        for c in captions(r["map"]):
            t = tok(c); grams |= {tuple(t[i:i + N]) for i in range(len(t) - N + 1)}
        cache[r["map"]] = grams
    t = tok(r["query"])
    hits = [" ".join(g) for g in (tuple(t[i:i + N]) for i in range(len(t) - N + 1)) if g in cache[r["map"]]]
    if hits:
        bad += 1; print("COPY", r["id"], hits)
print(f"{total} wordings checked, {bad} share a {N}-word run with a caption")
sys.exit(1 if bad else 0)
