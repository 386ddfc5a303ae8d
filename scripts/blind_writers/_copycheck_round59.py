"""Find any run of N (default 6) consecutive words shared by a suite line and a caption of its map.
Words: lower-case runs of letters/digits (hyphens and punctuation split words)."""
import json
import sys
from _common_round59 import BLIND, load, words

N = int(sys.argv[1]) if len(sys.argv) > 1 else 6
suite = BLIND / 'round59.jsonl'
cache, hits = {}, []


def grams(ws, n):
    return {tuple(ws[i:i + n]) for i in range(len(ws) - n + 1)}


for line in suite.read_text().splitlines():
    r = json.loads(line)
    if r['map'] not in cache:
        cache[r['map']] = [(o['id'], grams(words(o['caption']), N)) for o in load(r['map']) if o['caption']]
    q = grams(words(r['query']), N)
    for oid, cg in cache[r['map']]:
        for gram in q & cg:
            hits.append(f"{r['id']} shares '{' '.join(gram)}' with the caption of {oid}")
print('\n'.join(hits))
print(f'{len(hits)} shared {N}-word runs over {len(suite.read_text().splitlines())} lines')
sys.exit(1 if hits and N >= 6 else 0)
