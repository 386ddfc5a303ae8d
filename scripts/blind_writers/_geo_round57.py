import json
import math
from pathlib import Path
B = str(Path(__file__).resolve().parents[2]) + "/"
def load(p):
    return {o["id"]: o for o in json.load(open(p))["objects"]}
def d2(a, b):
    return math.dist(a["center"][:2], b["center"][:2])
def gap(a, b):
    g = []
    for i in range(2):
        lo = abs(a["center"][i]-b["center"][i]) - (a["size"][i]+b["size"][i])/2
        g.append(max(0, lo))
    return math.hypot(*g)
def rank(objs, ref, labels, room=None):
    rows = []
    for o in objs.values():
        if o["label"] in labels and o["id"] != ref["id"] and (room is None or o["room"] == room):
            rows.append((round(d2(o, ref), 3), round(gap(o, ref), 3), o["id"], o["label"], o["room"]))
    return sorted(rows)
M = B + "evals/blind/maps/"
c = load(M+"flat_c.json")
d = load(M+"flat_d.json")
f = load(M+"flat_f.json")
h = load(M+"flat_h.json")
a = load(B + "map_store/apartment.json")
sb = load(B + "evals/maps/scan_bedroom.json")
sk = load(B + "evals/maps/scan_kitchen.json")
sl = load(B + "evals/maps/scan_livingroom.json")
so = load(B + "evals/maps/scan_office.json")
print("c clock->nightstands", rank(c, c[29], {"nightstand"}))
print("d bookcase->chairs", rank(d, d[12], {"chair"}))
print("f sink36->cabinets", rank(f, f[36], {"cabinet"}))
print("h kettle->mugs", rank(h, h[25], {"mug"}))
print("h lamp48->nightstands", rank(h, h[48], {"nightstand"}))
print("a sofa1->pictures", rank(a, a[1], {"picture"}))
print("a dresser->plants", rank(a, a[38], {"plant"}))
print("a fridge->chairs", rank(a, a[16], {"chair", "armchair"}))
print("sb pillows", [(o["id"], o["center"]) for o in sb.values() if o["label"]=="pillow"], sb[1])
print("sk sink->kcab", rank(sk, sk[10], {"kitchen cabinet"}))
print("sl sofa->lamps", rank(sl, sl[1], {"lamp"}))
print("so shelves", [(o["id"], o["size"][2]) for o in so.values() if o["label"]=="bookshelf"])
