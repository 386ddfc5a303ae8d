"""Flag any wording sharing a 6-word run with a caption of its map."""
import json, re
from pathlib import Path
suite = Path("/work/blind28/evals/blind/round28.jsonl")
def caps(m):
    d = json.loads((suite.parent / m).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption", "") for o in d["objects"]]
    return [v["caption"] for v in d.values()]
W = lambda s: re.findall(r"[a-z0-9'-]+", s.lower())
n = 0
for l in suite.read_text().splitlines():
    r = json.loads(l); q = W(r["query"])
    grams = {tuple(q[i:i+6]) for i in range(len(q) - 5)}
    for c in caps(r["map"]):
        cw = W(c); cg = {tuple(cw[i:i+6]) for i in range(len(cw) - 5)}
        if grams & cg: print(r["id"], r["query"]); n += 1; break
print("flagged", n)
