"""No wording of round46.jsonl may share a run of 6 words with a caption of its map.
Captions: object 'caption' fields (object maps) or the caption strings of caption maps (both the
inner 'captions' sentence and the whole stored string). Run: python3 scripts/copycheck.py"""
import json, re, sys
from pathlib import Path

BLIND = Path(__file__).resolve().parents[2] / "evals" / "blind"
N = 6


def words(text):
    return re.findall(r"[a-z0-9]+", text.lower())


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


def captions(mapfield):
    d = json.loads((BLIND / mapfield).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption") or "" for o in d["objects"]]
    out = []
    for v in d.values():
        out.append(v.get("caption") or "")
    return out


cache, bad, n = {}, 0, 0
for line in (BLIND / "round46.jsonl").read_text().splitlines():
    r = json.loads(line)
    if r["map"] not in cache:
        g = set()
        for c in captions(r["map"]):
            g |= grams(words(c))
        cache[r["map"]] = g
    n += 1
    hit = grams(words(r["query"])) & cache[r["map"]]
    if hit:
        bad += 1
        print(f"{r['id']}: shares {[' '.join(h) for h in hit]}  | {r['query']}")
print(f"{n} wordings checked, {bad} share a {N}-word run with a caption")
sys.exit(1 if bad else 0)
