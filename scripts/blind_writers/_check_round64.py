"""Re-derive every o/or accept set, check every single-id claim (numerically for s), the style rules
and the counts of evals/blind/round64.jsonl. Prints problems; exit 1 if any."""
import json
import math
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _maps_round64 import load, BLIND
from _suite_data_round64 import GROUPS

SUITE = BLIND / "round64.jsonl"
MARGIN = 0.2
problems = []
def bad(msg): problems.append(msg)

# ---------------------------------------------------------------- helpers
def kind(o, labels):
    return o["label"] in labels or any(a in labels for a in o["alt"])

def select(objs, labels=None, room=None, kws=(), pred=None):
    out = []
    for o in objs:
        if labels is not None and not kind(o, labels):
            continue
        if room is not None and o["room"] != room:
            continue
        if any(not re.search(k, o["text"] + " " + o["label"]) for k in kws):
            continue
        if pred and not pred(o):
            continue
        out.append(o["id"])
    return sorted(out)

def by_id(objs): return {o["id"]: o for o in objs}
def dxy(a, b): return math.hypot(a["center"][0] - b["center"][0], a["center"][1] - b["center"][1])
def top(o): return o["center"][2] + o["size"][2] / 2
def bottom(o): return o["center"][2] - o["size"][2] / 2
def inside_xy(o, base):
    return all(abs(o["center"][i] - base["center"][i]) <= base["size"][i] / 2 for i in (0, 1))

def winner(scores, target, name, larger=False):
    """scores: {id: value}; target must be best by >= MARGIN."""
    order = sorted(scores, key=lambda k: -scores[k] if larger else scores[k])
    best, second = order[0], order[1]
    gap = abs(scores[best] - scores[second])
    ok = best == target and gap >= MARGIN
    return ok, f"{name}: best {best} ({scores[best]:.2f}) runner-up {second} ({scores[second]:.2f}) margin {gap:.2f}"

# ---------------------------------------------------------------- o / or specs: (labels, room)
KIND = {
 1: ({"mirror frame", "mirror", "mirror door"}, None),
 2: ({"doorway", "door frame", "door", "door/window frame"}, "bathroom"),
 3: ({"easy chair", "armchair"}, "bedroom"),
 7: ({"pillow", "cushion"}, None),
 13: ({"armchair"}, "living room"),
 17: ({"plant"}, None),
 19: ({"chair"}, "dining room"),
 25: ({"door"}, None),
 26: ({"desk"}, "studio"),
 29: ({"rug", "carpet", "mat"}, None),
 30: ({"chair", "dining chair"}, "kitchen"),
 38: ({"nightstand"}, "bedroom"),
 39: ({"trash can"}, None),
 43: ({"picture"}, None),
}
# ---------------------------------------------------------------- od / ord / ard specs: (labels or None=all, room, regexes, pred)
ALL = None
UNIQUE = {
 4: ({"bowl with sweets", "decorative bowl"}, None, ["white", "gold"], None),
 5: ({"easy chair", "chair", "folded chair", "couch"}, "bathroom", ["beige", "velvet"], None),
 6: (ALL, None, [r"\bpet\b"], None),
 8: ({"chair"}, None, ["speaker"], None),
 9: ({"desk", "table"}, None, ["white"], None),
 10: ({"desk", "table"}, "rec room", ["cable management"], None),
 11: (ALL, None, ["golden brown", "outlet"], None),
 12: ({"clock", "phone", "laptop", "monitor", "window"}, None, [r"\bclock\b|time", "wall"], lambda o: o["label"] != "window"),
 14: ({"chair", "armchair", "office chair"}, "kitchen", ["white", "plastic"], None),
 15: ({"coat rack", "wardrobe", "towel"}, "hallway", [], None),
 18: ({"sink"}, "bathroom", ["white", "small"], None),
 21: ({"chair"}, None, ["red checked"], None),
 22: ({"lamp"}, "bedroom", ["beige", "ceramic"], None),
 23: (ALL, None, [r"\biron"], None),
 27: ({"chair"}, "studio", ["blue", "mesh"], None),
 31: ({"picture", "photo", "painting"}, None, ["lighthouse"], None),
 32: ({"mirror"}, "bathroom", ["oval"], None),
 33: ({"kettle", "stove", "microwave"}, None, [r"\bred\b"], None),
 34: ({"printer"}, None, [], None),
 40: ({"kitchen cabinet"}, None, ["gray"], None),
 44: ({"ottoman", "sofa", "coffee table", "armchair", "side table"}, None, ["gray"],
      lambda o: max(o["size"][:2]) < 1.0 and o["size"][2] < 0.6),
 46: ({"keyboard"}, None, ["white"], None),
}
# sanity: without the room, the ord claims need the room (informational)
NEEDS_ROOM = {5, 10, 14, 18, 22, 27, 32}

# ---------------------------------------------------------------- s checks
def s_check(g, objs, target):
    idx = by_id(objs)
    if g == 16:   # flat_b: stand at foot of bed 30 facing headboard (north): left = smaller x among bedside lamps
        lamps = {i: idx[i]["center"][0] for i in select(objs, {"lamp"}, "bedroom")}
        bed = idx[30]
        assert bed["size"][1] > bed["size"][0]
        return winner(lamps, target, "bedside lamp x (left=west, facing north)")
    if g == 20:   # flat_e: highest lamp (centre z and top z)
        lamps = select(objs, {"lamp"})
        ok1, m1 = winner({i: idx[i]["center"][2] for i in lamps}, target, "lamp centre z", larger=True)
        ok2, m2 = winner({i: top(idx[i]) for i in lamps}, target, "lamp top z", larger=True)
        return ok1 and ok2, m1 + "; " + m2
    if g == 24:   # flat_g: bigger bin (height and volume)
        bins = select(objs, {"trash can"})
        ok1, m1 = winner({i: idx[i]["size"][2] for i in bins}, target, "bin height", larger=True)
        vol = {i: idx[i]["size"][0] * idx[i]["size"][1] * idx[i]["size"][2] for i in bins}
        order = sorted(vol, key=lambda k: -vol[k])
        return ok1 and order[0] == target, m1 + f"; volumes {vol}"
    if g == 28:   # flat_i: meeting-room chair nearest the wall display 10
        ch = select(objs, {"chair"}, "meeting room")
        return winner({i: dxy(idx[i], idx[10]) for i in ch}, target, "chair dist to display 10")
    if g == 35:   # apartment: higher of the books standing in bookshelf 11
        books = [i for i in select(objs, {"book"}) if inside_xy(idx[i], idx[11])]
        ok, m = winner({i: idx[i]["center"][2] for i in books}, target, f"books in shelf 11 {books} z", larger=True)
        return ok and len(books) == 2, m
    if g == 36:   # apartment: plant resting on dresser 38
        d = idx[38]
        on = [i for i in select(objs, {"plant"}) if inside_xy(idx[i], d) and abs(bottom(idx[i]) - top(d)) < 0.05]
        dist = {i: dxy(idx[i], d) for i in select(objs, {"plant"})}
        ok, m = winner(dist, target, "plant xy dist to dresser")
        return ok and on == [target], m + f"; resting on dresser: {on}"
    if g == 37:   # scan_bedroom: pillow nearest the foot of bed 1 (south edge, headboard north)
        bed = idx[1]
        foot_y = bed["center"][1] - bed["size"][1] / 2
        pil = select(objs, {"pillow"})
        return winner({i: abs(idx[i]["center"][1] - foot_y) for i in pil}, target, f"pillow dist to foot line y={foot_y:.2f}")
    if g == 41:   # scan_kitchen: cabinet directly under sink 10
        s = idx[10]
        cabs = select(objs, {"kitchen cabinet"})
        under = [i for i in cabs if inside_xy(s, idx[i]) and top(idx[i]) <= bottom(s) + 0.02]
        ok, m = winner({i: dxy(idx[i], s) for i in cabs if top(idx[i]) <= bottom(s) + 0.02}, target, "base cabinet xy dist to sink")
        return ok and under == [target], m + f"; under: {under}"
    if g == 42:   # scan_kitchen: chair nearest door 15
        return winner({i: dxy(idx[i], idx[15]) for i in select(objs, {"chair"})}, target, "chair dist to door 15")
    if g == 45:   # scan_livingroom: red cushion on your right sitting on sofa 1 facing TV 14 (north): right = larger x
        assert idx[14]["center"][1] > idx[1]["center"][1]
        red = {i: idx[i]["center"][0] for i in select(objs, {"pillow"}, kws=["red"])}
        ok, m = winner(red, target, "red cushion x (right=east)", larger=True)
        ok2, m2 = winner({i: idx[i]["center"][0] for i in select(objs, {"pillow"})}, target, "any cushion x", larger=True)
        return ok and ok2, m + "; " + m2
    if g == 47:   # scan_office: bookcase between the other two (distance to the midpoint of the other two)
        bs = select(objs, {"bookshelf"})
        assert len(bs) == 3
        sc = {}
        for i in bs:
            a, b = [idx[j] for j in bs if j != i]
            mid = [(a["center"][k] + b["center"][k]) / 2 for k in (0, 1)]
            sc[i] = math.hypot(idx[i]["center"][0] - mid[0], idx[i]["center"][1] - mid[1])
        return winner(sc, target, "bookcase dist to midpoint of the other two")
    if g == 48:   # scan_office: bin in the corner next to door 20
        bins = select(objs, {"trash can"})
        ok1, m1 = winner({i: dxy(idx[i], idx[20]) for i in bins}, target, "bin dist to door 20")
        W, H = 8, 6
        corner = {i: min(math.hypot(idx[i]["center"][0] - x, idx[i]["center"][1] - y) for x in (0, W) for y in (0, H)) for i in bins}
        return ok1 and corner[target] < 0.8, m1 + f"; dist to nearest room corner {corner}"
    return False, "no s check written"

# ---------------------------------------------------------------- style
IMPER = ("Go to ", "Take me ", "Head to ", "Bring me ", "Lead me ", "Guide me ", "Show me ")
REASON = re.compile(r"\b(because|since|so|not|rather than|instead)\b", re.I)
ARTICLES = {"a", "an", "the"}

def toks(s): return re.findall(r"[a-z0-9]+(?:['-][a-z0-9]+)*", s.lower())

rows = [json.loads(x) for x in SUITE.read_text().splitlines()]
groups = defaultdict(list)
for r in rows:
    groups[r["group"]].append(r)
vocab = set()
for r in rows:
    if not r["id"].endswith("w6"):
        vocab |= set(toks(r["query"]))
mapcache = {}
for r in rows:
    if r["map"] not in mapcache:
        mapcache[r["map"]] = load(r["map"])
    for o in mapcache[r["map"]][0]:
        vocab |= set(toks(o["text"] + " " + o["label"]))
vocab |= {"i", "pls", "wanna", "dont", "any", "one", "will", "do", "need", "is", "fine", "how", "it", "where", "there", "dying", "make"}

report = []
type_count, map_count = Counter(), Counter()
for gi, (mp, typ, target, accept, words, (typo, correct)) in enumerate(GROUPS, 1):
    gid = f"b64-g{gi:02d}"
    rs = sorted(groups[gid], key=lambda r: r["id"])
    if [r["query"] for r in rs] != words:
        bad(f"{gid}: suite lines differ from suite_data")
    objs, geo = mapcache[mp]
    idx = by_id(objs)
    type_count[typ] += 1
    map_count[mp] += 1
    # ---- content
    if typ in ("o", "or"):
        labels, room = KIND[gi]
        derived = select(objs, labels, room)
        if derived != sorted(accept):
            bad(f"{gid}: accept {sorted(accept)} != derived {derived}")
        report.append(f"{gid} {typ:3} {Path(mp).name:28} kind={sorted(labels)} room={room} -> {derived}")
    elif typ == "s":
        if not geo:
            bad(f"{gid}: s on a caption map")
        ok, msg = s_check(gi, objs, target)
        if not ok:
            bad(f"{gid}: spatial claim fails: {msg}")
        report.append(f"{gid} s   {Path(mp).name:28} {msg}")
        if accept != [target]:
            bad(f"{gid}: s must be single id")
    else:
        labels, room, kws, pred = UNIQUE[gi]
        got = select(objs, labels, room, kws, pred)
        if got != [target] or accept != [target]:
            bad(f"{gid}: claim matches {got}, target {target}")
        extra = ""
        if gi in NEEDS_ROOM:
            extra = f" (without room: {select(objs, labels, None, kws, pred)})"
        report.append(f"{gid} {typ:3} {Path(mp).name:28} {kws} room={room} -> {got}{extra}")
    # ---- label use (map labels of accepted ids, incl. alt labels)
    names = {idx[a]["label"] for a in accept}
    uses = sum(any(re.search(r"\b" + re.escape(n) + r"(s|es)?\b", q.lower()) for n in names) for q in words)
    if uses > 2:
        bad(f"{gid}: map label used in {uses} wordings")
    # ---- wording styles
    w1, w2, w3, w4, w5, w6 = words
    if not w1.startswith(IMPER):
        bad(f"{gid} w1 not a plain imperative: {w1}")
    if not (w2.startswith("Could you ") and w2.endswith("?")):
        bad(f"{gid} w2 not a Could-you question")
    t3 = w3.split()
    if len(t3) > 6 or ARTICLES & set(toks(w3)):
        bad(f"{gid} w3 not telegraphic: {w3}")
    if not REASON.search(w4):
        bad(f"{gid} w4 lacks a reason/contrast: {w4}")
    sents = [s for s in re.split(r"(?<=[.!?])\s+", w5.strip()) if s]
    if not (w5.startswith("This is ") and len(sents) == 2):
        bad(f"{gid} w5 not two sentences starting 'This is': {w5}")
    if w6 != w6.lower():
        bad(f"{gid} w6 not lower case")
    t6 = toks(w6)
    if t6.count(typo) != 1 or typo in vocab:
        bad(f"{gid} w6 typo {typo!r} not present once or is a real word")
    unknown = [t for t in t6 if t not in vocab and t != typo]
    if unknown:
        bad(f"{gid} w6 has other unknown words {unknown}")
    if len(set(q.lower() for q in words)) != 6:
        bad(f"{gid}: duplicate wordings")
    for w in words:
        if re.search(r"\s{2,}|\s[,.?]", w):
            bad(f"{gid}: spacing in {w!r}")

# ---- counts
want_types = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
if dict(type_count) != want_types:
    bad(f"type counts {dict(type_count)} != {want_types}")
fam = Counter()
for mp, n in map_count.items():
    f = ("caption" if "caption" in mp else "flat" if "flat_" in mp else "apartment" if mp == "apartment" else "scan")
    fam[f] += n
s_maps = Counter(Path(g[0]).name for g in GROUPS if g[1] == "s")
if len(rows) != 288:
    bad(f"{len(rows)} lines")
print("\n".join(report))
print("types", dict(type_count))
print("per map", {Path(k).name: v for k, v in map_count.items()})
print("per family", dict(fam))
print("s groups per map", dict(s_maps))
print("PROBLEMS:" if problems else "no problems", *problems, sep="\n")
sys.exit(1 if problems else 0)
