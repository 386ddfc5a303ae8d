"""No wording may share a run of 6 words with a caption of its map.
    python3 scripts/copycheck.py   (from /work/blind35)"""
import json, re, sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SUITE = ROOT / "evals" / "blind" / "round35.jsonl"
N = 6

def words(s): return re.findall(r"[a-z0-9]+(?:['-][a-z0-9]+)*", s.lower())

def captions(m):
    d = json.loads((SUITE.parent / m).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption") or "" for o in d["objects"]]
    out = []
    for v in d.values():
        cap = v.get("caption") or ""
        try:
            cap = json.loads(cap).get("captions", cap)
        except Exception:
            pass  # keep the raw text (some captions are not strict JSON)
        out.append(str(cap))
    return out

def grams(ws): return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}

def main():
    cache, bad = {}, 0
    rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
    for r in rows:
        if r["map"] not in cache:
            cache[r["map"]] = set().union(*(grams(words(c)) for c in captions(r["map"])))
        hit = grams(words(r["query"])) & cache[r["map"]]
        if hit:
            bad += 1
            print("COPY", r["id"], r["query"], "->", [" ".join(h) for h in hit])
    print(f"{len(rows)} wordings checked, {bad} sharing a {N}-word run with a caption")
    return 1 if bad else 0

if __name__ == "__main__":
    sys.exit(main())
