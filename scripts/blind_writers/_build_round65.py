"""Write evals/blind/round65.jsonl from scripts/suite_data.py (hand-written wordings)."""
import json
from pathlib import Path
from _suite_data_round65 import GROUPS

out = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round65.jsonl"
lines = []
for gi, g in enumerate(GROUPS, 1):
    assert len(g["w"]) == 6, gi
    group = f"b65-g{gi:02d}"
    for wi, q in enumerate(g["w"], 1):
        lines.append(json.dumps({"id": f"{group}-w{wi}", "map": g["map"], "query": q, "type": g["type"],
                                 "target": g["target"], "accept": sorted(g["accept"]), "group": group},
                                ensure_ascii=False))
out.write_text("\n".join(lines) + "\n", encoding="utf-8")
print(f"wrote {len(lines)} lines, {len(GROUPS)} groups to {out}")
