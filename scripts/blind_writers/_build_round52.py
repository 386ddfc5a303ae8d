"""Write evals/blind/round52.jsonl from scripts/groups.py (hand-written wordings)."""
import json, sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _groups_round52 import G, M

out = Path(__file__).resolve().parents[2] / "evals/blind/round52.jsonl"
lines = []
for n, grp in enumerate(G, 1):
    gid = f"b52-g{n:02d}"
    for w, q in enumerate(grp["words"], 1):
        lines.append(json.dumps({"id": f"{gid}-w{w}", "map": M[grp["map"]], "query": q, "type": grp["type"],
                                 "target": grp["target"], "accept": sorted(grp["accept"]), "group": gid},
                                ensure_ascii=False))
out.write_text("\n".join(lines) + "\n", encoding="utf-8")
print(len(G), "groups,", len(lines), "lines ->", out)
