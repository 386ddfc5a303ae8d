"""Check evals/blind/round57.jsonl against the maps and the brief's rules.

- o / or: re-derive the accept set from the map (every object whose label/category is one of the
  group's kind labels, in the named room for `or`) and compare.
- od / ord: the target has every distinguishing attribute (tags + caption text); every other
  object of the kind (in the room, for ord) lacks at least one.
- ard: exactly one object (in the room, if given) is of a kind that meets the need; the
  wordings use none of the forbidden kind words.
- s: numeric check of the relation from centres and sizes, margin >= 0.2 m over the runner-up.
- style: w1 imperative, w2 "Could you ...?", w3 <= 6 words and no articles, w4 reason/contrast,
  w5 two sentences starting "This is", w6 lower case with exactly the declared typo as its only
  non-dictionary word; no stray non-dictionary words elsewhere; map label in <= 2 wordings.
- counts per type and per map, 6 wordings per group, unique ids.
"""

import json
import math
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _build_round57 import G

ROOT = Path(__file__).resolve().parents[2]
SUITE = ROOT / "evals/blind/round57.jsonl"
# the writer read scripts/specs.json, which their build.py wrote from G
SPECS = {f"b57-g{i:02d}": {k: grp[k] for k in ("map", "type", "target", "accept", "spec", "typo", "forbid")}
         for i, grp in enumerate(G, 1)}
WORDS = {w.strip().lower() for w in open("/usr/share/dict/words", encoding="utf-8", errors="ignore")}
# ordinary words or abbreviations missing from the system word list
ALLOW = {"tv", "rec", "i'm", "i'd", "i've", "it's", "that's", "doesn't", "can't", "we're", "dad's",
         "dog's", "bed's", "sofa's", "studio's", "office's", "worktable", "washbasin", "worktop",
         "loveseat", "houseplants", "houseplant", "sectional", "l", "coloured", "favourite",
         "grey", "blue-grey", "grey-blue", "glass-top", "glass-topped", "wall-mounted", "ladder-back",
         "off-white", "two-seater", "two-seat", "right-hand", "gold-framed", "blue-gray",
         "blue-and-gold", "mustard-coloured", "l-shaped", "floorboards", "backless", "stargazing",
         "greenery", "patterning", "shimmery", "handheld", "colour", "bookcase", "bookshelves",
         "bookshelf", "nightstand", "kitchenette", "cushion", "paperback", "wingback", "cupboard",
         "textbook", "fridge", "settee", "drapes", "chaise", "gilded", "cobalt", "studded"}
IMPERATIVE = {"go", "take", "bring", "head", "lead", "guide", "show", "navigate", "move", "find"}
ARTICLES = {"a", "an", "the"}
REASON = re.compile(r"\b(not|so|because|since|as|for)\b")
errors, notes = [], []


def err(msg):
    errors.append(msg)


def resolve(map_):
    p = (ROOT / "evals/blind" / map_).resolve()
    return p if p.is_file() else ROOT / "map_store" / f"{map_}.json"


def load(map_):
    data = json.loads(resolve(map_).read_text())
    objs = {}
    if isinstance(data, dict) and "objects" in data:
        for o in data["objects"]:
            text = " ".join([o.get("caption", ""), " ".join(str(v) for v in o.get("tags", {}).values())]).lower()
            objs[int(o["id"])] = dict(label=o["label"], room=o["room"], text=text, geo=o)
        return objs, True
    for k, v in data.items():
        cap = v.get("caption", "")
        m = re.search(r'"captions"\s*:\s*"(.*?)"\s*,?\s*\n', cap, re.S)
        col = re.search(r'"color"\s*:\s*"(.*?)"', cap)
        mat = re.search(r'"material"\s*:\s*"(.*?)"', cap)
        text = " ".join(x.group(1) for x in (m, col, mat) if x).lower()
        objs[int(k)] = dict(label=v["category"], room=v.get("room_cat"), text=text, geo=None)
    return objs, False


def captions(map_):
    objs, _ = load(map_)
    return [o["text"] for o in objs.values()]


def rooms_of(objs, o):
    r = o["room"]
    if isinstance(r, int):  # apartment stores one room by id
        data = json.loads(resolve("apartment").read_text())
        r = {x["id"]: x["label"] for x in data["rooms"]}[r]
    return r


def dist(a, b):
    return math.dist(a["center"][:2], b["center"][:2])


def gap(a, b):
    g = [max(0.0, abs(a["center"][i] - b["center"][i]) - (a["size"][i] + b["size"][i]) / 2) for i in range(2)]
    return math.hypot(*g)


def overlap_xy(a, b):
    """overlap area of the two footprints (m^2)"""
    ov = 1.0
    for i in range(2):
        lo = max(a["center"][i] - a["size"][i] / 2, b["center"][i] - b["size"][i] / 2)
        hi = min(a["center"][i] + a["size"][i] / 2, b["center"][i] + b["size"][i] / 2)
        ov *= max(0.0, hi - lo)
    return ov


def top(o):
    return o["center"][2] + o["size"][2] / 2


def bottom(o):
    return o["center"][2] - o["size"][2] / 2


def check_spatial(gid, spec, objs, target):
    kind = [i for i, o in objs.items() if o["label"] in spec["kinds"]
            and (spec.get("room") is None or rooms_of(objs, o) == spec["room"])]
    rel, geo = spec["rel"], {i: objs[i]["geo"] for i in objs}
    ref = geo.get(spec.get("ref"))
    if rel == "nearest":  # smaller is better: centre distance and box gap
        score = {i: (dist(geo[i], ref), gap(geo[i], ref)) for i in kind if i != spec["ref"]}
    elif rel == "holds":  # the ref object stands on the candidate
        score = {i: (dist(geo[i], ref), 0 if (overlap_xy(geo[i], ref) > 0 and abs(bottom(ref) - top(geo[i])) < 0.06) else 9)
                 for i in kind}
    elif rel == "on":  # the candidate stands on the ref object
        score = {i: (dist(geo[i], ref), 0 if (overlap_xy(geo[i], ref) > 0 and abs(bottom(geo[i]) - top(ref)) < 0.06) else 9)
                 for i in kind}
    elif rel == "above":  # candidate over the ref: footprints overlap and candidate bottom >= ref top
        score = {i: (dist(geo[i], ref), 0 if (overlap_xy(geo[i], ref) > 0 and bottom(geo[i]) >= top(ref) - 0.01) else 9)
                 for i in kind}
    elif rel == "under":
        score = {i: (dist(geo[i], ref), 0 if (overlap_xy(geo[i], ref) > 0 and top(geo[i]) <= bottom(ref) + 0.01) else 9)
                 for i in kind}
        # horizontal overlap of footprints in x, as a second measure (bigger is better)
        ov = {i: overlap_xy(geo[i], ref) for i in kind}
        notes.append(f"{gid}: under: footprint overlaps with the sink {sorted(((round(v, 3), i) for i, v in ov.items()), reverse=True)[:3]}")
    elif rel == "foot_of_bed":  # bed head is where the nightstands are (north): foot = south edge midpoint
        bed = ref
        foot = {"center": [bed["center"][0], bed["center"][1] - bed["size"][1] / 2, 0], "size": [0, 0, 0]}
        ns = [objs[i]["geo"] for i in objs if objs[i]["label"] == "nightstand"]
        assert all(n["center"][1] > bed["center"][1] for n in ns), "head of the bed is not north"
        score = {i: (dist(geo[i], foot), gap(geo[i], foot)) for i in kind}
    elif rel == "right_beside":  # sitting on the ref facing `facing`: right = +x when facing north
        face = geo[spec["facing"]]
        assert face["center"][1] > ref["center"][1] + 2 and abs(face["center"][0] - ref["center"][0]) < 0.5
        beside = [i for i in kind if gap(geo[i], ref) < 0.5]
        notes.append(f"{gid}: lamps beside the sofa (gap<0.5 m): {beside}; others {[i for i in kind if i not in beside]}")
        score = {i: (-(geo[i]["center"][0] - ref["center"][0]), -(geo[i]["center"][0] - ref["center"][0])) for i in beside}
    elif rel == "shortest":
        score = {i: (geo[i]["size"][2], geo[i]["size"][2]) for i in kind}
    else:
        err(f"{gid}: unknown relation {rel}")
        return
    ranked = sorted(score.items(), key=lambda kv: kv[1])
    if ranked[0][0] != target:
        err(f"{gid}: spatial winner {ranked[0][0]} != target {target}: {ranked}")
        return
    if len(ranked) > 1:
        m0 = ranked[1][1][0] - ranked[0][1][0]
        m1 = ranked[1][1][1] - ranked[0][1][1]
        if rel in ("holds", "on", "above", "under"):
            ok = ranked[0][1][1] == 0 and ranked[1][1][1] == 9 and m0 >= 0.2
        else:
            ok = m0 >= 0.2 and m1 >= 0.2 - 1e-9 or (rel == "nearest" and m0 >= 0.2 and m1 >= 0.2)
        notes.append(f"{gid}: s {rel}: target {target} score {tuple(round(x, 3) for x in ranked[0][1])}, "
                     f"runner-up {ranked[1][0]} {tuple(round(x, 3) for x in ranked[1][1])}, centre margin {m0:.3f}")
        if not ok:
            err(f"{gid}: spatial margin too small: {ranked[:3]}")


def main():
    rows = [json.loads(line) for line in SUITE.read_text().splitlines()]
    ids = Counter(r["id"] for r in rows)
    for k, v in ids.items():
        if v > 1:
            err(f"duplicate id {k}")
    groups = defaultdict(list)
    for r in rows:
        groups[r["group"]].append(r)
    per_type, per_map, per_family = Counter(), Counter(), Counter()
    for gid, rs in groups.items():
        spec_all = SPECS[gid]
        spec, typ, target, accept = spec_all["spec"], rs[0]["type"], rs[0]["target"], sorted(rs[0]["accept"])
        if len(rs) != 6 or [r["id"] for r in rs] != [f"{gid}-w{j}" for j in range(1, 7)]:
            err(f"{gid}: wordings missing or out of order")
        if len({(r["map"], r["type"], r["target"], tuple(sorted(r["accept"]))) for r in rs}) != 1:
            err(f"{gid}: fields differ")
        objs, geom = load(rs[0]["map"])
        per_type[typ] += 1
        mapname = Path(rs[0]["map"]).name
        per_map[mapname] += 1
        per_family["caption" if not geom else "apartment" if mapname == "apartment" else
                   "scans" if mapname.startswith("scan") else "flats"] += 1
        qs = [r["query"] for r in rs]
        # ---- accept sets and claims
        if typ in ("o", "or"):
            derived = sorted(i for i, o in objs.items() if o["label"] in spec["kinds"]
                             and (typ == "o" or rooms_of(objs, o) == spec["room"]))
            if derived != accept:
                err(f"{gid}: accept {accept} but map gives {derived}")
            if len(derived) < 2:
                notes.append(f"{gid}: only one object of the kind")
        elif typ in ("od", "ord"):
            if accept != [target]:
                err(f"{gid}: single-id group with accept {accept}")
            kind = [i for i, o in objs.items() if o["label"] in spec["kinds"]
                    and (typ == "od" or rooms_of(objs, o) == spec["room"])]
            if target not in kind:
                err(f"{gid}: target not of the kind / room")
            if not all(a in objs[target]["text"] for a in spec["attrs"]):
                err(f"{gid}: target lacks {spec['attrs']}: {objs[target]['text']}")
            rivals = [i for i in kind if i != target and all(a in objs[i]["text"] for a in spec["attrs"])]
            if rivals:
                err(f"{gid}: attributes {spec['attrs']} also fit {rivals}")
            notes.append(f"{gid}: {typ} kind has {len(kind)} objects {kind}; attrs {spec['attrs']} fit only {target}")
        elif typ == "ard":
            if accept != [target]:
                err(f"{gid}: single-id group with accept {accept}")
            meets = [i for i, o in objs.items() if (o["label"] in spec["need_kinds"]
                     or any(re.search(r"\b" + w + r"\b", o["label"]) for w in spec["need_words"]))
                     and (spec.get("room") is None or rooms_of(objs, o) == spec["room"])]
            if spec.get("gray_low"):
                extra = [i for i, o in objs.items() if "gray" in o["text"] and o["geo"]["size"][2] <= 0.5]
                meets = sorted(set(meets) | set(extra))
            if meets != [target]:
                err(f"{gid}: need met by {meets}")
            for q in qs:
                for w in spec_all["forbid"]:
                    if re.search(r"\b" + re.escape(w) + r"\b", q.lower()):
                        err(f"{gid}: ard wording names the kind '{w}': {q}")
        elif typ == "s":
            if not geom:
                err(f"{gid}: spatial group on a caption map")
            if accept != [target]:
                err(f"{gid}: single-id group with accept {accept}")
            check_spatial(gid, spec, objs, target)
        # ---- label use
        labels = {objs[a]["label"].lower() for a in accept}
        uses = sum(any(re.search(r"\b" + re.escape(lab) + r"(s|es)?\b", q.lower()) for lab in labels) for q in qs)
        if uses > 2:
            err(f"{gid}: map label in {uses} wordings")
        # ---- style
        w1, w2, w3, w4, w5, w6 = qs
        if w1.split()[0].lower() not in IMPERATIVE:
            err(f"{gid} w1 not imperative")
        if not (w2.startswith("Could you ") and w2.endswith("?")):
            err(f"{gid} w2 not a Could-you question")
        t3 = re.findall(r"[a-z0-9'\-]+", w3.lower())
        if len(w3.split()) > 6 or ARTICLES & set(t3):
            err(f"{gid} w3 not telegraphic: {w3}")
        if not REASON.search(w4.lower()):
            err(f"{gid} w4 has no reason/contrast marker")
        sents = [s for s in re.split(r"(?<=[.!?])\s+", w5.strip()) if s]
        if len(sents) != 2 or not w5.startswith("This is "):
            err(f"{gid} w5 not two sentences starting 'This is': {sents}")
        if w6 != w6.lower():
            err(f"{gid} w6 not lower case")
        for j, q in enumerate(qs, 1):
            toks = [t.strip("'-") for t in re.findall(r"[a-z0-9'\-]+", q.lower())]
            unknown = [t for t in toks if t and t not in WORDS and t not in ALLOW
                       and not all(p in WORDS or p in ALLOW for p in t.split("-") if p)]
            if j == 6:
                if unknown != [spec_all["typo"]]:
                    err(f"{gid} w6 unknown words {unknown}, declared typo {spec_all['typo']!r}")
            elif unknown:
                err(f"{gid} w{j} unknown words {unknown}")
    # ---- counts
    want_type = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    if dict(per_type) != want_type:
        err(f"type counts {dict(per_type)} != {want_type}")
    if len(rows) != 288 or len(groups) != 48:
        err(f"{len(rows)} lines, {len(groups)} groups")
    s_maps = Counter(Path(g[0]["map"]).name for g in groups.values() if g[0]["type"] == "s")
    for e in errors:
        print("ERROR", e)
    if "-v" in sys.argv:
        for n in notes:
            print("note", n)
    print("per type", dict(per_type))
    print("per map", dict(per_map))
    print("per family", dict(per_family))
    print("s groups per map", dict(s_maps))
    print(f"{len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
