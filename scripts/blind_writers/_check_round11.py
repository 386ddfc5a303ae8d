"""Numeric checks for round11: spatial (s) groups from centres and sizes with margins, and
o / or accept sets recomputed from the map labels (and rooms).

    python3 /work/blind11/check_round11.py
"""
import json
import math
from collections import defaultdict
from pathlib import Path

BLIND = Path(__file__).resolve().parent / "evals" / "blind"
SUITE = BLIND / "round11.jsonl"


def objs(mp):
    d = json.loads((BLIND / mp).resolve().read_text())
    if "objects" in d:
        return {int(o["id"]): o for o in d["objects"]}
    return {int(k): {"label": v["category"], "room": v["room_cat"], "room_id": v["room_id"]} for k, v in d.items()}


def c(o):
    return o["center"]


def d2(a, b):  # horizontal distance between centres
    return math.hypot(c(a)[0] - c(b)[0], c(a)[1] - c(b)[1])


def dbox(a, b):  # horizontal gap between footprints (0 if overlapping)
    gx = max(0.0, abs(c(a)[0] - c(b)[0]) - (a["size"][0] + b["size"][0]) / 2)
    gy = max(0.0, abs(c(a)[1] - c(b)[1]) - (a["size"][1] + b["size"][1]) / 2)
    return math.hypot(gx, gy)


def on(a, b, tol=0.05):
    inside = all(abs(c(a)[i] - c(b)[i]) <= b["size"][i] / 2 for i in (0, 1))
    bottom, top = c(a)[2] - a["size"][2] / 2, c(b)[2] + b["size"][2] / 2
    return inside and abs(bottom - top) <= tol


MARGIN = 0.3
results = []


def ok(name, cond, detail):
    results.append((name, bool(cond), detail))


def spatial():
    m = objs("apartment")  # g18: higher of the two books on the living room bookshelf
    ok("g18 book 12 and 13 both inside bookshelf 11 footprint",
       all(abs(c(m[b])[i] - c(m[11])[i]) <= m[11]["size"][i] / 2 for b in (12, 13) for i in (0, 1)), "")
    ok("g18 z(12) > z(13) + margin", c(m[12])[2] > c(m[13])[2] + MARGIN, (c(m[12])[2], c(m[13])[2]))
    ok("g18 only books 12,13 in living room", sorted(k for k, o in m.items() if o["label"] == "book" and o["room"] == "living room") == [12, 13], "")

    m = objs("../maps/scan_livingroom.json")  # g22: red pillow nearest green armchair
    reds = [k for k, o in m.items() if o["label"] == "pillow" and (o.get("tags") or {}).get("color") == "red"]
    ok("g22 red pillows are 2 and 4", sorted(reds) == [2, 4], reds)
    ok("g22 d(2,arm5)+margin < d(4,arm5)", d2(m[2], m[5]) + MARGIN < d2(m[4], m[5]), (d2(m[2], m[5]), d2(m[4], m[5])))
    ok("g22 pillow 2 west of 4 (left when sitting facing north / right when facing the sofa from the north)",
       c(m[2])[0] + MARGIN < c(m[4])[0], "")
    ok("g22 sofa faces north: tv north of sofa", c(m[14])[1] > c(m[1])[1] + 1, "")
    ok("g22 coffee table north of sofa", c(m[7])[1] > c(m[1])[1], "")
    ok("g22 pillow 4 nearer leather armchair 6", d2(m[4], m[6]) + MARGIN < d2(m[2], m[6]), "")

    m = objs("../maps/scan_office.json")  # g23: blue office chair nearest the windows
    blues = [k for k, o in m.items() if o["label"] == "office chair" and o["tags"]["color"] == "blue"]
    ok("g23 blue chairs are 7 and 10", sorted(blues) == [7, 10], blues)
    wins = [o for o in m.values() if o["label"] == "window"]
    dw = {k: min(d2(m[k], w) for w in wins) for k in blues}
    ok("g23 chair 7 nearer a window by margin", dw[7] + MARGIN < dw[10], dw)
    ok("g23 both blue chairs at wooden table 2", all(abs(c(m[k])[0] - c(m[2])[0]) < 1.0 for k in blues), "")
    ok("g23 chair 7 on window (south) side of table 2, 10 on far side",
       c(m[7])[1] < c(m[2])[1] < c(m[10])[1] and all(c(w)[1] < c(m[2])[1] for w in wins), "")

    m = objs("../maps/scan_kitchen.json")  # g24: cup by the sink
    cups = [k for k, o in m.items() if o["label"] == "cup"]
    ds = {k: d2(m[k], m[10]) for k in cups}
    ok("g24 cup 25 nearest sink by margin", all(ds[25] + MARGIN < ds[k] for k in cups if k != 25), ds)
    ok("g24 cup 25 on a counter cabinet", any(on(m[25], m[k]) for k, o in m.items() if o["label"] == "kitchen cabinet"), "")
    ok("g24 other cups on table 16", all(on(m[k], m[16]) for k in cups if k != 25), "")

    m = objs("../maps/scan_bedroom.json")  # g25: bedside lamp nearest window
    lamps = [k for k, o in m.items() if o["label"] == "lamp"]
    ok("g25 lamps 8,9", sorted(lamps) == [8, 9], lamps)
    ok("g25 d(8,window)+margin < d(9,window)", d2(m[8], m[14]) + MARGIN < d2(m[9], m[14]), (d2(m[8], m[14]), d2(m[9], m[14])))
    ok("g25 d(9,door)+margin < d(8,door)", d2(m[9], m[15]) + MARGIN < d2(m[8], m[15]), "")
    ok("g25 headboard north (pillows north of bed centre); lamp 8 west of bed = left facing headboard",
       c(m[2])[1] > c(m[1])[1] and c(m[8])[0] + MARGIN < c(m[1])[0] < c(m[9])[0] - MARGIN, "")
    ok("g25 lamp 8 on nightstand 6 which is nearer desk 11", on(m[8], m[6]) and d2(m[6], m[11]) + MARGIN < d2(m[7], m[11]), "")

    m = objs("maps/flat_h.json")  # g26: nightstand with the book
    ok("g26 book 49 on nightstand 47", on(m[49], m[47]), "")
    ok("g26 book 49 not on 46 / lamp 48 on 46", not on(m[49], m[46]) and on(m[48], m[46]), "")
    ok("g26 no other book on any nightstand", all(not on(o, m[n]) for o in m.values() if o["label"] == "book" and o["id"] != 49
                                                 for n in (42, 46, 47)), "")

    m = objs("maps/flat_d.json")  # g27: stool nearest bin
    ok("g27 d(21,bin)+margin < d(22,bin)", d2(m[21], m[23]) + MARGIN < d2(m[22], m[23]), (d2(m[21], m[23]), d2(m[22], m[23])))
    ok("g27 stool 22 nearer fridge", d2(m[22], m[15]) < d2(m[21], m[15]), (d2(m[22], m[15]), d2(m[21], m[15])))
    ok("g27 stool 21 on the studio (west) side", c(m[21])[0] + MARGIN < c(m[22])[0], "")

    m = objs("maps/flat_i.json")  # g28: monitor next to the green lamp
    ok("g28 d(16,lamp18)+margin < d(17,lamp18)", d2(m[16], m[18]) + MARGIN < d2(m[17], m[18]), (d2(m[16], m[18]), d2(m[17], m[18])))
    ok("g28 monitor 16 and lamp 18 on desk 12", on(m[16], m[12], 0.1) and on(m[18], m[12], 0.1), "")
    ok("g28 facing north, 16 is left (west) of 17", c(m[16])[0] + MARGIN < c(m[17])[0], "")


def kinds():
    groups = defaultdict(list)
    for line in SUITE.read_text().splitlines():
        r = json.loads(line)
        groups[r["group"]].append(r)
    # o / or: accept must equal every instance of the kind (in the room)
    room_of = {"b11-g02": "living room", "b11-g14": "living room", "b11-g32": "bedroom", "b11-g33": "kitchen",
               "b11-g34": "master bedroom", "b11-g35": "kitchen", "b11-g36": "meeting room", "b11-g37": "living room"}
    for g, rows in sorted(groups.items()):
        r = rows[0]
        if r["type"] not in ("o", "or"):
            continue
        m = objs(r["map"])
        lab = m[r["target"]]["label"]
        want = [k for k, o in m.items() if o["label"] == lab and (r["type"] == "o" or o["room"] == room_of[g])]
        ok(f"{g} {r['type']} accept = all '{lab}'" + (f" in {room_of.get(g)}" if r["type"] == "or" else ""),
           sorted(want) == sorted(r["accept"]), (sorted(want), sorted(r["accept"])))


if __name__ == "__main__":
    spatial()
    kinds()
    bad = 0
    for name, good, detail in results:
        print("OK  " if good else "FAIL", name, detail if not good or detail else "")
        bad += not good
    print(f"{len(results)} checks, {bad} failed")
    raise SystemExit(1 if bad else 0)
