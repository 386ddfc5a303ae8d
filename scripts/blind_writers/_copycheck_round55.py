"""Find 6-word runs that a wording of round55.jsonl shares with any caption of its map."""
import json, re, sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _common_round55 import load

N = 6
SUITE = Path(__file__).resolve().parents[2] / "evals/blind/round55.jsonl"


def words(s):
    return re.findall(r"[a-z0-9]+", s.lower())


def grams(ws, n=N):
    return {tuple(ws[i:i + n]) for i in range(len(ws) - n + 1)}


cache = {}
hits = 0
rows = [json.loads(l) for l in SUITE.read_text(encoding="utf-8").splitlines()]
for r in rows:
    if r["map"] not in cache:
        _, _, caps = load(r["map"])
        g = set()
        for c in caps:
            g |= grams(words(c))
        cache[r["map"]] = g
    shared = grams(words(r["query"])) & cache[r["map"]]
    if shared:
        hits += 1
        print(f"{r['id']}: shares {[' '.join(x) for x in shared]} -- {r['query']}")
# also report the longest shared run overall, for the notes
longest = 0
for r in rows:
    ws = words(r["query"])
    for n in range(min(len(ws), 12), 0, -1):
        if any(t in set().union(*[grams(words(c), n) for c in load(r["map"])[2]]) for t in grams(ws, n)):
            longest = max(longest, n)
            break
print(f"{len(rows)} lines checked, {hits} with a shared {N}-word run; longest shared run {longest} words")
sys.exit(1 if hits else 0)
