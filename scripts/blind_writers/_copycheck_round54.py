"""Report any wording of round54.jsonl that shares a run of N (default 6) consecutive words with a caption of its map."""
import json, re, sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from _check_round54 import load, SUITE

def toks(s):
    return re.findall(r"[a-z0-9]+", s.lower())   # hyphens/apostrophes split, punctuation ignored

def grams(ts, n):
    return {tuple(ts[i:i + n]) for i in range(len(ts) - n + 1)}

def main(n=6):
    rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
    caps = {}
    hits, longest = [], (0, None, None)
    for r in rows:
        if r["map"] not in caps:
            objs, _ = load(r["map"])
            caps[r["map"]] = [(i, toks(o["text"])) for i, o in objs.items()]
        q = toks(r["query"])
        for i, c in caps[r["map"]]:
            shared = grams(q, n) & grams(c, n)
            if shared:
                hits.append((r["id"], i, " ".join(sorted(shared)[0])))
            # longest common run, for the record
            for k in range(min(len(q), len(c)), longest[0], -1):
                if grams(q, k) & grams(c, k):
                    longest = (k, r["id"], i)
                    break
    for h in hits:
        print("SHARED", *h)
    print(f"{len(rows)} wordings checked; {len(hits)} shared {n}-word runs; longest shared run {longest[0]} words ({longest[1]} vs object {longest[2]})")
    return 1 if hits else 0

if __name__ == "__main__":
    sys.exit(main(int(sys.argv[1]) if len(sys.argv) > 1 else 6))
