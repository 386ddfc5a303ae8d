"""No wording may share a run of 6 words with a caption of its map (captions and raw caption JSON text)."""
import re, sys
from _common_round44 import load_map, load_suite

N = 6
def words(s):
    return re.findall(r"[a-z0-9']+", s.lower())

def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}

rows, _ = load_suite()
cache = {}
bad = 0
for r in rows:
    if r["map"] not in cache:
        m = load_map(r["map"])
        g = set()
        for o in m["objs"].values():
            for txt in (o.get("caption") or "", o.get("raw") or ""):
                g |= grams(words(txt))
        cache[r["map"]] = g
    hit = grams(words(r["query"])) & cache[r["map"]]
    if hit:
        bad += 1
        print(r["id"], r["query"], "->", [" ".join(h) for h in hit])
print(f"{len(rows)} wordings checked, {bad} share a {N}-word run with a caption")
sys.exit(1 if bad else 0)
