"""No wording may share a run of 6 words with any caption of its map (caption maps: the caption
text as stored, JSON keys included; object maps: every object's caption). Exit 1 on a hit."""
import json
import re
import sys
from pathlib import Path

SUITE = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round34.jsonl"
N = 6


def words(s):
    return re.findall(r"[a-z0-9]+", s.lower().replace("'", ""))


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


def captions(path):
    d = json.loads(path.read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption") or "" for o in d["objects"]]
    return [v.get("caption") or "" for v in d.values()]


def main():
    cache, hits, n = {}, [], 0
    for line in SUITE.read_text().splitlines():
        r = json.loads(line)
        if r["map"] not in cache:
            g = set()
            for c in captions((SUITE.parent / r["map"]).resolve()):
                g |= grams(words(c))
            cache[r["map"]] = g
        n += 1
        shared = grams(words(r["query"])) & cache[r["map"]]
        if shared:
            hits.append(f"{r['id']}: {' '.join(sorted(shared)[0])}")
    print("\n".join(hits) if hits else f"no 6-word overlap in {n} wordings")
    return 1 if hits else 0


if __name__ == "__main__":
    sys.exit(main())
