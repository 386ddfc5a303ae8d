"""No wording may share a run of 6 words with a caption of its own map.
    python3 copycheck.py   (reads ../evals/blind/round31.jsonl and the maps it names)"""
import json, re, sys
from pathlib import Path

BLIND = Path(__file__).resolve().parents[1] / "evals" / "blind"
N = 6


def words(s):
    return re.findall(r"[a-z0-9]+", s.lower().replace("'", ""))


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


def captions(mapname):
    p = (BLIND / mapname).resolve()
    if not p.is_file():
        p = BLIND / mapname
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption", "") or "" for o in d["objects"]]
    out = []
    for v in d.values():
        m = re.search(r'"captions":\s*"(.*?)"\s*,?\s*}?\s*$', v["caption"], re.S)
        out.append(m.group(1) if m else v["caption"])
        out.append(v["caption"])  # the whole string as well, to be safe
    return out


cache, bad, n = {}, 0, 0
for line in (BLIND / "round31.jsonl").read_text().splitlines():
    r = json.loads(line)
    if r["map"] not in cache:
        cache[r["map"]] = set().union(*(grams(words(c)) for c in captions(r["map"])))
    shared = grams(words(r["query"])) & cache[r["map"]]
    n += 1
    if shared:
        bad += 1
        print(f"{r['id']}: shares {[' '.join(s) for s in shared]} :: {r['query']}")
print(f"copycheck: {n} wordings, {bad} share a {N}-word run with a caption of their map")
sys.exit(1 if bad else 0)
