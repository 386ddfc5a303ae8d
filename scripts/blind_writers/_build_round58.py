"""Write evals/blind/round58.jsonl from suite_data.GROUPS."""
import json
from _common_round58 import MAPS, SUITE
from _suite_data_round58 import GROUPS

lines = []
for g, grp in enumerate(GROUPS, 1):
    gid = f"b58-g{g:02d}"
    for w, q in enumerate(grp["w"], 1):
        lines.append(json.dumps({"id": f"{gid}-w{w}", "map": MAPS[grp["map"]][0], "query": q, "type": grp["type"],
                                 "target": grp["target"], "accept": sorted(grp["accept"]), "group": gid}))
SUITE.write_text("\n".join(lines) + "\n")
print(f"wrote {len(lines)} lines to {SUITE}")
