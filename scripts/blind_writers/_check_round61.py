"""Re-derive and check round61.jsonl: accept sets of o/or groups from the maps, the claim of every
single-id group (numerically for s, margin >= 0.2 m), the wording style rules and the counts."""
import json
import math
import re
import sys
from collections import Counter
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _maps_round61 import BLIND, load
from _groups_round61 import G

MARGIN = 0.2
DICT = {w.strip().lower() for w in open("/usr/share/dict/words", encoding="utf-8", errors="ignore")}
OK_WORDS = {"rec", "tv", "i'm", "it's", "there's", "i've", "you're", "that's", "what's", "kids'", "pet's",
            "sofa's", "l", "fridge", "towel",
            "loveseat", "nightstand", "seater", "touchless", "armless", "stargazing", "colour", "coloured"}
errors, notes = [], []


def err(m):
    errors.append(m)


def xy(o):
    return o["center"][0], o["center"][1]


def dist(a, b):
    return math.dist(xy(a), xy(b))


def ranked(cands, key, reverse=False):
    """(best, margin over the runner-up) of candidates sorted by key."""
    r = sorted(cands, key=key, reverse=reverse)
    return r[0], abs(key(r[1]) - key(r[0]))


def nearest(M, cand_ids, ref_id):
    return ranked([M[i] for i in cand_ids], lambda o: dist(o, M[ref_id]))


def lab(M, *labels, room=None, contains=False):
    ids = set()
    for o in M.values():
        ok = any((lb in o["label"]) if contains else (o["label"] == lb) for lb in labels)
        if ok and (room is None or o["room"] == room):
            ids.add(o["id"])
    return ids


def only(M, ids, pred):
    return {i for i in ids if pred(M[i])}


# ---- o / or: accept sets re-derived from the maps ----
def derive(gi, M):
    return {
        1: lambda: lab(M, "book"),
        2: lambda: lab(M, "towel", room="living room", contains=True),
        3: lambda: lab(M, "mirror", room="bathroom", contains=True),
        8: lambda: lab(M, "pillow"),
        9: lambda: lab(M, "curtain"),
        16: lambda: lab(M, "lamp", room="living room"),
        25: lambda: lab(M, "chair", room="dining room"),
        26: lambda: lab(M, "mirror"),
        29: lambda: lab(M, "plant"),
        30: lambda: lab(M, "chair", room="kitchen"),
        39: lambda: lab(M, "nightstand"),
        41: lambda: lab(M, "chair", room="kitchen"),
        47: lambda: lab(M, "plant"),
        48: lambda: lab(M, "keyboard", room="office"),
    }[gi]()


# ---- od / ord / ard: the set of objects meeting the stated description must be exactly {target} ----
def claim(gi, M):
    c = {
        4: lambda: only(M, lab(M, "couch", "sofa"), lambda o: "l-shaped" in o["caption"].lower()),
        5: lambda: only(M, lab(M, "sink", "washbasin", room="bathroom", contains=True), lambda o: "touchless" in o["caption"]),
        6: lambda: only(M, lab(M, "easy chair", room="bathroom"), lambda o: "velvet" in o["material"] and "beige" in o["color"]),
        7: lambda: {o["id"] for o in M.values() if "pet" in o["label"].split() or "dog" in o["caption"].lower()},
        10: lambda: only(M, lab(M, "desk"), lambda o: "white" in o["color"]),
        11: lambda: only(M, lab(M, "chair", room="rec room"), lambda o: "brown" in o["color"] and "leather" in o["material"]),
        12: lambda: only(M, lab(M, "sofa", "couch", "bed", "bench", room="rec room"), lambda o: "gray" in o["color"]),
        14: lambda: only(M, lab(M, "armchair"), lambda o: "mustard" in o["color"]),
        15: lambda: lab(M, "coat rack", room="hallway"),
        18: lambda: {o["id"] for o in M.values() if "dryer" in o["label"] or "dryer" in o["caption"].lower().replace("next to", "")} - lab(M, "washing machine"),
        19: lambda: only(M, lab(M, "chair"), lambda o: "yellow" in o["color"]),
        21: lambda: only(M, lab(M, "armchair", room="living room"), lambda o: "cream" in o["color"] and "leather" in o["material"]),
        22: lambda: {o["id"] for o in M.values() if o["label"] == "telescope" or "stargazing" in o["caption"]},
        23: lambda: only(M, lab(M, "cabinet"), lambda o: "mirrored" in o["caption"]),
        27: lambda: only(M, lab(M, "lamp", room="guest bedroom"), lambda o: "red" in o["color"]),
        28: lambda: {o["id"] for o in M.values() if o["room"] == "hallway" and "keys" in o["caption"]},
        31: lambda: only(M, lab(M, "sofa"), lambda o: "brown" in o["color"] and "leather" in o["material"]),
        32: lambda: only(M, lab(M, "cabinet", room="bathroom"), lambda o: "gray" in o["color"]),
        33: lambda: {o["id"] for o in M.values() if o["label"] == "washing machine" or "washer" in o["alt"]},
        34: lambda: lab(M, "mirror", room="hallway"),
        42: lambda: only(M, lab(M, "chair", room="kitchen"), lambda o: "red" in o["color"]),
        45: lambda: only(M, lab(M, "armchair"), lambda o: "leather" in o["material"]),
    }
    return c[gi]()


# ---- s: numeric checks; each returns (winner id, margin in metres) ----
def spatial(gi, M):
    if gi == 13:  # chair nearest the fridge (all chairs, also office chair)
        b, m = nearest(M, lab(M, "chair", "office chair"), 13)
        return b["id"], m
    if gi == 17:  # rug under the low table 2: xy distance rug centre -> table centre, rug below the table
        rugs = lab(M, "rug")
        t = M[2]
        assert all(M[r]["center"][2] < t["center"][2] for r in rugs)
        b, m = nearest(M, rugs, 2)
        return b["id"], m
    if gi == 20:  # chair nearest the sink 19 (all chairs; also among blue ones)
        b, m = nearest(M, lab(M, "chair"), 19)
        b2, m2 = nearest(M, only(M, lab(M, "chair"), lambda o: o["color"] == "blue"), 19)
        assert b2["id"] == b["id"]
        return b["id"], min(m, m2)
    if gi == 24:  # nightstand the book 49 lies on: xy distance, and book bottom at nightstand top
        bk = M[49]
        b, m = nearest(M, lab(M, "nightstand"), 49)
        top = b["center"][2] + b["size"][2] / 2
        bottom = bk["center"][2] - bk["size"][2] / 2
        assert abs(top - bottom) < 0.05 and dist(b, bk) < b["size"][0] / 2
        return b["id"], m
    if gi == 35:  # the higher book in the living room
        b, m = ranked([M[i] for i in lab(M, "book", room="living room")], lambda o: o["center"][2], reverse=True)
        return b["id"], m
    if gi == 36:  # the pillow on a sofa: xy distance to nearest sofa footprint
        sofas = [M[i] for i in lab(M, "sofa")]
        def gap(o):
            return min(math.hypot(max(abs(o["center"][0] - s["center"][0]) - s["size"][0] / 2, 0),
                                  max(abs(o["center"][1] - s["center"][1]) - s["size"][1] / 2, 0)) for s in sofas)
        b, m = ranked([M[i] for i in lab(M, "pillow")], gap)
        return b["id"], m
    if gi == 37:  # lamp nearest the window 14
        b, m = nearest(M, lab(M, "lamp"), 14)
        return b["id"], m
    if gi == 38:  # white pillow nearest the door 15
        b, m = nearest(M, only(M, lab(M, "pillow"), lambda o: o["color"] == "white"), 15)
        return b["id"], m
    if gi == 40:  # lower kitchen cabinet under the sink 10
        low = only(M, lab(M, "kitchen cabinet"), lambda o: o["center"][2] + o["size"][2] / 2 <= M[10]["center"][2])
        b, m = nearest(M, low, 10)
        return b["id"], m
    if gi == 43:  # red pillow on the right when sitting on the sofa facing the TV (TV north of sofa -> right = +x)
        assert M[14]["center"][1] > M[1]["center"][1]
        b, m = ranked([M[i] for i in only(M, lab(M, "pillow"), lambda o: o["color"] == "red")], lambda o: o["center"][0], reverse=True)
        b2, m2 = ranked([M[i] for i in lab(M, "pillow")], lambda o: o["center"][0], reverse=True)
        assert b2["id"] == b["id"]
        return b["id"], min(m, m2)
    if gi == 44:  # lamp nearest the door 22
        b, m = nearest(M, lab(M, "lamp"), 22)
        return b["id"], m
    if gi == 46:  # blue office chair nearest the printer 25
        b, m = nearest(M, only(M, lab(M, "office chair"), lambda o: o["color"] == "blue"), 25)
        return b["id"], m
    raise KeyError(gi)


def toks(q):
    return re.findall(r"[a-z']+", q.lower().replace("-", " "))


def indict(t):
    t = t.strip("'")
    if t in DICT or t in OK_WORDS or not t:
        return True
    for suf in ("s", "es", "'s"):
        if t.endswith(suf) and t[: -len(suf)] in DICT:
            return True
    return False


def edit(a, b):
    d = list(range(len(b) + 1))
    for i, ca in enumerate(a, 1):
        p, d[0] = d[0], i
        for j, cb in enumerate(b, 1):
            p, d[j] = d[j], min(d[j] + 1, d[j - 1] + 1, p + (ca != cb))
    return d[-1]


IMPERATIVE = {"go", "take", "head", "lead", "bring", "guide", "show", "walk", "get", "find", "steer"}
ARTICLES = {"a", "an", "the"}
REASON = re.compile(r"\b(so|because|since|not|rather than|instead of)\b", re.I)

suite = [json.loads(line) for line in (BLIND / "round61.jsonl").read_text().splitlines()]
assert len(suite) == 288 == 6 * len(G), len(suite)
maps, per_type, per_map = {}, Counter(), Counter()
for gi, g in enumerate(G, 1):
    gid = f"b61-g{gi:02d}"
    rows = [r for r in suite if r["group"] == gid]
    if [r["query"] for r in rows] != g["w"]:
        err(f"{gid}: suite lines differ from groups.py")
    M = maps.setdefault(g["map"], load(g["map"]))
    t, tgt, acc = g["type"], g["target"], set(g["accept"])
    per_type[t] += 1
    per_map[Path(g["map"]).name] += 1
    geom = next(iter(M.values()))["geometry"]
    if tgt not in acc:
        err(f"{gid}: target not in accept")
    # --- the claim ---
    if t in ("o", "or"):
        d = derive(gi, M)
        if d != acc:
            err(f"{gid}: accept {sorted(acc)} but map gives {sorted(d)}")
        notes.append(f"{gid} {t}: accept {sorted(d)} re-derived")
    elif t in ("od", "ord", "ard"):
        c = claim(gi, M)
        if c != {tgt} or acc != {tgt}:
            err(f"{gid}: description met by {sorted(c)}, target {tgt}, accept {sorted(acc)}")
    elif t == "s":
        if not geom:
            err(f"{gid}: s on a map without geometry")
        w, m = spatial(gi, M)
        if w != tgt or m < MARGIN - 1e-9 or acc != {tgt}:
            err(f"{gid}: spatial winner {w} margin {m:.3f}")
        notes.append(f"{gid} s: winner {w}, margin {m:.2f} m")
    # --- wordings ---
    w = g["w"]
    if len(w) != 6 or len({x.lower() for x in w}) != 6:
        err(f"{gid}: not six distinct wordings")
    if w[0].split()[0].lower() not in IMPERATIVE:
        err(f"{gid} w1: not a plain imperative: {w[0]}")
    if not (w[1].startswith("Could you ") and w[1].endswith("?")):
        err(f"{gid} w2: not a 'Could you ...?' question")
    w3 = re.findall(r"[A-Za-z0-9'\-]+", w[2])
    if len(w3) > 6 or ARTICLES & {x.lower() for x in w3}:
        err(f"{gid} w3: not telegraphic: {w[2]}")
    if not REASON.search(w[3]):
        err(f"{gid} w4: no reason or contrast: {w[3]}")
    sents = [s for s in re.split(r"(?<=[.!?])\s+", w[4].strip()) if s]
    if len(sents) != 2 or not sents[0].startswith("This is "):
        err(f"{gid} w5: not two sentences opening 'This is': {w[4]}")
    if w[5] != w[5].lower():
        err(f"{gid} w6: not all lower case")
    bad = [x for x in toks(w[5]) if not indict(x)]
    wrong, right = g["typo"]
    if bad != [wrong] or not indict(right) or edit(wrong, right) > 2:
        err(f"{gid} w6: typo check: non-words {bad}, declared {wrong}->{right}")
    for k in range(5):
        bad = [x for x in toks(w[k]) if not indict(x)]
        if bad:
            notes.append(f"{gid} w{k+1}: words not in the dictionary (check by eye): {bad}")
    # --- map label in at most 2 wordings (labels of the accept set) ---
    names = {M[a]["label"] for a in acc}
    uses = sum(any(re.search(r"\b" + re.escape(n) + r"(s|es)?\b", x.lower()) for n in names) for x in w)
    if uses > 2:
        err(f"{gid}: map label in {uses} wordings")
    # --- required words (room for or/ord, disambiguating words for s) ---
    if g["need"]:
        for k, x in enumerate(w, 1):
            if not any(n in x.lower() for n in g["need"]):
                err(f"{gid} w{k}: lacks one of {g['need']}")
    # --- ard names no object kind ---
    if t == "ard":
        kinds = {o["label"] for o in M.values()} | set(g.get("ban", []))
        for k, x in enumerate(w, 1):
            for kind in kinds:
                if re.search(r"\b" + re.escape(kind) + r"(s|es)?\b", x.lower()):
                    # a kind named only to rule it out after "not" is still a kind; report all
                    err(f"{gid} w{k}: ard wording names a kind '{kind}': {x}")
    # --- od names no room ---
    if t == "od":
        rooms = {o["room"] for o in M.values() if o["room"]}
        for k, x in enumerate(w, 1):
            for rm in rooms:
                if re.search(r"\b" + re.escape(rm) + r"\b", x.lower()):
                    err(f"{gid} w{k}: od wording names room '{rm}'")
    if t == "s" and not geom:
        err(f"{gid}: s on caption map")

# counts
want = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
if dict(per_type) != want:
    err(f"type counts {dict(per_type)} != {want}")
cap = sum(v for k, v in per_map.items() if "caption" in k)
flats = sum(v for k, v in per_map.items() if k.startswith("flat_"))
scans = sum(v for k, v in per_map.items() if k.startswith("scan_"))
print(f"groups {len(G)}; per type {dict(per_type)}")
print(f"per map {dict(per_map)}")
print(f"caption maps {cap}, flats {flats}, apartment {per_map['apartment']}, scans {scans}")
for n in notes:
    print("note:", n)
for e in errors:
    print("ERROR:", e)
print(f"{len(errors)} errors")
sys.exit(1 if errors else 0)
