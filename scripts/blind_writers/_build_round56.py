import json
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _groups_round56 import G
out = Path(__file__).resolve().parents[2] / "evals/blind/round56.jsonl"
with open(out, "w", encoding="utf-8") as f:
    for i, g in enumerate(G, 1):
        gid = f"b56-g{i:02d}"
        assert len(g["w"]) == 6
        for j, q in enumerate(g["w"], 1):
            f.write(json.dumps({"id": f"{gid}-w{j}", "map": g["map"], "query": q, "type": g["type"],
                                "target": g["target"], "accept": sorted(g["accept"]), "group": gid},
                               ensure_ascii=False) + "\n")
print("groups", len(G))
