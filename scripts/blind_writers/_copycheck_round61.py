"""Report every wording of round61.jsonl that shares a run of N (6) consecutive words with any caption of its map."""
import json
import re
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _maps_round61 import BLIND, load

N = 6


def words(s):
    return re.findall(r"[a-z0-9]+", s.lower())


def grams(ws):
    return {tuple(ws[i:i + N]) for i in range(len(ws) - N + 1)}


suite = BLIND / "round61.jsonl"
if "--self-test" in sys.argv:  # a caption's own words must be caught
    for name in ("maps/flat_c.json", "apartment", "../../../shared/data/iesm_maps/scene_00829_caption.json"):
        objs = load(name)
        o = next(x for x in objs.values() if len(words(x["caption"])) >= N)
        assert grams(words("Take me to " + o["caption"])) & grams(words(o["caption"])), name
    print("self-test passed")
cache, hits, n = {}, 0, 0
for line in suite.read_text().splitlines():
    row = json.loads(line)
    if row["map"] not in cache:
        objs = load(row["map"])
        cap = {}
        for o in objs.values():
            for text in {o["caption"], o.get("raw_caption", "")}:
                for g in grams(words(text)):
                    cap.setdefault(g, o["id"])
        cache[row["map"]] = cap
    n += 1
    for g in grams(words(row["query"])):
        if g in cache[row["map"]]:
            hits += 1
            print(f"{row['id']}: shares '{' '.join(g)}' with caption of object {cache[row['map']][g]}")
print(f"{n} wordings checked, {hits} shared {N}-word runs")
sys.exit(1 if hits else 0)
