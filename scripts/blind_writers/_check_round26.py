"""Checks round26: o/or accept sets equal every instance of the kind (in the room), and every
spatial (s) group's claim holds numerically from centres and sizes with a margin."""
import json, math
from pathlib import Path

B = Path(__file__).resolve().parents[2] / "evals/blind"
rows = [json.loads(l) for l in (B / "round26.jsonl").read_text().splitlines()]
groups = {}
for r in rows:
    groups.setdefault(r["group"], r)

def load(m):
    d = json.loads((B / m).resolve().read_text())
    if "objects" in d:
        return {o["id"]: o for o in d["objects"]}, True
    out = {}
    for k, v in d.items():
        room = v.get("room_cat")
        try:
            room = json.loads(v["caption"]).get("room_cat", room)
        except Exception:
            pass
        out[int(k)] = {"label": v["category"], "room": room}
    return out, False

fails = 0
def ok(cond, msg):
    global fails
    print(("OK  " if cond else "FAIL"), msg)
    fails += not cond

# o / or: accept == all of the kind (in the room)
ROOMS = {"b26-g08": "bathroom", "b26-g09": "bedroom", "b26-g10": "bedroom", "b26-g11": "dining room",
         "b26-g12": "living room", "b26-g13": "living room", "b26-g14": "rec room"}
for g, r in groups.items():
    objs, _ = load(r["map"])
    lab = objs[r["target"]]["label"]
    if r["type"] == "o":
        ok(sorted(i for i, o in objs.items() if o["label"] == lab) == r["accept"], f"{g} o all '{lab}'")
    if r["type"] == "or":
        room = ROOMS[g]
        want = sorted(i for i, o in objs.items() if o["label"] == lab and o["room"] == room)
        ok(want == r["accept"], f"{g} or all '{lab}' in {room}: {want}")
    if r["type"] in ("od", "ord", "ard", "s"):
        ok(r["accept"] == [r["target"]], f"{g} single target")

M = 0.2  # margin in metres
def obj(m, i): return load(m)[0][i]
def c(m, i): return obj(m, i)["center"]
def d2(m, a, b):
    p, q = c(m, a), c(m, b); return math.hypot(p[0] - q[0], p[1] - q[1])
def dpt(m, a, pt):
    p = c(m, a); return math.hypot(p[0] - pt[0], p[1] - pt[1])
def on_top(m, top, base):
    t, b = obj(m, top), obj(m, base)
    inside = all(abs(t["center"][k] - b["center"][k]) <= b["size"][k] / 2 for k in (0, 1))
    gap = (t["center"][2] - t["size"][2] / 2) - (b["center"][2] + b["size"][2] / 2)
    return inside and abs(gap) < 0.08

SB, SK, SO = "../maps/scan_bedroom.json", "../maps/scan_kitchen.json", "../maps/scan_office.json"
FE, FC, FI, FB = "maps/flat_e.json", "maps/flat_c.json", "maps/flat_i.json", "maps/flat_b.json"
# g37 lamp nearest window; facing north from bed foot, left = smaller x; lamp 9 nearer door
ok(d2(SB, 8, 14) + M < d2(SB, 9, 14), f"g37 lamp8 {d2(SB,8,14):.2f} vs lamp9 {d2(SB,9,14):.2f} to window")
ok(c(SB, 8)[0] + M < c(SB, 9)[0] and d2(SB, 9, 15) + M < d2(SB, 8, 15), "g37 left when facing north; 9 by door")
ok(c(SB, 1)[1] < c(SB, 6)[1], "g37 headboard is north (nightstands north of bed centre)")
# g38 nightstand 6 holds clock 21; 7 holds book 20; 6 nearer window
ok(on_top(SB, 21, 6) and not on_top(SB, 21, 7) and on_top(SB, 20, 7), "g38 clock on 6, book on 7")
ok(d2(SB, 6, 14) + M < d2(SB, 7, 14), "g38 6 nearer window")
# g39 cabinet under sink: sink sits on cabinet 3 only among lower cabinets
lower = [1, 2, 3, 4, 5, 6]
ok([i for i in lower if on_top(SK, 10, i)] == [3], f"g39 sink on {[i for i in lower if on_top(SK,10,i)]}")
# g40 cup 25 between coffee maker 12 and sink 10, on counter; 23, 24 on table 16
x = c(SK, 25)[0]
ok(c(SK, 12)[0] + 0.1 < x < c(SK, 10)[0] - 0.1 and abs(c(SK, 25)[1] - c(SK, 12)[1]) < 0.2, "g40 cup 25 between")
ok(on_top(SK, 23, 16) and on_top(SK, 24, 16) and not on_top(SK, 25, 16), "g40 other cups on table")
ok(c(SK, 25)[2] > 0.9, "g40 cup 25 at counter height")
# g41 black chairs at wooden table 2: those within 1.2 m of table 2 centre
near2 = [i for i in range(3, 11) if d2(SO, i, 2) < 1.3]
black = [i for i in near2 if obj(SO, i)["tags"]["color"] == "black"]
win = min(black, key=lambda i: min(dpt(SO, i, c(SO, 18)), dpt(SO, i, c(SO, 19))))
oth = [i for i in black if i != win]
ok(win == 8 and all(min(dpt(SO, j, c(SO, 18)), dpt(SO, j, c(SO, 19))) > min(dpt(SO, 8, c(SO, 18)), dpt(SO, 8, c(SO, 19))) + M for j in oth),
   f"g41 black chairs at table 2 {black}, nearest window {win}")
ok(obj(SO, 2)["tags"].get("material") == "wood" and d2(SO, 8, 7) < 1.05, "g41 table 2 wood; blue 7 beside 8")
ok(d2(SO, 9, 14) < d2(SO, 8, 14) and d2(SO, 9, 15) < d2(SO, 8, 15), "g41 chair 9 is the one by the bookshelves")
# g42 tallest / biggest bookshelf, in the middle
h = {i: obj(SO, i)["size"][2] for i in (14, 15, 16)}
vol = {i: math.prod(obj(SO, i)["size"]) for i in (14, 15, 16)}
ok(max(h, key=h.get) == 15 and sorted(h.values())[-1] - sorted(h.values())[-2] >= 0.15, f"g42 heights {h}")
ok(max(vol, key=vol.get) == 15 and sorted(c(SO, i)[0] for i in (14, 15, 16))[1] == c(SO, 15)[0], "g42 biggest, middle")
# g43 book 12 higher than 13 on the same bookshelf 11
ok(c(APT := "apartment", 12)[2] - c(APT, 13)[2] > M and d2(APT, 12, 11) < 0.5 and d2(APT, 13, 11) < 0.5, "g43 12 above 13 on shelf 11")
# g44 plant 39 on dresser 38; plant 8 in living room
ok(on_top(APT, 39, 38), "g44 plant 39 on dresser")
# g45 flat_e: green chair nearest black chair 14, same side (same y); from the living room (west) looking east, left = north
greens = [11, 12, 13]
ds = {i: d2(FE, i, 14) for i in greens}
ok(min(ds, key=ds.get) == 13 and sorted(ds.values())[1] - ds[13] > M, f"g45 distances to 14 {ds}")
ok(abs(c(FE, 13)[1] - c(FE, 14)[1]) < 0.05 and [i for i in greens if c(FE, i)[1] > c(FE, 10)[1] + M] == [13], "g45 only green on north side")
# g46 flat_c white chair nearest stove 14, and west side of table
ds = {i: d2(FC, i, 14) for i in (19, 20)}
ok(ds[19] + M < ds[20] and c(FC, 19)[0] + M < c(FC, 18)[0] < c(FC, 20)[0], f"g46 {ds}")
# g47 flat_i red chair nearest tv 10, east side of table 5
ds = {i: d2(FI, i, 10) for i in (6, 7)}
ok(ds[7] + M < ds[6] and c(FI, 7)[0] > c(FI, 5)[0] + M, f"g47 {ds}")
# g48 flat_b nightstand nearest window 36, left facing north (headboard north), holds fabric lamp 33
ds = {i: d2(FB, i, 36) for i in (31, 32)}
ok(ds[31] + M < ds[32] and c(FB, 31)[0] < c(FB, 32)[0] and on_top(FB, 33, 31) and on_top(FB, 34, 32), f"g48 {ds}")
ok(c(FB, 31)[1] > c(FB, 30)[1], "g48 headboard north")
print("failures:", fails)
