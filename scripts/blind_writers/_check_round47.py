"""Re-derive every o/or accept set from the maps, check ord rooms and every spatial claim numerically.

    python3 scripts/check.py      (reads scripts/emit.py GROUPS and the maps; exits 1 on any failure)
Spatial margins: distance and height claims need >= 0.2 m between the target and the runner-up, under both
centre distance (horizontal) and box-gap distance; left/right claims need >= 0.2 m along the axis.
"""
import math
import sys

from _common_round47 import load
from _build_round47 import GROUPS, MAPS

MARGIN = 0.2
fails = []


def box(o):
    c, s = o["center"], o["size"]
    return [(c[i] - s[i] / 2, c[i] + s[i] / 2) for i in range(3)]


def gap(a, b):
    """Horizontal distance between two axis-aligned footprints (0 when they overlap)."""
    ba, bb = box(a), box(b)
    d = [max(0.0, bb[i][0] - ba[i][1], ba[i][0] - bb[i][1]) for i in range(2)]
    return math.hypot(*d)


def cdist(a, b):
    return math.hypot(a["center"][0] - b["center"][0], a["center"][1] - b["center"][1])


def inside_xy(p, o):
    b = box(o)
    return b[0][0] <= p[0] <= b[0][1] and b[1][0] <= p[1] <= b[1][1]


def in_poly(p, poly):
    x, y = p
    xs = [q[0] for q in poly]
    ys = [q[1] for q in poly]
    return min(xs) <= x <= max(xs) and min(ys) <= y <= max(ys)  # all rooms here are rectangles


def fail(g, msg):
    fails.append(f"g{g:02d}: {msg}")


def check_spatial(g, objs, target, claim):
    kind, ref, cands = claim
    if target not in cands:
        return fail(g, "target not among candidates")
    labels = {objs[c]["label"] for c in cands}
    if len(labels) != 1 or len(cands) < 2:
        fail(g, f"candidates are not several objects of one kind: {labels}")
    others = [c for c in cands if c != target]
    if kind == "nearest":
        refs = ref if isinstance(ref, list) else [ref]
        for name, f in (("centre", cdist), ("gap", gap)):
            d = {c: min(f(objs[c], objs[r]) for r in refs) for c in cands}
            runner = min(d[c] for c in others)
            ok = d[target] + MARGIN <= runner
            print(f"  g{g:02d} nearest {refs} ({name}): " + ", ".join(f"{c}:{d[c]:.2f}" for c in cands),
                  "OK" if ok else "FAIL")
            if not ok:
                fail(g, f"nearest by {name}: margin {runner - d[target]:.2f}")
    elif kind == "side":
        axis = 0 if ref[1] == "x" else 1
        sign = 1 if ref[0] == "+" else -1
        v = {c: sign * objs[c]["center"][axis] for c in cands}
        m = min(v[target] - v[c] for c in others)
        print(f"  g{g:02d} side {ref}: " + ", ".join(f"{c}:{objs[c]['center'][axis]}" for c in cands),
              f"margin {m:.2f}", "OK" if m >= MARGIN else "FAIL")
        if m < MARGIN:
            fail(g, f"side margin {m:.2f}")
    elif kind in ("on", "under"):
        sup = objs[ref]

        def holds(c):
            o = objs[c]
            if kind == "on":  # c rests on ref
                return abs(box(o)[2][0] - box(sup)[2][1]) <= 0.05 and inside_xy(o["center"], sup)
            return abs(box(o)[2][1] - box(sup)[2][0]) <= 0.05 and inside_xy(sup["center"], o)  # ref rests on c
        res = {c: holds(c) for c in cands}
        ok = res[target] and not any(res[c] for c in others)
        print(f"  g{g:02d} {kind} {ref} ({sup['label']}): {res}", "OK" if ok else "FAIL")
        if not ok:
            fail(g, f"{kind} claim does not single out the target: {res}")
    elif kind == "lowest_top":
        top = {c: box(objs[c])[2][1] for c in cands}
        m = min(top[c] for c in others) - top[target]
        print(f"  g{g:02d} lowest top: {top} margin {m:.2f}", "OK" if m >= MARGIN else "FAIL")
        if m < MARGIN:
            fail(g, f"height margin {m:.2f}")
    else:
        fail(g, f"unknown claim {kind}")


def main():
    cache = {}
    for g, key, typ, target, accept, room, claim, words in GROUPS:
        if key not in cache:
            cache[key] = load(MAPS[key])
        objs, geom, polys = cache[key]
        if target not in objs or any(a not in objs for a in accept) or target not in accept:
            fail(g, "ids missing")
            continue
        lab = objs[target]["label"]
        if typ == "o":
            want = sorted(i for i, o in objs.items() if o["label"] == lab)
            print(f"  g{g:02d} o '{lab}': derived {want}")
            if sorted(accept) != want:
                fail(g, f"accept {sorted(accept)} != derived {want}")
        elif typ == "or":
            want = sorted(i for i, o in objs.items() if o["label"] == lab and o["room"] == room)
            if geom:  # also by room polygon containment of the centre
                poly = sorted(i for i, o in objs.items() if o["label"] == lab and in_poly(o["center"][:2], polys[room]))
                if poly != want:
                    fail(g, f"room field {want} and polygon {poly} disagree")
            print(f"  g{g:02d} or '{lab}' in {room}: derived {want}")
            if sorted(accept) != want:
                fail(g, f"accept {sorted(accept)} != derived {want}")
        elif typ == "ord":
            if objs[target]["room"] != room or accept != [target]:
                fail(g, f"ord target room {objs[target]['room']} != {room} or accept not single")
            same = [i for i, o in objs.items() if o["label"] == lab and o["room"] == room]
            print(f"  g{g:02d} ord '{lab}' in {room}: same label there {same}")
        elif typ in ("od", "ard"):
            if typ == "od" and accept != [target]:
                fail(g, "od accept not single")
            print(f"  g{g:02d} {typ} -> {target} '{lab}': {objs[target]['caption'][:80]}")
        elif typ == "s":
            if not geom:
                fail(g, "spatial group on a map without geometry")
            elif accept != [target]:
                fail(g, "s accept not single")
            else:
                check_spatial(g, objs, target, claim)
    for f in fails:
        print("FAIL", f)
    print(f"{len(GROUPS)} groups checked, {len(fails)} failures")
    return 1 if fails else 0




def style():
    """Wording-style checks: w1 imperative, w2 polite question, w3 short with no articles,
    w5 two sentences starting 'This is', w6 lower case."""
    import re
    bad = []
    for g, *_r in GROUPS:
        w = _r[-1]
        if not re.match(r"(Go|Take|Bring|Head|Find|Show)\b", w[0]):
            bad.append((g, 1))
        if not (w[1].startswith("Could you") and w[1].endswith("?")):
            bad.append((g, 2))
        if re.search(r"\b(a|an|the)\b", w[2].lower()) or len(w[2].split()) > 8:
            bad.append((g, 3))
        if not (w[4].startswith("This is") and len(re.findall(r"[.!?](\s|$)", w[4])) == 2
                and re.search(r"[.] Its? ", w[4])):
            bad.append((g, 5))
        if w[5] != w[5].lower():
            bad.append((g, 6))
    print("style problems:", bad or "none")
    return bad


if __name__ == "__main__":
    rc = main()
    sys.exit(1 if (rc or style()) else 0)
