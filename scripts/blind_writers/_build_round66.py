"""Write evals/blind/round66.jsonl from suite_data.GROUPS."""
import json
from pathlib import Path
from _suite_data_round66 import GROUPS
out = Path(__file__).resolve().parents[2] / 'evals' / 'blind' / 'round66.jsonl'
lines = []
for gi, g in enumerate(GROUPS, 1):
    gid = f"b66-g{gi:02d}"
    assert len(g['w']) == 6, gid
    for wi, q in enumerate(g['w'], 1):
        lines.append(json.dumps({"id": f"{gid}-w{wi}", "map": g['map'], "query": q, "type": g['type'],
                                 "target": g['target'], "accept": sorted(g['accept']), "group": gid}, ensure_ascii=False))
out.write_text("\n".join(lines) + "\n", encoding='utf-8')
print(len(lines), 'lines ->', out)
