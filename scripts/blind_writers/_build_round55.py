"""Write evals/blind/round55.jsonl from scripts/groups.py (hand-written wordings and hand-decided accept sets)."""
import json, sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _groups_round55 import G


out = Path(__file__).resolve().parents[2] / "evals/blind/round55.jsonl"
lines = []
for gi, g in enumerate(G, 1):
    gid = f"b55-g{gi:02d}"
    accept = sorted(g.get("accept", [g["target"]]))
    assert g["target"] in accept, (gid, accept)
    for wi, q in enumerate(g["w"], 1):
        lines.append(json.dumps({"id": f"{gid}-w{wi}", "map": g["map"], "query": q, "type": g["type"],
                                 "target": g["target"], "accept": accept, "group": gid}, ensure_ascii=False))
out.write_text("\n".join(lines) + "\n", encoding="utf-8")
print(f"wrote {len(lines)} lines to {out}")
