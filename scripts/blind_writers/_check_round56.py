"""Own checks for round56: accept sets of o/or re-derived from the maps, single-id claims
(numeric for s), style rules per wording position, label usage, counts."""
import json
import re
import sys
import math
from collections import Counter, defaultdict
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _groups_round56 import G

ROOT = Path(__file__).resolve().parents[2]
BASE = ROOT / "evals/blind"
SUITE = BASE / "round56.jsonl"

def load(mapname):
    p = (BASE / mapname).resolve()
    if not p.is_file():
        p = ROOT / "map_store" / f"{mapname}.json"
    d = json.loads(p.read_text())
    objs = {}
    if isinstance(d, dict) and "objects" in d:
        rooms = d["rooms"]
        for o in d["objects"]:
            x, y = o["center"][:2]
            pr = [r["label"] for r in rooms if min(q[0] for q in r["polygon"]) <= x <= max(q[0] for q in r["polygon"])
                  and min(q[1] for q in r["polygon"]) <= y <= max(q[1] for q in r["polygon"])]
            room = o.get("room")
            if room not in [r["label"] for r in rooms]:   # e.g. apartment coffee table has room "1"
                room = pr[0] if pr else room
            tags = o.get("tags", {})
            objs[o["id"]] = dict(id=o["id"], label=o["label"].lower(), room=room, poly_rooms=pr,
                                 c=o["center"], s=o["size"], tags=tags, rgb=o.get("color_rgb"),
                                 text=(o.get("caption", "") + " " + " ".join(str(v) for v in tags.values())).lower(),
                                 caption=o.get("caption", ""))
        return objs, True
    for k, v in d.items():
        try:
            cap = json.loads(v["caption"])
            text = " ".join(str(x) for x in cap.values())
        except Exception:
            text = v["caption"]
        objs[int(k)] = dict(id=int(k), label=v["category"].lower(), room=v.get("room_cat"), text=text.lower(),
                            caption=v["caption"])
    return objs, False

ERR = []
def err(m):
    ERR.append(m)
    print("ERROR", m)

# ---------- geometry helpers ----------
def lo(o, i): return o["c"][i] - o["s"][i] / 2
def hi(o, i): return o["c"][i] + o["s"][i] / 2
def cdist(a, b): return math.dist(a["c"][:2], b["c"][:2])
def gap(a, b):  # horizontal box-to-box gap
    dx = max(0, lo(a, 0) - hi(b, 0), lo(b, 0) - hi(a, 0))
    dy = max(0, lo(a, 1) - hi(b, 1), lo(b, 1) - hi(a, 1))
    return math.hypot(dx, dy)
def inside_xy(a, b, tol=0.05):
    return lo(b, 0) - tol <= a["c"][0] <= hi(b, 0) + tol and lo(b, 1) - tol <= a["c"][1] <= hi(b, 1) + tol
def on(a, b): return inside_xy(a, b) and abs(lo(a, 2) - hi(b, 2)) < 0.1
def above(a, b): return inside_xy(a, b) and lo(a, 2) > hi(b, 2) + 0.2
def margin_min(vals, target, label):
    """vals: {id: value}; target must be the unique minimum with margin >= 0.2"""
    srt = sorted(vals.items(), key=lambda kv: kv[1])
    ok = srt[0][0] == target and (len(srt) == 1 or srt[1][1] - srt[0][1] >= 0.2)
    print(f"    {label}: " + ", ".join(f"{k}:{v:.2f}" for k, v in srt[:4]) + ("  OK" if ok else "  FAIL"))
    return ok

# ---------- o / or: kind definitions ----------
KIND = {1: ({"hand towel", "set of towels"}, None), 2: ({"book"}, None), 3: ({"mirror frame"}, "bathroom"),
        8: ({"curtain"}, None), 9: ({"desk"}, "rec room"), 13: ({"plant"}, None), 14: ({"chair"}, "kitchen"),
        21: ({"pillow"}, None), 24: ({"kitchen cabinet"}, "kitchen"), 26: ({"plant"}, None),
        30: ({"monitor"}, "office"), 33: ({"lamp"}, None), 37: ({"chair"}, "dining room"), 44: ({"chair"}, "kitchen")}

def red(o):
    if o.get("rgb"):
        r, g, b = o["rgb"]
        return r > 150 and g < 90 and b < 90
    return "red" == str(o.get("tags", {}).get("color", ""))

# ---------- single-id predicates (must select exactly the target) ----------
SEATS = {"chair", "armchair", "office chair", "sofa", "easy chair", "couch", "folded chair", "bench"}
PRED = {
 4: lambda o: "l-shaped" in o["text"],
 5: lambda o: "honey" in o["text"] and o["room"] == "bathroom" and "table" in o["label"],
 6: lambda o: "pet" in o["label"].split() or " pet " in o["text"],
 7: lambda o: o["room"] == "bedroom" and "wireless" in o["text"],
 10: lambda o: o["label"] == "pillow" and "navy" in o["text"],
 11: lambda o: o["label"] == "pillow" and "orange" in o["text"] and "stripe" in o["text"] and o["room"] == "rec room",
 12: lambda o: o["label"] == "clock" or "red dot" in o["text"],
 15: lambda o: o["label"] == "rug" and o["tags"].get("shape") == "round",
 16: lambda o: o["label"] == "book" and "yellow" in o["text"] and o["room"] == "living room",
 17: lambda o: o["room"] == "kitchen" and red(o),
 27: lambda o: o["label"] == "armchair" and o["tags"].get("color") == "green",
 31: lambda o: o["label"] == "keyboard" and o["tags"].get("color") == "white" and o["room"] == "office",
 34: lambda o: o["label"] in {"armchair", "chair"} and "yellow" in o["text"] and o["room"] == "living room",
 36: lambda o: o["room"] == "study" and o["label"] in SEATS and "green" in o["text"],
 38: lambda o: o["label"] == "chair" and "tray" in o["text"],
 39: lambda o: o["room"] == "kids bedroom" and ("homework" in o["text"] or o["label"] in {"desk", "table"}),
 41: lambda o: o["label"] == "bicycle" and "blue" in o["text"],
 42: lambda o: o["label"] == "lamp" and "teal" in o["text"] and o["room"] == "bedroom",
 43: lambda o: re.search(r"\biron", o["text"]) is not None,
 46: lambda o: o["label"] == "door" and "frosted" in o["text"],
 47: lambda o: o["label"] == "nightstand" and o["tags"].get("color") == "white" and o["room"] == "bedroom",
 48: lambda o: o["room"] == "studio" and "print" in o["text"],
}
# extra narrowing facts used in the wordings, reported for review
SIDE = {
 7: lambda objs: [o["id"] for o in objs.values() if o["room"] == "bedroom" and o["label"] in SEATS | {"chair"}],
 17: lambda objs: [o["id"] for o in objs.values() if o["room"] == "kitchen" and re.search(r"boil|water|stove|microwave|kettle", o["text"] + o["label"])],
 36: lambda objs: [o["id"] for o in objs.values() if o["room"] == "study" and o["label"] in SEATS],
 39: lambda objs: [o["id"] for o in objs.values() if o["label"] in {"desk", "table"}],
 12: lambda objs: [o["id"] for o in objs.values() if re.search(r"clock|time|phone", o["text"] + o["label"])],
}

# ---------- spatial checks ----------
def s_check(n, objs):
    def L(lab):
        return {i: o for i, o in objs.items() if o["label"] == lab}
    ok = True
    if n == 18:   # apartment: lamp on the desk
        desk = objs[47]
        lamps = L("lamp")
        ok &= [i for i, o in lamps.items() if on(o, desk)] == [56]
        ok &= margin_min({i: gap(o, desk) for i, o in lamps.items()}, 56, "lamp gap to desk 47")
    elif n == 19:  # apartment: plant on the dresser, others on the floor
        ok &= [i for i, o in L("plant").items() if on(o, objs[38])] == [39]
        ok &= all(lo(o, 2) < 0.05 for i, o in L("plant").items() if i != 39)
        ok &= margin_min({i: abs(lo(o, 2) - hi(objs[38], 2)) + gap(o, objs[38]) for i, o in L("plant").items()}, 39, "plant off dresser top")
    elif n == 20:  # apartment: picture above the sofa
        sofas = L("sofa")
        ok &= [i for i, o in L("picture").items() if any(above(o, s) for s in sofas.values())] == [6]
        ok &= margin_min({i: min(gap(o, s) for s in sofas.values()) for i, o in L("picture").items()}, 6, "picture gap to nearest sofa")
    elif n == 22:  # scan_bedroom: pillow farthest from headboard (north edge of bed)
        bed = objs[1]
        head = hi(bed, 1)
        ok &= margin_min({i: -(head - o["c"][1]) for i, o in L("pillow").items()}, 5, "pillow -dist from headboard")
        ok &= margin_min({i: abs(o["c"][1] - lo(bed, 1)) for i, o in L("pillow").items()}, 5, "pillow dist to foot")
    elif n == 23:  # scan_bedroom: nightstand nearest the window, not near the door
        ok &= margin_min({i: cdist(o, objs[14]) for i, o in L("nightstand").items()}, 6, "nightstand to window")
        ok &= margin_min({i: gap(o, objs[14]) for i, o in L("nightstand").items()}, 6, "nightstand gap window")
        ok &= margin_min({i: cdist(o, objs[15]) for i, o in L("nightstand").items()}, 7, "nightstand to door (other one)")
        ok &= (objs[6]["c"][0] < objs[1]["c"][0]) and (objs[14]["c"][0] < objs[1]["c"][0])
    elif n == 25:  # scan_kitchen: chair nearest door
        ok &= margin_min({i: cdist(o, objs[15]) for i, o in objs.items() if o["label"] in SEATS}, 21, "seat to door")
        ok &= margin_min({i: gap(o, objs[15]) for i, o in objs.items() if o["label"] in SEATS}, 21, "seat gap door")
        t = objs[16]
        ok &= abs(objs[21]["c"][1] - t["c"][1]) < 0.05 and objs[21]["c"][0] < lo(t, 0)
    elif n == 28:  # scan_livingroom: lamp on right side table, sitting on sofa facing TV (+y) -> right = +x
        sofa, tv = objs[1], objs[14]
        assert tv["c"][1] > sofa["c"][1]
        tl = {i: o for i, o in L("lamp").items() if any(on(o, st) for st in L("side table").values())}
        print("    lamps on side tables", sorted(tl))
        ok &= margin_min({i: -(o["c"][0] - sofa["c"][0]) for i, o in tl.items()}, 11, "-x offset from sofa")
    elif n == 29:  # scan_livingroom: middle cushion of sofa
        sofa = objs[1]
        pl = {i: o for i, o in L("pillow").items() if on(o, sofa) or inside_xy(o, sofa)}
        ok &= margin_min({i: abs(o["c"][0] - sofa["c"][0]) for i, o in pl.items()}, 3, "pillow offset from sofa centre")
        xs = sorted(pl, key=lambda i: pl[i]["c"][0])
        ok &= len(xs) == 3 and xs[1] == 3
    elif n == 32:  # scan_office: shortest bookshelf
        ok &= margin_min({i: o["s"][2] for i, o in L("bookshelf").items()}, 16, "bookshelf height")
    elif n == 35:  # flat_b: kitchen seat nearest the stove
        st = objs[15]
        ks = {i: o for i, o in objs.items() if o["room"] == "kitchen" and o["label"] in SEATS}
        ok &= margin_min({i: cdist(o, st) for i, o in ks.items()}, 22, "kitchen seat to stove (centre)")
        ok &= margin_min({i: gap(o, st) for i, o in ks.items()}, 22, "kitchen seat to stove (gap)")
        allseat = {i: o for i, o in objs.items() if o["label"] in SEATS}
        margin_min({i: cdist(o, st) for i, o in allseat.items()}, 22, "(info) any seat in flat to stove, centre")
    elif n == 40:  # flat_e: lamp above the dining table
        ok &= [i for i, o in L("lamp").items() if above(o, objs[10])] == [16]
        ok &= margin_min({i: gap(o, objs[10]) + (0 if above(o, objs[10]) else 1) for i, o in L("lamp").items()}, 16, "lamp vs dining table")
    elif n == 45:  # flat_i: mug on the coffee table
        ok &= [i for i, o in L("mug").items() if on(o, objs[35])] == [36]
        ok &= margin_min({i: gap(o, objs[35]) + abs(lo(o, 2) - hi(objs[35], 2)) for i, o in L("mug").items()}, 36, "mug vs coffee table")
    else:
        print("    no spatial check defined")
        ok = False
    return ok

# ---------- style ----------
IMPER = ("go ", "take ", "head ", "bring ", "lead ", "guide ", "find ", "show ", "navigate ")
ARTICLES = {"a", "an", "the"}
REASON = re.compile(r"\b(not|so|because|since|as)\b")
def words(q): return re.findall(r"[a-z0-9'-]+", q.lower())
def label_uses(q, labels):
    return any(re.search(r"\b" + re.escape(lab) + r"(s|es)?\b", q.lower()) for lab in labels)
ARD_KIND = {6: ["bed"], 7: ["chair", "seat", "armchair"], 12: ["clock"], 17: ["kettle", "stove"],
            36: ["armchair", "chair", "seat"], 39: ["desk", "table"], 43: ["board"], 48: ["printer"]}

def main():
    rows = [json.loads(line) for line in SUITE.read_text().splitlines()]
    if len(rows) != 288:
        err(f"{len(rows)} lines")
    by = defaultdict(list)
    for r in rows:
        by[r["group"]].append(r)
    maps = {}
    per_type, per_map = Counter(), Counter()
    for n, g in enumerate(G, 1):
        gid = f"b56-g{n:02d}"
        rs = by[gid]
        if [r["query"] for r in rs] != g["w"]:
            err(f"{gid} suite lines differ from groups.py")
        if g["map"] not in maps:
            maps[g["map"]] = load(g["map"])
        objs, geo = maps[g["map"]]
        t, tgt, acc = g["type"], g["target"], sorted(g["accept"])
        per_type[t] += 1
        per_map[g["map"]] += 1
        print(f"{gid} [{t}] {Path(g['map']).name} target {tgt} ({objs[tgt]['label']}, {objs[tgt]['room']}) accept {acc}")
        if geo and objs[tgt]["poly_rooms"] and objs[tgt]["room"] not in objs[tgt]["poly_rooms"]:
            err(f"{gid} target room {objs[tgt]['room']} vs polygon {objs[tgt]['poly_rooms']}")
        # --- semantic claim ---
        if t in ("o", "or"):
            labs, room = KIND[n]
            der = sorted(i for i, o in objs.items() if o["label"] in labs and (room is None or o["room"] == room))
            if der != acc:
                err(f"{gid} accept {acc} != derived {der}")
            near = sorted({o["label"] for o in objs.values() if any(w in o["label"] for lb in labs for w in lb.split() if len(w) > 3) and o["label"] not in labs})
            if near:
                print(f"    (review) related labels not accepted: {near}")
            if room:
                others = sorted(i for i, o in objs.items() if o["label"] in labs and o["room"] != room)
                print(f"    same kind elsewhere: {others}")
        else:
            if acc != [tgt]:
                err(f"{gid} single-id type with accept {acc}")
        if t in ("od", "ord", "ard"):
            hit = sorted(i for i, o in objs.items() if PRED[n](o))
            print(f"    predicate hits {hit}")
            if hit != [tgt]:
                err(f"{gid} predicate selects {hit}")
            if n in SIDE:
                print(f"    (review) related objects: {SIDE[n](objs)}")
        if t == "s":
            if not geo:
                err(f"{gid} spatial on caption map")
            elif not s_check(n, objs):
                err(f"{gid} spatial claim fails")
        # --- style ---
        w = g["w"]
        if not w[0].lower().startswith(IMPER):
            err(f"{gid} w1 not a plain imperative")
        if not (w[1].startswith("Could you ") and w[1].endswith("?")):
            err(f"{gid} w2 form")
        ww = words(w[2])
        if len(ww) > 6 or ARTICLES & set(ww):
            err(f"{gid} w3 telegraphic rule: {ww}")
        if not (REASON.search(w[3].lower())):
            err(f"{gid} w4 has no reason/contrast marker")
        sents = [s for s in re.split(r"(?<=[.!?])\s+", w[4].strip()) if s]
        if len(sents) != 2 or not sents[0].startswith("This is "):
            err(f"{gid} w5 two-sentence form: {len(sents)}")
        if w[5] != w[5].lower():
            err(f"{gid} w6 not lower case")
        typo, right = g["typo"]
        w6w = words(w[5])
        if w6w.count(typo) != 1:
            err(f"{gid} w6 typo {typo!r} count {w6w.count(typo)}")
        if any(typo in words(x) for x in w[:5]):
            err(f"{gid} typo word also in other wordings")
        if right in w6w:
            err(f"{gid} w6 also has the correct spelling {right!r}")
        if len({x.lower() for x in w}) != 6:
            err(f"{gid} duplicate wordings")
        labels = {objs[a]["label"] for a in acc}
        uses = sum(label_uses(x, labels) for x in w)
        if uses > 2:
            err(f"{gid} label in {uses} wordings")
        if t == "ard":
            bad = [x for x in w if any(re.search(r"\b" + k + r"(s|es)?\b", x.lower()) for k in ARD_KIND[n] + sorted(labels))]
            if bad:
                err(f"{gid} ard names a kind: {bad}")
        if t in ("or", "ord"):
            rn = objs[tgt]["room"]
            alias = {"living room": ["living room", "lounge"], "bathroom": ["bathroom", "washroom"],
                     "kids bedroom": ["kids", "children"], "rec room": ["rec room"]}.get(rn, [rn])
            miss = [i + 1 for i, x in enumerate(w) if not any(a in x.lower() for a in alias)]
            if miss:
                err(f"{gid} room not named in wordings {miss}")
    print("\ngroups per type", dict(per_type))
    print("groups per map", {Path(k).name: v for k, v in per_map.items()})
    fam = Counter()
    for k, v in per_map.items():
        f = "caption" if "iesm_maps" in k else "apartment" if k == "apartment" else "scan" if "scan_" in k else "flat"
        fam[f] += v
    print("per family", dict(fam))
    sm = Counter(Path(g["map"]).name for g in G if g["type"] == "s")
    print("s groups per map", dict(sm))
    want = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    if dict(per_type) != want:
        err("type counts")
    if len(G) != 48:
        err("group count")
    # w1 opening variety
    print("w1 openings", Counter(" ".join(g["w"][0].split()[:2]) for g in G).most_common(8))
    print("\nERRORS:", len(ERR))
    return 1 if ERR else 0

if __name__ == "__main__":
    sys.exit(main())
