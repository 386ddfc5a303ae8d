"""Re-derive o/or accept sets from the maps and check every s claim numerically (margin >= 0.2 m)."""
import json, math, re, sys
from pathlib import Path
from collections import defaultdict

ROOT = Path(__file__).resolve().parents[1]
SUITE = ROOT / "evals/blind/round27.jsonl"
rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
groups = defaultdict(list)
for r in rows:
    groups[r["group"]].append(r)

def load(m):
    d = json.loads((SUITE.parent / m).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        rooms = d["rooms"]
        def room_of(o):
            x, y = o["center"][:2]
            hits = [r["label"] for r in rooms
                    if min(p[0] for p in r["polygon"]) <= x <= max(p[0] for p in r["polygon"])
                    and min(p[1] for p in r["polygon"]) <= y <= max(p[1] for p in r["polygon"])]
            return hits
        return {o["id"]: {"label": o["label"], "rooms": room_of(o), "roomfield": o.get("room"),
                          "c": o["center"], "s": o["size"], "caption": o.get("caption", "")} for o in d["objects"]}
    out = {}
    for k, v in d.items():
        try:
            cap = json.loads(v["caption"]).get("captions", "")
        except Exception:
            m2 = re.search(r'"captions":\s*"(.*?)"', v["caption"], re.S); cap = m2.group(1) if m2 else ""
        out[int(k)] = {"label": v["category"], "rooms": [v["room_cat"]] if v["room_cat"] else [], "caption": cap}
    return out

# expected room for or groups (by group number)
OR_ROOM = {"b27-g02": "bedroom", "b27-g03": "living room", "b27-g10": "rec room", "b27-g19": "kitchen",
           "b27-g33": "living room", "b27-g38": "kitchen", "b27-g47": "bedroom"}
problems = []
maps = {}
for g, rs in groups.items():
    r = rs[0]
    M = maps.setdefault(r["map"], load(r["map"]))
    lab = M[r["target"]]["label"]
    if r["type"] == "o":
        exp = sorted(i for i, o in M.items() if o["label"] == lab)
        if exp != sorted(r["accept"]): problems.append(f"{g} o: accept {r['accept']} != {exp}")
        else: print(f"{g} o   '{lab}': {exp} OK")
    elif r["type"] == "or":
        room = OR_ROOM[g]
        exp = sorted(i for i, o in M.items() if o["label"] == lab and room in o["rooms"])
        if "roomfield" in M[r["target"]]:
            exp2 = sorted(i for i, o in M.items() if o["label"] == lab and o["roomfield"] == room)
            if exp2 != exp: problems.append(f"{g} or: polygon {exp} vs room field {exp2}")
        if exp != sorted(r["accept"]): problems.append(f"{g} or: accept {r['accept']} != {exp}")
        else: print(f"{g} or  '{lab}' in {room}: {exp} OK")
    else:
        if len(r["accept"]) != 1: problems.append(f"{g}: single-id type with {r['accept']}")

def C(m, i): return maps[m][i]["c"]
def S(m, i): return maps[m][i]["s"]
def d2(m, a, b):
    ca, cb = C(m, a), C(m, b); return math.hypot(ca[0]-cb[0], ca[1]-cb[1])
def gap(m, a, b):
    """horizontal box-to-box gap (0 when touching/overlapping)."""
    ca, sa, cb, sb = C(m, a), S(m, a), C(m, b), S(m, b)
    gx = max(0, abs(ca[0]-cb[0]) - (sa[0]+sb[0])/2); gy = max(0, abs(ca[1]-cb[1]) - (sa[1]+sb[1])/2)
    return math.hypot(gx, gy)
def same_label(m, i): return [j for j, o in maps[m].items() if o["label"] == maps[m][i]["label"]]

def nearest(g, m, target, cands, ref, fn=d2, what="nearest"):
    ds = {c: fn(m, c, ref) for c in cands}
    best = min(ds, key=ds.get); second = sorted(ds.values())[1]
    ok = best == target and second - ds[target] >= 0.2
    print(f"{g} s   {what} to {ref} ({maps[m][ref]['label']}): " + ", ".join(f"{c}:{v:.2f}" for c, v in sorted(ds.items(), key=lambda kv: kv[1])) + (" OK" if ok else " FAIL"))
    if not ok: problems.append(f"{g}: {what} to {ref} fails")
def farthest(g, m, target, cands, ref):
    ds = {c: d2(m, c, ref) for c in cands}
    best = max(ds, key=ds.get); second = sorted(ds.values())[-2]
    ok = best == target and ds[target] - second >= 0.2
    print(f"{g} s   farthest from {ref}: {ds} " + ("OK" if ok else "FAIL"))
    if not ok: problems.append(f"{g}: farthest from {ref} fails")
def extreme(g, m, target, cands, axis, sign, what):
    vals = {c: sign*C(m, c)[axis] for c in cands}
    best = max(vals, key=vals.get); second = sorted(vals.values())[-2]
    ok = best == target and vals[target] - second >= 0.2
    print(f"{g} s   {what}: {vals} " + ("OK" if ok else "FAIL"))
    if not ok: problems.append(f"{g}: {what} fails")
def on_top(g, m, top, base, others):
    ct, st, cb, sb = C(m, top), S(m, top), C(m, base), S(m, base)
    inside = abs(ct[0]-cb[0]) <= sb[0]/2 and abs(ct[1]-cb[1]) <= sb[1]/2
    rest = abs((ct[2]-st[2]/2) - (cb[2]+sb[2]/2)) <= 0.05
    oth = [o for o in others if o != top and abs(C(m, o)[0]-cb[0]) <= sb[0]/2 and abs(C(m, o)[1]-cb[1]) <= sb[1]/2]
    ok = inside and rest and not oth
    print(f"{g} s   {top} on {base}: inside={inside} resting={rest} other same-kind over it={oth} " + ("OK" if ok else "FAIL"))
    if not ok: problems.append(f"{g}: on-top check fails")
def under(g, m, low, top, cands):
    """`top` sits over exactly `low` among cands: x-y overlap and low's top at top's bottom."""
    ct, st = C(m, top), S(m, top)
    ov = []
    for c in cands:
        cc, sc = C(m, c), S(m, c)
        ox = min(ct[0]+st[0]/2, cc[0]+sc[0]/2) - max(ct[0]-st[0]/2, cc[0]-sc[0]/2)
        oy = min(ct[1]+st[1]/2, cc[1]+sc[1]/2) - max(ct[1]-st[1]/2, cc[1]-sc[1]/2)
        below = cc[2]+sc[2]/2 <= ct[2]-st[2]/2 + 0.02
        if ox > 0.05 and oy > 0.05 and below: ov.append((c, round(ox, 2)))
    ok = [c for c, _ in ov] == [low]
    print(f"{g} s   under {top}: {ov} " + ("OK" if ok else "FAIL"))
    if not ok: problems.append(f"{g}: under check fails")

FD, FF, FG, FH = "maps/flat_d.json", "maps/flat_f.json", "maps/flat_g.json", "maps/flat_h.json"
APT, SK, SO, SL, SB = "apartment", "../maps/scan_kitchen.json", "../maps/scan_office.json", "../maps/scan_livingroom.json", "../maps/scan_bedroom.json"
for m in (FD, FF, FG, FH, APT, SK, SO, SL, SB): maps.setdefault(m, load(m))
# g17 flat_d chair 5: of the round-table chairs (4,5): east, farther from bookcase 12, nearer plant 14
extreme("b27-g17", FD, 5, [4, 5], 0, 1, "east-most round-table chair")
farthest("b27-g17", FD, 5, [4, 5], 12)
nearest("b27-g17", FD, 5, [4, 5], 14)
print("   round-table chairs within 1 m of table 3:", [c for c in same_label(FD, 5) if gap(FD, c, 3) < 0.3])
# g18 flat_d lamp 8 next to sofa bed 1, in corner
nearest("b27-g18", FD, 8, same_label(FD, 8), 1, gap, "gap")
nearest("b27-g18", FD, 9, [9, 8, 34], 6, gap, "(contrast: desk lamp) gap")
# g21 flat_f chair 13: of table chairs (12-15), nearest dresser 16; south-east of table 11; farther from stove 17 than 14
nearest("b27-g21", FF, 13, [12, 13, 14, 15], 16)
t = C(FF, 11); print("   SE of table:", [c for c in [12, 13, 14, 15] if C(FF, c)[0] > t[0] and C(FF, c)[1] < t[1]])
# g22 flat_f armchair 2 next to fireplace 4; other one near floor lamp 6
nearest("b27-g22", FF, 2, same_label(FF, 2), 4, gap, "gap")
nearest("b27-g22", FF, 3, same_label(FF, 2), 6, d2, "(contrast) nearest")
# g23 flat_g nightstand 32: nearer wardrobe 36; west of bed 31; the other nearer hamper 37
nearest("b27-g23", FG, 32, same_label(FG, 32), 36)
extreme("b27-g23", FG, 32, same_label(FG, 32), 0, -1, "west-most nightstand")
nearest("b27-g23", FG, 33, same_label(FG, 32), 37, d2, "(contrast) nearest")
# g24 flat_g bicycle 2: nearer workbench 4, east, other nearer west wall
nearest("b27-g24", FG, 2, same_label(FG, 2), 4)
extreme("b27-g24", FG, 2, same_label(FG, 2), 0, 1, "east-most bike")
# g30 flat_h chair 17: among dining chairs 16-18 nearest window 20; south side east end
nearest("b27-g30", FH, 17, [16, 17, 18], 20)
print("   all chairs in flat_h near window:", {c: round(d2(FH, c, 20), 2) for c in same_label(FH, 17)})
t = C(FH, 15); print("   south of table & east:", [c for c in [16, 17, 18] if C(FH, c)[1] < t[1] and C(FH, c)[0] > t[0]])
# g37 apartment plant 39 on dresser 38
on_top("b27-g37", APT, 39, 38, same_label(APT, 39))
# g39 scan_kitchen cabinet 3 under sink 10
under("b27-g39", SK, 3, 10, same_label(SK, 3))
# g43 scan_office chair 10 nearest door 20; north side & east end of table 2
nearest("b27-g43", SO, 10, same_label(SO, 10), 20)
t = C(SO, 2); print("   north+east of table 2:", [c for c in same_label(SO, 10) if C(SO, c)[1] > t[1] and t[0] < C(SO, c)[0] < t[0]+1.2])
# g46 scan_livingroom pillow 4: nearest brown armchair 6, east-most (right when sitting facing TV 14 to the north), nearest side table 9
nearest("b27-g46", SL, 4, same_label(SL, 4), 6)
extreme("b27-g46", SL, 4, same_label(SL, 4), 0, 1, "east-most pillow")
nearest("b27-g46", SL, 4, same_label(SL, 4), 9)
print("   TV north of sofa:", C(SL, 14)[1] > C(SL, 1)[1])
# g48 scan_bedroom lamp 9: nearest door 15, other nearest window 14, east of bed centre
nearest("b27-g48", SB, 9, same_label(SB, 9), 15)
nearest("b27-g48", SB, 8, same_label(SB, 9), 14, d2, "(contrast) nearest")
print("   lamp 9 on nightstand 7:", C(SB, 9)[:2] == C(SB, 7)[:2], "east of bed:", C(SB, 9)[0] > C(SB, 1)[0])

# wording checks: label uses, verbatim caption copying (6+ consecutive caption words), ard naming its label
for g, rs in groups.items():
    M = maps[rs[0]["map"]]
    lab = M[rs[0]["target"]]["label"].lower()
    uses = [r["id"] for r in rs if re.search(r"\b" + re.escape(lab) + r"(s|es)?\b", r["query"].lower())]
    if rs[0]["type"] == "ard" and uses: problems.append(f"{g}: ard names its label in {uses}")
    for r in rs:
        q = re.findall(r"[a-z']+", r["query"].lower())
        for i in set(r["accept"]) | {r["target"]}:
            cw = re.findall(r"[a-z']+", M[i]["caption"].lower())
            grams = {tuple(cw[k:k+6]) for k in range(len(cw)-5)}
            if any(tuple(q[k:k+6]) in grams for k in range(len(q)-5)):
                problems.append(f"{r['id']}: copies 6+ caption words")
print("\nPROBLEMS:" if problems else "\nno problems")
for p in problems: print(" ", p)
sys.exit(1 if problems else 0)
