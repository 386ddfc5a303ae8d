"""Numeric check of the 12 spatial (s) groups of round20 from centres and sizes (margin-based)."""
import json, math
from pathlib import Path
B = Path(__file__).parent / "evals"
def load(p): return {o["id"]: o for o in json.loads((B / p).read_text())["objects"]}
def d2(a, b): return math.dist(a["center"][:2], b["center"][:2])
def on(top, base, tol=0.05):
    t, b = top, base
    inside = all(abs(t["center"][i] - b["center"][i]) <= b["size"][i] / 2 for i in (0, 1))
    return inside and abs((t["center"][2] - t["size"][2] / 2) - (b["center"][2] + b["size"][2] / 2)) <= tol
def nearest(m, cands, ref, target, margin):
    ds = sorted((d2(m[c], m[ref]), c) for c in cands)
    ok = ds[0][1] == target and ds[1][0] - ds[0][0] >= margin
    return ok, [(c, round(d, 2)) for d, c in ds]
ok = []
fb, fe, ff, fh = (load(f"blind/maps/flat_{x}.json") for x in "befh")
slr, sbr, apt = load("maps/scan_livingroom.json"), load("maps/scan_bedroom.json"), load("blind/apartment")
lamps_b = [i for i, o in fb.items() if o["label"] == "lamp"]
r = [i for i in lamps_b if on(fb[i], fb[6])]; ok.append(("g18 flat_b lamp on side table 6", r == [7], r))
# g19: brown dining chairs 20,21; farther from stove 15
d = {c: round(d2(fb[c], fb[15]), 2) for c in (20, 21)}; ok.append(("g19 flat_b brown chair farthest from stove", max(d, key=d.get) == 21 and abs(d[20]-d[21]) >= 0.3, d))
# g25: sage chairs 11,12,13 nearest black chair 14
r = nearest(fe, [11, 12, 13], 14, 13, 0.3); ok.append(("g25 flat_e sage chair next to black chair", *r))
# g30: blue chairs 12,13,15 nearest stove 17
r = nearest(ff, [12, 13, 15], 17, 15, 0.3); ok.append(("g30 flat_f blue chair nearest stove", *r))
r = [i for i, o in ff.items() if o["label"] == "lamp" and on(o, ff[38])]; ok.append(("g31 flat_f lamp on desk 38", r == [40], r))
r = [i for i, o in fh.items() if o["label"] == "nightstand" and on(fh[49], o)]; ok.append(("g37 flat_h nightstand under book 49", r == [47], r))
r = nearest(slr, [17, 18], 22, 18, 0.5); ok.append(("g39 scan_lr plant nearest door", *r))
r = nearest(slr, [20, 21], 22, 21, 0.5); ok.append(("g40 scan_lr window next to door", *r))
p = sorted((slr[i]["center"][0], i) for i in (2, 3, 4)); ok.append(("g41 scan_lr middle pillow on sofa", p[1][1] == 3 and all(abs(slr[i]["center"][0]-slr[1]["center"][0]) <= slr[1]["size"][0]/2 and abs(slr[i]["center"][1]-slr[1]["center"][1]) <= slr[1]["size"][1]/2 for i in (2,3,4)), p))
r = nearest(sbr, [8, 9], 14, 8, 0.5); ok.append(("g43 scan_bed lamp nearest window", *r))
bed = sbr[1]; foot = bed["center"][1] - bed["size"][1] / 2
r = sorted((round(sbr[i]["center"][1] - foot, 2), i) for i in (2, 3, 4, 5)); ok.append(("g44 scan_bed pillow nearest foot of bed", r[0][1] == 5 and r[1][0] - r[0][0] >= 0.5, r))
z = {i: apt[i]["center"][2] for i in (12, 13)}; ok.append(("g47 apt lower book on shelf 11", min(z, key=z.get) == 13 and abs(z[12]-z[13]) >= 0.3, z))
bad = 0
for name, good, info in ok:
    print("OK " if good else "BAD", name, info); bad += not good
print(len(ok), "checks,", bad, "bad")
