"""No wording of round33 may share a run of N=6 words with any caption of its map."""
import json, re, sys
from pathlib import Path

BLIND = Path(__file__).resolve().parents[1] / "evals" / "blind"
N = 6


def words(t):
    return re.findall(r"[a-z0-9']+", t.lower())


def grams(t, n=N):
    w = words(t)
    return {tuple(w[i:i + n]) for i in range(len(w) - n + 1)}


def captions(mp):
    d = json.loads((BLIND / mp).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return [o.get("caption", "") or "" for o in d["objects"]]
    return [v.get("caption", "") or "" for v in d.values()]


def main():
    suite = BLIND / "round33.jsonl"
    cache, bad, worst = {}, [], 0
    for line in suite.read_text().splitlines():
        r = json.loads(line)
        if r["map"] not in cache:
            cache[r["map"]] = set().union(*[grams(c) for c in captions(r["map"])] or [set()])
        hit = grams(r["query"]) & cache[r["map"]]
        if hit:
            bad.append((r["id"], r["query"], sorted(hit)))
        # longest shared run, for information
        cw = words(r["query"])
        for n in range(5, 0, -1):
            caps = None
            if any(tuple(cw[i:i + n]) in set().union(*[grams(c, n) for c in captions(r["map"])] or [set()])
                   for i in range(len(cw) - n + 1)):
                worst = max(worst, n)
                break
    for b in bad:
        print("SHARED 6-word run:", *b)
    print(f"checked {len(suite.read_text().splitlines())} wordings; violations: {len(bad)}; longest shared run <= {max(worst, 6 if bad else worst)} words")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
