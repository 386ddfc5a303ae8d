"""Re-derive and check round59: accept sets of o/or groups, single-id claims (numerically for s),
style rules of the six wordings, and counts. Reads suite_src (the hand-written groups) and the maps."""
import math
import re
import sys
from collections import Counter
from _common_round59 import MAPREL, load, words
from _suite_src_round59 import G

errors, notes = [], []
DICT = {w.strip().lower() for w in open('/usr/share/dict/words') if w.strip().isalpha()}
EXTRA = {'colour', 'pls', 'tv', 'rec', 'trashcan', 'armchair', 'houseplant', 'bedside', 'i', 'x', 'thats',
         'lounger', 'sectional', 'wastebasket', 'kitchenette', 'paperwork', 'chaise', 'mugs', 'couches',
         'planets', 'cushion', 'tables', 'lights', 'volumes', 'carpets', 'cupboard', 'stand', 'greenery',
         'organiser', 'colourful', 'coloured', 'multicoloured', 'moulded', 'favourite', 'centre'}
IMPERATIVE = {'go', 'take', 'head', 'lead', 'bring', 'show', 'guide', 'find'}
ARTICLES = {'a', 'an', 'the'}


def known(w):
    return w in DICT or w in EXTRA or (w.endswith('s') and w[:-1] in DICT) or w.isdigit()


def room_ok(o, room):
    return room is None or (o['room'] or '').lower() == room


def xy(o):
    return o['center'][0], o['center'][1]


def box(o):
    (cx, cy, cz), (dx, dy, dz) = o['center'], o['size']
    return cx - dx / 2, cx + dx / 2, cy - dy / 2, cy + dy / 2, cz - dz / 2, cz + dz / 2


def dist_to_box_xy(p, b):
    x, y = p
    ddx = max(b[0] - x, 0, x - b[1])
    ddy = max(b[2] - y, 0, y - b[3])
    return math.hypot(ddx, ddy)


def spatial(objs, cands, rel):
    """{id: score}; lower is better; target must be lowest with margin >= 0.2."""
    byid = {o['id']: o for o in objs}
    kind = rel[0]
    out = {}
    for o in cands:
        if kind == 'nearest':
            r = byid[rel[1]]
            out[o['id']] = math.dist(xy(o), xy(r))
        elif kind == 'left_facing':
            # facing south (-y): left is +x, so a lower score is a larger x
            assert rel[1] == 'south'
            out[o['id']] = -o['center'][0]
        elif kind == 'under':
            r = byid[rel[1]]
            below = box(o)[5] <= box(r)[4] + 0.05
            out[o['id']] = dist_to_box_xy(xy(o), box(r)) + (0 if below else 99)
        elif kind == 'on':
            r = byid[rel[1]]
            out[o['id']] = dist_to_box_xy(xy(o), box(r)) + abs(box(o)[4] - box(r)[5]) * 0  # footprint test
        elif kind == 'between':
            a, b = xy(byid[rel[1]]), xy(byid[rel[2]])
            p = xy(o)
            ab = (b[0] - a[0], b[1] - a[1])
            t = ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / (ab[0] ** 2 + ab[1] ** 2)
            tc = min(max(t, 0), 1)
            proj = (a[0] + tc * ab[0], a[1] + tc * ab[1])
            out[o['id']] = math.dist(p, proj) + (0 if 0 < t < 1 else 99)
    return out


per_type, per_map = Counter(), Counter()
for n, grp in enumerate(G, 1):
    gid = f"b59-g{n:02d}"
    objs = load(MAPREL[grp['map']])
    byid = {o['id']: o for o in objs}
    sp = grp['spec']
    t, target, accept = grp['type'], grp['target'], sorted(grp['accept'])
    per_type[t] += 1
    per_map[grp['map']] += 1
    kind = set(sp['kind'])
    room = sp.get('room')
    if target not in accept:
        errors.append(f'{gid}: target not in accept')
    if t in ('o', 'or'):
        if t == 'or' and not room:
            errors.append(f'{gid}: or without a room')
        derived = sorted(o['id'] for o in objs if o['label'] in kind and room_ok(o, room))
        if derived != accept:
            errors.append(f'{gid}: accept {accept} but map gives {derived}')
    else:
        if len(accept) != 1:
            errors.append(f'{gid}: single-id type with accept {accept}')
        if t in ('ord',) and not room:
            errors.append(f'{gid}: ord without a room')
        cands = [o for o in objs if o['label'] in kind and room_ok(o, room)]
        if t == 's':
            if byid[target]['center'] is None:
                errors.append(f'{gid}: s on a map without geometry')
                continue
            sc = spatial(objs, [o for o in cands if o['id'] not in sp['rel'][1:]], sp['rel'])
            ranked = sorted(sc.items(), key=lambda kv: kv[1])
            best, second = ranked[0], ranked[1] if len(ranked) > 1 else (None, math.inf)
            margin = second[1] - best[1]
            msg = f'{gid} s {sp["rel"]}: ' + ', '.join(f'{i}:{v:.2f}' for i, v in ranked[:4]) + f' margin {margin:.2f}'
            notes.append(msg)
            if best[0] != target or margin < 0.2:
                errors.append('FAIL ' + msg)
        else:
            must = [m.lower() for m in sp.get('must', [])]
            hits = [o['id'] for o in cands if all(m in o['text'] for m in must)]
            notes.append(f'{gid} {t}: pool {len(cands)} ({sorted(kind)}, room={room}), matching {must} -> {hits}')
            if hits != [target]:
                errors.append(f'{gid}: description matches {hits}, not just {target}')
    # style
    w = grp['w']
    if len(w) != 6 or len({x.lower() for x in w}) != 6:
        errors.append(f'{gid}: not six distinct wordings')
    ws = [words(x) for x in w]
    if ws[0][0] not in IMPERATIVE or w[0].endswith('?'):
        errors.append(f'{gid} w1 not a plain imperative: {w[0]}')
    if not (w[1].startswith('Could you ') and w[1].endswith('?')):
        errors.append(f'{gid} w2 not "Could you ...?"')
    if len(w[2].split()) > 6 or ARTICLES & set(ws[2]):
        errors.append(f'{gid} w3 not telegraphic: {w[2]}')
    if not re.search(r', not |\bso\b|\bbecause\b|\bsince\b', w[3]):
        errors.append(f'{gid} w4 has no reason/contrast: {w[3]}')
    sents = [s for s in re.split(r'(?<=[.!?])\s+', w[4].strip()) if s]
    if not w[4].startswith('This is ') or len(sents) != 2:
        errors.append(f'{gid} w5 not two sentences starting "This is": {w[4]}')
    bad, right = grp['typo']
    if w[5] != w[5].lower():
        errors.append(f'{gid} w6 not lower case')
    unknown = [x for x in ws[5] if not known(x)]
    if unknown != [bad] or ws[5].count(bad) != 1 or not known(right):
        errors.append(f'{gid} w6 typo check: unknown words {unknown}, declared typo {bad}->{right}')
    for k in range(5):
        unk = [x for x in ws[k] if not known(x)]
        if unk:
            notes.append(f'{gid} w{k+1} words not in dictionary (check by eye): {unk}')
    # the map label in at most two wordings (the validator's regex)
    labels = {byid[a]['label'].lower() for a in accept}
    uses = sum(any(re.search(r'\b' + re.escape(lab) + r'(s|es)?\b', x.lower()) for lab in labels) for x in w)
    if uses > 2:
        errors.append(f'{gid}: label in {uses} wordings')

# counts and spread
want = {'o': 7, 'or': 7, 'od': 7, 'ord': 7, 'ard': 8, 's': 12}
if dict(per_type) != want:
    errors.append(f'type counts {dict(per_type)} != {want}')
cap = per_map['00829'] + per_map['office3']
flats = sum(per_map[m] for m in ('flat_c', 'flat_d', 'flat_f', 'flat_h'))
scans = sum(per_map[m] for m in per_map if m.startswith('scan_'))
s_maps = Counter(grp['map'] for grp in G if grp['type'] == 's')
print('notes:')
print('\n'.join('  ' + x for x in notes))
print(f'per type {dict(per_type)}; per map {dict(per_map)}')
print(f'caption maps {cap}, flats {flats}, apartment {per_map["apartment"]}, scans {scans}; s groups per map {dict(s_maps)}')
print('ERRORS:' if errors else 'no errors')
print('\n'.join(errors))
sys.exit(1 if errors else 0)
