"""Report any wording of round56 sharing a run of N (default 6) consecutive words with a caption of its map."""
import json
import re
import sys
from pathlib import Path
ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "evals/blind"
N = int(sys.argv[1]) if len(sys.argv) > 1 else 6
def toks(s): return re.findall(r"[a-z0-9]+", s.lower())
def grams(t, n): return {tuple(t[i:i + n]) for i in range(len(t) - n + 1)}
def captions(mapname):
    p = (BASE / mapname).resolve()
    if not p.is_file():
        p = ROOT / "map_store" / f"{mapname}.json"
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption", "") for o in d["objects"] if o.get("caption")]
    out = []
    for v in d.values():
        out.append(v["caption"])            # whole stored caption text (JSON string), incl. its "captions" field
    return out
cache, hits, n = {}, 0, 0
for line in (BASE / "round56.jsonl").read_text().splitlines():
    r = json.loads(line)
    n += 1
    if r["map"] not in cache:
        cache[r["map"]] = set().union(*[grams(toks(c), N) for c in captions(r["map"])] or [set()])
    shared = grams(toks(r["query"]), N) & cache[r["map"]]
    if shared:
        hits += 1
        print(r["id"], "shares", [" ".join(g) for g in shared])
print(f"{n} wordings checked against {N}-word runs of their map's captions; {hits} with a shared run")
sys.exit(1 if hits else 0)
