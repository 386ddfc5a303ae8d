"""Write evals/blind/round63.jsonl from scripts/groups.py."""
import json
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _groups_round63 import G
out = Path(__file__).resolve().parents[2] / "evals/blind/round63.jsonl"
with out.open("w", encoding="utf-8") as f:
    for i, gr in enumerate(G, 1):
        for j, q in enumerate(gr["w"], 1):
            row = {"id": f"b63-g{i:02d}-w{j}", "map": gr["map"], "query": q, "type": gr["type"],
                   "target": gr["target"], "accept": sorted(gr["accept"]), "group": f"b63-g{i:02d}"}
            f.write(json.dumps(row, ensure_ascii=False) + "\n")
print("wrote", out, len(G), "groups")
