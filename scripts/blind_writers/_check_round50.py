"""Re-derive every o/or accept set from its map, check every single-id claim (numerically for s),
the style rules of the six wordings, the label rule and the counts of round50.jsonl."""
import json, math, re, sys
from pathlib import Path
from collections import Counter, defaultdict
from _common_round50 import load
sys.path.insert(0, str(Path(__file__).resolve().parent))
from _build_round50 import GROUPS

SUITE = Path(__file__).resolve().parents[2] / "evals/blind/round50.jsonl"
MARGIN = 0.2
errors, notes = [], []
rows = [json.loads(l) for l in open(SUITE, encoding="utf-8")]
groups = defaultdict(list)
for r in rows:
    groups[r["group"]].append(r)
MAPS = {}
def M(name):
    if name not in MAPS:
        MAPS[name] = load(name)
    return MAPS[name]

def kind_of(o, kinds):
    return o["label"].lower() in kinds or any(a.lower() in kinds for a in o["alt"])

# ---- o / or: kinds (labels or alt labels) and room; accept must equal the derived set ----
KINDS = {
 "b50-g01": ({"book"}, None), "b50-g02": ({"curtain"}, "living room"), "b50-g03": ({"mirror frame", "mirror"}, "bathroom"),
 "b50-g08": ({"pillow", "cushion"}, None), "b50-g09": ({"curtain"}, "rec room"),
 "b50-g13": ({"chair"}, "kitchen"), "b50-g17": ({"plant"}, None), "b50-g18": ({"chair"}, "dining room"),
 "b50-g23": ({"lamp"}, "bedroom"), "b50-g25": ({"mug"}, None), "b50-g29": ({"rug", "carpet"}, None),
 "b50-g30": ({"sofa", "couch"}, "living room"), "b50-g37": ({"pillow", "cushion"}, None), "b50-g46": ({"monitor"}, None),
}
# ---- od / ord / ard: candidate kinds, room, required words in caption/tags -> exactly one object ----
CLAIMS = {
 "b50-g04": (None, None, ["l-shaped"]),
 "b50-g05": ({"book"}, "bathroom", ["red", "leather"]),
 "b50-g06": ({"bed for pet", "bed", "couch", "easy chair"}, "bathroom", ["pet"]),
 "b50-g07": ({"briefcase", "backpack", "clothes bag", "toiletry bag", "clothes container", "unknown"}, "bedroom", ["black", "leather", "lock"]),
 "b50-g10": ({"window"}, None, ["clock"]),
 "b50-g11": ({"pillow"}, "rec room", ["navy"]),
 "b50-g12": ({"sofa", "bench", "couch", "chair"}, "rec room", ["gray", "fabric"]),
 "b50-g14": ({"lamp"}, None, ["green glass", "brass"]),
 "b50-g15": ({"coat rack", "wardrobe"}, "hallway", []),
 "b50-g19": ({"chair", "armchair"}, "main bedroom", ["rattan", "cream"]),
 "b50-g21": ({"bicycle"}, None, ["blue", "stabilisers"]),
 "b50-g22": ({"ironing board", "table", "basket", "washing machine", "dryer"}, "laundry room", ["iron"]),
 "b50-g26": ({"door"}, None, ["green", "brass"]),
 "b50-g27": ({"nightstand"}, "bedroom", ["oak", "open shelf"]),
 "b50-g31": ({"picture"}, None, ["lighthouse"]),
 "b50-g32": ({"mirror"}, "hallway", ["gold"]),
 "b50-g33": ({"chair"}, "kitchen", ["white", "spindle"]),
 "b50-g34": ({"washing machine", "bathtub", "sink"}, "bathroom", ["@label:washing machine"]),
 "b50-g38": ({"mirror", "window"}, "bedroom", ["@label:mirror"]),
 "b50-g40": ({"chair"}, "kitchen", ["@color:red"]),
 "b50-g43": ({"ottoman", "coffee table", "sofa", "side table", "armchair"}, "living room", ["@color:gray", "@small"]),
 "b50-g47": ({"keyboard"}, None, ["@color:white"]),
}
def meets(o, word):
    if word.startswith("@label:"):
        return o["label"] == word[7:]
    if word.startswith("@color:"):
        return word[7:] in o["color"].lower()
    if word == "@small":
        return max(o["size"][:2]) < 1.0
    return word in o["text"]

# ---- s: numeric checks ----
def xy(o): return o["center"][:2]
def dist(a, b): return math.dist(xy(a), xy(b))
def lo(o, k): return o["center"][k] - o["size"][k] / 2
def hi(o, k): return o["center"][k] + o["size"][k] / 2
def ranked(scores):
    """[(score, id)] ascending; return (best id, margin to the runner-up)."""
    s = sorted(scores)
    return s[0][1], (s[1][0] - s[0][0]) if len(s) > 1 else math.inf, s

def s_check(g, objs):
    L = lambda lab, room=None: {i: o for i, o in objs.items() if o["label"] == lab and (room is None or o["room"] == room)}
    if g == "b50-g16":   # armchair next to a window
        wins = L("window").values()
        return ranked([(min(dist(o, w) for w in wins), i) for i, o in L("armchair").items()])
    if g == "b50-g20":   # lamp hanging above the dining table: horizontal distance from the table centre, and above its top
        t = objs[10]
        sc = [(dist(o, t), i) for i, o in L("lamp").items()]
        assert lo(objs[16], 2) > hi(t, 2), "lamp 16 not above the table top"
        return ranked(sc)
    if g == "b50-g24":   # kitchen chair nearest the sink
        return ranked([(dist(o, objs[13]), i) for i, o in L("chair", "kitchen").items()])
    if g == "b50-g28":   # studio screens, viewer facing north (+y): left = smaller x
        return ranked([(o["center"][0], i) for i, o in L("monitor", "studio").items()])
    if g == "b50-g35":   # living-room books: higher = larger z (score = -z)
        return ranked([(-o["center"][2], i) for i, o in L("book", "living room").items()])
    if g == "b50-g36":   # plant on top of the dresser: xy inside its footprint, bottom at its top
        d = objs[38]
        def sc(o):
            inside = all(lo(d, k) <= o["center"][k] <= hi(d, k) for k in (0, 1))
            return abs(lo(o, 2) - hi(d, 2)) + (0 if inside else 10) + dist(o, d)
        return ranked([(sc(o), i) for i, o in L("plant").items()])
    if g == "b50-g39":   # pillow nearest the foot (south edge, head is north) of the bed
        b = objs[1]
        return ranked([(o["center"][1] - lo(b, 1), i) for i, o in L("pillow").items()])
    if g == "b50-g41":   # chair nearest the window (centre distance; box distance checked too)
        w = objs[14]
        def boxd(o):
            dx = max(lo(w, 0) - hi(o, 0), lo(o, 0) - hi(w, 0), 0); dy = max(lo(w, 1) - hi(o, 1), lo(o, 1) - hi(w, 1), 0)
            return math.hypot(dx, dy)
        best2, m2, _ = ranked([(boxd(o), i) for i, o in L("chair").items()])
        if best2 != 20 or m2 < MARGIN:
            errors.append(f"{g}: box distance gives {best2} margin {m2:.2f}")
        return ranked([(dist(o, w), i) for i, o in L("chair").items()])
    if g == "b50-g42":   # base cabinet right under the sink: horizontal centre distance among cabinets below the sink
        s = objs[10]
        return ranked([(dist(o, s), i) for i, o in L("kitchen cabinet").items() if hi(o, 2) <= lo(s, 2) + 0.02])
    if g == "b50-g44":   # red cushions, sitting on the sofa facing the TV (+y): left = smaller x
        return ranked([(o["center"][0], i) for i, o in L("pillow").items() if o["color"] == "red"])
    if g == "b50-g45":   # lamp nearest the door
        return ranked([(dist(o, objs[22]), i) for i, o in L("lamp").items()])
    if g == "b50-g48":   # bookshelf between the other two: score = distance from the midpoint of the x range
        sh = L("bookshelf")
        xs = [o["center"][0] for o in sh.values()]
        mid = (min(xs) + max(xs)) / 2
        same_row = max(o["center"][1] for o in sh.values()) - min(o["center"][1] for o in sh.values())
        assert same_row < 0.05, "bookshelves not in one row"
        return ranked([(abs(o["center"][0] - mid), i) for i, o in sh.items()])
    raise KeyError(g)

# ---- style ----
IMPER = {"go", "take", "head", "find", "bring", "lead", "guide", "walk", "show", "navigate", "get", "move", "drive"}
ARTICLES = {"a", "an", "the"}
def words(s): return re.findall(r"[a-z0-9]+(?:['’-][a-z0-9]+)*", s.lower())
def sentences(s): return [x for x in re.split(r"(?<=[.!?])\s+", s.strip()) if x]

TYPO = {f"b50-g{n:02d}": t for n, *_rest, t in GROUPS}
vocab = set()
for r in rows:
    if not r["id"].endswith("-w6"):
        vocab |= set(words(r["query"]))
for name in {r["map"] for r in rows}:
    objs, _ = M(name)
    for o in objs.values():
        vocab |= set(words(o["caption"] + " " + o["label"] + " " + " ".join(o["alt"]) + " " + o["color"]))
vocab |= {"hey", "just", "get", "can", "you", "where", "do", "i", "need", "go", "sat", "whichever", "whichever's",
          "comfy", "cosy", "snoozes", "crash", "blouse", "grab", "either", "side", "real", "quick", "kind", "happens",
          "grey", "volumes"}  # reviewed by hand: real words

per_type, per_map = Counter(), Counter()
for g, rs in sorted(groups.items()):
    rs.sort(key=lambda r: r["id"])
    r0 = rs[0]
    typ, mp, tgt, acc = r0["type"], r0["map"], r0["target"], sorted(r0["accept"])
    per_type[typ] += 1; per_map[mp] += 1
    objs, geo = M(mp)
    if len(rs) != 6 or [r["id"][-2:] for r in rs] != [f"w{k}" for k in range(1, 7)]:
        errors.append(f"{g}: wordings {[r['id'] for r in rs]}")
    if tgt not in acc or any(a not in objs for a in acc):
        errors.append(f"{g}: target/accept not in map")
    if typ in ("o", "or"):
        kinds, room = KINDS[g]
        if (typ == "or") != (room is not None):
            errors.append(f"{g}: room spec does not fit type {typ}")
        derived = sorted(i for i, o in objs.items() if kind_of(o, kinds) and (room is None or o["room"] == room))
        if derived != acc:
            errors.append(f"{g}: accept {acc} but map gives {derived}")
        notes.append(f"{g} {typ:3} {mp.split('/')[-1]:28} kinds={sorted(kinds)} room={room} -> {derived}")
    elif typ == "s":
        if not geo:
            errors.append(f"{g}: s on a map without geometry")
        best, margin, sc = s_check(g, objs)
        ok = best == tgt and margin >= MARGIN and acc == [tgt]
        if not ok:
            errors.append(f"{g}: spatial best {best} (target {tgt}) margin {margin:.2f}")
        notes.append(f"{g} s   {mp.split('/')[-1]:28} best={best} margin={margin:.2f} ranking={[(round(a, 2), b) for a, b in sc[:3]]}")
    else:
        kinds, room, req = CLAIMS[g]
        cand = [i for i, o in objs.items() if (kinds is None or o["label"].lower() in kinds)
                and (room is None or o["room"] == room) and all(meets(o, w) for w in req)]
        if cand != [tgt] or acc != [tgt]:
            errors.append(f"{g}: claim matches {cand}, target {tgt}, accept {acc}")
        if typ == "od" and room is not None:
            errors.append(f"{g}: od claim should not need a room")
        if typ in ("ord",) and room is None:
            errors.append(f"{g}: ord claim without a room")
        notes.append(f"{g} {typ:3} {mp.split('/')[-1]:28} kinds={sorted(kinds) if kinds else 'any'} room={room} need={req} -> {cand}")
    # style
    q = [r["query"] for r in rs]
    if words(q[0])[0] not in IMPER or q[0].endswith("?"):
        errors.append(f"{g} w1 not a plain imperative: {q[0]}")
    if not (q[1].startswith("Could you ") and q[1].endswith("?")):
        errors.append(f"{g} w2 not a 'Could you ...?' question: {q[1]}")
    w3 = words(q[2])
    if len(w3) > 6 or ARTICLES & set(w3):
        errors.append(f"{g} w3 not telegraphic: {q[2]}")
    if not re.search(r"\b(so|because|since|not)\b", q[3].lower()):
        errors.append(f"{g} w4 has no reason or contrast: {q[3]}")
    s5 = sentences(q[4])
    if len(s5) != 2 or not q[4].startswith("This is "):
        errors.append(f"{g} w5 not two sentences starting 'This is': {q[4]}")
    if q[5] != q[5].lower():
        errors.append(f"{g} w6 not all lower case: {q[5]}")
    typo = TYPO[g]
    w6 = words(q[5])
    if w6.count(typo) != 1 or typo in vocab:
        errors.append(f"{g} w6 typo {typo!r} missing, repeated or a real word: {q[5]}")
    unknown = [w for w in w6 if w != typo and w not in vocab]
    if unknown:
        errors.append(f"{g} w6 has further unknown words {unknown}: {q[5]}")
    # label rule
    labs = {objs[a]["label"].lower() for a in acc}
    uses = sum(any(re.search(r"\b" + re.escape(l) + r"(s|es)?\b", x.lower()) for l in labs) for x in q)
    if uses > 2:
        errors.append(f"{g}: map label in {uses} wordings")
    if len({x.lower() for x in q}) != 6:
        errors.append(f"{g}: duplicate wordings")

# counts
WANT = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
if dict(per_type) != WANT:
    errors.append(f"type counts {dict(per_type)} != {WANT}")
fam = Counter()
for mp, n in per_map.items():
    fam["caption" if "caption" in mp else "flat" if "flat_" in mp else "apartment" if mp == "apartment" else "scan"] += n
s_maps = Counter(groups[g][0]["map"].split("/")[-1] for g in groups if groups[g][0]["type"] == "s")
if len(rows) != 288 or len(groups) != 48:
    errors.append(f"{len(rows)} lines, {len(groups)} groups")

for n in notes:
    print(n)
print("groups per type", dict(per_type))
print("groups per map", {k.split('/')[-1]: v for k, v in per_map.items()})
print("groups per map family", dict(fam))
print("s groups per map", dict(s_maps))
for e in errors:
    print("ERROR", e)
print(f"check: {len(rows)} lines, {len(groups)} groups, {len(errors)} errors")
sys.exit(1 if errors else 0)
