"""Check round19: accept sets of o/or groups against the maps, label use, and every s group numerically.

    python3 /work/blind19/check_spatial19.py
"""

import json
import math
import re
from collections import defaultdict
from pathlib import Path

SUITE = Path(__file__).resolve().parent / "evals" / "blind" / "round19.jsonl"
MARGIN = 0.2  # metres a relation must win by
TOL = 0.03    # contact tolerance for "on"/"under"


def load(mp):
    data = json.loads((SUITE.parent / mp).resolve().read_text())
    if "objects" in data:
        return {o["id"]: o for o in data["objects"]}, True
    return {int(k): {"id": int(k), "label": v["category"], "room": v["room_cat"]} for k, v in data.items()}, False


def box(o):
    c, s = o["center"], o["size"]
    return [c[i] - s[i] / 2 for i in range(3)], [c[i] + s[i] / 2 for i in range(3)]


def on(a, b):
    """a rests on b: footprints overlap, a's bottom within b's top band (a may sink into soft b)."""
    (alo, ahi), (blo, bhi) = box(a), box(b)
    ov = all(alo[i] < bhi[i] and blo[i] < ahi[i] for i in range(2))
    return ov and blo[2] + 0.5 * (bhi[2] - blo[2]) <= alo[2] <= bhi[2] + TOL


def under(a, b):
    (alo, ahi), (blo, bhi) = box(a), box(b)
    ov = all(alo[i] < bhi[i] and blo[i] < ahi[i] for i in range(2))
    return ov and ahi[2] <= blo[2] + TOL


def gap(a, b):
    """horizontal distance between the footprints of two boxes (0 when they overlap)."""
    (alo, ahi), (blo, bhi) = box(a), box(b)
    d = [max(blo[i] - ahi[i], alo[i] - bhi[i], 0) for i in range(2)]
    return math.hypot(*d)


def dist(a, b):
    return math.hypot(a["center"][0] - b["center"][0], a["center"][1] - b["center"][1])


def lab(objs, *labels):
    return [o for o in objs.values() if o["label"] in labels]


def only(name, objs, cands, pred, target):
    hits = [o["id"] for o in cands if pred(o)]
    ok = hits == [target]
    print(f"{'OK ' if ok else 'BAD'} {name}: candidates {[o['id'] for o in cands]} -> {hits}")
    return ok


def nearest(name, cands, key, target, reverse=False):
    vals = sorted((key(o), o["id"]) for o in cands)
    if reverse:
        vals = vals[::-1]
    ok = vals[0][1] == target and abs(vals[1][0] - vals[0][0]) >= MARGIN
    print(f"{'OK ' if ok else 'BAD'} {name}: {[(i, round(v, 2)) for v, i in vals]}")
    return ok


def spatial():
    res = []
    A, _ = load("apartment")
    res.append(only("g18 apartment lamp on nightstand", A, lab(A, "lamp"), lambda o: on(o, A[33]), 34))
    res.append(only("g19 apartment pillow on a sofa", A, lab(A, "pillow"),
                    lambda o: any(on(o, s) for s in lab(A, "sofa")), 14))
    C, _ = load("maps/flat_c.json")
    res.append(only("g24 flat_c nightstand under the alarm clock", C, lab(C, "nightstand"), lambda o: on(C[29], o), 27))
    res.append(nearest("g25 flat_c chair nearest fridge", lab(C, "chair"), lambda o: gap(o, C[13]), 20))
    D, _ = load("maps/flat_d.json")
    res.append(nearest("g30 flat_d stool nearest fridge", lab(D, "stool"), lambda o: gap(o, D[15]), 22))
    G, _ = load("maps/flat_g.json")
    res.append(nearest("g34 flat_g lamp next to sofa", lab(G, "lamp"), lambda o: gap(o, G[25]), 29))
    I, _ = load("maps/flat_i.json")
    res.append(only("g40 flat_i mug on coffee table", I, lab(I, "mug"), lambda o: on(o, I[35]), 36))
    O, _ = load("../maps/scan_office.json")
    shelves = sorted(lab(O, "bookshelf"), key=lambda o: o["center"][0])
    xs = [o["center"][0] for o in shelves]
    ok = shelves[1]["id"] == 15 and min(xs[1] - xs[0], xs[2] - xs[1]) >= MARGIN and \
        all(abs(o["center"][1] - shelves[0]["center"][1]) < 0.2 for o in shelves)
    print(f"{'OK ' if ok else 'BAD'} g43 scan_office middle bookshelf: x order {[(o['id'], o['center'][0]) for o in shelves]}; "
          f"tallest {max(shelves, key=lambda o: o['size'][2])['id']}")
    res.append(ok and max(shelves, key=lambda o: o["size"][2])["id"] == 15)
    res.append(nearest("g44 scan_office plant nearest a window", lab(O, "plant"),
                       lambda o: min(gap(o, w) for w in lab(O, "window")), 23))
    res.append(only("g45 scan_office monitor on the white table", O, lab(O, "monitor"), lambda o: on(o, O[1]), 11))
    K, _ = load("../maps/scan_kitchen.json")
    res.append(only("g47 scan_kitchen cup on a kitchen cabinet (counter)", K, lab(K, "cup"),
                    lambda o: any(on(o, c) for c in lab(K, "kitchen cabinet")), 25))
    res.append(only("g47b scan_kitchen cup near sink (<0.8 m)", K, lab(K, "cup"), lambda o: gap(o, K[10]) < 0.8, 25))
    res.append(only("g48 scan_kitchen cabinet under sink", K, lab(K, "kitchen cabinet"), lambda o: under(o, K[10]), 3))
    return all(res)


def accepts():
    ok = True
    groups = defaultdict(list)
    for line in SUITE.read_text().splitlines():
        r = json.loads(line)
        groups[r["group"]].append(r)
    for g, rows in groups.items():
        r = rows[0]
        objs, _ = load(r["map"])
        labels = {objs[a]["label"] for a in r["accept"]}
        if r["type"] in ("o", "or"):
            (label,) = labels
            rooms = {objs[a]["room"] for a in r["accept"]}
            want = sorted(o["id"] for o in objs.values() if o["label"] == label
                          and (r["type"] == "o" or o["room"] in rooms))
            good = want == sorted(r["accept"]) and len(rooms) == 1 or r["type"] == "o" and want == sorted(r["accept"])
            if not good:
                ok = False
            print(f"{'OK ' if good else 'BAD'} {g} {r['type']} {label!r} rooms {rooms}: accept {sorted(r['accept'])} all {want}")
        # label words: whole label at most twice; for ard, no label word at all
        label_uses = sum(any(re.search(r"\b" + re.escape(l.lower()) + r"(s|es)?\b", x["query"].lower()) for l in labels)
                         for x in rows)
        words = {w for l in labels for w in re.split(r"[ /]+", l.lower()) if len(w) > 2 and w not in ("for", "the", "with")}
        word_uses = [x["id"] for x in rows if any(re.search(r"\b" + re.escape(w) + r"(s|es)?\b", x["query"].lower())
                                                  for w in words)]
        if label_uses > 2 or (r["type"] == "ard" and word_uses):
            ok = False
            print(f"BAD {g} label uses {label_uses}; ard word uses {word_uses}")
    return ok


if __name__ == "__main__":
    a = spatial()
    b = accepts()
    print("ALL OK" if a and b else "PROBLEMS")
