"""Serialise the hand-written groups in suite_data.py to evals/blind/round64.jsonl."""
import json
import sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _suite_data_round64 import GROUPS
out = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round64.jsonl"
lines = []
for g, (mp, typ, target, accept, words, _typo) in enumerate(GROUPS, 1):
    assert len(words) == 6
    for w, q in enumerate(words, 1):
        lines.append(json.dumps({"id": f"b64-g{g:02d}-w{w}", "map": mp, "query": q, "type": typ,
                                 "target": target, "accept": sorted(accept), "group": f"b64-g{g:02d}"}))
out.write_text("\n".join(lines) + "\n", encoding="utf-8")
print(len(GROUPS), "groups,", len(lines), "lines ->", out)
