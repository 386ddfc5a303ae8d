"""Numeric check of every s group in round25 from map centres and sizes (margins in metres)."""
import json, math
from pathlib import Path
B = Path(__file__).resolve().parent / "evals/blind"
def objs(m):
    return {o["id"]: o for o in json.load(open(B / m))["objects"]}
def c(o): return o["center"]
def d2(a, b): return math.dist(c(a)[:2], c(b)[:2])
def on(top, base, tol=0.05):
    (x, y, z), (sx, sy, sz) = top["center"], top["size"]
    (bx, by, bz), (bsx, bsy, bsz) = base["center"], base["size"]
    inside = abs(x - bx) <= bsx / 2 and abs(y - by) <= bsy / 2
    return inside and abs((z - sz / 2) - (bz + bsz / 2)) <= tol
def nearest(O, ids, ref, margin=0.3):
    ds = sorted((d2(O[i], ref), i) for i in ids)
    assert ds[1][0] - ds[0][0] >= margin, ds
    return ds[0][1]
ok = []
O = objs("maps/flat_b.json")   # g28 lamp on side table
assert on(O[7], O[6]) and not on(O[5], O[6]); ok.append("g28")
O = objs("maps/flat_h.json")   # g29 right nightstand facing bed from foot (head north) + book on it
bed = O[45]; assert O[46]["center"][1] > bed["center"][1] and O[47]["center"][0] - bed["center"][0] > 0.5 > 0 > O[46]["center"][0] - bed["center"][0]
assert on(O[49], O[47]) and on(O[48], O[46]); ok.append("g29")
O = objs("maps/flat_g.json")   # g30 chair nearest counter
assert nearest(O, [18, 19], O[12]) == 18; ok.append("g30")
O = objs("maps/flat_d.json")   # g31 stool nearest bin
assert nearest(O, [21, 22], O[23]) == 21; ok.append("g31")
O = objs("../maps/scan_office.json")
w = [O[18], O[19]]             # g41 blue chair nearest the window wall (y ~ 0)
assert O[10]["center"][1] - O[7]["center"][1] > 1.0 and O[7]["tags"]["color"] == O[10]["tags"]["color"] == "blue"; ok.append("g41")
assert on(O[29], O[1], 0.03) and on(O[30], O[2], 0.03); ok.append("g42")   # keyboard on white table
xs = sorted((O[i]["center"][0], i) for i in (14, 15, 16)); assert xs[1][1] == 15; ok.append("g43")
O = objs("../maps/scan_livingroom.json")
xs = sorted((O[i]["center"][0], i) for i in (2, 3, 4)); assert xs[1][1] == 3 and all(on(O[i], O[1], 0.15) for i in (2, 3, 4)); ok.append("g44")
# g45 facing TV (north, +y) from sofa: left = -x; lamps on side tables
assert O[14]["center"][1] > O[1]["center"][1] + 3 and on(O[10], O[8]) and on(O[11], O[9]) and O[10]["center"][0] < O[11]["center"][0] - 1; ok.append("g45")
O = objs("../maps/scan_kitchen.json")
assert nearest(O, [17, 18, 19, 20, 21, 22], O[15]) == 21; ok.append("g46")
assert on(O[25], O[2]) and d2(O[25], O[10]) < 0.7 and not on(O[23], O[2]) and all(d2(O[i], O[10]) > 1.5 for i in (23, 24)); ok.append("g47")
O = objs("apartment")
assert on(O[39], O[38]) and not any(on(O[i], O[38]) for i in (8, 55)); ok.append("g48")
print("spatial checks passed:", ok)
