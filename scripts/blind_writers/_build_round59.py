"""Write round59.jsonl from suite_src.G."""
import json
from _common_round59 import MAPREL, BLIND
from _suite_src_round59 import G

lines = []
for n, grp in enumerate(G, 1):
    gid = f"b59-g{n:02d}"
    for k, q in enumerate(grp['w'], 1):
        lines.append(json.dumps(dict(id=f"{gid}-w{k}", map=MAPREL[grp['map']], query=q, type=grp['type'],
                                     target=grp['target'], accept=sorted(grp['accept']), group=gid),
                                ensure_ascii=False))
(BLIND / 'round59.jsonl').write_text('\n'.join(lines) + '\n', encoding='utf-8')
print(len(G), 'groups', len(lines), 'lines')
