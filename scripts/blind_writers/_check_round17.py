"""Numerical checks of the s groups in round17.jsonl, plus accept-set checks for o/or groups and a
label-word count (ard: none; others: <= 2). Reads only the suite and its maps."""
import json, math, re, sys
from pathlib import Path

B = Path(__file__).resolve().parent.parent / "evals" / "blind"
rows = [json.loads(l) for l in (B / "round17.jsonl").read_text().splitlines()]
groups = {}
for r in rows:
    groups.setdefault(r["group"], []).append(r)

def load(m):
    d = json.loads((B / m).resolve().read_text())
    if "objects" in d:
        return {o["id"]: o for o in d["objects"]}, True
    return {int(k): {"id": int(k), "label": v["category"], "room": v.get("room_cat")} for k, v in d.items()}, False

def dxy(a, b):
    return math.dist(a["center"][:2], b["center"][:2])

def bottom(o): return o["center"][2] - o["size"][2] / 2
def top(o): return o["center"][2] + o["size"][2] / 2
def xy_inside(a, b, tol=0.05):  # a's centre inside b's footprint
    return all(abs(a["center"][i] - b["center"][i]) <= b["size"][i] / 2 + tol for i in (0, 1))
def on(a, b): return xy_inside(a, b) and abs(bottom(a) - top(b)) < 0.08
def vol(o): return o["size"][0] * o["size"][1] * o["size"][2]
def of(objs, label): return [o for o in objs.values() if o["label"] == label]

ok = True
def claim(name, cond, info=""):
    global ok
    print(("PASS " if cond else "FAIL ") + name, info)
    ok &= bool(cond)

M = lambda m: load(m)[0]
# scan_office
so = M("../maps/scan_office.json")
d = {o["id"]: round(dxy(o, so[20]), 2) for o in of(so, "trash can")}
claim("scan_office bin nearest door 20 -> 21", min(d, key=d.get) == 21 and sorted(d.values())[1] - d[21] > 1.0, d)
xs = sorted((o["center"][0], o["id"]) for o in of(so, "bookshelf"))
claim("scan_office middle of 3 bookshelves by x -> 15", len(xs) == 3 and xs[1][1] == 15 and xs[1][0] - xs[0][0] > 0.5 and xs[2][0] - xs[1][0] > 0.5, xs)
onw = [o["id"] for o in of(so, "monitor") if on(o, so[1])]
claim("scan_office monitor on white table 1 -> 11", onw == [11], onw)
claim("  table 1 is the white one, 2 brown", so[1]["tags"]["color"] == "white" and so[2]["tags"]["color"] == "brown")
# scan_bedroom
sb = M("../maps/scan_bedroom.json")
d = {o["id"]: round(dxy(o, sb[15]), 2) for o in of(sb, "lamp")}
claim("scan_bedroom lamp farthest from door 15 -> 8", max(d, key=d.get) == 8 and d[8] - min(d.values()) > 1.0, d)
d2 = {o["id"]: round(dxy(o, sb[21]), 2) for o in of(sb, "lamp")}
claim("  lamp 8 is the one next to the clock", min(d2, key=d2.get) == 8, d2)
ons = [o["id"] for o in of(sb, "nightstand") if on(sb[20], o)]
claim("scan_bedroom nightstand under book 20 -> 7", ons == [7], ons)
claim("  clock 21 is on nightstand 6", on(sb[21], sb[6]))
# apartment
ap = M("apartment")
d = {o["id"]: round(dxy(o, ap[1]) - (max(ap[1]["size"][:2]) / 2), 2) for o in of(ap, "lamp")}
gap = ap[7]["center"][0] - ap[7]["size"][0] / 2 - (ap[1]["center"][0] + ap[1]["size"][0] / 2)
claim("apartment lamp nearest sofa 1 -> 7", min(d, key=d.get) == 7 and sorted(d.values())[1] - d[7] > 2, (d, "edge gap", round(gap, 2)))
und = [o["id"] for o in of(ap, "cabinet") if xy_inside(ap[41], o) and abs(top(o) - bottom(ap[41])) < 0.08]
claim("apartment cabinet right under washbasin 41 -> 42", und == [42], und)
und17 = [o["id"] for o in of(ap, "cabinet") if xy_inside(ap[17], o) and top(o) <= bottom(ap[17]) + 0.05]
claim("  no cabinet-labelled object under the kitchen sink 17", und17 == [], und17)
# flat_d
fd = M("maps/flat_d.json")
d = {o["id"]: round(dxy(o, fd[13]), 2) for o in of(fd, "chair")}
s = sorted(d.values())
claim("flat_d chair nearest tv 13 -> 4", min(d, key=d.get) == 4 and s[1] - s[0] > 0.5, d)
# flat_g
fg = M("maps/flat_g.json")
bed = fg[31]
ns = of(fg, "nightstand")
claim("  flat_g nightstands at the north (head) end of bed 31", all(o["center"][1] > bed["center"][1] + 0.5 for o in ns))
west = min(ns, key=lambda o: o["center"][0])
claim("flat_g facing north, left=west nightstand -> 32", west["id"] == 32 and west["center"][0] < bed["center"][0] - 0.8 and all(o["center"][0] > bed["center"][0] + 0.8 for o in ns if o is not west), [(o["id"], o["center"][0]) for o in ns])
v = {o["id"]: round(vol(o), 2) for o in of(fg, "bicycle")}
claim("flat_g bigger bicycle -> 2", max(v, key=v.get) == 2 and v[2] > 1.5 * min(v.values()), v)
# flat_i
fi = M("maps/flat_i.json")
onm = [o["id"] for o in of(fi, "mug") if on(o, fi[35])]
claim("flat_i mug on coffee table 35 -> 36", onm == [36], onm)
d = {o["id"]: round(dxy(o, fi[13]), 2) for o in of(fi, "chair")}
s = sorted(d.values())
claim("flat_i chair nearest white desk 13 -> 15", min(d, key=d.get) == 15 and s[1] - s[0] > 1.0, d)

# o / or accept sets recomputed; label counts
LAB = {}
for g, rs in sorted(groups.items()):
    r = rs[0]
    objs, geo = load(r["map"])
    lab = {objs[a]["label"] for a in r["accept"]}
    if r["type"] == "o":
        want = sorted(o["id"] for o in objs.values() if o["label"] in lab)
        claim(f"{g} o accept = all {lab}", want == r["accept"], want)
    if r["type"] == "or":
        rooms = {objs[a]["room"] for a in r["accept"]}
        want = sorted(o["id"] for o in objs.values() if o["label"] in lab and o["room"] in rooms)
        claim(f"{g} or accept = all {lab} in {rooms}", want == r["accept"] and len(rooms) == 1, want)
    if r["type"] in ("od", "ord", "ard", "s"):
        assert len(r["accept"]) == 1, g
    uses = [q["id"] for q in rs if any(re.search(r"\b" + re.escape(l.lower()) + r"(s|es)?\b", q["query"].lower()) for l in lab)]
    lim = 0 if r["type"] == "ard" else 2
    claim(f"{g} label {lab} in {len(uses)} wordings (<= {lim})", len(uses) <= lim, uses)
print("ALL OK" if ok else "SOME FAILED")
sys.exit(0 if ok else 1)
