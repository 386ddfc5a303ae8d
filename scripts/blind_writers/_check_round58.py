"""Independent checks of round58.jsonl: accept sets of o/or groups re-derived from the maps, every single-id claim
(numerically for s), wording style rules, label use, typo, and counts."""
import json
import math
import re
import sys
from collections import Counter, defaultdict
from _common_round58 import FIELD_TO_KEY, SUITE, load, words
from _suite_data_round58 import GROUPS

errors = []
report = []
DICT = {w.strip().lower() for w in open("/usr/share/dict/words")}
DICT |= {"i", "tv", "x", "a3", "gym", "doggy", "whichever", "handiest", "snoozes", "houseplant", "chequered", "rec", "nightstand"}

rows = [json.loads(line) for line in SUITE.read_text().splitlines()]
groups = defaultdict(list)
for r in rows:
    groups[r["group"]].append(r)
MAPCACHE = {}


def objs(key):
    if key not in MAPCACHE:
        MAPCACHE[key] = load(key)
    return MAPCACHE[key][0]


def err(g, msg):
    errors.append(f"{g}: {msg}")


def dist(a, b, dims=2):
    return math.dist(a["center"][:dims], b["center"][:dims])


def top(o):
    return o["center"][2] + o["size"][2] / 2


def bottom(o):
    return o["center"][2] - o["size"][2] / 2


def inside_xy(p, box):
    return all(abs(p["center"][i] - box["center"][i]) <= box["size"][i] / 2 for i in (0, 1))


def text(o):
    return " ".join([o["label"], o["room"] or "", " ".join(c for c in o["captions"] if c),
                     " ".join(str(v) for v in o["tags"].values() if v)]).lower()


def ranked(g, scores, target, best="min", margin=0.2, what=""):
    """scores: id -> value; target must be best with margin over the runner-up."""
    order = sorted(scores, key=lambda i: scores[i], reverse=(best == "max"))
    if order[0] != target:
        err(g, f"s claim {what}: best is {order[0]} not {target} ({scores})")
        return
    gap = abs(scores[order[0]] - scores[order[1]]) if len(order) > 1 else float("inf")
    if gap < margin:
        err(g, f"s claim {what}: margin {gap:.2f} < {margin}")
    report.append(f"{g} s {what}: target {target}={scores[target]:.2f}, runner-up {order[1] if len(order) > 1 else '-'}"
                  f"={scores[order[1]] if len(order) > 1 else float('nan'):.2f}, margin {gap:.2f}")


def of_label(ob, label, room=None):
    return {i for i, o in ob.items() if o["label"] == label and (room is None or o["room"] == room)}


def only(g, found, target, what):
    if found != {target}:
        err(g, f"claim {what}: matches {sorted(found)}, expected only {target}")
    else:
        report.append(f"{g} {what}: only {target}")


# ---------- single-id claims, written per group id (target id -> check) ----------
def single_claims(g, key, t, ob):
    if key == "scene_00829" and t == 211:
        only(g, {i for i, o in ob.items() if "bowl" in o["label"] and "blue" in text(o)}, t, "blue bowl")
    elif key == "scene_00829" and t == 110:
        only(g, {i for i, o in ob.items() if "table" in o["label"] and "bathroom" in (o["room"] or "")}, t, "table in a bathroom")
        only(g, {i for i, o in ob.items() if "honey" in text(o) or "x-shaped" in text(o)}, t, "honey wood / X base")
    elif key == "scene_00829" and t == 181:
        only(g, {i for i, o in ob.items() if "chair" in o["label"] and "armless" in text(o) and o["room"] == "bedroom"}, t, "armless chair in bedroom")
        only(g, of_label(ob, "chair", "bedroom"), t, "label chair in bedroom")
    elif key == "scene_00829" and t == 192:
        only(g, {i for i, o in ob.items() if "pet" in text(o) or "dog" in text(o) or "cat " in text(o)}, t, "pet sleeping place")
    elif key == "scene_office3" and t == 40:
        only(g, {i for i in of_label(ob, "pillow") if "stripe" in text(ob[i])}, t, "striped pillow")
        if of_label(ob, "pillow") & {i for i, o in ob.items() if "orange" in text(o)} != {8, 40}:
            err(g, "expected two orange pillows (contrast)")
    elif key == "scene_office3" and t == 3:
        only(g, {i for i, o in ob.items() if o["label"] in ("sofa", "couch") and o["room"] == "rec room" and "gray" in text(o)}, t, "gray sofa in rec room")
    elif key == "scene_office3" and t == 25:
        only(g, {i for i, o in ob.items() if o["label"] == "clock" or "red dot" in text(o)}, t, "tells the time / red dot")
    elif key == "flat_b" and t == 26:
        only(g, {i for i in of_label(ob, "lamp") if "green" in text(ob[i])}, t, "green lamp")
    elif key == "flat_b" and t == 29:
        only(g, {i for i, o in ob.items() if o["label"] in ("coat rack", "coat hook", "hook") or "jacket" in text(o)}, t, "place to hang a jacket")
    elif key == "flat_b" and t == 31:
        ranked(g, {i: dist(ob[i], ob[36]) for i in of_label(ob, "nightstand")}, t, what="nightstand nearest bedroom window 36")
        ranked(g, {i: dist(ob[i], ob[35]) for i in of_label(ob, "nightstand")}, 32, what="(w4 contrast) nightstand nearest wardrobe 35")
    elif key == "flat_e" and t == 7:
        only(g, of_label(ob, "mirror", "living room"), t, "mirror in living room")
        if "round" not in text(ob[t]) or "gold" not in text(ob[t]):
            err(g, "target not round/gold")
    elif key == "flat_e" and t == 33:
        only(g, {i for i, o in ob.items() if "dry" in text(o) and o["label"] != "towel"}, t, "something that dries clothes")
    elif key == "flat_e" and t == 16:
        table = ob[10]
        only(g, {i for i in of_label(ob, "lamp") if inside_xy(ob[i], table) and bottom(ob[i]) > top(table)}, t, "lamp above dining table 10")
        ranked(g, {i: top(ob[i]) for i in of_label(ob, "lamp")}, t, best="max", what="highest lamp")
        if not inside_xy(ob[4], dict(center=ob[1]["center"], size=[ob[1]["size"][0] + 1.2, ob[1]["size"][1] + 1.2])):
            err(g, "w4 contrast: floor lamp 4 not by the sofa")
    elif key == "flat_g" and t == 19:
        only(g, {i for i in of_label(ob, "chair") if "red" in text(ob[i]) and "check" in text(ob[i])}, t, "chair with red checked cushion")
    elif key == "flat_g" and t == 11:
        only(g, {i for i, o in ob.items() if "iron" in text(o) and "ironing" in o["label"]}, t, "ironing")
    elif key == "flat_g" and t == 34:
        bed = ob[31]
        stands = of_label(ob, "nightstand", "bedroom")
        assert all(ob[s]["center"][1] > bed["center"][1] for s in stands), "headboard not north"
        lamps = {i for i in of_label(ob, "lamp", "bedroom")}
        # viewer at the foot (south) facing north: left is -x
        ranked(g, {i: -(ob[i]["center"][0] - bed["center"][0]) for i in lamps}, t, best="max", what="leftmost bedside lamp facing north from foot of bed 31")
    elif key == "flat_i" and t == 13:
        only(g, {i for i in of_label(ob, "desk", "studio") if "white" in text(ob[i])}, t, "white desk in studio")
        if {i for i in of_label(ob, "desk") if "white" in text(ob[i])} == {t}:
            err(g, "room not needed (only white desk anyway)")
    elif key == "flat_i" and t == 20:
        only(g, {i for i, o in ob.items() if "print" in text(o) or "scan" in text(o)}, t, "prints/scans")
    elif key == "flat_i" and t == 36:
        ct = ob[35]
        only(g, {i for i in of_label(ob, "mug") if inside_xy(ob[i], ct) and abs(bottom(ob[i]) - top(ct)) < 0.05}, t, "mug on coffee table 35")
        ranked(g, {i: dist(ob[i], ct) for i in of_label(ob, "mug")}, t, what="mug nearest coffee table")
        if not (inside_xy(ob[31], ob[26]) and abs(bottom(ob[31]) - top(ob[26])) < 0.05):
            err(g, "w4 contrast: mug 31 not on worktop")
    elif key == "apartment" and t == 2:
        only(g, {i for i in of_label(ob, "sofa") if "leather" in text(ob[i]) and "brown" in text(ob[i])}, t, "brown leather sofa")
    elif key == "apartment" and t == 37:
        only(g, {i for i in of_label(ob, "rug") if "round" in text(ob[i])}, t, "round rug")
        if not inside_xy(ob[3], ob[9]):
            err(g, "w4 contrast: rug 9 not under coffee table 3")
    elif key == "apartment" and t == 31:
        only(g, of_label(ob, "picture", "hallway"), t, "picture in hallway")
        only(g, {i for i in of_label(ob, "picture") if "lighthouse" in text(ob[i])}, t, "lighthouse picture")
    elif key == "apartment" and t == 45:
        only(g, {i for i, o in ob.items() if o["label"] in ("washing machine", "dryer", "washer")}, t, "washes clothes")
    elif key == "apartment" and t == 1:
        def size(i):
            return max(ob[i]["size"][:2])

        ranked(g, {i: size(i) for i in of_label(ob, "sofa")}, t, best="max", what="longest sofa")
        ranked(g, {i: ob[i]["size"][0] * ob[i]["size"][1] for i in of_label(ob, "sofa")}, t, best="max", what="largest sofa footprint (m2)")
    elif key == "apartment" and t == 23:
        chairs = of_label(ob, "chair") | of_label(ob, "armchair")
        ranked(g, {i: dist(ob[i], ob[17]) for i in chairs}, t, what="chair nearest kitchen sink 17")
    elif key == "scan_bedroom" and t == 9:
        ranked(g, {i: dist(ob[i], ob[15]) for i in of_label(ob, "lamp")}, t, what="lamp nearest door 15")
        ranked(g, {i: dist(ob[i], ob[14]) for i in of_label(ob, "lamp")}, 8, what="(w4 contrast) lamp nearest window 14")
    elif key == "scan_bedroom" and t == 4:
        pil = of_label(ob, "pillow")
        head = {i for i in pil if ob[i]["center"][1] > ob[1]["center"][1]}  # head of bed (north half)
        if head != {2, 3, 4}:
            err(g, f"pillows at head of bed {head}")
        mid = [(ob[2]["center"][k] + ob[3]["center"][k]) / 2 for k in (0, 1)]
        ranked(g, {i: math.dist(ob[i]["center"][:2], mid) for i in pil - {2, 3}}, t, what="pillow nearest midpoint of 2 and 3")
        xs = sorted(head, key=lambda i: ob[i]["center"][0])
        if xs[1] != t:
            err(g, "target not the middle one by x")
    elif key == "scan_kitchen" and t == 23:
        only(g, {i for i in of_label(ob, "cup") if "blue" in text(ob[i])}, t, "blue cup")
    elif key == "scan_kitchen" and t == 27:
        ranked(g, {i: dist(ob[i], ob[13]) for i in of_label(ob, "trash can")}, t, what="bin nearest fridge 13")
        ranked(g, {i: dist(ob[i], ob[15]) for i in of_label(ob, "trash can")}, 26, what="(w4 contrast) bin nearest door 15")
    elif key == "scan_kitchen" and t == 8:
        sink = ob[10]
        cabs = of_label(ob, "kitchen cabinet")
        above = {i for i in cabs if bottom(ob[i]) > top(sink)}
        only(g, {i for i in above if inside_xy(sink, ob[i])}, t, "upper cabinet over sink 10")
        ranked(g, {i: dist(ob[i], sink) for i in above}, t, what="upper cabinet nearest sink (xy)")
        only(g, {i for i in cabs if top(ob[i]) <= bottom(sink) + 0.06 and inside_xy(sink, ob[i])}, 3, "(w4 contrast) cabinet under sink")
    elif key == "scan_livingroom" and t == 24:
        only(g, of_label(ob, "remote"), t, "remote")
        if not (inside_xy(ob[t], ob[7]) and abs(bottom(ob[t]) - top(ob[7])) < 0.05):
            err(g, "remote not on coffee table")
    elif key == "scan_livingroom" and t == 12:
        corners = [(0, 0), (6, 0), (6, 5), (0, 5)]
        ranked(g, {i: min(math.dist(ob[i]["center"][:2], c) for c in corners) for i in of_label(ob, "lamp")}, t, what="lamp nearest a room corner")
        for i in (10, 11):
            if not any(inside_xy(ob[i], ob[s]) for s in of_label(ob, "side table")):
                err(g, f"w4 contrast: lamp {i} not on a side table")
    elif key == "scan_office" and t == 2:
        only(g, {i for i in of_label(ob, "table") if "wood" in text(ob[i])}, t, "wooden table")
    elif key == "scan_office" and t == 16:
        ranked(g, {i: top(ob[i]) for i in of_label(ob, "bookshelf")}, t, what="lowest bookshelf top")
    else:
        err(g, f"no claim check written for {key} target {t}")


# ---------- per-group checks ----------
per_type, per_map = Counter(), Counter()
data_by_gid = {f"b58-g{n:02d}": grp for n, grp in enumerate(GROUPS, 1)}
for g, rs in sorted(groups.items()):
    r0 = rs[0]
    key = FIELD_TO_KEY[r0["map"]]
    ob = objs(key)
    typ, t, acc = r0["type"], r0["target"], set(r0["accept"])
    per_type[typ] += 1
    per_map[key] += 1
    if len(rs) != 6 or [r["id"] for r in rs] != [f"{g}-w{k}" for k in range(1, 7)]:
        err(g, "not six wordings w1..w6 in order")
    if t not in acc:
        err(g, "target not in accept")
    # accept sets
    if typ in ("o", "or"):
        expect = of_label(ob, ob[t]["label"], ob[t]["room"] if typ == "or" else None)
        if expect != acc:
            err(g, f"accept {sorted(acc)} != derived {sorted(expect)}")
        else:
            report.append(f"{g} {typ}: accept = every '{ob[t]['label']}'" + (f" in '{ob[t]['room']}'" if typ == "or" else "") + f" -> {sorted(acc)}")
        if len(acc) < 2:
            err(g, "o/or group with a single object")
    else:
        if len(acc) != 1:
            err(g, "single-id type with several accepted ids")
        if typ == "s" and not ob[t]["geo"]:
            err(g, "s on a caption map")
        single_claims(g, key, t, ob)
    # style
    q = [r["query"] for r in rs]
    if not re.match(r"(Go|Take|Head|Lead|Bring|Walk|Stand|Show|Find|Get|Navigate) ", q[0]) or q[0].endswith("?"):
        err(g, f"w1 not a plain imperative: {q[0]}")
    if not (q[1].startswith("Could you ") and q[1].endswith("?")):
        err(g, f"w2 not 'Could you ...?': {q[1]}")
    w3 = q[2].split()
    if len(w3) > 6 or {w.lower().strip(",.?") for w in w3} & {"a", "an", "the"}:
        err(g, f"w3 too long or has articles: {q[2]}")
    if not re.search(r"\bnot\b|\bso\b|\bbecause\b|\bsince\b|\brather than\b", q[3], re.I):
        err(g, f"w4 no reason/contrast: {q[3]}")
    sents = [s for s in re.split(r"(?<=[.!?])\s+", q[4].strip()) if s]
    if len(sents) != 2 or not q[4].startswith("This is "):
        err(g, f"w5 not two sentences starting 'This is': {q[4]}")
    if q[5] != q[5].lower():
        err(g, f"w6 not lower case: {q[5]}")
    wrong, right = data_by_gid[g]["typo"]
    toks = words(q[5])
    if toks.count(wrong) != 1 or wrong in DICT or right not in DICT:
        err(g, f"w6 typo {wrong!r}->{right!r} not a single non-word occurrence")
    others = [w for w in toks if w != wrong and w not in DICT]
    if others:
        err(g, f"w6 has other non-dictionary words {others}")
    if len({x.lower() for x in q}) != 6:
        err(g, "duplicate wordings")
    # label use (same rule as the validator)
    names = {ob[a]["label"].lower() for a in acc}
    uses = sum(any(re.search(r"\b" + re.escape(n) + r"(s|es)?\b", x.lower()) for n in names) for x in q)
    if uses > 2:
        err(g, f"map label in {uses} wordings")
    # ard: no target kind named (label or its head noun)
    if typ == "ard":
        head = ob[t]["label"].lower().split(" for ")[0].split()[-1]
        for k, x in enumerate(q, 1):
            if re.search(r"\b" + re.escape(head) + r"(s|es)?\b", x.lower()):
                err(g, f"ard w{k} names the kind {head!r}")

want_types = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
if dict(per_type) != want_types:
    errors.append(f"type counts {dict(per_type)} != {want_types}")
if len(rows) != 288 or len(groups) != 48:
    errors.append(f"{len(rows)} lines, {len(groups)} groups")
cap = per_map["scene_00829"] + per_map["scene_office3"]
flats = sum(per_map[f"flat_{x}"] for x in "begi")
scans = sum(per_map[k] for k in per_map if k.startswith("scan_"))
s_maps = Counter(FIELD_TO_KEY[rs[0]["map"]].split("_")[0] for rs in groups.values() if rs[0]["type"] == "s")
print("\n".join(report))
print(f"per type {dict(per_type)}")
print(f"per map {dict(per_map)}; caption {cap}, flats {flats}, apartment {per_map['apartment']}, scans {scans}; s groups by map family {dict(s_maps)}")
print("\n".join(errors) if errors else "check: no errors")
sys.exit(1 if errors else 0)
