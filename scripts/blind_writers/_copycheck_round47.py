"""No wording may share a run of 6 words with any caption of its map.

    python3 scripts/copycheck.py     (exits 1 when a wording copies a 6-word run)
Words are lower-cased alphanumeric runs (hyphens and punctuation split words).
"""
import re
import sys

from _common_round47 import load
from _build_round47 import GROUPS, MAPS

N = 6


def grams(text):
    w = re.findall(r"[a-z0-9]+", text.lower())
    return {tuple(w[i:i + N]) for i in range(len(w) - N + 1)}


def main():
    caps = {}
    bad = 0
    total = 0
    for g, key, *_rest in GROUPS:
        words = _rest[-1]
        if key not in caps:
            objs = load(MAPS[key])[0]
            caps[key] = set().union(*(grams(o["caption"] or "") | grams(o.get("raw", "")) for o in objs.values()))
        for k, q in enumerate(words, 1):
            total += 1
            hit = grams(q) & caps[key]
            if hit:
                bad += 1
                print(f"g{g:02d} w{k}: shares {[' '.join(h) for h in hit]}  <- {q}")
    print(f"{total} wordings checked, {bad} share a {N}-word run with a caption of their map")
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
