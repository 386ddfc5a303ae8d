"""No wording of round 66 may share a run of 6 consecutive words with any caption of its map."""
import json
import re
import sys
from pathlib import Path
from _show_round66 import load
N = 6
def toks(s): return re.findall(r"[a-z0-9]+", s.lower())
caps = {}
bad = 0
longest = (0, '')
rows = [json.loads(x) for x in open(Path(__file__).resolve().parents[2] / 'evals' / 'blind' / 'round66.jsonl')]
for r in rows:
    if r['map'] not in caps:
        d, objs, geo = load(r['map'])
        grams = {}
        for o in objs:
            t = toks(o.get('caption') or '')
            for k in range(2, 20):
                for i in range(len(t) - k + 1):
                    grams.setdefault(k, set()).add(tuple(t[i:i + k]))
        caps[r['map']] = grams
    g = caps[r['map']]
    q = toks(r['query'])
    best = 0
    for k in range(2, 20):
        if any(tuple(q[i:i + k]) in g.get(k, ()) for i in range(len(q) - k + 1)):
            best = k
    if best >= N:
        bad += 1
        print('SHARED RUN', best, r['id'], r['query'])
    if best > longest[0]:
        longest = (best, r['id'])
print(f"copycheck: {len(rows)} wordings, {bad} with a shared run of {N}+ words; longest shared run {longest[0]} words ({longest[1]})")
sys.exit(1 if bad else 0)
