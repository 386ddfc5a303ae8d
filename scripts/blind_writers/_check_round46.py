"""Re-derive o/or accept sets and check every spatial claim of round46.jsonl numerically.
Run: python3 scripts/check.py   (exit 1 on any failure)"""
import json, math, re, sys
from collections import defaultdict
from pathlib import Path

BLIND = Path(__file__).resolve().parents[2] / "evals" / "blind"
SUITE = BLIND / "round46.jsonl"
MARGIN = 0.2
fails = []


def load(mapfield):
    p = (BLIND / mapfield).resolve()
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        rooms = {r["id"]: r["label"] for r in d.get("rooms", [])}
        objs = {}
        for o in d["objects"]:
            room = o.get("room")
            if isinstance(room, int):
                room = rooms[room]
            objs[int(o["id"])] = dict(label=o["label"], room=room, c=o["center"], s=o["size"])
        return objs, True
    return {int(k): dict(label=v["category"], room=v["room_cat"]) for k, v in d.items()}, False


def lo(o, i): return o["c"][i] - o["s"][i] / 2
def hi(o, i): return o["c"][i] + o["s"][i] / 2
def d2(a, b): return math.hypot(a["c"][0] - b["c"][0], a["c"][1] - b["c"][1])


def on(a, b, tol=0.06):
    """a rests on b: a's footprint centre inside b's footprint, a's bottom near b's top."""
    inside = lo(b, 0) <= a["c"][0] <= hi(b, 0) and lo(b, 1) <= a["c"][1] <= hi(b, 1)
    return inside and abs(lo(a, 2) - hi(b, 2)) <= tol


def under(a, b, tol=0.06):
    inside = lo(a, 0) <= b["c"][0] <= hi(a, 0) and lo(a, 1) <= b["c"][1] <= hi(a, 1)
    return inside and hi(a, 2) <= lo(b, 2) + tol


def ok(cond, msg):
    print(("ok   " if cond else "FAIL ") + msg)
    if not cond:
        fails.append(msg)


def nearest(objs, target, cands, ref_pt, what):
    ds = sorted((math.hypot(objs[c]["c"][0] - ref_pt[0], objs[c]["c"][1] - ref_pt[1]), c) for c in cands)
    ok(ds[0][1] == target and ds[1][0] - ds[0][0] >= MARGIN,
       f"{what}: nearest {ds[0][1]} ({ds[0][0]:.2f}) next {ds[1][1]} ({ds[1][0]:.2f}) target {target}")


def lev(a, b):
    prev = list(range(len(b) + 1))
    for i, ca in enumerate(a, 1):
        cur = [i]
        for j, cb in enumerate(b, 1):
            cur.append(min(prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (ca != cb)))
        prev = cur
    return prev[-1]


def names_room(query, room):
    """the wording names the room, allowing one typo (the w6 style) or 'recreation room'."""
    words = re.findall(r"[a-z]+", query.lower().replace("recreation", "rec"))
    n = len(room.split())
    return any(lev(" ".join(words[i:i + n]), room) <= 1 for i in range(len(words)))


def by_label(objs, label, room=None):
    return sorted(i for i, o in objs.items() if o["label"] == label and (room is None or o["room"] == room))


rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
groups = defaultdict(list)
for r in rows:
    groups[r["group"]].append(r)

# room named in each "or" group (checked against the wording text as well)
OR_ROOM = {"b46-g03": "bedroom", "b46-g04": "bathroom", "b46-g10": "rec room", "b46-g13": "living room",
           "b46-g22": "bedroom", "b46-g30": "kitchen", "b46-g31": "living room"}
# room named in ord groups: target must be in it
ORD_ROOM = {"b46-g07": "bedroom", "b46-g12": "rec room", "b46-g18": "dining room", "b46-g26": "bedroom",
            "b46-g27": "studio", "b46-g33": "living room", "b46-g34": "office"}

for g, rs in sorted(groups.items()):
    r = rs[0]
    objs, geo = load(r["map"])
    t, acc = r["target"], sorted(r["accept"])
    lab = objs[t]["label"]
    if r["type"] == "o":
        ok(acc == by_label(objs, lab), f"{g} o '{lab}': accept {acc} == all {by_label(objs, lab)}")
    elif r["type"] == "or":
        room = OR_ROOM[g]
        want = by_label(objs, lab, room)
        ok(acc == want and all(names_room(q["query"], room) for q in rs),
           f"{g} or '{lab}' in {room}: accept {acc} == {want}; others elsewhere {sorted(set(by_label(objs, lab)) - set(want))}")
    elif r["type"] == "ord":
        ok(acc == [t] and objs[t]["room"] == ORD_ROOM[g] and all(names_room(q["query"], ORD_ROOM[g]) for q in rs), f"{g} ord target {t} '{lab}' in {objs[t]['room']}")
    else:
        ok(acc == [t], f"{g} {r['type']} single target {t} '{lab}'")

# ---------------- spatial groups ----------------
def M(g):
    return load(groups[g][0]["map"])[0]

# g14 flat_b: the lamp on the side table
o = M("b46-g14")
ok(on(o[7], o[6]) and [l for l in by_label(o, "lamp") if any(on(o[l], o[s]) for s in by_label(o, "side table"))] == [7],
   "g14 lamp 7 rests on side table 6 and is the only lamp on a side table")
ok(o[5]["s"][2] >= 1.5, "g14 lamp 5 is the tall floor one")
# g19 flat_e: chair nearest the NW corner of dining table 10; NE corner -> 14
o = M("b46-g19")
tb = o[10]
chairs = by_label(o, "chair", "dining room")
nearest(o, 13, chairs, (lo(tb, 0), hi(tb, 1)), "g19 chair at NW corner of table 10")
nearest(o, 14, chairs, (hi(tb, 0) - 0.2, hi(tb, 1)), "g19 black chair 14 at NE side corner")  # NE corner minus high chair at east end
ok(o[14]["c"][1] > tb["c"][1] and o[14]["c"][0] > tb["c"][0], "g19 chair 14 is north-east of table centre")
# g23 flat_g: from the foot of bed 31 facing the headboard (north), lamp on the left (west)
o = M("b46-g23")
bed = o[31]
ok(all(o[n]["c"][1] > bed["c"][1] for n in (32, 33)) and hi(bed, 1) > 10.9, "g23 headboard is at the north end (nightstands north)")
ok(on(o[34], o[32]) and on(o[35], o[33]), "g23 lamps 34, 35 on nightstands 32, 33")
ok(o[34]["c"][0] + MARGIN <= o[35]["c"][0], "g23 facing north, left = west: lamp 34 west of lamp 35")
# g28 flat_i: red chair nearer the display 10
o = M("b46-g28")
reds = [c for c in by_label(o, "chair", "meeting room") if c in (6, 7)]
ok(reds == [6, 7], "g28 red chairs in meeting room are 6, 7 (tags checked by hand)")
nearest(o, 7, reds, o[10]["c"], "g28 red chair nearest tv 10")
ok(o[10]["c"][0] > 6.9, "g28 display on the east wall")
# g37 apartment: plant on the dresser
o = M("b46-g37")
ok(on(o[39], o[38]) and [p for p in by_label(o, "plant") if on(o[p], o[38])] == [39], "g37 plant 39 on dresser 38, only one")
ok(all(lo(o[p], 2) < 0.05 for p in (8, 55)), "g37 other plants stand on the floor")
# g38 apartment: chair nearest the stove 19
o = M("b46-g38")
nearest(o, 23, by_label(o, "chair"), o[19]["c"], "g38 chair nearest stove 19")
ok(d2(o[24], o[22]) > 0 and o[24]["c"][1] > o[22]["c"][1], "g38 chair 24 is on the far (north) side of the table")
# g41 scan_livingroom: sitting on sofa 1 facing tv 14 (north), red pillow on the left (west)
o = M("b46-g41")
ok(o[14]["c"][1] > o[1]["c"][1], "g41 tv is north of sofa: facing north")
ok(all(on(o[p], o[1], tol=0.5) for p in (2, 4)), "g41 red pillows 2, 4 on the sofa (loose)")
ok(o[2]["c"][0] + MARGIN <= o[4]["c"][0], "g41 left = west: pillow 2 west of pillow 4")
# g42 scan_livingroom: lamp nearest the green armchair 5
o = M("b46-g42")
nearest(o, 10, by_label(o, "lamp"), o[5]["c"], "g42 lamp nearest armchair 5")
ok(on(o[10], o[8]) and on(o[11], o[9]), "g42 lamps 10, 11 on side tables 8, 9")
# g43 scan_kitchen: cabinet under sink 10
o = M("b46-g43")
unders = [c for c in by_label(o, "kitchen cabinet") if under(o[c], o[10])]
ok(unders == [3], f"g43 cabinets under sink: {unders}")
ok(under(o[1], o[12]), "g43 cabinet 1 is under the coffee maker")
# g45 scan_office: middle bookshelf
o = M("b46-g45")
bs = sorted(by_label(o, "bookshelf"), key=lambda b: o[b]["c"][0])
ok(len(bs) == 3 and bs[1] == 15 and min(o[bs[1]]["c"][0] - o[bs[0]]["c"][0], o[bs[2]]["c"][0] - o[bs[1]]["c"][0]) >= MARGIN,
   f"g45 bookshelves west->east {bs}: middle 15")
ok(all(o[b]["c"][1] > 5.5 for b in bs), "g45 bookshelves along the north wall")
# g46 scan_office: office chair nearest door 20
o = M("b46-g46")
nearest(o, 10, by_label(o, "office chair"), o[20]["c"], "g46 office chair nearest door 20")
# g47 scan_bedroom: from foot of bed 1 facing headboard (north), nightstand on the right (east)
o = M("b46-g47")
ok(all(o[p]["c"][1] > o[1]["c"][1] for p in (2, 3)), "g47 pillows at north end: headboard north")
ok(o[7]["c"][0] - MARGIN >= o[6]["c"][0], "g47 right = east: nightstand 7 east of 6")
# descriptive placement claims used in other groups
o = M("b46-g48")
ok(on(o[21], o[6]), "g48 clock 21 on nightstand 6")
o = M("b46-g35")
ok(on(o[54], o[53]), "g35 printer 54 on filing cabinet 53")
o = M("b46-g33")
ok(on(o[14], o[1], tol=0.2), "g33 yellow pillow 14 rests on sofa 1 (loose)")
o = load("maps/flat_b.json")[0]
ok(on(o[26], o[24]), "g16 banker's lamp 26 on desk 24")
o = load("maps/flat_i.json")[0]
ok(on(o[46], o[44]), "g26 rattan lamp 46 on white nightstand 44")
ok(on(o[31], o[26]), "g25 mug 31 on worktop 26")
o = load("maps/flat_g.json")[0]
ok(all(o[b]["room"] == "garage" for b in (2, 3)), "g21 both bikes in the garage")

# ---------------- wording styles ----------------
for r in rows:
    q, w = r["query"], r["id"][-2:]
    if w == "w1":
        ok(q.split()[0] in ("Go", "Take", "Standing", "Sitting"), f"{r['id']} w1 imperative")
    elif w == "w2":
        ok(q.startswith("Could you") and q.endswith("?"), f"{r['id']} w2 polite question")
    elif w == "w3":
        ok(len(q.split()) <= 8 and not set(re.findall(r"[a-z]+", q.lower())) & {"a", "an", "the"}, f"{r['id']} w3 telegraphic")
    elif w == "w5":
        ok(q.startswith("This is") and q.count(". ") == 1 and q.endswith("."), f"{r['id']} w5 two sentences")
    elif w == "w6":
        ok(q == q.lower(), f"{r['id']} w6 lower case")

print(f"{len(fails)} failures")
sys.exit(1 if fails else 0)
