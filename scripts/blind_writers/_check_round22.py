"""Numeric checks for round22: spatial groups from centres/sizes with margins, o/or accept completeness,
no map label in ard wordings, typo tally."""
import json, math, re
from pathlib import Path
B = Path(__file__).parent / "evals/blind"
def load(m):
    d = json.loads((B / m).resolve().read_text())
    if "objects" in d:
        return {o["id"]: o for o in d["objects"]}
    out = {}
    for k, v in d.items():
        c = v["caption"]
        try: room = json.loads(c).get("room_cat")
        except Exception:
            mm = re.search(r'"room_cat":\s*"([^"]*)"', c); room = mm.group(1) if mm else None
        out[int(k)] = {"label": v["category"], "room": room}
    return out
def d2(a, b): return math.dist(a["center"][:2], b["center"][:2])
def on_top(top, base, tol=0.03):
    (tx, ty, tz), (ts) = top["center"], top["size"]
    (bx, by, bz), bs = base["center"], base["size"]
    inside = abs(tx - bx) <= bs[0] / 2 and abs(ty - by) <= bs[1] / 2
    return inside and abs((tz - ts[2] / 2) - (bz + bs[2] / 2)) <= tol
ok = True
def req(cond, msg):
    global ok
    print(("OK  " if cond else "FAIL"), msg); ok &= bool(cond)
M = {k: load(v) for k, v in {"fc": "maps/flat_c.json", "fe": "maps/flat_e.json", "fg": "maps/flat_g.json",
     "fh": "maps/flat_h.json", "sb": "../maps/scan_bedroom.json", "sk": "../maps/scan_kitchen.json", "ap": "apartment"}.items()}
fc, fe, fg, fh, sb, sk, ap = (M[k] for k in ["fc", "fe", "fg", "fh", "sb", "sk", "ap"])
# g37 lamp 7 on side table 6; no other lamp on a side table
req(on_top(fc[7], fc[6]) and not any(on_top(fc[i], fc[6]) for i in (5, 28, 36)), "flat_c lamp 7 on side table 6 only")
# g38 nightstand 27 under alarm clock 29, not 26
req(on_top(fc[29], fc[27]) and not on_top(fc[29], fc[26]), "flat_c clock 29 on nightstand 27")
# g39 lamp 16 over table 10, z above top; others not over
t = fe[10]
over = lambda o: abs(o["center"][0]-t["center"][0]) <= t["size"][0]/2 and abs(o["center"][1]-t["center"][1]) <= t["size"][1]/2 and o["center"][2]-o["size"][2]/2 > t["center"][2]+t["size"][2]/2 + 0.5
req(over(fe[16]) and not over(fe[4]) and not over(fe[26]), "flat_e lamp 16 hangs over table 10")
# g40 bed 31: headboard side = side with nightstands (y larger); facing +y, right = +x
b = fg[31]
req(fg[32]["center"][1] > b["center"][1] and fg[33]["center"][0] - b["center"][0] > 0.5 and b["center"][0] - fg[32]["center"][0] > 0.5, "flat_g nightstand 33 right when facing headboard (+y)")
# g41 mug 26 nearest kettle 25, margin
ds = {i: d2(fh[i], fh[25]) for i in (13, 26, 32)}; s = sorted(ds.values())
req(min(ds, key=ds.get) == 26 and s[1] - s[0] > 0.5 and s[0] < 0.6, f"flat_h mug next to kettle {ds}")
# g42 black chairs 16,17: nearer window 20
ds = {i: d2(fh[i], fh[20]) for i in (16, 17)}
req(min(ds, key=ds.get) == 17 and abs(ds[16]-ds[17]) > 0.5 and all(fh[i]["tags"]["color"] == "black" for i in (16, 17)) and fh[18]["tags"]["color"] != "black", f"flat_h chair nearer window {ds}")
# g43 pillow 5 at foot: headboard at nightstand side (y larger)
bed = sb[1]; foot_y = bed["center"][1] - bed["size"][1]/2
ys = {i: sb[i]["center"][1] for i in (2, 3, 4, 5)}
req(sb[6]["center"][1] > bed["center"][1] and min(ys, key=ys.get) == 5 and sorted(ys.values())[1] - ys[5] > 0.5 and ys[5] - foot_y < 0.5, f"scan_bedroom pillow at foot {ys}")
# g44 lamp 8 nearest window 14, lamp 9 nearest door 15
dw = {i: d2(sb[i], sb[14]) for i in (8, 9)}; dd = {i: d2(sb[i], sb[15]) for i in (8, 9)}
req(min(dw, key=dw.get) == 8 and abs(dw[8]-dw[9]) > 0.5 and min(dd, key=dd.get) == 9, f"scan_bedroom lamp near window {dw} door {dd}")
# g45 cabinet 3 directly under sink 10 (lower cabinets 1-6)
under = [i for i in range(1, 7) if on_top(sk[10], sk[i])]
req(under == [3], f"scan_kitchen cabinet under sink {under}")
# g46 chair 21 nearest door 15
ds = {i: d2(sk[i], sk[15]) for i in range(17, 23)}; s = sorted(ds.values())
req(min(ds, key=ds.get) == 21 and s[1]-s[0] > 0.5 and sk[21]["tags"]["color"] == "red", f"scan_kitchen chair near door {ds}")
# g47 book 12 higher than 13, both on bookshelf 11 footprint
inb = lambda o, s: abs(o["center"][0]-s["center"][0]) <= s["size"][0]/2 and abs(o["center"][1]-s["center"][1]) <= s["size"][1]/2
req(inb(ap[12], ap[11]) and inb(ap[13], ap[11]) and ap[12]["center"][2] - ap[13]["center"][2] > 0.3, "apartment book 12 above 13 on shelf 11")
# g48 plant 39 on dresser 38, no other plant on it
req(on_top(ap[39], ap[38]) and not any(on_top(ap[i], ap[38]) for i in (8, 55)), "apartment plant 39 on dresser 38")
# o/or completeness and label rules
rows = [json.loads(l) for l in (B / "round22.jsonl").read_text().splitlines()]
groups = {}
for r in rows: groups.setdefault(r["group"], []).append(r)
maps = {}
typos = []
for g, rs in groups.items():
    r = rs[0]; m = maps.setdefault(r["map"], load(r["map"]))
    lab = m[r["target"]]["label"]
    if r["type"] == "o":
        req(sorted(r["accept"]) == sorted(i for i, o in m.items() if o["label"] == lab), f"{g} o accept = all {lab}")
    if r["type"] == "or":
        room = m[r["target"]]["room"]
        req(sorted(r["accept"]) == sorted(i for i, o in m.items() if o["label"] == lab and o["room"] == room), f"{g} or accept = all {lab} in {room}")
    if r["type"] == "ard":
        labs = {m[a]["label"].lower() for a in r["accept"]}
        req(not any(re.search(r"\b" + re.escape(l) + r"(s|es)?\b", x["query"].lower()) for x in rs for l in labs), f"{g} ard names no label")
print("ALL OK" if ok else "SOME FAILED")
