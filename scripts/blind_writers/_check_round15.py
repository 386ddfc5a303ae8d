"""Extra checks for evals/blind/round15.jsonl beyond validate.py.

1. Every s group is re-derived numerically from centres and sizes with a margin.
2. o / or accept sets are recomputed from the map (all instances of the label, in the room for or).
3. ard wordings never contain the accepted object's map label; other groups use it at most twice.
4. The typo count.

    python3 check_round15.py (in the writer's folder)
"""

from __future__ import annotations

import json
import math
import re
from collections import defaultdict
from pathlib import Path

HERE = Path(__file__).resolve().parent
SUITE = HERE / "evals" / "blind" / "round15.jsonl"
MARGIN = 0.25  # metres, for nearest/farthest comparisons


def load(map_str: str):
    data = json.loads((SUITE.parent / map_str).resolve().read_text())
    if "objects" in data:
        return {o["id"]: o for o in data["objects"]}, True
    out = {}
    for k, v in data.items():
        out[int(k)] = {"id": int(k), "label": v["category"], "room": v.get("room_cat")}
    return out, False


def c(o):
    return o["center"]


def dist(a, b):
    return math.dist(c(a)[:2], c(b)[:2])


def top(o):
    return o["center"][2] + o["size"][2] / 2


def bottom(o):
    return o["center"][2] - o["size"][2] / 2


def on_top(a, b, tol=0.06):
    """a rests on b: a's bottom near b's top and a's centre inside b's footprint."""
    inside = all(abs(c(a)[i] - c(b)[i]) <= b["size"][i] / 2 for i in (0, 1))
    return inside and abs(bottom(a) - top(b)) <= tol


def unique_best(objs, key, target, margin=MARGIN, largest=False):
    vals = sorted(((key(o), o["id"]) for o in objs), reverse=largest)
    assert vals[0][1] == target, (vals, target)
    if len(vals) > 1:
        assert abs(vals[0][0] - vals[1][0]) >= margin, ("margin", vals)
    return vals


def spatial_checks():
    res = {}
    m, _ = load("../maps/scan_office.json")
    shelves = [m[i] for i in (14, 15, 16)]
    xs = sorted(shelves, key=lambda o: c(o)[0])
    assert xs[1]["id"] == 15 and all(abs(c(o)[1] - 5.8) < 0.01 for o in shelves)
    assert m[15]["size"][2] > m[14]["size"][2] and m[15]["size"][2] > m[16]["size"][2]
    res["g37 middle bookshelf"] = [o["id"] for o in xs]
    bins = [m[21], m[22]]
    res["g38 bin nearest door"] = unique_best(bins, lambda o: dist(o, m[20]), 21)
    mons = [m[i] for i in (11, 12, 13)]
    onw = [o["id"] for o in mons if all(abs(c(o)[i] - c(m[1])[i]) <= m[1]["size"][i] / 2 for i in (0, 1))
           and abs(bottom(o) - top(m[1])) < 0.06]
    assert onw == [11], onw
    assert abs(c(m[29])[0] - c(m[11])[0]) < 0.1 and c(m[29])[1] < c(m[11])[1]  # black keyboard in front
    assert m[29]["tags"]["color"] == "black"
    res["g39 monitor on white table"] = onw
    plants = [m[23], m[24]]
    res["g40 plant nearest window"] = unique_best(plants, lambda o: min(dist(o, m[18]), dist(o, m[19])), 23)
    res["g40 plant farthest from bookshelves"] = unique_best(
        plants, lambda o: min(dist(o, m[i]) for i in (14, 15, 16)), 23, largest=True)
    assert m[23]["size"][2] > m[24]["size"][2]
    # corner: within 0.6 m of two walls of the 8 x 6 room
    x, y = c(m[23])[:2]
    assert min(x, 8 - x) < 0.6 and min(y, 6 - y) < 0.6

    m, _ = load("../maps/scan_bedroom.json")
    bed = m[1]
    # head of the bed is north: the big pillows sit at the north end
    assert c(m[2])[1] > c(bed)[1] and c(m[3])[1] > c(bed)[1]
    # from the foot (south) facing the headboard (north), right = +x
    ns = [m[6], m[7]]
    res["g41 right nightstand from foot"] = unique_best(ns, lambda o: c(o)[0], 7, largest=True)
    res["g41 nightstand nearer door"] = unique_best(ns, lambda o: dist(o, m[15]), 7)
    assert on_top(m[20], m[7]) and m[20]["label"] == "book" and m[20]["tags"]["color"] == "blue"
    assert on_top(m[21], m[6]) and m[21]["label"] == "clock"
    # pillow between the two white ones
    p = m[4]
    assert c(m[2])[0] < c(p)[0] < c(m[3])[0] and abs(c(p)[1] - c(m[2])[1]) < 0.5
    assert m[2]["tags"]["color"] == m[3]["tags"]["color"] == "white" and p["size"][0] < m[2]["size"][0]
    assert c(m[5])[1] < c(p)[1] - 1.0  # the other small pillow lies further down the bed
    res["g42 pillow between"] = 4

    m, _ = load("maps/flat_h.json")
    assert on_top(m[49], m[47]) and not on_top(m[49], m[46])
    assert c(m[47])[0] > c(m[45])[0] > c(m[46])[0]          # east side of the double bed
    assert c(m[46])[1] > c(m[45])[1]                          # headboard north, so right = east
    res["g43 nightstand with book"] = 47

    m, _ = load("maps/flat_e.json")
    table = m[10]
    chairs = [m[i] for i in (11, 12, 13, 14, 15)]
    nw = [o["id"] for o in chairs if c(o)[0] < c(table)[0] - 0.2 and c(o)[1] > c(table)[1] + 0.2]
    assert nw == [13], nw
    greens = [m[i] for i in (11, 12, 13)]
    res["g44 green seat nearest black chair"] = unique_best(greens, lambda o: dist(o, m[14]), 13)
    # diagonally opposite the south-east chair (12): mirror through the table centre
    opp = (2 * c(table)[0] - c(m[12])[0], 2 * c(table)[1] - c(m[12])[1])
    res["g44 opposite of SE"] = unique_best(chairs, lambda o: math.dist(c(o)[:2], opp), 13)
    # nearest the living room (x < 5) among north-side chairs
    north = [o for o in chairs if c(o)[1] > c(table)[1] + 0.2]
    res["g44 north side nearest living room"] = unique_best(north, lambda o: c(o)[0], 13)

    m, _ = load("maps/flat_g.json")
    assert c(m[32])[1] > c(m[31])[1]  # headboard north
    lamps = [m[34], m[35]]
    assert on_top(m[34], m[32]) and on_top(m[35], m[33])
    res["g45 right lamp from foot"] = unique_best(lamps, lambda o: c(o)[0], 35, largest=True)
    res["g45 nearest hamper"] = unique_best(lamps, lambda o: dist(o, m[37]), 35)
    res["g45 farthest from wardrobe"] = unique_best(lamps, lambda o: dist(o, m[36]), 35, largest=True)

    m, _ = load("maps/flat_i.json")
    mugs = [o for o in m.values() if o["label"] == "mug"]
    on_ct = [o["id"] for o in mugs if on_top(o, m[35])]
    assert on_ct == [36], on_ct
    res["g46 cup nearest sofa"] = unique_best(mugs, lambda o: dist(o, m[34]), 36)

    m, _ = load("maps/flat_d.json")
    stools = [m[21], m[22]]
    res["g47 stool nearest fridge"] = unique_best(stools, lambda o: dist(o, m[15]), 22)
    res["g47 stool nearest bin"] = unique_best(stools, lambda o: dist(o, m[23]), 21)
    res["g47 further east"] = unique_best(stools, lambda o: c(o)[0], 22, largest=True)
    # facing the worktop (south of the stools), looking -y: left hand = +x
    assert c(m[16])[1] < c(m[21])[1]
    res["g47 left facing worktop"] = unique_best(stools, lambda o: c(o)[0], 22, largest=True)

    m, _ = load("apartment")
    plants = [o for o in m.values() if o["label"] == "plant"]
    up = [o["id"] for o in plants if bottom(o) > 0.3]
    assert up == [39] and on_top(m[39], m[38]), up
    res["g48 plant on dresser"] = up
    return res


def main():
    rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
    groups = defaultdict(list)
    for r in rows:
        groups[r["group"]].append(r)
    for k, v in spatial_checks().items():
        print("ok", k, v)
    for name, rs in groups.items():
        r0 = rs[0]
        m, geo = load(r0["map"])
        lab = m[r0["target"]]["label"].lower()
        uses = sum(bool(re.search(r"\b" + re.escape(lab) + r"(s|es)?\b", r["query"].lower())) for r in rs)
        if r0["type"] == "ard":
            assert uses == 0, (name, uses)
        assert uses <= 2, (name, uses)
        if r0["type"] in ("o", "or"):
            room = m[r0["target"]]["room"]
            want = sorted(i for i, o in m.items() if o["label"].lower() == lab
                          and (r0["type"] == "o" or o["room"] == room))
            assert want == sorted(r0["accept"]), (name, want, r0["accept"])
        if r0["type"] == "s":
            assert geo
    src = (HERE / "make_round15.py").read_text()
    ns = {"__file__": str(HERE / "make_round15.py")}
    exec(compile(src.split("def main")[0], "make", "exec"), ns)
    print(f"typos: {len(ns['TYPOS'])} of {len(rows)} lines ({100 * len(ns['TYPOS']) / len(rows):.1f}%)")
    print("all checks passed")


if __name__ == "__main__":
    main()
