"""Write evals/blind/round62.jsonl from scripts/groups.py (hand-written wordings)."""
import json
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _groups_round62 import GROUPS

out = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round62.jsonl"
lines = []
for g, spec in enumerate(GROUPS, 1):
    gid = f"b62-g{g:02d}"
    assert len(spec["w"]) == 6, gid
    for w, q in enumerate(spec["w"], 1):
        lines.append(json.dumps({"id": f"{gid}-w{w}", "map": spec["map"], "query": q, "type": spec["type"],
                                 "target": spec["target"], "accept": sorted(spec["accept"]), "group": gid},
                                ensure_ascii=False))
out.write_text("\n".join(lines) + "\n", encoding="utf-8")
print(f"wrote {len(lines)} lines to {out}")
