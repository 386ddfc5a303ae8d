"""Report any wording of round51.jsonl that shares a run of 6 consecutive words with a caption of its map."""
import json, re, sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from _common_round51 import captions

SUITE = Path(__file__).resolve().parents[2] / "evals/blind/round51.jsonl"
N = 6


def toks(s):
    return re.findall(r"[a-z0-9]+", s.lower())


def grams(t, n=N):
    return {tuple(t[i:i + n]) for i in range(len(t) - n + 1)}


def main():
    cache, hits, longest = {}, 0, (0, "", "")
    for line in SUITE.read_text(encoding="utf-8").splitlines():
        r = json.loads(line)
        if r["map"] not in cache:
            cache[r["map"]] = [toks(c) for c in captions(r["map"])]
        q = toks(r["query"])
        for c in cache[r["map"]]:
            shared = grams(q) & grams(c)
            if shared:
                hits += 1
                print(f"{r['id']}: shares {' '.join(sorted(shared)[0])!r} with caption {' '.join(c)!r}")
            # longest common run, for the notes
            for n in range(min(len(q), len(c)), longest[0], -1):
                common = grams(q, n) & grams(c, n)
                if common:
                    longest = (n, r["id"], " ".join(sorted(common)[0]))
                    break
    print(f"{hits} wording/caption pairs share a {N}-word run; longest shared run {longest[0]} words "
          f"({longest[1]}: {longest[2]!r})")
    return 1 if hits else 0


if __name__ == "__main__":
    sys.exit(main())
