"""Re-derive o/or accept sets from the maps and check every spatial claim numerically (centres, sizes)."""
import math, sys
from _common_round44 import load_map, load_suite

rows, groups = load_suite()
MAPS = {}
def M(name):
    if name not in MAPS:
        MAPS[name] = load_map(name)
    return MAPS[name]

errors = []
def need(cond, msg):
    if not cond:
        errors.append(msg)

def room_of(m, o):
    return o.get("room")

# rooms named in the or / ord groups (the room the wording names)
ROOM = {"b44-g04": "bedroom", "b44-g05": "bathroom", "b44-g06": "living room", "b44-g10": "living room",
        "b44-g11": "bathroom", "b44-g16": "dining room", "b44-g17": "bedroom", "b44-g20": "studio",
        "b44-g21": "dining room", "b44-g22": "bedroom", "b44-g34": "kitchen", "b44-g35": "bathroom",
        "b44-g38": "office", "b44-g39": "kitchen"}

for g, rs in groups.items():
    r = rs[0]
    m = M(r["map"]); objs = m["objs"]; t = objs[r["target"]]; lab = t["label"]
    acc = sorted(r["accept"])
    if r["type"] == "o":
        exp = sorted(i for i, o in objs.items() if o["label"] == lab)
        need(acc == exp, f"{g}: o accept {acc} != {exp}")
    elif r["type"] == "or":
        exp = sorted(i for i, o in objs.items() if o["label"] == lab and room_of(m, o) == ROOM[g])
        need(acc == exp, f"{g}: or accept {acc} != {exp}")
    elif r["type"] in ("od", "ord", "s"):
        need(acc == [r["target"]], f"{g}: single id expected")
        if r["type"] == "ord":
            need(room_of(m, t) == ROOM[g], f"{g}: target room {room_of(m, t)} != {ROOM[g]}")
            # the room holds other objects of the label, or at least the room is right
    elif r["type"] == "ard":
        need(all(objs[a]["label"] == lab for a in acc), f"{g}: ard set mixes labels")
        exp = sorted(i for i, o in objs.items() if o["label"] == lab)
        if len(acc) > 1:
            need(acc == exp, f"{g}: ard set {acc} != all {lab} {exp}")
    if r["type"] == "s":
        need(m["geo"], f"{g}: spatial on caption map")

# ---------------- spatial helpers ----------------
def c(o): return o["center"]
def bottom(o): return o["center"][2] - o["size"][2] / 2
def top(o): return o["center"][2] + o["size"][2] / 2
def d2(a, b): return math.hypot(c(a)[0] - c(b)[0], c(a)[1] - c(b)[1])
def inside_xy(a, b):
    return all(abs(c(a)[k] - c(b)[k]) <= b["size"][k] / 2 for k in (0, 1))
def on(a, b): return abs(bottom(a) - top(b)) <= 0.05 and inside_xy(a, b)
def margin_min(target, others, key):
    """target has the smallest key, by at least 0.2 over every other."""
    kt = key(target)
    return all(key(o) - kt >= 0.2 for o in others)
def of(mapname, label, room=None, excl=()):
    return [o for o in M(mapname)["objs"].values() if o["label"] == label and (room is None or o["room"] == room)
            and o["id"] not in excl]

def S(g):
    r = groups[g][0]; return M(r["map"])["objs"], r["target"]

# g26 flat_b: bedside lamp east of the bed, on the east nightstand (right as seen from the foot; headboard north)
o, t = S("b44-g26"); bed = o[30]
need(on(o[34], o[32]) and c(o[34])[0] - c(bed)[0] >= 0.2, "g26 lamp 34 not on nightstand 32 east of bed")
need(top(bed) < bottom(o[34]) + 1 and c(bed)[1] < 8.8, "g26 bed")
others = [x for x in of("maps/flat_b.json", "lamp", "bedroom") if x["id"] != 34]
need(all(c(x)[0] < c(bed)[0] - 0.2 for x in others), "g26 another bedroom lamp east of bed")
# g27 flat_e: dining chair farthest from black metal chair 14
o, t = S("b44-g27")
cand = of("maps/flat_e.json", "chair", "dining room", excl=(14,))
need(margin_min(o[11], [x for x in cand if x["id"] != 11], lambda x: -d2(x, o[14])), "g27 farthest margin")
# g28 flat_g: lamp nearest wardrobe 36 (all lamps)
o, t = S("b44-g28")
cand = of("maps/flat_g.json", "lamp")
need(margin_min(o[34], [x for x in cand if x["id"] != 34], lambda x: d2(x, o[36])), "g28 nearest margin")
need(d2(o[35], o[37]) + 0.2 <= d2(o[34], o[37]), "g28 other lamp nearer hamper")
# g29 flat_i: mug on coffee table 35, the other mugs not
o, t = S("b44-g29")
need(on(o[36], o[35]) and not on(o[23], o[35]) and not on(o[31], o[35]), "g29 on")
need(on(o[23], o[12]) and on(o[31], o[26]), "g29 other mugs on desk / worktop")
need(0.2 <= c(o[34])[1] - c(o[35])[1] and abs(c(o[34])[0] - c(o[35])[0]) < 0.5, "g29 coffee table in front of sofa")
# g30 flat_i: desk on the left facing north in the studio = smallest x
o, t = S("b44-g30")
cand = of("maps/flat_i.json", "desk", "studio")
need(margin_min(o[12], [x for x in cand if x["id"] != 12], lambda x: c(x)[0]), "g30 west margin")
need(all(c(x)[1] + x["size"][1] / 2 > 9.4 for x in cand), "g30 desks against north wall (y=10)")
# g31 flat_b: armchair nearest window 13 (and nearest any window)
o, t = S("b44-g31")
cand = of("maps/flat_b.json", "armchair")
for w in (13, 36):
    need(margin_min(o[2], [x for x in cand if x["id"] != 2], lambda x: d2(x, o[w])), f"g31 nearest window {w}")
need(c(o[13])[0] < 0.1, "g31 window 13 in west wall")
# g43 scan_office: blue office chair closer to windows
o, t = S("b44-g43")
wins = of("../maps/scan_office.json", "window")
blue = [x for x in of("../maps/scan_office.json", "office chair") if x["tags"].get("color") == "blue"]
need(sorted(x["id"] for x in blue) == [7, 10], "g43 blue chairs")
need(margin_min(o[7], [o[10]], lambda x: min(d2(x, w) for w in wins)), "g43 nearer windows")
tables = of("../maps/scan_office.json", "table")
need(min(tables, key=lambda x: d2(x, o[7]))["id"] == 2 and o[2]["tags"].get("material") == "wood", "g43 at wooden table")
# g44 scan_office: middle bookshelf between the other two
o, t = S("b44-g44")
bs = sorted(of("../maps/scan_office.json", "bookshelf"), key=lambda x: c(x)[0])
need([x["id"] for x in bs] == [14, 15, 16] and len({c(x)[1] for x in bs}) == 1, "g44 between")
need(all(c(x)[0] - c(bs[i])[0] >= 0.2 for i, x in enumerate(bs[1:])), "g44 spacing")
need(all(c(x)[1] > 5.5 for x in bs), "g44 north wall")
# g45 scan_bedroom: pillow farthest from headboard (north end of bed)
o, t = S("b44-g45")
head_y = c(o[1])[1] + o[1]["size"][1] / 2
ps = of("../maps/scan_bedroom.json", "pillow")
need(margin_min(o[5], [x for x in ps if x["id"] != 5], lambda x: -(head_y - c(x)[1])), "g45 farthest")
need(all(inside_xy(x, o[1]) for x in ps), "g45 pillows on bed")
# g46 scan_kitchen: cup on the counter (a base cabinet), next to sink; others on the table
o, t = S("b44-g46")
base = [x for x in of("../maps/scan_kitchen.json", "kitchen cabinet") if top(x) < 1.0]
need(any(on(o[25], b) for b in base), "g46 on counter")
need(on(o[23], o[16]) and on(o[24], o[16]), "g46 others on table")
need(d2(o[25], o[10]) <= 0.7 and min(d2(o[25], x) for x in of("../maps/scan_kitchen.json", "cup") if x["id"] != 25) > 1.0, "g46 by sink")
# g47 scan_livingroom: standing at TV (north) facing sofa (south): left = east = larger x
o, t = S("b44-g47")
need(c(o[14])[1] - c(o[1])[1] > 2, "g47 tv north of sofa")
st = of("../maps/scan_livingroom.json", "side table")
need(margin_min(o[9], [x for x in st if x["id"] != 9], lambda x: -c(x)[0]), "g47 east")
need(all(abs(c(x)[1] - c(o[1])[1]) < 0.3 for x in st), "g47 beside sofa")
# g48 apartment: the higher of the two books on the living room bookshelf
o, t = S("b44-g48")
bk = [x for x in of("apartment", "book") if inside_xy(x, o[11])]
need(sorted(x["id"] for x in bk) == [12, 13], "g48 books on shelf")
need(bottom(o[12]) - bottom(o[13]) >= 0.2 and c(o[12])[2] - c(o[13])[2] >= 0.2, "g48 higher")

for e in errors:
    print("ERROR", e)
print(f"{len(groups)} groups checked; {len(errors)} errors")
sys.exit(1 if errors else 0)
