"""Find any wording that shares a run of 6 consecutive words with a caption of its map.
Two tokenisations are tried (hyphenated words kept whole, and split at hyphens/apostrophes)."""
import json, re, sys
from pathlib import Path
from _common_round50 import load

SUITE = Path(__file__).resolve().parents[2] / "evals/blind/round50.jsonl"
N = 6

def toks(s, split):
    s = s.lower()
    if split:
        return re.findall(r"[a-z0-9]+", s)
    return re.findall(r"[a-z0-9]+(?:['’-][a-z0-9]+)*", s)

def grams(t):
    return {tuple(t[i:i + N]) for i in range(len(t) - N + 1)}

rows = [json.loads(l) for l in open(SUITE, encoding="utf-8")]
cache, bad = {}, 0
for r in rows:
    if r["map"] not in cache:
        objs, _ = load(r["map"])
        caps = [o["caption"] for o in objs.values() if o["caption"]] + [o.get("raw", "") for o in objs.values() if o.get("raw")]
        cache[r["map"]] = {sp: set().union(*(grams(toks(c, sp)) for c in caps)) for sp in (False, True)}
    for sp in (False, True):
        hit = grams(toks(r["query"], sp)) & cache[r["map"]][sp]
        if hit:
            bad += 1
            print(f"{r['id']}: shares {' '.join(sorted(hit)[0])!r} with a caption: {r['query']}")
            break
print(f"copycheck: {len(rows)} wordings, {bad} sharing a {N}-word run with a caption")
sys.exit(1 if bad else 0)
