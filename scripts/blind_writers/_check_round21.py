"""Numeric check of every s group in round21 from centres and sizes (margin given per check)."""
import json, math
from pathlib import Path
B = Path(__file__).resolve().parents[1] / "evals" / "blind"
def load(rel):
    return {o["id"]: o for o in json.load(open(B / rel))["objects"]}
def d(a, b): return math.dist(a["center"][:2], b["center"][:2])
def nearest(m, cands, ref, margin=0.3):
    ds = sorted((d(m[c], m[ref]), c) for c in cands)
    return ds[0][1], ds[1][0] - ds[0][0] >= margin, ds
def nearest_any(m, cands, refs, margin=0.3):
    ds = sorted((min(d(m[c], m[r]) for r in refs), c) for c in cands)
    return ds[0][1], ds[1][0] - ds[0][0] >= margin, ds
res = []
so, sl, ap, fb, fd = load("../maps/scan_office.json"), load("../maps/scan_livingroom.json"), load("apartment"), load("maps/flat_b.json"), load("maps/flat_d.json")
# labels of candidates are checked to be complete
def kind(m, lab): return [i for i, o in m.items() if o["label"] == lab]
blue = [i for i in kind(so, "office chair") if so[i].get("tags", {}).get("color") == "blue"]
res.append(("g37 blue chair nearest door", 10, nearest(so, blue, 20)))
h = sorted((so[i]["size"][2], i) for i in kind(so, "bookshelf"))
res.append(("g38 shortest bookshelf", 16, (h[0][1], h[1][0] - h[0][0] >= 0.3, h)))
res.append(("g39 bin by door", 21, nearest(so, kind(so, "trash can"), 20)))
res.append(("g40 plant by bookshelves", 24, nearest_any(so, kind(so, "plant"), kind(so, "bookshelf"))))
xs = {i: sl[i]["center"][0] for i in kind(sl, "pillow")}
mid = [i for i in xs if min(xs[j] for j in (2, 4)) + 0.3 < xs[i] < max(xs[j] for j in (2, 4)) - 0.3]
res.append(("g41 pillow between red ones", 3, (mid[0] if len(mid) == 1 else None, len(mid) == 1, xs)))
res.append(("g42 lamp nearest leather armchair", 11, nearest(sl, kind(sl, "lamp")[:2] + [12], 6)))
res.append(("g43 picture above sofa", 15, nearest(sl, kind(sl, "picture"), 1)))
res.append(("g44 plant by bookshelf", 17, nearest(sl, kind(sl, "plant"), 19)))
lr = [i for i in kind(ap, "book") if ap[i]["room"] == "living room"]
z = sorted((ap[i]["center"][2], i) for i in lr)
res.append(("g45 lowest living-room book", 13, (z[0][1], z[1][0] - z[0][0] >= 0.3, z)))
pl, dr = ap[39], ap[38]
on = (abs(pl["center"][0] - dr["center"][0]) < dr["size"][0] / 2 and abs(pl["center"][1] - dr["center"][1]) < dr["size"][1] / 2
      and abs((pl["center"][2] - pl["size"][2] / 2) - (dr["center"][2] + dr["size"][2] / 2)) < 0.05)
others = [i for i in kind(ap, "plant") if i != 39 and abs(ap[i]["center"][2] - ap[i]["size"][2] / 2) > 0.05]
res.append(("g46 plant on dresser", 39, (39 if on and not others else None, on and not others, others)))
bed = fb[30]; foot = (bed["center"][0], bed["center"][1] - bed["size"][1] / 2)  # headboard north, viewer looks +y, right = +x
rx = sorted(((fb[i]["center"][0] - foot[0]), i) for i in kind(fb, "lamp") if fb[i]["room"] == bed["room"])
res.append(("g47 right bedside lamp from foot", 34, (rx[-1][1], rx[-1][0] > 0.5 and rx[0][0] < -0.5, rx)))
res.append(("g48 stool nearest fridge", 22, nearest(fd, kind(fd, "stool"), 15)))
bad = 0
for name, want, (got, ok, info) in res:
    good = got == want and ok
    bad += not good
    print("OK " if good else "BAD", name, "->", got, info)
print("all spatial groups pass" if not bad else f"{bad} failing")
