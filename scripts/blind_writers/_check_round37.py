#!/usr/bin/env python3
"""Re-derive o/or accept sets, check od/ord uniqueness and every spatial claim numerically.
Reads emit.G (the hand-written groups) and the maps. Exit 1 on any failure."""
import json, math, os, sys
sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import emit

BASE = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "evals", "blind")
MARGIN = 0.2

def load(mp):
    p = os.path.join(BASE, mp)
    d = json.load(open(p))
    if "objects" in d:
        rooms = {r["id"]: r["label"] for r in d.get("rooms", [])}
        objs = {}
        for o in d["objects"]:
            room = o.get("room")
            if isinstance(room, int) or (isinstance(room, str) and room.isdigit()):
                room = rooms[int(room)]  # a room given by its id
            objs[o["id"]] = dict(label=o["label"], room=room, c=o["center"], s=o["size"], tags=o.get("tags", {}))
        return objs, True
    return {int(k): dict(label=v["category"], room=v["room_cat"], room_id=v["room_id"]) for k, v in d.items()}, False

def d2(a, b):
    return math.hypot(a["c"][0] - b["c"][0], a["c"][1] - b["c"][1])

def top(o): return o["c"][2] + o["s"][2] / 2
def bot(o): return o["c"][2] - o["s"][2] / 2
def xy_overlap(a, b):
    return all(abs(a["c"][i] - b["c"][i]) < (a["s"][i] + b["s"][i]) / 2 for i in (0, 1))

def claim(objs, cl):
    k = cl[0]
    if k == "on":
        a, b = objs[cl[1]], objs[cl[2]]
        ok = xy_overlap(a, b) and abs(bot(a) - top(b)) <= 0.05
        return ok, f"on {cl[1]} {cl[2]} gap={bot(a)-top(b):.3f}"
    if k in ("nearest", "farthest"):
        t, cands, ref = cl[1], cl[2], objs[cl[3]]
        ds = {c: d2(objs[c], ref) for c in cands}
        others = [ds[c] for c in cands if c != t]
        if k == "nearest":
            m = min(others) - ds[t]
        else:
            m = ds[t] - max(others)
        return m >= MARGIN, f"{k} {t} to {cl[3]} margin={m:.2f} {({c: round(v, 2) for c, v in ds.items()})}"
    if k == "higher":
        m = objs[cl[1]]["c"][2] - objs[cl[2]]["c"][2]
        return m >= MARGIN, f"higher {cl[1]}>{cl[2]} margin={m:.2f}"
    if k == "taller":
        m = top(objs[cl[1]]) - top(objs[cl[2]])
        return m >= MARGIN, f"taller top {cl[1]}>{cl[2]} margin={m:.2f}"
    if k == "lowest_top":
        t, cands = cl[1], cl[2]
        m = min(top(objs[c]) for c in cands if c != t) - top(objs[t])
        return m >= MARGIN, f"lowest top {t} margin={m:.2f}"
    if k == "left_from":  # target, other, viewer, facing-object
        t, o, v, f = (objs[x] for x in cl[1:5])
        dx, dy = f["c"][0] - v["c"][0], f["c"][1] - v["c"][1]
        n = math.hypot(dx, dy); lx, ly = -dy / n, dx / n
        pt = (t["c"][0] - v["c"][0]) * lx + (t["c"][1] - v["c"][1]) * ly
        po = (o["c"][0] - v["c"][0]) * lx + (o["c"][1] - v["c"][1]) * ly
        return pt - po >= MARGIN and pt > 0 > po, f"left_from {cl[1]} lateral={pt:.2f} other={po:.2f}"
    return False, f"unknown claim {k}"

def main():
    bad = 0
    for gi, (mp, typ, tgt, acc, meta, ws) in enumerate(emit.G, 1):
        objs, geo = load(mp)
        tag = f"g{gi:02d} {typ} {mp.split('/')[-1]}"
        msgs = []
        if typ in ("o", "or"):
            want = sorted(i for i, o in objs.items() if o["label"] == meta["label"]
                          and (typ == "o" or o["room"] == meta["room"]))
            ok = want == sorted(acc) and tgt in acc
            msgs.append(f"derived {want}")
        elif typ in ("od", "ord"):
            ok = acc == [tgt] and objs[tgt]["label"] == meta["label"]
            if typ == "ord":
                ok &= objs[tgt]["room"] == meta["room"]
                same = [i for i, o in objs.items() if o["label"] == meta["label"] and o["room"] == meta["room"]]
            else:
                same = [i for i, o in objs.items() if o["label"] == meta["label"]]
            if "tags" in meta:  # the stated tags pick out the target among its label (and room)
                hit = [i for i in same if all(v in str(objs[i]["tags"].get(k, "")) for k, v in meta["tags"].items())]
                ok &= hit == [tgt]
                msgs.append(f"tag match {hit} among {same}")
            else:
                msgs.append(f"same label{'/room' if typ == 'ord' else ''}: {same} (decided by caption)")
        elif typ == "s":
            ok = geo and acc == [tgt]
            for cl in meta["claims"]:
                r, m = claim(objs, cl)
                ok &= r
                msgs.append(("OK " if r else "FAIL ") + m)
        else:  # ard: single id or a set, checked by hand
            ok = tgt in acc
            msgs.append(f"{[objs[a]['label'] for a in acc]}")
        bad += not ok
        print(("PASS " if ok else "FAIL ") + tag + " target " + str(tgt) + " | " + "; ".join(msgs))
    print("failures:", bad)
    return 1 if bad else 0

if __name__ == "__main__":
    sys.exit(main())
