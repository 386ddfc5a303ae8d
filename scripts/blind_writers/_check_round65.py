"""Check evals/blind/round65.jsonl against the maps and the brief's rules.

- re-derives every o/or accept set from the map (kind labels below, room where given);
- checks each od/ord/ard claim: among the objects of the named kind(s) (and room), exactly the
  target carries all the description terms (for ard: the only object that serves the need);
- checks each s claim numerically from centres and sizes, with a margin >= 0.2 m over the
  runner-up;
- checks the style rules of w1..w6, the map-label rule, counts per type and per map.

    python3 scripts/check.py
"""
import json
import math
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from _common_round65 import load_objects, words  # noqa: E402
from _suite_data_round65 import GROUPS  # noqa: E402  (only for the declared typos of w6)

SUITE = Path(__file__).resolve().parents[2] / "evals" / "blind" / "round65.jsonl"
MARGIN = 0.2

C829 = "../../../shared/data/iesm_maps/scene_00829_caption.json"
OFF3 = "../../../shared/data/iesm_maps/scene_office3_caption.json"
FC, FD, FF, FH = "maps/flat_c.json", "maps/flat_d.json", "maps/flat_f.json", "maps/flat_h.json"
APT = "apartment"
SB, SK, SL, SO = ("../maps/scan_bedroom.json", "../maps/scan_kitchen.json",
                  "../maps/scan_livingroom.json", "../maps/scan_office.json")

# group number -> (map, type, spec).  Kinds are the labels a person would accept for the words used.
SPECS = {
    1: (C829, "o", dict(kind={"mirror frame"})),
    2: (C829, "o", dict(kind={"book"})),
    3: (C829, "or", dict(kind={"easy chair"}, room="bedroom")),
    4: (C829, "or", dict(kind={"set of towels", "hand towel"}, room="living room")),
    5: (C829, "od", dict(kind={"decorative bowl", "bowl with sweets"}, terms=["blue", "gold"])),
    6: (C829, "ord", dict(kind={"doorway", "door frame", "door/window frame"}, room="living room",
                          terms=["peephole", "gold"])),
    7: (C829, "ard", dict(serves={"bed for pet"}, room="bathroom")),
    8: (OFF3, "o", dict(kind={"pillow"})),
    9: (OFF3, "or", dict(kind={"curtain"}, room="rec room")),
    10: (OFF3, "od", dict(kind={"desk", "table"}, terms=["cable", "brown"])),
    11: (OFF3, "ord", dict(kind={"chair"}, room="rec room", terms=["black", "plastic", "speaker"])),
    12: (OFF3, "ard", dict(serves={"clock"}, room="rec room")),
    13: (FC, "o", dict(kind={"lamp"})),
    14: (FC, "ord", dict(kind={"armchair"}, room="living room", terms=["mustard", "yellow"])),
    15: (FC, "ard", dict(serves={"coat rack"}, room="hallway")),
    16: (FC, "s", dict(rel="under", kind={"nightstand"}, anchor=29)),
    17: (FD, "s", dict(rel="tallest", kind={"plant"})),
    18: (FD, "or", dict(kind={"lamp"}, room="studio")),
    19: (FD, "od", dict(kind={"rug"}, terms=["round", ("rainbow", "multicolored")])),
    20: (FD, "ard", dict(serves={"dryer"}, room="laundry room")),
    21: (FF, "s", dict(rel="nearest", kind={"chair"}, anchor=17)),
    22: (FF, "o", dict(kind={"rug"})),
    23: (FF, "ord", dict(kind={"cabinet"}, room="bathroom", terms=["mirrored", "medicine"])),
    24: (FF, "ard", dict(serves={"telescope"}, room="porch")),
    25: (FH, "s", dict(rel="nearest", kind={"chair"}, anchor=20)),
    26: (FH, "or", dict(kind={"nightstand"}, room="master bedroom")),
    27: (FH, "od", dict(kind={"mirror"}, terms=["oval", ("brass", "gold")])),
    28: (FH, "ard", dict(serves={"sink"}, room="kitchen")),
    29: (APT, "o", dict(kind={"mirror"})),
    30: (APT, "or", dict(kind={"chair"}, room="kitchen")),
    31: (APT, "od", dict(kind={"sofa"}, terms=["brown", "leather", "small"])),
    32: (APT, "ord", dict(kind={"book"}, room="living room", terms=["yellow", "photo"])),
    33: (APT, "ard", dict(serves={"printer"}, room="office")),
    34: (APT, "s", dict(rel="on", kind={"pillow"}, anchor=32)),
    35: (APT, "s", dict(rel="below", kind={"sofa"}, anchor=6)),
    36: (APT, "s", dict(rel="nearest", kind={"chair"}, anchor=19)),
    37: (SB, "s", dict(rel="nearest", kind={"nightstand"}, anchor=15)),
    38: (SB, "s", dict(rel="leftmost", kind={"pillow"}, facing=(0.0, 1.0))),
    39: (SB, "od", dict(kind={"pillow"}, terms=["blue"])),
    40: (SK, "s", dict(rel="nearest", kind={"cup"}, anchor=10)),
    41: (SK, "s", dict(rel="above", kind={"kitchen cabinet"}, anchor=10)),
    42: (SK, "or", dict(kind={"chair"}, room="kitchen")),
    43: (SL, "s", dict(rel="rightmost", kind={"pillow"}, facing=(0.0, 1.0), terms=["red"])),
    44: (SL, "o", dict(kind={"picture"})),
    45: (SL, "ord", dict(kind={"lamp"}, room="living room", terms=["black"])),
    46: (SO, "od", dict(kind={"keyboard"}, terms=["white"])),
    47: (SO, "ord", dict(kind={"bookshelf"}, room="office", terms=["white"])),
    48: (SO, "ard", dict(serves={"whiteboard"}, room="office")),
}

CAPTION_MAPS = {C829, OFF3}
FLATS = {FC, FD, FF, FH}
SCANS = {SB, SK, SL, SO}
WANT_TYPES = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
IMPERATIVES = {"take", "go", "head", "lead", "bring", "guide", "navigate", "show", "find", "please"}
STOP = {"a", "an", "the", "to", "of", "in", "on", "i", "me", "it", "is", "and", "or", "there", "take",
        "go", "where", "what", "with", "by"}


def has_term(text: str, term) -> bool:
    alts = term if isinstance(term, tuple) else (term,)
    return any(re.search(r"\b" + re.escape(t), text) for t in alts)


def footprint_dist(p, o) -> float:
    """xy distance from point p to the footprint of box o (0 inside)."""
    (cx, cy, _), (sx, sy, _) = o["center"], o["size"]
    dx = max(abs(p[0] - cx) - sx / 2, 0.0)
    dy = max(abs(p[1] - cy) - sy / 2, 0.0)
    return math.hypot(dx, dy)


def top(o):
    return o["center"][2] + o["size"][2] / 2


def bottom(o):
    return o["center"][2] - o["size"][2] / 2


def spatial_scores(objs, spec):
    """candidate id -> score, lower is better (the claimed object should be lowest)."""
    cands = {i: o for i, o in objs.items() if o["label"] in spec["kind"]}
    if "terms" in spec:
        cands = {i: o for i, o in cands.items() if all(has_term(o["text"], t) for t in spec["terms"])}
    rel = spec["rel"]
    a = objs.get(spec.get("anchor"))
    scores = {}
    for i, o in cands.items():
        c = o["center"]
        if rel == "nearest":
            scores[i] = math.dist(c[:2], a["center"][:2])
        elif rel == "tallest":
            scores[i] = -top(o)
        elif rel == "on":      # o rests on the anchor
            scores[i] = footprint_dist(c, a) + abs(bottom(o) - top(a))
        elif rel == "under":   # the anchor rests on o
            scores[i] = footprint_dist(a["center"], o) + abs(bottom(a) - top(o))
        elif rel == "below":   # o is below the anchor (anchor hangs above it)
            scores[i] = footprint_dist(a["center"], o) + max(top(o) - bottom(a), 0.0)
        elif rel == "above":   # o is above the anchor: must start above its top
            scores[i] = math.dist(c[:2], a["center"][:2]) if bottom(o) >= top(a) - 1e-6 else math.inf
        elif rel in ("leftmost", "rightmost"):
            fx, fy = spec["facing"]
            left = (-fy, fx)   # the viewer's left, facing (fx, fy)
            along = c[0] * left[0] + c[1] * left[1]
            scores[i] = -along if rel == "leftmost" else along
        else:
            raise ValueError(rel)
    return scores


def check_claim(objs, geo, gtype, spec, target, accept):
    """list of problems with the group's accept set / claim."""
    probs = []
    room_ok = (lambda o: o["room"] == spec["room"]) if "room" in spec else (lambda o: True)
    if gtype in ("o", "or"):
        derived = sorted(i for i, o in objs.items() if o["label"] in spec["kind"] and room_ok(o))
        if derived != sorted(accept):
            probs.append(f"accept {sorted(accept)} != derived {derived}")
        return probs, f"derived {derived}"
    if sorted(accept) != [target]:
        probs.append("single-id group with more than one accepted id")
    if gtype in ("od", "ord"):
        kind = [i for i, o in objs.items() if o["label"] in spec["kind"] and room_ok(o)]
        hits = [i for i in kind if all(has_term(objs[i]["text"], t) for t in spec["terms"])]
        if hits != [target]:
            probs.append(f"description matches {hits} among kind {kind}")
        return probs, f"{len(kind)} of kind, match {hits}"
    if gtype == "ard":
        serv = [i for i, o in objs.items() if o["label"] in spec["serves"] and room_ok(o)]
        anywhere = [i for i, o in objs.items() if o["label"] in spec["serves"]]
        if serv != [target]:
            probs.append(f"need served by {serv}")
        return probs, f"serves in room {serv}, anywhere {anywhere}"
    if gtype == "s":
        if not geo:
            return ["spatial group on a map without geometry"], ""
        sc = spatial_scores(objs, spec)
        order = sorted(sc, key=sc.get)
        if not order or order[0] != target:
            probs.append(f"best is {order[:1]} not {target}: {sc}")
            return probs, ""
        best = sc[order[0]]
        nxt = sc[order[1]] if len(order) > 1 else math.inf
        if spec["rel"] in ("on", "under", "below") and best > 0.05:
            probs.append(f"target does not touch/overlap the anchor (score {best:.3f})")
        if spec["rel"] == "above" and footprint_dist(objs[spec["anchor"]]["center"], objs[target]) > 0:
            probs.append("anchor centre not under the target footprint")
        if nxt - best < MARGIN:
            probs.append(f"margin {nxt - best:.3f} < {MARGIN}")
        detail = ", ".join(f"{i}:{sc[i]:.2f}" for i in order[:4])
        if "terms" in spec:  # the claim must also hold among all objects of the kind
            sc_all = spatial_scores(objs, {k: v for k, v in spec.items() if k != "terms"})
            o_all = sorted(sc_all, key=sc_all.get)
            m_all = sc_all[o_all[1]] - sc_all[o_all[0]] if len(o_all) > 1 else math.inf
            if o_all[0] != target or m_all < MARGIN:
                probs.append(f"without the description terms: best {o_all[0]}, margin {m_all:.3f}")
            detail += f"; among all of the kind margin {m_all:.2f}"
        return probs, f"{spec['rel']} scores {detail}; margin {nxt - best:.2f}"
    return [f"unknown type {gtype}"], ""


def load_dict():
    p = Path("/usr/share/dict/american-english")
    return {w.strip().lower() for w in p.read_text(encoding="utf-8", errors="ignore").splitlines()}


def edit_distance(a, b):
    d = list(range(len(b) + 1))
    for i, ca in enumerate(a, 1):
        prev, d[0] = d[0], i
        for j, cb in enumerate(b, 1):
            prev, d[j] = d[j], min(d[j] + 1, d[j - 1] + 1, prev + (ca != cb))
    return d[-1]


def main():
    rows = [json.loads(x) for x in SUITE.read_text(encoding="utf-8").splitlines()]
    groups = defaultdict(list)
    for r in rows:
        groups[r["group"]].append(r)
    errors, notes = [], []
    dictionary = load_dict()
    vocab = set()
    for r in rows:
        if not r["id"].endswith("w6"):
            vocab.update(words(r["query"]))
    maps = {}
    per_type, per_map, s_maps = Counter(), Counter(), Counter()
    if len(rows) != 288 or len(groups) != 48:
        errors.append(f"{len(rows)} lines, {len(groups)} groups")
    for gname in sorted(groups):
        g = sorted(groups[gname], key=lambda r: r["id"])
        num = int(gname.split("-g")[1])
        r0 = g[0]
        mp, gtype, spec = SPECS[num]
        if mp != r0["map"] or gtype != r0["type"]:
            errors.append(f"{gname}: spec map/type {mp}/{gtype} != suite {r0['map']}/{r0['type']}")
            continue
        if r0["map"] not in maps:
            maps[r0["map"]] = load_objects(r0["map"])
        objs, geo = maps[r0["map"]]
        probs, detail = check_claim(objs, geo, gtype, spec, r0["target"], r0["accept"])
        errors += [f"{gname} ({gtype}, {Path(mp).name}): {p}" for p in probs]
        notes.append(f"{gname} {gtype:3s} {Path(mp).name:28s} target {r0['target']:>3} ({objs[r0['target']]['label']}): {detail}")
        per_type[gtype] += 1
        cat = ("caption" if mp in CAPTION_MAPS else "flats" if mp in FLATS else "apartment" if mp == APT
               else "scans")
        per_map[cat] += 1
        if gtype == "s":
            s_maps[cat] += 1
        # ----- style -----
        q = [r["query"] for r in g]
        if [r["id"][-2:] for r in g] != ["w1", "w2", "w3", "w4", "w5", "w6"]:
            errors.append(f"{gname}: wording ids {[r['id'] for r in g]}")
        if words(q[0])[0] not in IMPERATIVES:
            errors.append(f"{gname} w1 not an imperative: {q[0]}")
        if not (q[1].startswith("Could you ") and q[1].endswith("?")):
            errors.append(f"{gname} w2 not 'Could you ...?': {q[1]}")
        w3 = words(q[2])
        if len(q[2].split()) > 6 or {"a", "an", "the"} & set(w3):
            errors.append(f"{gname} w3 telegraphic rule: {q[2]}")
        if not re.search(r"\b(so|because|since|as)\b|, not\b|\bnot the\b", q[3]):
            errors.append(f"{gname} w4 no reason/contrast: {q[3]}")
        sents = [s for s in re.split(r"(?<=[.!?])\s+", q[4].strip()) if s]
        if not q[4].startswith("This is ") or len(sents) != 2:
            errors.append(f"{gname} w5 not two sentences starting 'This is': {q[4]}")
        if q[5] != q[5].lower():
            errors.append(f"{gname} w6 not lower case: {q[5]}")
        typo, meant = GROUPS[num - 1]["typo"]
        odd = [w for w in words(q[5]) if w not in dictionary and w not in vocab]
        if odd != [typo] or typo in dictionary or edit_distance(typo, meant) > 2 or meant in STOP:
            errors.append(f"{gname} w6 typo check: unknown words {odd}, declared {typo!r}->{meant!r}")
        if meant not in words(" ".join(q[:5])) and meant not in dictionary:
            errors.append(f"{gname} w6 intended word {meant!r} unknown")
        # ----- map label rule (same as validate.py) and alt labels -----
        names = {objs[a]["label"].lower() for a in r0["accept"]}
        uses = sum(any(re.search(r"\b" + re.escape(n) + r"(s|es)?\b", x.lower()) for n in names) for x in q)
        if uses > 2:
            errors.append(f"{gname}: map label in {uses} wordings")
        alts = {a.lower() for i in r0["accept"] for a in objs[i]["alt"]}
        alt_uses = sum(any(re.search(r"\b" + re.escape(n) + r"(s|es)?\b", x.lower()) for n in alts) for x in q)
        if alt_uses:
            notes.append(f"{gname}: an alt label appears in {alt_uses} wordings (label uses {uses})")
        if len({x.lower() for x in q}) != 6:
            errors.append(f"{gname}: duplicate wordings")
    if dict(per_type) != WANT_TYPES:
        errors.append(f"types {dict(per_type)} != {WANT_TYPES}")
    if s_maps["caption"] or not (s_maps["flats"] and s_maps["apartment"] and s_maps["scans"]):
        errors.append(f"s spread {dict(s_maps)}")
    for n in notes:
        print(n)
    print(f"groups per type {dict(per_type)}; per map family {dict(per_map)}; s per family {dict(s_maps)}")
    for e in errors:
        print("ERROR", e)
    print(f"{len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
