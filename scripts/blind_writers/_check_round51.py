"""Check evals/blind/round51.jsonl against the maps: re-derive o/or accept sets, verify every single-id
claim (numerically for s: centre distances / heights with >= 0.2 m margin over the runner-up), the
wording style rules, the label rule and the counts.  Prints problems; exit 1 if any."""
import json, math, re, sys
from collections import Counter, defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from _common_round51 import load, captions

SUITE = Path(__file__).resolve().parents[2] / "evals/blind/round51.jsonl"
MARGIN = 0.2
problems = []


def bad(msg):
    problems.append(msg)


# ---------------------------------------------------------------- helpers over a map
def ids(recs, labels=None, room=None, pred=None):
    out = set()
    for r in recs.values():
        if labels is not None and r["label"] not in labels:
            continue
        if room is not None and r["room"] != room:
            continue
        if pred is not None and not pred(r):
            continue
        out.add(r["id"])
    return out


def text(r):
    return " ".join([r["label"], r["color"], r["material"], r["caption"], json.dumps(r["tags"])]).lower()


def has(*words):
    return lambda r: all(w.lower() in text(r) for w in words)


def d2(a, b):
    return math.dist(a["center"][:2], b["center"][:2])


def ranked(values):
    """values: {id: score}, lower is better -> (best id, margin over runner-up)."""
    order = sorted(values.items(), key=lambda kv: kv[1])
    return order[0][0], (order[1][1] - order[0][1]) if len(order) > 1 else math.inf


def nearest(recs, cands, ref):
    return ranked({c: d2(recs[c], recs[ref]) for c in cands})


def bottom(r):
    return r["center"][2] - r["size"][2] / 2


def top(r):
    return r["center"][2] + r["size"][2] / 2


def rests_on(upper, lower):
    """upper's centre lies inside lower's footprint and upper's bottom is at lower's top (5 cm)."""
    (x, y), (cx, cy) = upper["center"][:2], lower["center"][:2]
    sx, sy = lower["size"][:2]
    return abs(x - cx) <= sx / 2 and abs(y - cy) <= sy / 2 and abs(bottom(upper) - top(lower)) <= 0.05


def supported(recs, cands, thing_labels):
    """candidates that have an object with one of thing_labels resting on them."""
    return {c for c in cands if any(rests_on(t, recs[c]) for t in recs.values() if t["label"] in thing_labels)}


def expect_winner(g, what, best, margin, target):
    if best != target:
        bad(f"{g}: {what}: winner {best}, expected {target}")
    elif margin < MARGIN:
        bad(f"{g}: {what}: margin {margin:.2f} < {MARGIN}")
    else:
        report.append(f"{g}: {what}: {best} by {margin:.2f} m")


report = []

# ---------------------------------------------------------------- the spec, written by hand
# o / or: (kind labels, room or None) -> accept set re-derived from the map
KIND = {
    "b51-g01": ({"book"}, None),
    "b51-g02": ({"set of towels", "hand towel"}, None),
    "b51-g03": ({"easy chair"}, "bedroom"),
    "b51-g08": ({"window"}, None),
    "b51-g09": ({"pillow"}, "rec room"),
    "b51-g13": ({"lamp"}, None),
    "b51-g14": ({"chair"}, "kitchen"),
    "b51-g17": ({"lamp"}, "studio"),
    "b51-g21": ({"armchair"}, None),
    "b51-g29": ({"sofa"}, None),
    "b51-g30": ({"book"}, "living room"),
    "b51-g31": ({"chair"}, "kitchen"),
    "b51-g40": ({"chair"}, None),
    "b51-g43": ({"lamp"}, "living room"),
}

# od / ord / ard: (candidate labels or None, room or None, predicate) -> must be exactly {target}
UNIQUE = {
    "b51-g04": (None, None, has("peephole")),
    "b51-g05": ({"easy chair"}, "bathroom", has("beige", "velvet")),
    "b51-g06": (None, None, has("pet")),
    "b51-g07": (None, "bedroom", has("wine", "glass door")),
    "b51-g10": ({"pillow"}, None, has("navy", "velvet")),
    "b51-g11": ({"desk"}, "rec room", has("white", "wood")),
    "b51-g12": ({"clock", "phone", "watch"}, "rec room", has("wall")),  # the phone also tells time, not on a wall
    "b51-g15": ({"armchair"}, None, has("mustard")),
    "b51-g18": ({"lamp"}, "kids room", has("pink", "moon")),
    "b51-g19": ({"ironing board", "iron"}, "laundry room", None),
    "b51-g22": ({"rug"}, "bedroom", has("striped")),
    "b51-g23": ({"telescope", "binoculars"}, "porch", None),
    "b51-g25": ({"mirror"}, None, has("led")),
    "b51-g26": ({"armchair"}, "living room", has("yellow", "velvet")),
    "b51-g27": (None, "hallway", has("keys")),
    "b51-g32": ({"sofa"}, None, has("brown", "leather", "worn")),
    "b51-g33": ({"book"}, "office", has("green")),
    "b51-g34": ({"printer"}, "office", None),
    "b51-g37": ({"pillow"}, None, has("red")),
    "b51-g42": ({"coffee maker", "kettle"}, None, None),
    "b51-g45": ({"armchair"}, None, has("green")),
    "b51-g46": ({"table"}, "office", has("wood")),
}

# extra facts used by contrasts in w4/w5 of single-id groups: (description, fn(recs) -> bool)
FACTS = {
    "b51-g04": [("smart lock belongs to another doorway", lambda R: ids(R, None, None, has("smart lock")) == {3})],
    "b51-g05": [("other beige velvet easy chair is in the living room", lambda R: ids(R, {"easy chair"}, "living room", has("beige", "velv")) != set())],
    "b51-g07": [("other bedroom wine storage has no glass door", lambda R: ids(R, None, "bedroom", has("wine")) == {264, 273})],
    "b51-g10": [("other pillows orange/yellow", lambda R: {R[i]["color"] for i in ids(R, {"pillow"}) - {13}} <= {"orange", "yellow"})],
    "b51-g11": [("other desks brown wood", lambda R: all(R[i]["color"] == "brown" for i in ids(R, {"desk"}) - {7}))],
    "b51-g15": [("other armchair grey", lambda R: [R[i]["color"] for i in ids(R, {"armchair"}) - {2}] == ["gray"])],
    "b51-g18": [("studio desk lamp is silver", lambda R: R[9]["color"] == "silver" and R[9]["room"] == "studio")],
    "b51-g22": [("lounge rug red patterned", lambda R: ids(R, {"rug"}, "living room", has("red", "patterned")) == {7})],
    "b51-g23": [("rocking chair is on the porch", lambda R: R[21]["room"] == "porch" and "rocking" in R[21]["caption"])],
    "b51-g25": [("other mirror oval brass", lambda R: ids(R, {"mirror"}, None, has("oval", "brass")) == {2})],
    "b51-g26": [("other living room armchair brown leather", lambda R: ids(R, {"armchair"}, "living room") - {11} == {10} and R[10]["material"] == "leather"),
                ("yellow armchair in a corner", lambda R: "corner" in R[11]["caption"])],
    "b51-g31": [("office chair is red", lambda R: R[48]["color"] == "red")],
    "b51-g32": [("big sofa is gray three-seater", lambda R: "three-seater" in R[1]["caption"] and R[1]["color"] == "gray")],
    "b51-g33": [("other books in living room", lambda R: ids(R, {"book"}, "living room") == {12, 13})],
    "b51-g37": [("other pillows white/blue", lambda R: {R[i]["color"] for i in ids(R, {"pillow"}) - {4}} == {"white", "blue"})],
    "b51-g45": [("other armchair brown leather", lambda R: R[6]["material"] == "leather" and R[6]["color"] == "brown")],
    "b51-g46": [("other office table white", lambda R: R[1]["color"] == "white")],
}


def spatial(g, R):
    """Hand-coded numeric checks of every s group."""
    if g == "b51-g16":  # flat_c chair closest to the fridge (13); contrast: 19 is the far-west one
        expect_winner(g, "chair nearest fridge", *nearest(R, ids(R, {"chair"}), 13), 20)
        expect_winner(g, "westernmost kitchen chair (contrast)", *ranked({c: R[c]["center"][0] for c in ids(R, {"chair"}, "kitchen")}), 19)
    elif g == "b51-g20":  # flat_d stool nearest the bin 23; west side; other nearer fridge 15
        expect_winner(g, "stool nearest bin", *nearest(R, ids(R, {"stool"}), 23), 21)
        expect_winner(g, "westernmost stool", *ranked({c: R[c]["center"][0] for c in ids(R, {"stool"})}), 21)
        expect_winner(g, "stool nearest fridge (contrast)", *nearest(R, ids(R, {"stool"}), 15), 22)
    elif g == "b51-g24":  # flat_f kitchen chair nearest dresser 16; south-east; 14 by the stove 17
        k = ids(R, {"chair"}, "kitchen")
        expect_winner(g, "kitchen chair nearest dresser", *nearest(R, k, 16), 13)
        expect_winner(g, "most south-east kitchen chair", *ranked({c: R[c]["center"][1] - R[c]["center"][0] for c in k}), 13)
        expect_winner(g, "kitchen chair nearest stove (contrast)", *nearest(R, k, 17), 14)
    elif g == "b51-g28":  # flat_h bedside table with the paperback 49 on it; east side of bed 45
        n = ids(R, {"nightstand"})
        got = supported(R, n, {"book"})
        (bad if got != {47} else report.append)(f"{g}: nightstands with a book on them {got}")
        near = min(math.dist(R[49]["center"][:2], R[c]["center"][:2]) for c in n - {47})
        (bad if near < 1 else report.append)(f"{g}: book to nearest other nightstand {near:.2f} m")
        lamps = supported(R, n, {"lamp"})
        (bad if 47 in lamps or not lamps else report.append)(f"{g}: nightstands with a lamp {lamps}")
        east = R[47]["center"][0] - R[45]["center"][0]
        (bad if east < MARGIN else report.append)(f"{g}: 47 east of bed centre by {east:.2f}; 46 at {R[46]['center'][0] - R[45]['center'][0]:.2f}")
        (bad if R[49]["color"] != "orange" else report.append)(f"{g}: book colour {R[49]['color']}")
    elif g == "b51-g35":  # apartment higher book on living room bookcase
        b = ids(R, {"book"}, "living room")
        expect_winner(g, "highest living-room book", *ranked({c: -R[c]["center"][2] for c in b}), 12)
        (bad if not all(abs(R[c]["center"][0] - R[11]["center"][0]) < 0.2 for c in b) else report.append)(f"{g}: both books on bookcase 11")
    elif g == "b51-g36":  # apartment plant resting on the dresser 38; others on the floor
        p = ids(R, {"plant"})
        got = {c for c in p if rests_on(R[c], R[38])}
        (bad if got != {39} else report.append)(f"{g}: plants on the dresser {got}")
        expect_winner(g, "plant bottom highest off floor", *ranked({c: -bottom(R[c]) for c in p}), 39)
    elif g == "b51-g38":  # scan_bedroom nightstand with the book 20; clock 21 on the other; door side
        n = ids(R, {"nightstand"})
        got = supported(R, n, {"book"})
        (bad if got != {7} else report.append)(f"{g}: nightstands with a book {got}")
        got = supported(R, n, {"clock"})
        (bad if got != {6} else report.append)(f"{g}: nightstands with a clock {got}")
        expect_winner(g, "nightstand nearest door", *nearest(R, n, 15), 7)
        (bad if R[20]["color"] != "blue" else report.append)(f"{g}: book is blue")
    elif g == "b51-g39":  # scan_bedroom lamp nearest the door 15; the other nearest the window 14
        l = ids(R, {"lamp"})
        expect_winner(g, "lamp nearest door", *nearest(R, l, 15), 9)
        expect_winner(g, "lamp nearest window (contrast)", *nearest(R, l, 14), 8)
    elif g == "b51-g41":  # scan_kitchen cabinet under the sink 10; microwave on another
        c = ids(R, {"kitchen cabinet"})
        got = {k for k in c if rests_on(R[10], R[k])}
        (bad if got != {3} else report.append)(f"{g}: cabinets under the sink {got}")
        expect_winner(g, "cabinet centre nearest sink", *nearest(R, c, 10), 3)
        got = {k for k in c if rests_on(R[11], R[k])}
        (bad if got != {6} else report.append)(f"{g}: cabinets under the microwave {got}")
    elif g == "b51-g44":  # scan_livingroom red pillow nearest leather armchair 6; east end
        red = ids(R, {"pillow"}, None, lambda r: r["color"] == "red")
        expect_winner(g, "red pillow nearest armchair 6", *nearest(R, red, 6), 4)
        expect_winner(g, "easternmost red pillow", *ranked({c: -R[c]["center"][0] for c in red}), 4)
        (bad if R[6]["material"] != "leather" else report.append)(f"{g}: armchair 6 leather")
    elif g == "b51-g47":  # scan_office shortest bookshelf
        expect_winner(g, "shortest bookshelf", *ranked({c: R[c]["size"][2] for c in ids(R, {"bookshelf"})}), 16)
    elif g == "b51-g48":  # scan_office office chair nearest the red backpack 28; blue neighbour 7
        ch = ids(R, {"office chair"})
        expect_winner(g, "office chair nearest backpack", *nearest(R, ch, 28), 8)
        (bad if R[28]["color"] != "red" else report.append)(f"{g}: backpack red")
        best, m = nearest(R, ch - {8}, 8)
        (bad if best != 7 or R[7]["color"] != "blue" else report.append)(f"{g}: nearest chair to 8 is {best} ({R[best]['color']})")
    else:
        bad(f"{g}: no spatial check written")


# w6 typos: (misspelt token, intended word)
TYPO = {
    "b51-g01": ("volum", "volume"), "b51-g02": ("towls", "towels"), "b51-g03": ("armchiar", "armchair"),
    "b51-g04": ("peephol", "peephole"), "b51-g05": ("bathrom", "bathroom"), "b51-g06": ("sleepign", "sleeping"),
    "b51-g07": ("glas", "glass"), "b51-g08": ("windos", "windows"), "b51-g09": ("cusion", "cushion"),
    "b51-g10": ("cushon", "cushion"), "b51-g11": ("whtie", "white"), "b51-g12": ("tiem", "time"),
    "b51-g13": ("lmaps", "lamps"), "b51-g14": ("chiar", "chair"), "b51-g15": ("mustrad", "mustard"),
    "b51-g16": ("frdige", "fridge"), "b51-g17": ("studoi", "studio"), "b51-g18": ("childern's", "children's"),
    "b51-g19": ("iorn", "iron"), "b51-g20": ("tarsh", "trash"), "b51-g21": ("eazy", "easy"),
    "b51-g22": ("bedroon", "bedroom"), "b51-g23": ("plannets", "planets"), "b51-g24": ("dinning", "dining"),
    "b51-g25": ("rectangualr", "rectangular"), "b51-g26": ("velvt", "velvet"), "b51-g27": ("kyes", "keys"),
    "b51-g28": ("paprback", "paperback"), "b51-g29": ("coutch", "couch"), "b51-g30": ("livng", "living"),
    "b51-g31": ("kitchn", "kitchen"), "b51-g32": ("lether", "leather"), "b51-g33": ("textbok", "textbook"),
    "b51-g34": ("prnit", "print"), "b51-g35": ("lving", "living"), "b51-g36": ("drawres", "drawers"),
    "b51-g37": ("cushoin", "cushion"), "b51-g38": ("tabel", "table"), "b51-g39": ("dorr", "door"),
    "b51-g40": ("seet", "seat"), "b51-g41": ("cuboard", "cupboard"), "b51-g42": ("cofee", "coffee"),
    "b51-g43": ("lihgt", "light"), "b51-g44": ("pilow", "pillow"), "b51-g45": ("gren", "green"),
    "b51-g46": ("woodden", "wooden"), "b51-g47": ("shortst", "shortest"), "b51-g48": ("backpak", "backpack"),
}

ARTICLES = {"a", "an", "the"}


def words(q):
    return re.findall(r"[a-z0-9][a-z0-9'\-]*", q.lower())


def sentences(q):
    return [s for s in re.split(r"(?<=[.?!])\s+", q.strip()) if s]


def main():
    rows = [json.loads(l) for l in SUITE.read_text(encoding="utf-8").splitlines()]
    groups = defaultdict(list)
    for r in rows:
        groups[r["group"]].append(r)
    maps = {}
    all_queries = Counter(r["query"].lower() for r in rows)
    for q, n in all_queries.items():
        if n > 1:
            bad(f"duplicate wording across suite: {q!r}")

    # vocabulary of correctly spelt words: w1-w5 of every group, every caption and label of every map
    vocab = set()
    for r in rows:
        if not r["id"].endswith("w6"):
            vocab |= set(words(r["query"]))
    for r in rows:
        if r["map"] not in maps:
            maps[r["map"]] = load(r["map"])
    for recs, _ in maps.values():
        for rec in recs.values():
            vocab |= set(words(rec["caption"] + " " + rec["label"] + " " + rec["room"]))
    # real English words that occur only in some w6 wordings (checked by eye)
    vocab |= {"kind", "flip", "dog's", "keep", "see", "tickets", "lamps", "stripy"}

    per_type, per_map, fam = Counter(), Counter(), Counter()
    for g, rs in sorted(groups.items()):
        rs.sort(key=lambda r: r["id"])
        r0 = rs[0]
        recs, geom = maps[r0["map"]]
        typ, target, accept = r0["type"], r0["target"], set(r0["accept"])
        per_type[typ] += 1
        per_map[r0["map"]] += 1
        family = ("caption" if not geom else "apartment" if r0["map"] == "apartment"
                  else "flat" if "flat_" in r0["map"] else "scan")
        fam[family] += 1
        if [r["id"] for r in rs] != [f"{g}-w{i}" for i in range(1, 7)]:
            bad(f"{g}: ids {[r['id'] for r in rs]}")
        if any((r["type"], r["target"], set(r["accept"]), r["map"]) != (typ, target, accept, r0["map"]) for r in rs):
            bad(f"{g}: lines disagree")
        if target not in accept:
            bad(f"{g}: target not in accept")
        # --- claims
        if typ in ("o", "or"):
            labels, room = KIND[g]
            if typ == "or" and room is None or typ == "o" and room is not None:
                bad(f"{g}: spec room does not fit type")
            derived = ids(recs, labels, room)
            (bad if derived != accept else report.append)(f"{g}: {typ} {sorted(labels)} in {room}: derived {sorted(derived)} vs accept {sorted(accept)}")
        elif typ in ("od", "ord", "ard"):
            if len(accept) != 1:
                bad(f"{g}: single-id type with accept {accept}")
            labels, room, pred = UNIQUE[g]
            if typ == "ord" and room is None:
                bad(f"{g}: ord without room in spec")
            got = ids(recs, labels, room, pred)
            (bad if got != {target} else report.append)(f"{g}: {typ} unique match {sorted(got)} (target {target})")
            for desc, fn in FACTS.get(g, []):
                (report.append if fn(recs) else bad)(f"{g}: fact '{desc}': {fn(recs)}")
        elif typ == "s":
            if not geom:
                bad(f"{g}: spatial on a caption map")
            if len(accept) != 1:
                bad(f"{g}: s with accept {accept}")
            spatial(g, recs)
        # --- label rule (same regex as validate.py) and alt labels for information
        names = {recs[a]["label"].lower() for a in accept}
        uses = sum(any(re.search(r"\b" + re.escape(n) + r"(s|es)?\b", r["query"].lower()) for n in names) for r in rs)
        if uses > 2:
            bad(f"{g}: map label in {uses} wordings")
        # --- style
        q = [r["query"] for r in rs]
        if not re.match(r"^(Go to|Take me to) ", q[0]):
            bad(f"{g} w1 not a plain imperative: {q[0]}")
        if not (q[1].startswith("Could you ") and q[1].endswith("?")):
            bad(f"{g} w2: {q[1]}")
        w3 = words(q[2])
        if len(w3) > 6 or ARTICLES & set(w3):
            bad(f"{g} w3 too long or has articles: {q[2]}")
        if not re.search(r"\b(so|because|since|not)\b", q[3].lower()):
            bad(f"{g} w4 has no reason/contrast marker: {q[3]}")
        s5 = sentences(q[4])
        if not q[4].startswith("This is ") or len(s5) != 2:
            bad(f"{g} w5 shape ({len(s5)} sentences): {q[4]}")
        if q[5] != q[5].lower():
            bad(f"{g} w6 not lower case: {q[5]}")
        typo, meant = TYPO[g]
        w6 = words(q[5])
        if w6.count(typo) != 1 or typo in vocab or meant not in vocab:
            bad(f"{g} w6 typo {typo!r} (meant {meant!r}) missing, repeated or a real word")
        unknown = [w for w in w6 if w != typo and w not in vocab]
        if unknown:
            bad(f"{g} w6 other words not in the vocabulary (second typo?): {unknown}")
        if len({x.lower() for x in q}) != 6:
            bad(f"{g}: wordings not distinct")

    # --- counts
    want = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    if dict(per_type) != want:
        bad(f"type counts {dict(per_type)} != {want}")
    if len(rows) != 288 or len(groups) != 48:
        bad(f"{len(rows)} lines, {len(groups)} groups")
    s_fam = Counter()
    for g, rs in groups.items():
        if rs[0]["type"] == "s":
            s_fam["apartment" if rs[0]["map"] == "apartment" else "flat" if "flat_" in rs[0]["map"] else "scan"] += 1
    for line in report:
        print("ok  ", line)
    print("types", dict(per_type))
    print("families", dict(fam), "s per family", dict(s_fam))
    for m, n in sorted(per_map.items()):
        print(f"  {n:2d}  {m}")
    for p in problems:
        print("PROBLEM", p)
    print(f"{len(problems)} problems")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
