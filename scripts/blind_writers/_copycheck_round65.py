"""Report any wording of round65.jsonl that shares a run of N (default 6) consecutive words with
any caption of its own map.   python3 scripts/copycheck.py [N]"""
import json
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common_round65 import captions_of, words  # noqa: E402

SUITE = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round65.jsonl"


def grams(ws, n):
    return {tuple(ws[i:i + n]) for i in range(len(ws) - n + 1)}


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 6
    rows = [json.loads(x) for x in SUITE.read_text(encoding="utf-8").splitlines()]
    cache = {}
    hits = 0
    longest = (0, None)
    for r in rows:
        if r["map"] not in cache:
            caps = captions_of(r["map"])
            cache[r["map"]] = {k: set().union(*(grams(words(c), k) for c in caps)) for k in range(1, 13)}
        qw = words(r["query"])
        for k in range(12, 0, -1):
            if grams(qw, k) & cache[r["map"]][k]:
                if k > longest[0]:
                    longest = (k, r["id"])
                break
        shared = grams(qw, n) & cache[r["map"]][n]
        if shared:
            hits += 1
            print(f"{r['id']}: shares {[' '.join(s) for s in shared]}")
    print(f"{len(rows)} wordings checked; {hits} share a {n}-word run with a caption; "
          f"longest shared run {longest[0]} words ({longest[1]})")
    return 1 if hits else 0


if __name__ == "__main__":
    sys.exit(main())
