"""Re-derive every o/or accept set from its map, check every single-id claim (numerically for s), the
style rules of the six wordings, the label rule and the counts of round 66."""
import json
import math
import re
import sys
from collections import Counter
from itertools import combinations
from pathlib import Path
from _show_round66 import load
from _suite_data_round66 import GROUPS

errors = []
def err(g, msg): errors.append(f"{g}: {msg}")

CACHE = {}
def objs(key):
    if key not in CACHE:
        d, o, geo = load(key)
        CACHE[key] = ({x['id']: x for x in o}, geo)
    return CACHE[key]

def text(o):
    t = [o['label'], o.get('caption') or '']
    for v in (o.get('tags') or {}).values():
        if v:
            t.append(str(v))
    return ' '.join(t).lower()

def room_of(o):
    return (o.get('room') or '')
def dist(a, b):  # centre distance in the floor plane
    return math.hypot(a['center'][0] - b['center'][0], a['center'][1] - b['center'][1])
def box_gap(a, b):  # horizontal gap between two boxes
    dx = max(0, abs(a['center'][0] - b['center'][0]) - (a['size'][0] + b['size'][0]) / 2)
    dy = max(0, abs(a['center'][1] - b['center'][1]) - (a['size'][1] + b['size'][1]) / 2)
    return math.hypot(dx, dy)
def overlap_xy(a, b):
    return all(abs(a['center'][i] - b['center'][i]) < (a['size'][i] + b['size'][i]) / 2 for i in (0, 1))
def bottom(o): return o['center'][2] - o['size'][2] / 2
def top(o): return o['center'][2] + o['size'][2] / 2

def ranked(scores, target, gname, what, margin=0.2):
    """scores: id -> value (lower is better). Target must be best by >= margin."""
    order = sorted(scores.items(), key=lambda kv: kv[1])
    if order[0][0] != target:
        err(gname, f"{what}: best is {order[0]} not {target}; {order}")
        return
    gap = order[1][1] - order[0][1] if len(order) > 1 else float('inf')
    if gap < margin:
        err(gname, f"{what}: margin {gap:.3f} < {margin}; {order}")
    return [(k, round(v, 3)) for k, v in order]

def spatial(gname, g, objs_by_id):
    c = g['claim']
    cands = {i: o for i, o in objs_by_id.items() if o['label'] in c['cands'] and (not c.get('room') or room_of(o) == c['room'])}
    if 'filt' in c:
        cands = {i: o for i, o in cands.items() if all((o['tags'] or {}).get(k) == v for k, v in c['filt'].items())}
    kind = c['s']
    t = g['target']
    if kind == 'nearest':
        ref = objs_by_id[c['ref']]
        sc = {i: dist(o, ref) for i, o in cands.items() if i != c['ref']}
        return ranked(sc, t, gname, f"nearest to {c['ref']}")
    if kind == 'next_to':
        sc = {i: min(box_gap(o, objs_by_id[r]) for r in c['refs']) for i, o in cands.items()}
        return ranked(sc, t, gname, f"box gap to {c['refs']}")
    if kind == 'on':
        ref = objs_by_id[c['ref']]
        for i, o in cands.items():
            on = overlap_xy(o, ref) and abs(bottom(o) - top(ref)) < 0.05
            if on != (i == t):
                err(gname, f"on: object {i} on={on}")
        sc = {i: dist(o, ref) for i, o in cands.items()}
        return ranked(sc, t, gname, f"distance to top of {c['ref']}")
    if kind == 'under':
        ref = objs_by_id[c['ref']]
        for i, o in cands.items():
            under = overlap_xy(o, ref) and top(o) <= bottom(ref) + 0.01
            if under != (i == t):
                err(gname, f"under: object {i} under={under}")
        sc = {i: dist(o, ref) for i, o in cands.items()}
        return ranked(sc, t, gname, f"distance below {c['ref']}")
    if kind == 'above':
        ref = objs_by_id[c['ref']]
        for i, o in cands.items():
            above = overlap_xy(o, ref) and bottom(o) >= top(ref) - 0.01
            if above != (i == t) and above:
                err(gname, f"above: object {i} is also above")
        if not (overlap_xy(objs_by_id[t], ref) and bottom(objs_by_id[t]) >= top(ref)):
            err(gname, "above: target not above")
        sc = {i: dist(o, ref) for i, o in cands.items() if bottom(o) >= top(ref)}
        return ranked(sc, t, gname, f"horizontal distance among boxes above {c['ref']}")
    if kind == 'right_of_view':
        bed = objs_by_id[c['bed']]
        # headboard side = the side where the bedside tables are (larger y here, checked)
        stands = [o for o in objs_by_id.values() if o['label'] == 'nightstand' and room_of(o) == room_of(bed)]
        head_north = all(s['center'][1] > bed['center'][1] for s in stands)
        if not head_north:
            err(gname, "headboard is not north")
        # viewer at the foot facing north: right = +x; score = -x offset
        sc = {i: -(o['center'][0] - bed['center'][0]) for i, o in cands.items()}
        return ranked(sc, t, gname, "rightness facing headboard (-dx)")
    if kind == 'left_of_seat':
        seat, faces = objs_by_id[c['seat']], objs_by_id[c['faces']]
        if not faces['center'][1] > seat['center'][1]:
            err(gname, "sofa does not face north")
        # sitting facing north: left = -x
        sc = {i: o['center'][0] for i, o in cands.items()}
        for i, o in cands.items():
            if not overlap_xy(o, seat):
                err(gname, f"cushion {i} not on the sofa")
        return ranked(sc, t, gname, "x (smaller = further left when facing north)")
    if kind == 'corner_near':
        d, _, _ = load(g['map'])
        poly = d['rooms'][0]['polygon']
        sc = {i: min(math.hypot(o['center'][0] - x, o['center'][1] - y) for x, y in poly) for i, o in cands.items()}
        r1 = ranked(sc, t, gname, "distance to nearest room corner")
        ref = objs_by_id[c['ref']]
        sc2 = {i: dist(o, ref) for i, o in cands.items()}
        r2 = ranked(sc2, t, gname, f"distance to door {c['ref']}")
        return [r1, r2]
    if kind == 'between':
        def seg(p, a, b):
            ax, ay = a['center'][:2]
            bx, by = b['center'][:2]
            px, py = p['center'][:2]
            vx, vy = bx - ax, by - ay
            tt = ((px - ax) * vx + (py - ay) * vy) / (vx * vx + vy * vy)
            if not 0.1 <= tt <= 0.9:
                return float('inf')
            return math.hypot(px - ax - tt * vx, py - ay - tt * vy)
        sc = {}
        for i, o in cands.items():
            others = [x for j, x in cands.items() if j != i]
            sc[i] = min(seg(o, a, b) for a, b in combinations(others, 2))
        return ranked(sc, t, gname, "distance to the segment between two other pillows")
    if kind == 'shortest':
        sc = {i: o['size'][2] for i, o in cands.items()}
        return ranked(sc, t, gname, "height")
    err(gname, f"unknown spatial kind {kind}")

ARD_FORBIDDEN = {  # kind words that an ard wording must not name
    'b66-g06': ['bed', 'basket', 'cushion'], 'b66-g12': ['sofa', 'couch', 'settee', 'bench'],
    'b66-g15': ['sink', 'basin', 'washbasin', 'tap'], 'b66-g19': ['dryer', 'drier', 'machine'],
    'b66-g23': ['board', 'ironing board'], 'b66-g33': ['printer'], 'b66-g34': ['mirror', 'looking glass'],
    'b66-g39': ['bin', 'trash', 'trash can', 'wastebasket', 'garbage'],
}
W1_VERBS = ('Go ', 'Take ', 'Head ', 'Lead ', 'Guide ', 'Bring ', 'Show ', 'Find ', 'Navigate ')
W4_MARKS = (' not ', ' so ', 'because', ' since ')
ARTICLES = {'a', 'an', 'the'}

def words(q): return re.findall(r"[a-z0-9']+", q.lower())

# vocabulary of all non-w6 wordings, for the typo check
VOCAB = set()
for g in GROUPS:
    for q in g['w'][:5]:
        VOCAB |= set(words(q))
ALLOW = {'can', 'you', 'me', 'any', 'one', 'is', 'fine', 'where', 'take', 'there', 'where\'s', 'the', 'in', 'a',
         'just', 'need', 'whichever', 'closest', 'go', 'please', 'to', 'it', 'find', 'comfy', 'sit', 'get', 'i',
         'my', 'wet', 'of', 'them', 'do', 'does', 'kitty', 'thing', 'soft', 'white', 'and', 'brown', 'crash',
         'for', 'nap', 'somewhere', 'storage', 'with', 'grey', 'tickets', 'this', 'away', 'anything', 'on',
         'at', 'top', 'bed', 'underneath', 'closer', 'end', 'facing', 'from', 'right', 'light', 'left', 'far', 'sitting', 'by', 'over'}

per_type, per_map = Counter(), Counter()
report = []
for gi, g in enumerate(GROUPS, 1):
    gname = f"b66-g{gi:02d}"
    objs_by_id, geo = objs(g['map'])
    per_type[g['type']] += 1
    per_map[g['map'].split('/')[-1]] += 1
    c = g['claim']
    t = g['target']
    if t not in g['accept']:
        err(gname, "target not in accept")
    # --- claims ---
    if g['type'] in ('o', 'or'):
        derived = sorted(i for i, o in objs_by_id.items() if o['label'] in c['kind'] and (g['type'] == 'o' or room_of(o) == c['room']))
        if g['type'] == 'or' and not c.get('room'):
            err(gname, "or without room")
        if derived != sorted(g['accept']):
            err(gname, f"accept {sorted(g['accept'])} != derived {derived}")
        if len(derived) < 2:
            err(gname, "kind group with a single instance")
        report.append(f"{gname} {g['type']} {c['kind']} room={c.get('room')} -> {derived}")
    elif g['type'] in ('od', 'ord', 'ard'):
        if len(g['accept']) != 1:
            err(gname, "single-id type with several accepted ids")
        if g['type'] == 'ord' and not c.get('room'):
            err(gname, "ord without room")
        if g['type'] == 'od' and c.get('room'):
            err(gname, "od with a room")
        pool = {i: o for i, o in objs_by_id.items() if o['label'] in c['kind'] and (not c.get('room') or room_of(o) == c['room'])}
        match = sorted(i for i, o in pool.items() if all(m in text(o) for m in c.get('must', [])))
        if match != [t]:
            err(gname, f"claim matches {match}, not [{t}]")
        extra = ''
        if g['type'] == 'ord':
            noroom = sorted(i for i, o in objs_by_id.items() if o['label'] in c['kind'] and all(m in text(o) for m in c.get('must', [])))
            same_kind_room = sorted(pool)
            extra = f" | description alone -> {noroom}; kind in room -> {same_kind_room}"
        report.append(f"{gname} {g['type']} {c['kind']} room={c.get('room')} must={c.get('must')} -> {match}{extra}")
    elif g['type'] == 's':
        if not geo:
            err(gname, "spatial on a caption map")
        if len(g['accept']) != 1:
            err(gname, "spatial with several accepted ids")
        r = spatial(gname, g, objs_by_id)
        report.append(f"{gname} s {c['s']} -> {r}")
    # --- style ---
    w = g['w']
    if len(w) != 6 or len({q.lower() for q in w}) != 6:
        err(gname, "not six distinct wordings")
    if not w[0].startswith(W1_VERBS) or w[0].endswith('?'):
        err(gname, f"w1 not a plain imperative: {w[0]}")
    if not (w[1].startswith('Could you ') and w[1].endswith('?')):
        err(gname, "w2 not 'Could you ...?'")
    ww = words(w[2])
    if len(w[2].split()) > 6 or ARTICLES & set(ww):
        err(gname, f"w3 telegraphic rule: {w[2]}")
    if not any(m in ' ' + w[3].lower() for m in W4_MARKS):
        err(gname, f"w4 has no reason/contrast marker: {w[3]}")
    sents = [s for s in re.split(r'(?<=[.!?])\s+', w[4].strip()) if s]
    if len(sents) != 2 or not sents[0].startswith('This is '):
        err(gname, f"w5 not two sentences starting 'This is': {w[4]}")
    if w[5] != w[5].lower():
        err(gname, "w6 not all lower case")
    typo, right = g['typo']
    w6w = words(w[5])
    if w6w.count(typo) != 1:
        err(gname, f"w6 typo {typo!r} not present once")
    if typo in VOCAB:
        err(gname, f"typo {typo!r} is a word used elsewhere")
    if right not in VOCAB | ALLOW:
        err(gname, f"intended word {right!r} not seen elsewhere")
    unknown = [x for x in w6w if x != typo and x not in VOCAB | ALLOW]
    if unknown:
        err(gname, f"w6 words not seen elsewhere (second typo?): {unknown}")
    # --- label rule (exact map label in at most 2 wordings) ---
    labs = {objs_by_id[a]['label'].lower() for a in g['accept']}
    uses = sum(any(re.search(r"\b" + re.escape(lab) + r"(s|es)?\b", q.lower()) for lab in labs) for q in w)
    if uses > 2:
        err(gname, f"map label in {uses} wordings")
    # --- ard names no object kind of its target ---
    if g['type'] == 'ard':
        bad = ARD_FORBIDDEN.get(gname, []) + [objs_by_id[t]['label'].lower()]
        for q in w:
            for b in bad:
                if re.search(r"\b" + re.escape(b) + r"s?\b", q.lower()):
                    err(gname, f"ard names a kind {b!r}: {q}")

want_types = {'o': 7, 'or': 7, 'od': 7, 'ord': 7, 'ard': 8, 's': 12}
if dict(per_type) != want_types:
    err('counts', f"types {dict(per_type)}")
if len(GROUPS) != 48:
    err('counts', f"{len(GROUPS)} groups")
# the jsonl on disk matches the data
lines = open(Path(__file__).resolve().parents[2] / 'evals' / 'blind' / 'round66.jsonl').read().splitlines()
if len(lines) != 288:
    err('file', f"{len(lines)} lines")
for n, (line, (gi, wi)) in enumerate(zip(lines, [(a, b) for a in range(48) for b in range(6)])):
    r = json.loads(line)
    if r['query'] != GROUPS[gi]['w'][wi] or r['target'] != GROUPS[gi]['target']:
        err('file', f"line {n+1} differs from data")

if '-v' in sys.argv:
    print('\n'.join(report))
print('per type', dict(per_type))
print('per map', dict(per_map))
print('\n'.join(errors) if errors else 'check.py: no errors')
sys.exit(1 if errors else 0)
