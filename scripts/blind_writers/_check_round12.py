"""Numeric checks of round 12: every s group from centres/sizes with margins, and that every o/or accept
set holds exactly the instances of the kind (in the room) on the map. Reads only the suite and its maps."""
import json, math, re
from pathlib import Path

SUITE = Path(__file__).parent / "evals" / "blind" / "round12.jsonl"
rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
groups = {}
for r in rows:
    groups.setdefault(r["group"], r)

def load(mp):
    d = json.loads((SUITE.parent / mp).resolve().read_text())
    if "objects" in d:
        return {int(o["id"]): o for o in d["objects"]}
    return {int(k): {"label": v["category"], "room": v.get("room_cat")} for k, v in d.items()}

def bot(o): return o["center"][2] - o["size"][2] / 2
def top(o): return o["center"][2] + o["size"][2] / 2
def xy_inside(a, b):  # centre of a within footprint of b
    return all(abs(a["center"][i] - b["center"][i]) <= b["size"][i] / 2 for i in (0, 1))
def d2(a, b): return math.dist(a["center"][:2], b["center"][:2])

def on(o, base, tol=0.03): return xy_inside(o, base) and abs(bot(o) - top(base)) <= tol
fails = 0
def ok(cond, msg):
    global fails
    print(("OK  " if cond else "FAIL"), msg)
    fails += not cond

def spatial(g, M, t):
    if g == "b12-g16":   # flat_b lamp on side table 6
        hits = [i for i, o in M.items() if o["label"] == "lamp" and on(o, M[6])]
        ok(hits == [t], f"{g} lamps on side table 6: {hits}")
    elif g == "b12-g17":  # flat_b kitchen chair farthest from stove 15
        ds = sorted(((d2(o, M[15]), i) for i, o in M.items() if o["label"] == "chair" and o["room"] == "kitchen"), reverse=True)
        ok(ds[0][1] == t and ds[0][0] - ds[1][0] > 0.3, f"{g} farthest from stove {[(round(d,2),i) for d,i in ds]}")
    elif g == "b12-g21":  # flat_c nightstand under alarm clock 29; left when lying in bed (head north -> left = east)
        hits = [i for i, o in M.items() if o["label"] == "nightstand" and on(M[29], o)]
        east = max((o["center"][0], i) for i, o in M.items() if o["label"] == "nightstand")[1]
        ok(hits == [t] and east == t and M[25]["center"][1] < M[t]["center"][1], f"{g} clock on {hits}, east stand {east}")
    elif g == "b12-g26":  # flat_d stool nearer the hob 18 (and farther from fridge 15)
        ds = sorted((d2(o, M[18]), i) for i, o in M.items() if o["label"] == "stool")
        fr = sorted((d2(o, M[15]), i) for i, o in M.items() if o["label"] == "stool")
        ok(ds[0][1] == t and ds[1][0] - ds[0][0] > 0.3 and fr[-1][1] == t, f"{g} stools to hob {[(round(d,2),i) for d,i in ds]}, to fridge {[(round(d,2),i) for d,i in fr]}")
    elif g == "b12-g31":  # flat_e green chair on north side, next to black chair 14
        greens = {i: o for i, o in M.items() if o["label"] == "chair" and o["room"] == "dining room" and "green" in o["tags"]["color"]}
        north = [i for i, o in greens.items() if o["center"][1] > M[10]["center"][1] + 0.3]
        near = min((d2(o, M[14]), i) for i, o in greens.items())
        ok(north == [t] and near[1] == t, f"{g} north greens {north}, nearest to black {near}")
    elif g == "b12-g35":  # flat_g mirror above sink 40
        hits = [i for i, o in M.items() if o["label"] == "mirror" and abs(o["center"][0] - M[40]["center"][0]) < 0.3
                and abs(o["center"][1] - M[40]["center"][1]) < 0.5 and bot(o) > top(M[40])]
        ok(hits == [t], f"{g} mirrors above sink {hits}")
    elif g == "b12-g38":  # scan_kitchen cabinet under sink 10
        hits = [i for i, o in M.items() if o["label"] == "kitchen cabinet" and xy_inside(M[10], o) and top(o) <= bot(M[10]) + 0.03]
        ok(hits == [t], f"{g} cabinets under sink {hits}")
    elif g == "b12-g48":  # apartment: higher of the books on living-room bookshelf 11
        bs = sorted(((o["center"][2], i) for i, o in M.items() if o["label"] == "book" and xy_inside(o, M[11])), reverse=True)
        ok(len(bs) == 2 and bs[0][1] == t and bs[0][0] - bs[1][0] > 0.3, f"{g} books on shelf 11 by height {bs}")
    else:
        ok(False, f"{g} has no spatial check")

for g, r in sorted(groups.items()):
    M = load(r["map"])
    t = r["target"]
    if r["type"] == "s":
        spatial(g, M, t)
    elif r["type"] in ("o", "or"):
        lab = M[t]["label"]; room = M[t]["room"]
        kinds = {"set of towels", "hand towel"} if g == "b12-g01" else {lab}  # any towel counts as a towel
        want = sorted(i for i, o in M.items() if o["label"] in kinds and (r["type"] == "o" or o["room"] == room))
        ok(want == sorted(r["accept"]), f"{g} {r['type']} {lab!r} {room if r['type']=='or' else ''}: map {want} vs accept {sorted(r['accept'])}")
print("failures:", fails)
