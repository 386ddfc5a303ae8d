"""Write evals/blind/round61.jsonl from scripts/groups.py."""
import json
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _groups_round61 import G
out = Path(__file__).resolve().parents[2] / "evals/blind/round61.jsonl"
lines = []
for gi, g in enumerate(G, 1):
    gid = f"b61-g{gi:02d}"
    assert len(g["w"]) == 6, gid
    for wi, q in enumerate(g["w"], 1):
        lines.append(json.dumps({"id": f"{gid}-w{wi}", "map": g["map"], "query": q, "type": g["type"],
                                 "target": g["target"], "accept": sorted(g["accept"]), "group": gid}))
out.write_text("\n".join(lines) + "\n", encoding="utf-8")
print(f"wrote {len(lines)} lines to {out}")
