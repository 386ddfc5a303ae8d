#!/usr/bin/env python3
"""No wording may share a run of 6 words with any caption of its map. Exit 1 on a hit."""
import json, os, re, sys
BASE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "evals", "blind")
N = 6

def words(t): return re.findall(r"[a-z0-9']+", t.lower())

def captions(mp):
    d = json.load(open(os.path.join(BASE, mp)))
    if "objects" in d:
        return [o.get("caption", "") or "" for o in d["objects"]]
    out = []
    for v in d.values():
        c = v.get("caption", "")
        out.append(c)  # raw text (JSON-ish) covers the captions field and every other field
    return out

def grams(ws): return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}

def main():
    cache, hits, n = {}, 0, 0
    for line in open(os.path.join(BASE, "round37.jsonl")):
        r = json.loads(line); n += 1
        if r["map"] not in cache:
            g = set()
            for c in captions(r["map"]):
                g |= grams(words(c))
            cache[r["map"]] = g
        common = grams(words(r["query"])) & cache[r["map"]]
        if common:
            hits += 1
            print("HIT", r["id"], r["query"], [" ".join(x) for x in common])
    print(f"{n} wordings checked, {hits} with a shared {N}-word run")
    return 1 if hits else 0

if __name__ == "__main__":
    sys.exit(main())
