"""Check round29 against its maps: re-derive every o/or accept set, check the label (and room) of every
od/ord/ard target, and check every spatial claim numerically from centres and sizes (margin >= 0.2 m).

    python3 scripts/check.py        (exit 1 on any failure)
"""
import json, math, sys
from pathlib import Path

SUITE = Path(__file__).resolve().parents[1] / "evals" / "blind" / "round29.jsonl"
MARGIN = 0.2


def load(mp):
    p = (SUITE.parent / mp).resolve()
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        return {o["id"]: dict(label=o["label"], room=str(o["room"]), c=o["center"], s=o["size"]) for o in d["objects"]}
    return {int(k): dict(label=v["category"], room=v["room_cat"]) for k, v in d.items()}


# o / or: (label, room or None) the group asks for; accept must be every such object
CATEGORY = {"g01": ("couch", None), "g02": ("mirror frame", None), "g03": ("side table", "living room"),
            "g04": ("easy chair", "bedroom"), "g08": ("curtain", None), "g13": ("lamp", None),
            "g14": ("mug", None), "g15": ("nightstand", "bedroom"), "g16": ("chair", "dining room"),
            "g17": ("lamp", "living room"), "g29": ("pillow", None), "g37": ("book", None),
            "g38": ("chair", "kitchen"), "g39": ("mirror", "hallway")}
# od / ord / ard with one target: expected (label, room or None) of the target
SINGLE = {"g05": ("curtain", None), "g06": ("easy chair", "bedroom"), "g07": ("toilet", None),
          "g09": ("pillow", None), "g10": ("chair", None), "g11": ("desk", "rec room"), "g12": ("clock", None),
          "g18": ("lamp", None), "g19": ("chair", None), "g20": ("chair", "dining room"),
          "g21": ("chair", "studio"), "g22": ("armchair", "living room"), "g23": ("dryer", None),
          "g24": ("bowl", None), "g31": ("remote", None), "g40": ("sofa", None), "g41": ("chair", None),
          "g42": ("chair", "kitchen"), "g43": ("book", "office"), "g44": ("microwave", None),
          "g45": ("printer", None)}
ARD_SET = {"g30": "trash can"}  # every object of this label serves the need equally
# labels that must be unique on the map for single-id ard groups (no second object of that label)
UNIQUE_ARD = {"g07", "g12", "g23", "g24", "g31", "g44", "g45"}


def top(o): return o["c"][2] + o["s"][2] / 2
def bottom(o): return o["c"][2] - o["s"][2] / 2
def dist(a, b): return math.hypot(a[0] - b[0], a[1] - b[1])
def inside_xy(p, o): return all(abs(p[i] - o["c"][i]) <= o["s"][i] / 2 for i in (0, 1))
def on(a, b): return inside_xy(a["c"], b) and abs(bottom(a) - top(b)) <= 0.05


def extreme(O, cands, key, what, target, pick):
    vals = {i: key(O[i]) for i in cands}
    order = sorted(vals, key=vals.get, reverse=(pick == "max"))
    gap = abs(vals[order[0]] - vals[order[1]])
    return order[0] == target and gap >= MARGIN, \
        f"{what} ({pick}): " + ", ".join(f"{i}={vals[i]:.2f}" for i in cands) + f"; pick {order[0]}, gap {gap:.2f}"


def spatial(g, O, target):
    if g == "g25":  # flat_c: the nightstand the alarm clock 29 stands on
        supp = [i for i, o in O.items() if o["label"] == "nightstand" and on(O[29], o)]
        return supp == [target], f"nightstands under alarm clock 29: {supp}"
    if g == "g26":  # flat_h: armchair nearest the tv 8
        return extreme(O, [10, 11], lambda o: dist(o["c"], O[8]["c"]), "dist to tv", target, "min")
    if g == "g27":  # flat_f: kitchen chair farthest from the fridge 20
        ch = [i for i, o in O.items() if o["label"] == "chair" and o["room"] == "kitchen"]
        return extreme(O, ch, lambda o: dist(o["c"], O[20]["c"]), "dist to fridge", target, "max")
    if g == "g28":  # flat_d: stool farther from the bin 23
        return extreme(O, [21, 22], lambda o: dist(o["c"], O[23]["c"]), "dist to bin", target, "max")
    if g == "g32":  # scan_bedroom: pillow nearest the foot of the bed (head against the north wall y=4)
        bed = O[1]
        assert bed["c"][1] + bed["s"][1] / 2 > 3.9
        foot = (bed["c"][0], bed["c"][1] - bed["s"][1] / 2)
        return extreme(O, [2, 3, 4, 5], lambda o: dist(o["c"], foot), "dist to bed foot", target, "min")
    if g == "g33":  # scan_kitchen: cup nearest the sink 10
        return extreme(O, [23, 24, 25], lambda o: dist(o["c"], O[10]["c"]), "dist to sink", target, "min")
    if g == "g34":  # scan_kitchen: wall cabinet directly above the sink 10
        above = [i for i, o in O.items() if o["label"] == "kitchen cabinet" and inside_xy(O[10]["c"], o)
                 and bottom(o) > top(O[10]) + MARGIN]
        return above == [target], f"kitchen cabinets above sink 10: {above}"
    if g == "g35":  # scan_office: lowest (shortest) bookshelf
        return extreme(O, [14, 15, 16], top, "top height", target, "min")
    if g == "g36":  # scan_livingroom: sitting on sofa 1 (south wall) facing the tv 14 (north) -> left is west (-x)
        assert O[14]["c"][1] > O[1]["c"][1]
        return extreme(O, [8, 9], lambda o: o["c"][0], "x (west=left)", target, "min")
    if g == "g46":  # apartment: the higher of the two living-room books
        lr = [i for i, o in O.items() if o["label"] == "book" and o["room"] == "living room"]
        return extreme(O, lr, top, "top height", target, "max")
    if g == "g47":  # apartment: plant standing on the dresser 38
        ons = [i for i, o in O.items() if o["label"] == "plant" and on(o, O[38])]
        return ons == [target], f"plants on dresser 38: {ons}"
    if g == "g48":  # apartment: the cabinet the printer 54 stands on
        supp = [i for i, o in O.items() if o["label"] == "cabinet" and on(O[54], o)]
        return supp == [target], f"cabinets under printer 54: {supp}"
    raise KeyError(g)


def main():
    rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
    groups = {}
    for r in rows:
        groups.setdefault(r["group"].split("-")[1], r)
    fails = 0
    for g, r in sorted(groups.items()):
        O = load(r["map"])
        t, acc = r["type"], sorted(r["accept"])
        if t in ("o", "or"):
            lab, room = CATEGORY[g]
            want = sorted(i for i, o in O.items() if o["label"] == lab and (room is None or o["room"] == room))
            ok, msg = want == acc, f"derived {want}"
        elif t == "s":
            ok, msg = spatial(g, O, r["target"])
            ok = ok and acc == [r["target"]]
        elif g in ARD_SET:
            want = sorted(i for i, o in O.items() if o["label"] == ARD_SET[g])
            ok, msg = want == acc, f"derived {want}"
        else:
            lab, room = SINGLE[g]
            o = O[r["target"]]
            ok = o["label"] == lab and (room is None or o["room"] == room) and acc == [r["target"]]
            msg = f"target {r['target']} is {o['label']!r} in {o['room']!r}"
            if g in UNIQUE_ARD:
                n = sum(1 for x in O.values() if x["label"] == lab)
                ok, msg = ok and n == 1, msg + f"; {n} object(s) with that label"
        fails += not ok
        print(f"{'OK ' if ok else 'FAIL'} {g} {t:<3} {Path(r['map']).name:<28} {msg}")
    print(f"{len(groups)} groups, {fails} failures")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
