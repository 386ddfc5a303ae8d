"""Report any wording of round52.jsonl that shares a run of N (default 6) consecutive words with a caption of its map.

    python3 scripts/copycheck.py [N]
Words: lower-cased runs of letters/digits (hyphens and punctuation split words)."""
import json, re, sys
from pathlib import Path

N = int(sys.argv[1]) if len(sys.argv) > 1 else 6
BLIND = Path(__file__).resolve().parents[2] / "evals/blind"
SUITE = BLIND / "round52.jsonl"


def words(t):
    return re.findall(r"[a-z0-9]+", t.lower())


def captions(mapname):
    p = Path(__file__).resolve().parents[2] / "map_store/apartment.json" if mapname == "apartment" else (BLIND / mapname).resolve()
    d = json.loads(p.read_text())
    out = []
    if isinstance(d, dict) and "objects" in d:
        out = [o.get("caption") or "" for o in d["objects"]]
    else:
        for v in d.values():
            out.append(v["caption"])  # the whole caption string (covers the "captions" text and its fields)
    return out


grams = {}
hits = 0
rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
for r in rows:
    if r["map"] not in grams:
        g = set()
        for c in captions(r["map"]):
            w = words(c)
            g |= {tuple(w[i:i + N]) for i in range(len(w) - N + 1)}
        grams[r["map"]] = g
    w = words(r["query"])
    shared = {tuple(w[i:i + N]) for i in range(len(w) - N + 1)} & grams[r["map"]]
    if shared:
        hits += 1
        print(r["id"], [" ".join(s) for s in shared])
print(f"copycheck (n={N}): {hits} of {len(rows)} wordings share a {N}-word run with a caption of their map")
sys.exit(1 if hits and N == 6 else 0)
