#!/usr/bin/env python3
"""Own checks for round24: label-word usage per group, typo share, and numeric checks of every s group."""
import json, math, os, re, collections
H = os.path.dirname(os.path.abspath(__file__))
EV = os.path.join(H, "..", "evals")
def load_map(m):
    if m == "apartment": p = os.path.join(EV, "blind", "apartment")
    elif m.startswith("../maps/"): p = os.path.join(EV, "maps", m[8:])
    elif m.startswith("maps/"): p = os.path.join(EV, "blind", m)
    else: p = "/work/shared/data/iesm_maps/" + os.path.basename(m)
    d = json.load(open(p))
    if "objects" in d: return {o["id"]: o for o in d["objects"]}
    return {int(k): dict(v, label=v["category"]) for k, v in d.items()}
rows = [json.loads(l) for l in open(os.path.join(EV, "blind", "round24.jsonl"))]
groups = collections.OrderedDict()
for r in rows: groups.setdefault(r["group"], []).append(r)
from make_round24 import TYPOS
bad = 0
for g, rs in groups.items():
    objs = load_map(rs[0]["map"]); lab = objs[rs[0]["target"]]["label"].lower()
    n = sum(1 for r in rs if re.search(r"\b" + re.escape(lab) + r"s?\b", r["query"].lower()))
    lim = 0 if rs[0]["type"] == "ard" else 2
    if n > lim: print("LABEL", g, lab, n); bad += 1
    # accept sanity for o/or: all instances of label (in room)
    t = rs[0]["type"]
    if t in ("o", "or"):
        same = sorted(i for i, o in objs.items() if o["label"] == objs[rs[0]["target"]]["label"])
        print(g, t, "label", lab, "all instances", same, "accept", rs[0]["accept"],
              "rooms", [objs[i].get("room", objs[i].get("room_cat")) for i in same])
typo = [r["id"] for r in rows if any(re.search(r"\b%s\b" % w, r["query"]) for w in TYPOS)]
print("typo lines", len(typo), "%.1f%%" % (100.0 * len(typo) / len(rows)))
qs = collections.Counter(r["query"].lower() for r in rows)
print("duplicate wordings", [q for q, c in qs.items() if c > 1])

# ---- numeric s checks ----
def M(m): return load_map(m)
def c(o): return o["center"]
def d2(a, b): return math.hypot(c(a)[0] - c(b)[0], c(a)[1] - c(b)[1])
def on_top(top, base, tol=0.05):
    (x, y, z), (sx, sy, sz) = top["center"], top["size"]
    (X, Y, Z), (SX, SY, SZ) = base["center"], base["size"]
    return abs((z - sz / 2) - (Z + SZ / 2)) <= tol and abs(x - X) <= SX / 2 and abs(y - Y) <= SY / 2
def ok(name, cond, info=""):
    global bad
    print(("OK  " if cond else "FAIL"), name, info)
    if not cond: bad += 1
MARGIN = 0.3
# g37 scan_kitchen: base cabinet under the sink -> 3
k = M("../maps/scan_kitchen.json"); sink = k[10]
under = [i for i, o in k.items() if o["label"] == "kitchen cabinet" and o["center"][2] + o["size"][2] / 2 <= sink["center"][2] - sink["size"][2] / 2 + 0.05
         and abs(o["center"][0] - sink["center"][0]) < (o["size"][0] + sink["size"][0]) / 2 - 0.1]
ok("g37 cabinet under sink", under == [3], under)
# g38 chair farthest from door -> 22
ds = sorted(((d2(o, k[15]), i) for i, o in k.items() if o["label"] == "chair"), reverse=True)
ok("g38 farthest chair from door", ds[0][1] == 22 and ds[0][0] - ds[1][0] > MARGIN, ds[:3])
# g39 scan_livingroom middle pillow between the others -> 3
l = M("../maps/scan_livingroom.json"); ps = sorted((o["center"][0], i) for i, o in l.items() if o["label"] == "pillow")
def rests_in(p, sofa):
    (x, y, z), (sx, sy, sz) = p["center"], p["size"]; (X, Y, Z), (SX, SY, SZ) = sofa["center"], sofa["size"]
    return abs(x - X) <= SX / 2 and abs(y - Y) <= SY / 2 and Z - SZ / 2 < z - sz / 2 <= Z + SZ / 2 + 0.05
ok("g39 middle pillow", ps[1][1] == 3 and all(rests_in(l[i], l[1]) for _, i in ps)
   and ps[1][0] - ps[0][0] > MARGIN and ps[2][0] - ps[1][0] > MARGIN, ps)
# g40 scan_bedroom lamp nearest door -> 9 (and the other one nearest window)
b = M("../maps/scan_bedroom.json")
ds = sorted((d2(o, b[15]), i) for i, o in b.items() if o["label"] == "lamp")
ok("g40 lamp nearest door", ds[0][1] == 9 and ds[1][0] - ds[0][0] > MARGIN, ds)
ds = sorted((d2(o, b[14]), i) for i, o in b.items() if o["label"] == "lamp")
ok("g40 other lamp by window", ds[0][1] == 8 and ds[1][0] - ds[0][0] > MARGIN, ds)
# g41 facing headboard (north, +y) from foot: left = smaller x among white pillows -> 2
bed = b[1]; head_y = bed["center"][1] + bed["size"][1] / 2
wp = sorted((o["center"][0], i) for i, o in b.items() if o["label"] == "pillow" and o["tags"].get("color") == "white")
ok("g41 headboard is north end", all(b[i]["center"][1] > bed["center"][1] for _, i in wp), head_y)
ok("g41 left white pillow", wp[0][1] == 2 and wp[1][0] - wp[0][0] > MARGIN, wp)
# g42 apartment plant on top of dresser -> 39
a = M("apartment")
ons = [i for i, o in a.items() if o["label"] == "plant" and on_top(o, a[38])]
ok("g42 plant on dresser", ons == [39], ons)
# g43 lower book on living room bookshelf -> 13
bk = [i for i, o in a.items() if o["label"] == "book" and abs(o["center"][0] - a[11]["center"][0]) < a[11]["size"][0] / 2
      and abs(o["center"][1] - a[11]["center"][1]) < a[11]["size"][1] / 2]
bk.sort(key=lambda i: a[i]["center"][2])
ok("g43 lower book on LR shelf", bk == [13, 12] and a[12]["center"][2] - a[13]["center"][2] > MARGIN, bk)
# g44 flat_e green chair nearest the black chair 14 -> 13
e = M("maps/flat_e.json")
ds = sorted((d2(o, e[14]), i) for i, o in e.items() if o["label"] == "chair" and "green" in o["tags"].get("color", ""))
ok("g44 green chair next to black", ds[0][1] == 13 and ds[1][0] - ds[0][0] > MARGIN, ds)
# g45 flat_h smaller sofa -> 6
h = M("maps/flat_h.json")
vs = sorted((o["size"][0] * o["size"][1] * o["size"][2], i) for i, o in h.items() if o["label"] == "sofa")
ok("g45 smaller sofa", vs[0][1] == 6 and vs[1][0] > 1.3 * vs[0][0], vs)
# g46 flat_c lamp on the side table -> 7; other lamp by sofa (5) on floor
cc = M("maps/flat_c.json")
ons = [i for i, o in cc.items() if o["label"] == "lamp" and on_top(o, cc[6])]
ok("g46 lamp on side table", ons == [7] and abs(cc[5]["center"][2] - cc[5]["size"][2] / 2) < 0.05, ons)
# g47 flat_i meeting room chair nearest the wall display 10 -> 9
fi = M("maps/flat_i.json")
ds = sorted((d2(o, fi[10]), i) for i, o in fi.items() if o["label"] == "chair" and o["room"] == "meeting room")
ok("g47 chair nearest screen", ds[0][1] == 9 and ds[1][0] - ds[0][0] > MARGIN, ds)
# g48 flat_d stool nearest fridge -> 22; also nearest seat of any kind
fd = M("maps/flat_d.json")
ds = sorted((d2(o, fd[15]), i) for i, o in fd.items() if o["label"] == "stool")
ok("g48 stool nearest fridge", ds[0][1] == 22 and ds[1][0] - ds[0][0] > MARGIN, ds)
ds = sorted((d2(o, fd[15]), i) for i, o in fd.items() if o["label"] in ("stool", "chair", "sofa bed", "bench"))
ok("g48 nearest seat of any kind", ds[0][1] == 22 and ds[1][0] - ds[0][0] > MARGIN, ds[:3])
print("problems:", bad)
