"""Re-derive o/or accept sets and check spatial claims and wording styles of round41.jsonl."""
import json, math, re, sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SUITE = ROOT / "evals" / "blind" / "round41.jsonl"
MARGIN = 0.2
errors = []

def load(mp):
    p = (SUITE.parent / mp).resolve()
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        rooms = {str(r["id"]): r["label"] for r in d.get("rooms", [])}
        objs = {}
        for o in d["objects"]:
            room = rooms.get(str(o.get("room")), o.get("room"))
            objs[int(o["id"])] = dict(o, room=room)
        return objs, True
    return {int(k): {"label": v["category"], "room": v.get("room_cat")} for k, v in d.items()}, False

rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
groups = defaultdict(list)
for r in rows:
    groups[r["group"]].append(r)

# room named in each "or" group
OR_ROOM = {3: "bathroom", 4: "bedroom", 9: "rec room", 13: "living room", 17: "studio",
           26: "master bedroom", 28: "living room"}
# room named in each "ord" group (target must be in it)
ORD_ROOM = {6: "living room", 14: "bedroom", 25: "living room", 30: "office", 35: "kitchen",
            37: "bathroom", 46: "master bedroom"}

def xy(o): return o["center"][0], o["center"][1]
def dist(a, b): return math.dist(xy(a), xy(b))
def bottom(o): return o["center"][2] - o["size"][2] / 2
def top(o): return o["center"][2] + o["size"][2] / 2
def on(a, b):
    inside = all(abs(a["center"][i] - b["center"][i]) <= b["size"][i] / 2 for i in (0, 1))
    return inside and abs(bottom(a) - top(b)) <= 0.05

def nearest(objs, cands, ref, target, far=False):
    d = sorted(((dist(objs[c], objs[ref]), c) for c in cands), reverse=far)
    ok = d[0][1] == target and abs(d[1][0] - d[0][0]) >= MARGIN
    return ok, d

def spatial(n, objs, tgt):
    L = lambda lab: [i for i, o in objs.items() if o["label"] == lab]
    if n == 15: return nearest(objs, L("chair"), 13, tgt)
    if n == 19: return nearest(objs, L("stool"), 23, tgt, far=True)
    if n == 22: return nearest(objs, [c for c in L("chair") if objs[c]["tags"].get("color") == "blue"], 17, tgt)
    if n == 24:
        ons = [m for m in L("mug") if on(objs[m], objs[28])]
        return ons == [tgt], ons
    if n == 33:
        bk = sorted(((objs[b]["center"][2], b) for b in L("book") if objs[b]["room"] == "living room"), reverse=True)
        return bk[0][1] == tgt and bk[0][0] - bk[1][0] >= MARGIN and on_shelf(objs, bk), bk
    if n == 34:
        ons = [p for p in L("pillow") if on(objs[p], objs[32])]
        return ons == [tgt], ons
    if n == 38:
        ons = {c: [s for s in objs if s != c and on(objs[c], objs[s])] for c in L("cup")}
        return ons[tgt] and all(16 in v for c, v in ons.items() if c != tgt) and 16 not in ons[tgt], ons
    if n == 39:
        xs = sorted(((objs[c]["center"][0], c) for c in L("chair")), reverse=True)
        east_edge = objs[16]["center"][0] + objs[16]["size"][0] / 2
        return xs[0][1] == tgt and xs[0][0] > east_edge and xs[0][0] - xs[1][0] >= MARGIN, xs
    if n == 42:
        # sofa 1 faces north (TV 14 is north of it): a seated person's left is west (smaller x)
        assert objs[14]["center"][1] > objs[1]["center"][1]
        lamps = [l for l in L("lamp") if any(on(objs[l], objs[s]) for s in L("side table"))]
        xs = sorted((objs[l]["center"][0], l) for l in lamps)
        return xs[0][1] == tgt and xs[1][0] - xs[0][0] >= MARGIN and xs[0][0] < objs[1]["center"][0], xs
    if n == 43: return nearest(objs, L("plant"), 14, tgt, far=True)
    if n == 45:
        whites = [p for p in L("pillow") if objs[p]["tags"].get("color") == "white"]
        a, b = sorted(objs[w]["center"][0] for w in whites)
        betw = [p for p in L("pillow") if p not in whites and a + MARGIN <= objs[p]["center"][0] <= b - MARGIN]
        return betw == [tgt], (whites, betw)
    if n == 47: return nearest(objs, L("monitor"), 17, tgt, far=True)
    return False, "no check"

def on_shelf(objs, bk):
    shelf = objs[11]
    return all(abs(objs[b]["center"][0] - shelf["center"][0]) < shelf["size"][0] and
               abs(objs[b]["center"][1] - shelf["center"][1]) < shelf["size"][1] / 2 + 0.05 for _, b in bk)

counts = defaultdict(int)
for g, rs in sorted(groups.items()):
    n = int(g.split("-g")[1]); r0 = rs[0]
    objs, geo = load(r0["map"]); t = r0["type"]; tgt = r0["target"]; acc = sorted(r0["accept"])
    counts[t] += 1
    lab = objs[tgt]["label"]
    if t == "o":
        want = sorted(i for i, o in objs.items() if o["label"] == lab)
        if want != acc: errors.append(f"{g}: o accept {acc} != {want}")
    elif t == "or":
        want = sorted(i for i, o in objs.items() if o["label"] == lab and o["room"] == OR_ROOM[n])
        if want != acc: errors.append(f"{g}: or accept {acc} != {want}")
    elif t == "ord":
        if objs[tgt]["room"] != ORD_ROOM[n] or acc != [tgt]: errors.append(f"{g}: ord room/accept")
    elif t in ("od", "ard"):
        if acc != [tgt]: errors.append(f"{g}: {t} accept not single")
    elif t == "s":
        if not geo: errors.append(f"{g}: spatial without geometry")
        ok, info = spatial(n, objs, tgt)
        print(f"{g} s target {tgt}: {'OK' if ok else 'FAIL'} {info}")
        if not ok: errors.append(f"{g}: spatial claim fails {info}")
    # wording styles
    q = {r["id"][-2:]: r["query"] for r in rs}
    if not q["w1"].split()[0] in ("Go", "Take", "Bring", "Find", "Show"): errors.append(f"{g}: w1 not imperative")
    if not (q["w2"].startswith("Could you") and q["w2"].endswith("?")): errors.append(f"{g}: w2 not polite question")
    if re.search(r"\b(a|an|the)\b", q["w3"].lower()) or len(q["w3"].split()) > 5: errors.append(f"{g}: w3 not telegraphic")
    if not (q["w5"].startswith("This is") and len(re.findall(r"[.!?](\s|$)", q["w5"])) == 2): errors.append(f"{g}: w5 not two sentences")
    if q["w6"] != q["w6"].lower(): errors.append(f"{g}: w6 not lower case")
    names = {objs[a]["label"].lower() for a in acc}
    uses = sum(any(re.search(r"\b" + re.escape(l) + r"(s|es)?\b", x.lower()) for l in names) for x in q.values())
    if uses > 2: errors.append(f"{g}: label in {uses} wordings")

print(dict(counts))
for e in errors: print("ERROR", e)
print("errors:", len(errors))
sys.exit(1 if errors else 0)
