"""Round 53: report any wording that shares a run of N (default 6) consecutive words with any caption of its map."""
import json, re, sys
from pathlib import Path

BASE = Path(__file__).resolve().parents[2] / "evals/blind"
N = int(sys.argv[1]) if len(sys.argv) > 1 else 6

def words(s):
    return re.findall(r"[a-z0-9]+", s.lower())

def captions(mapname):
    p = (BASE / mapname).resolve()
    if not p.is_file():
        p = Path(__file__).resolve().parents[2] / "map_store" / f"{mapname}.json"
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption", "") for o in d["objects"] if o.get("caption")]
    out = []
    for v in d.values():
        raw = v["caption"]
        try:
            out.append(json.loads(re.sub(r",\s*}\s*$", "}", raw)).get("captions", raw))
        except ValueError:
            out.append(raw)
        out.append(raw)  # the whole stored string too
    return out

def grams(ws, n):
    return {tuple(ws[i:i + n]) for i in range(len(ws) - n + 1)}

rows = [json.loads(l) for l in (BASE / "round53.jsonl").read_text().splitlines()]
cache, hits, longest = {}, 0, 0
for r in rows:
    if r["map"] not in cache:
        caps = captions(r["map"])
        cache[r["map"]] = [words(c) for c in caps]
    q = words(r["query"])
    for cw in cache[r["map"]]:
        for n in range(min(len(q), len(cw)), 0, -1):
            if grams(q, n) & grams(cw, n):
                longest = max(longest, n)
                if n >= N:
                    hits += 1
                    print(f"{r['id']}: {n}-word run shared: {' '.join(sorted(grams(q, n) & grams(cw, n))[0])}")
                break
print(f"{len(rows)} lines checked against {sum(len(v) for v in cache.values())} captions; "
      f"{hits} runs of >= {N} words; longest shared run {longest} words")
sys.exit(1 if hits else 0)
