"""Independent checks of evals/blind/round54.jsonl against the maps (blind helper, round 54).

Re-derives o/or accept sets, checks each single-id claim with a predicate over the map, checks each
spatial claim numerically (margin >= 0.2 m), the style rules of w1..w6, label use, and the counts.
"""
import json, math, re, sys
from collections import Counter, defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from _build_round54 import GROUPS  # only for the declared w6 typos

B = Path(__file__).resolve().parents[2] / "evals/blind"
SUITE = B / "round54.jsonl"

def map_path(m):
    return Path(__file__).resolve().parents[2] / "map_store/apartment.json" if m == "apartment" else (B / m).resolve()

def load(m):
    d = json.loads(map_path(m).read_text())
    objs = {}
    if isinstance(d, dict) and "objects" in d:
        rooms = d["rooms"]
        for o in d["objects"]:
            room = o.get("room")
            if not isinstance(room, str):  # e.g. apartment coffee table has room=1
                room = next(r["label"] for r in rooms if r["id"] == room)
            text = " ".join([o.get("caption", ""), json.dumps(o.get("tags") or {})]).lower()
            objs[o["id"]] = dict(label=o["label"], room=room, c=o["center"], s=o["size"], text=text)
        return objs, True
    for k, v in d.items():
        try:
            cap = json.loads(v["caption"])
        except Exception:
            cap = {}
            mm = re.search(r'"captions":\s*"(.*)"', v["caption"])
            if mm:
                cap["captions"] = mm.group(1)
            for f in ("color", "material"):
                mm = re.search(r'"%s":\s*"([^"]*)"' % f, v["caption"])
                if mm:
                    cap[f] = mm.group(1)
        text = " ".join(str(cap.get(f, "")) for f in ("captions", "color", "material")).lower()
        objs[int(k)] = dict(label=v["category"], room=v.get("room_cat"), text=text)
    return objs, False

# ---------- per-group specs (keyed by target map + group number) ----------
# o/or: (labels, room)   -> accept must equal every object with label in labels (and room)
KIND = {
 1: ({"book"}, None), 2: ({"easy chair"}, "bedroom"), 7: ({"pillow"}, None), 8: ({"desk"}, "rec room"),
 13: ({"lamp"}, None), 17: ({"chair"}, "dining room"), 21: ({"bicycle"}, "garage"), 25: ({"mug"}, None),
 26: ({"chair"}, "meeting room"), 29: ({"plant"}, None), 30: ({"chair"}, "kitchen"),
 40: ({"trash can"}, None), 43: ({"side table"}, "living room"), 46: ({"bookshelf"}, None),
}
# od/ord/ard: (labels or None, room or None, words that must all appear in caption/tags) -> exactly {target}
PRED = {
 3: ({"couch"}, None, ["l-shaped", "chaise"]),
 4: ({"set of towels"}, None, ["'h'"]),
 5: ({"easy chair"}, "bathroom", ["beige", "velvet"]),
 6: (None, None, ["pet"]),
 9: ({"pillow"}, None, ["orange", "stripes"]),
 10: ({"chair"}, "rec room", ["brown"]),
 11: (None, None, ["world map"]),
 12: (None, None, ["clock", "wall"]),
 14: ({"chair"}, "kitchen", ["white", "plastic"]),
 15: (None, "hallway", ["coat"]),
 18: ({"table"}, "balcony", ["white", "metal"]),
 19: (None, "dining room", ["baby"]),
 22: ({"chair"}, None, ["red checked"]),
 23: (None, None, ["iron"]),
 27: ({"nightstand"}, "bedroom", ["oak", "open shelf"]),
 31: ({"sofa"}, None, ["brown", "leather"]),
 32: ({"book"}, "office", ["green"]),
 33: ({"mirror"}, "hallway", []),
 37: ({"pillow"}, "bedroom", ["red"]),
 41: ({"microwave"}, None, []),   # scan: the only appliance that reheats food
 44: ({"armchair"}, None, ["brown", "leather"]),
 47: ({"keyboard"}, None, ["white"]),
}

def dist2(a, b):
    return math.hypot(a["c"][0] - b["c"][0], a["c"][1] - b["c"][1])

def overlap_xy(a, b):
    return all(abs(a["c"][i] - b["c"][i]) < (a["s"][i] + b["s"][i]) / 2 for i in (0, 1))

def top(o): return o["c"][2] + o["s"][2] / 2
def bottom(o): return o["c"][2] - o["s"][2] / 2

def ranked(objs, kind, key):
    """Objects of `kind` sorted by key (smaller = better): [(value, id), ...]."""
    return sorted((key(o), i) for i, o in objs.items() if o["label"] == kind)

def margin_check(r, target, what):
    (v0, i0), (v1, i1) = r[0], r[1]
    ok = i0 == target and v1 - v0 >= 0.2
    return ok, f"{what}: best {i0} ({v0:.2f}), runner-up {i1} ({v1:.2f}), margin {v1 - v0:.2f}"

def spatial(g, objs, target):
    O = objs
    if g == 16:  # nightstand nearest the bedroom window (36)
        return [margin_check(ranked(O, "nightstand", lambda o: dist2(o, O[36])), target, "nightstand to window 36")]
    if g == 20:  # lamp hanging above dining table 10
        r = ranked(O, "lamp", lambda o: dist2(o, O[10]) if overlap_xy(o, O[10]) and bottom(o) > top(O[10]) else 99 + dist2(o, O[10]))
        res = [margin_check(r, target, "lamp above table 10 (horizontal dist, 99+ if not above)")]
        res.append((O[4]["s"][2] >= 1.5 and dist2(O[4], O[1]) < 1.8, "w4: lamp 4 is a floor lamp by the sofa 1"))
        return res
    if g == 24:  # bedside lamp nearer the wardrobe 36
        r = [(dist2(O[i], O[36]), i) for i in (34, 35)]
        r.sort()
        res = [margin_check(r, target, "bedside lamps 34/35 to wardrobe 36")]
        res.append((margin_check(ranked(O, "lamp", lambda o: dist2(o, O[36])), target, "all lamps to wardrobe")[0], "all lamps: 34 nearest wardrobe"))
        res.append((O[36]["c"][0] < O[31]["c"][0] and O[34]["c"][0] < O[31]["c"][0], "w5: wardrobe side of bed = west, lamp 34 west"))
        return res
    if g == 28:  # monitor nearest shelving 21
        res = [margin_check(ranked(O, "monitor", lambda o: dist2(o, O[21])), target, "monitor to shelving 21")]
        r = ranked(O, "monitor", lambda o: dist2(o, O[18]))
        res.append((r[0][1] == 16 and r[1][0] - r[0][0] >= 0.2, f"w4: monitor by green lamp 18 is 16 ({r})"))
        return res
    if g == 34:  # sofa under painting 6
        r = ranked(O, "sofa", lambda o: dist2(o, O[6]) if overlap_xy(o, O[6]) and bottom(O[6]) > top(o) else 99 + dist2(o, O[6]))
        res = [margin_check(r, target, "sofa under picture 6")]
        vol = lambda o: o["s"][0] * o["s"][1] * o["s"][2]
        res.append((vol(O[2]) < vol(O[1]), "w4: the other sofa (2) is the small one"))
        return res
    if g == 35:  # lowest book
        return [margin_check(ranked(O, "book", lambda o: o["c"][2]), target, "book height z")]
    if g == 36:  # cabinet under the washbasin 41
        r = ranked(O, "cabinet", lambda o: dist2(o, O[41]) if overlap_xy(o, O[41]) and top(o) <= bottom(O[41]) + 0.1 else 99 + dist2(o, O[41]))
        res = [margin_check(r, target, "cabinet under sink 41")]
        c21, k18 = O[21], O[18]
        res.append((overlap_xy(c21, k18) and bottom(c21) > top(k18), "w4: cabinet 21 is above kitchen counter 18"))
        # nothing else under a sink: cabinet 21 is above sink 17, not under it
        res.append((bottom(O[21]) > top(O[17]), "cabinet 21 is above (not under) kitchen sink 17"))
        return res
    if g == 38:  # lamp nearest window 14
        res = [margin_check(ranked(O, "lamp", lambda o: dist2(o, O[14])), target, "lamp to window 14")]
        r = ranked(O, "lamp", lambda o: dist2(o, O[15]))
        res.append((r[0][1] == 9 and r[1][0] - r[0][0] >= 0.2, f"w4: lamp near door 15 is 9 ({r})"))
        res.append((O[14]["c"][0] < O[1]["c"][0] and O[8]["c"][0] < O[1]["c"][0], "w2: window side of bed = west, lamp 8 west"))
        return res
    if g == 39:  # facing the headboard (north) from the foot: left = west = smallest x
        head_north = max(o["c"][1] for i, o in O.items() if o["label"] == "nightstand") > O[1]["c"][1]
        res = [margin_check(ranked(O, "pillow", lambda o: o["c"][0]), target, "pillow x (left when facing +y)")]
        res.append((head_north, "headboard at the north end (nightstands north of bed centre)"))
        res.append((O[2]["c"][0] < O[4]["c"][0] < O[3]["c"][0], "w4: red pillow 4 is in the middle (x)"))
        return res
    if g == 42:  # kitchen cabinet directly under sink 10
        r = ranked(O, "kitchen cabinet", lambda o: dist2(o, O[10]) if overlap_xy(o, O[10]) and top(o) <= bottom(O[10]) + 0.05 else 99 + dist2(o, O[10]))
        res = [margin_check(r, target, "cabinet under sink 10")]
        r2 = ranked(O, "kitchen cabinet", lambda o: dist2(o, O[10]))
        res.append((r2[0][1] == 3 and r2[1][0] - r2[0][0] >= 0.2, f"plain horizontal distance too: {r2[:3]}"))
        return res
    if g == 45:  # sitting on sofa 1 facing the tv 14 (north): left = west
        facing_north = O[14]["c"][1] > O[1]["c"][1]
        res = [margin_check(ranked(O, "lamp", lambda o: o["c"][0]), target, "lamp x (left when facing +y)")]
        res.append((facing_north, "tv is north of the sofa"))
        return res
    if g == 48:  # office chair nearest red backpack 28
        return [margin_check(ranked(O, "office chair", lambda o: dist2(o, O[28])), target, "office chair to backpack 28")]
    return [(False, f"no spatial check for group {g}")]

# ---------- style ----------
IMPERATIVE = ("go ", "take ", "head ", "bring ", "lead ", "find ", "show ", "guide ", "get ")
ARTICLES = {"a", "an", "the"}
REASON = [" so ", "because", "since", " not ", "not the", "rather than", "i need", "i want", "i'm"]

def words(s):
    return re.findall(r"[a-z0-9'-]+", s.lower())

def label_uses(rows, labels):
    names = {labels[a].lower() for a in rows[0]["accept"]}
    return sum(any(re.search(r"\b" + re.escape(l) + r"(s|es)?\b", r["query"].lower()) for l in names) for r in rows)

def main():
    rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
    problems = []
    groups = defaultdict(list)
    for r in rows:
        groups[r["group"]].append(r)
    typos = {f"b54-g{g:02d}": GROUPS[g - 1][5] for g in range(1, len(GROUPS) + 1)}
    # vocabulary for the typo check: every word of w1..w5 of the suite plus every caption word of every map used
    vocab = set()
    cache = {}
    for r in rows:
        if r["map"] not in cache:
            cache[r["map"]] = load(r["map"])
        if not r["id"].endswith("w6"):
            vocab |= set(words(r["query"]))
    for objs, _ in cache.values():
        for o in objs.values():
            vocab |= set(words(o["text"])) | set(words(o["label"]))
    # correctly spelled w6 words that occur nowhere else in the suite or captions (checked by eye)
    extra_ok = {"lounging", "his", "comfy", "what", "thing", "here", "trousers"}
    vocab |= extra_ok
    # counts
    types = Counter(g[0]["type"] for g in groups.values())
    maps = Counter(g[0]["map"] for g in groups.values())
    if len(rows) != 288 or len(groups) != 48:
        problems.append(f"counts: {len(rows)} lines, {len(groups)} groups")
    want = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    if dict(types) != want:
        problems.append(f"type counts {dict(types)}")
    report = []
    for name in sorted(groups):
        g = int(name[-2:])
        grp = sorted(groups[name], key=lambda r: r["id"])
        r0 = grp[0]
        objs, geo = cache[r0["map"]]
        labels = {i: o["label"] for i, o in objs.items()}
        # ids / consistency
        if [r["id"] for r in grp] != [f"{name}-w{k}" for k in range(1, 7)]:
            problems.append(f"{name}: ids {[r['id'] for r in grp]}")
        if len({(r["map"], r["type"], r["target"], tuple(r["accept"])) for r in grp}) != 1:
            problems.append(f"{name}: inconsistent fields")
        t, target, accept = r0["type"], r0["target"], sorted(r0["accept"])
        if target not in accept:
            problems.append(f"{name}: target not in accept")
        # semantics
        if t in ("o", "or"):
            labs, room = KIND[g]
            derived = sorted(i for i, o in objs.items() if o["label"] in labs and (room is None or o["room"] == room))
            if t == "or" and room is None or t == "o" and room is not None:
                problems.append(f"{name}: kind spec does not fit type")
            ok = derived == accept
            report.append(f"{name} {t:3} {Path(r0['map']).name:28} derived {derived} {'OK' if ok else 'MISMATCH ' + str(accept)}")
            if not ok:
                problems.append(f"{name}: accept {accept} != derived {derived}")
        elif t in ("od", "ord", "ard"):
            if len(accept) != 1:
                problems.append(f"{name}: single-id type with accept {accept}")
            labs, room, ws = PRED[g]
            if t == "ord" and room is None:
                problems.append(f"{name}: ord without room")
            if t == "ard" and label_uses(grp, labels):
                problems.append(f"{name}: ard names the target's kind label")
            hits = sorted(i for i, o in objs.items() if (labs is None or o["label"] in labs)
                          and (room is None or o["room"] == room) and all(w in o["text"] or w in o["label"].lower() for w in ws))
            ok = hits == [target]
            report.append(f"{name} {t:3} {Path(r0['map']).name:28} predicate {labs} {room} {ws} -> {hits} {'OK' if ok else 'FAIL'}")
            if not ok:
                problems.append(f"{name}: predicate selects {hits}, target {target}")
        elif t == "s":
            if not geo:
                problems.append(f"{name}: spatial on caption map")
            for ok, msg in spatial(g, objs, target):
                report.append(f"{name} s   {Path(r0['map']).name:28} {msg} {'OK' if ok else 'FAIL'}")
                if not ok:
                    problems.append(f"{name}: {msg}")
        # style
        q = [r["query"] for r in grp]
        if not q[0].lower().startswith(IMPERATIVE):
            problems.append(f"{name} w1 not imperative: {q[0]}")
        if not (q[1].startswith("Could you ") and q[1].endswith("?")):
            problems.append(f"{name} w2 not a Could-you question: {q[1]}")
        w3 = words(q[2])
        if len(w3) > 6 or ARTICLES & set(w3):
            problems.append(f"{name} w3 telegraphic rule: {q[2]}")
        if not any(m in " " + q[3].lower() + " " for m in REASON):
            problems.append(f"{name} w4 lacks reason/contrast: {q[3]}")
        sents = [s for s in re.split(r"(?<=[.!?])\s+", q[4].strip()) if s]
        if len(sents) != 2 or not sents[0].startswith("This is ") or not q[4].rstrip()[-1] in ".!?":
            problems.append(f"{name} w5 two-sentence rule: {q[4]}")
        typo, right = typos[name]
        w6 = words(q[5])
        unknown = [w for w in w6 if w not in vocab]
        if q[5] != q[5].lower() or unknown != [typo] or w6.count(typo) != 1:
            problems.append(f"{name} w6 typo rule: unknown words {unknown}, declared {typo}: {q[5]}")
        if right not in vocab:
            problems.append(f"{name} w6 intended word {right} not in vocab")
        # label rule
        n = label_uses(grp, labels)
        if n > 2:
            problems.append(f"{name}: label in {n} wordings")
        if len({x.lower() for x in q}) != 6:
            problems.append(f"{name}: duplicate wordings")
    for line in report:
        print(line)
    print("groups per type", dict(types))
    print("groups per map", {Path(k).name: v for k, v in maps.items()})
    print("PROBLEMS:" if problems else "no problems")
    for p in problems:
        print("  ", p)
    return 1 if problems else 0

if __name__ == "__main__":
    sys.exit(main())
