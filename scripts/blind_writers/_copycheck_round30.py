"""No wording may share a run of 6 words with a caption of its map.
    python3 scripts/copycheck.py [N=6]"""
import json, re, sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SUITE = ROOT / "evals" / "blind" / "round30.jsonl"
N = int(sys.argv[1]) if len(sys.argv) > 1 else 6


def words(t):
    return re.findall(r"[a-z0-9]+", t.lower())


def grams(ws, n):
    return {tuple(ws[i:i + n]) for i in range(len(ws) - n + 1)}


def captions(mp):
    p = SUITE.parent / mp
    if not p.is_file():
        p = ROOT / "map_store" / f"{mp}.json"
    d = json.loads(p.read_text())
    if "objects" in d:
        return [str(o.get("caption") or "") for o in d["objects"]]
    return [str(v.get("caption") or "") for v in d.values()]  # whole raw caption text, all fields


def main():
    cache, bad, n = {}, 0, 0
    for line in SUITE.read_text().splitlines():
        r = json.loads(line); n += 1
        if r["map"] not in cache:
            cache[r["map"]] = set().union(*(grams(words(c), N) for c in captions(r["map"])))
        hit = grams(words(r["query"]), N) & cache[r["map"]]
        if hit:
            bad += 1
            print(r["id"], "shares", [" ".join(h) for h in hit], "|", r["query"])
    print(f"{n} wordings, {bad} sharing a {N}-word run with a caption of their map")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
