"""Report any wording of evals/blind/round57.jsonl that shares a run of N (default 6) consecutive
words with any caption of its map (object captions, or the 'captions' text of caption maps).
Also prints the longest shared run per group for information."""

import json
import re
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
N = int(sys.argv[1]) if len(sys.argv) > 1 else 6


def toks(s):
    return re.findall(r"[a-z0-9]+", s.lower())


def captions(map_):
    p = (ROOT / "evals/blind" / map_).resolve()
    if not p.is_file():
        p = ROOT / "map_store" / f"{map_}.json"
    data = json.loads(p.read_text())
    if isinstance(data, dict) and "objects" in data:
        return [o.get("caption", "") for o in data["objects"]]
    return [v.get("caption", "") for v in data.values()]  # whole caption string, incl. the 'captions' text


def longest(a, b):
    best = 0
    for i in range(len(a)):
        for j in range(len(b)):
            k = 0
            while i + k < len(a) and j + k < len(b) and a[i + k] == b[j + k]:
                k += 1
            best = max(best, k)
    return best


def main():
    rows = [json.loads(line) for line in (ROOT / "evals/blind/round57.jsonl").read_text().splitlines()]
    cache, hits, worst = {}, 0, {}
    for r in rows:
        caps = cache.setdefault(r["map"], [toks(c) for c in captions(r["map"])])
        q = toks(r["query"])
        for c in caps:
            L = longest(q, c)
            if L > worst.get(r["group"], (0, ""))[0]:
                worst[r["group"]] = (L, r["id"])
            if L >= N:
                hits += 1
                print(f"HIT {r['id']}: shares {L} words with a caption")
                break
    print("longest shared run per group:", {g: v[0] for g, v in sorted(worst.items())})
    print(f"{hits} wordings share a run of >= {N} words with a caption")
    return 1 if hits else 0


if __name__ == "__main__":
    sys.exit(main())
