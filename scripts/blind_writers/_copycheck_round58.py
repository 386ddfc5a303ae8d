"""Report any run of N (default 6) consecutive words shared by a suite wording and a caption of its map."""
import json
import sys
from _common_round58 import FIELD_TO_KEY, SUITE, load, words


def grams(ws, n):
    return {tuple(ws[i:i + n]) for i in range(len(ws) - n + 1)}


def main(n=6):
    caps = {}
    hits = 0
    near = 0
    for line in SUITE.read_text().splitlines():
        row = json.loads(line)
        key = FIELD_TO_KEY[row["map"]]
        if key not in caps:
            objs, _ = load(key)
            caps[key] = [(i, words(c)) for i, o in objs.items() for c in o["captions"] if c]
        q = words(row["query"])
        for i, cw in caps[key]:
            shared = grams(q, n) & grams(cw, n)
            if shared:
                hits += 1
                print(f"{row['id']}: shares {' '.join(sorted(shared)[0])!r} with caption of {i}")
            if grams(q, n - 1) & grams(cw, n - 1):
                near += 1
    print(f"copycheck: {hits} wording/caption pairs share a {n}-word run; {near} share a {n-1}-word run (allowed)")
    return 1 if hits else 0


if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else 6))
