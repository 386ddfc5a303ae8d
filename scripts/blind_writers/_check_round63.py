"""Re-derive every group's claim from its map and check the style rules and counts of round63.

    python3 scripts/check.py
"""
import json
import math
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _common_round63 import BLIND, load, words
from _groups_round63 import G

SUITE = BLIND / "round63.jsonl"
errors, notes = [], []
rows = [json.loads(x) for x in SUITE.read_text().splitlines()]
bygroup = defaultdict(list)
for r in rows:
    bygroup[r["group"]].append(r)

def err(gid, msg): errors.append(f"{gid}: {msg}")

def d2(a, b): return math.hypot(a[0] - b[0], a[1] - b[1])

def pick(objs, labels, room=None):
    return [o for o in objs if o["label"] in labels and (room is None or o["room"] == room)]

def margin_check(gid, scores, target, best="min", what=""):
    """scores: {id: value}; target must be best with >= 0.2 over runner-up."""
    order = sorted(scores, key=lambda i: scores[i], reverse=(best == "max"))
    if order[0] != target:
        err(gid, f"{what}: best is {order[0]} not {target} ({scores})")
        return
    if len(order) > 1:
        m = abs(scores[order[0]] - scores[order[1]])
        notes.append(f"{gid} {what}: target {target}={scores[target]:.2f}, runner-up {order[1]}={scores[order[1]]:.2f}, margin {m:.2f}")
        if m < 0.2 - 1e-9:
            err(gid, f"{what}: margin {m:.3f} < 0.2")

IMPERATIVES = ("Go to", "Take me to", "Bring me to", "Head to", "Lead me to", "Show me", "Navigate to")
ARTICLES = {"a", "an", "the"}
REASON = (", not ", " not the ", " so ", "because", "since", "rather than", " except ")
STOP = {"the", "a", "an", "to", "in", "on", "of", "by", "me", "my", "is", "it", "i", "and", "or", "any", "one"}

maps = {}
per_type, per_map = Counter(), Counter()
all_queries = Counter()
for i, gr in enumerate(G, 1):
    gid = f"b63-g{i:02d}"
    rs = bygroup.get(gid, [])
    if [r["query"] for r in rs] != gr["w"]:
        err(gid, "suite lines differ from source (rebuild)")
    if gr["map"] not in maps:
        maps[gr["map"]] = load(gr["map"])
    objs = maps[gr["map"]]
    byid = {o["id"]: o for o in objs}
    t, spec, target, accept = gr["type"], gr["spec"], gr["target"], sorted(gr["accept"])
    per_type[t] += 1
    per_map[Path(gr["map"]).name] += 1
    geometry = objs[0]["center"] is not None
    if target not in accept:
        err(gid, "target not in accept")
    # ---- claims
    if t in ("o", "or"):
        got = sorted(o["id"] for o in pick(objs, spec["labels"], spec.get("room")))
        if got != accept:
            err(gid, f"accept {accept} but map gives {got}")
    elif t in ("od", "ord", "ard"):
        if accept != [target]:
            err(gid, "single-id type with several accepted ids")
        cands = pick(objs, spec["labels"], spec.get("room"))
        cands = [o for o in cands if all(w in o["text"] for w in spec.get("words", []))]
        if [o["id"] for o in cands] != [target]:
            err(gid, f"claim met by {[o['id'] for o in cands]}")
        if t == "ord" and "room" not in spec:
            err(gid, "ord without room")
        if t == "od" and "room" in spec:
            err(gid, "od with room")
        if t == "ord":  # does the room matter? (information only)
            wo = [o["id"] for o in pick(objs, spec["labels"]) if all(w in o["text"] for w in spec.get("words", []))]
            notes.append(f"{gid} ord: without the room the description fits {wo}")
    elif t == "s":
        if not geometry:
            err(gid, "spatial group on a caption map")
            continue
        if accept != [target]:
            err(gid, "s with several accepted ids")
        k = spec["kind"]
        cands = pick(objs, spec["cands"], spec.get("room"))
        if k == "nearest":
            ref = byid[spec["ref"]]
            margin_check(gid, {o["id"]: d2(o["center"], ref["center"]) for o in cands if o["id"] != ref["id"]},
                         target, "min", f"nearest {ref['label']} {ref['id']}")
            if "broad" in spec:
                bro = pick(objs, spec["broad"], spec.get("broad_room"))
                margin_check(gid, {o["id"]: d2(o["center"], ref["center"]) for o in bro if o["id"] != ref["id"]},
                             target, "min", f"broad {spec['broad']} nearest {ref['label']}")
        elif k == "largest":
            margin_check(gid, {o["id"]: max(o["size"][:2]) for o in cands}, target, "max", "longest footprint side")
            margin_check(gid, {o["id"]: o["size"][0] * o["size"][1] for o in cands}, target, "max", "footprint area m2")
        elif k == "tallest":
            margin_check(gid, {o["id"]: o["size"][2] for o in cands}, target, "max", "height")
            margin_check(gid, {o["id"]: o["center"][2] + o["size"][2] / 2 for o in cands}, target, "max", "top z")
        elif k == "between":
            a, b = (byid[r]["center"] for r in spec["refs"])
            mid = [(a[0] + b[0]) / 2, (a[1] + b[1]) / 2]
            cs = [o for o in cands if o["id"] not in spec["refs"]]
            margin_check(gid, {o["id"]: d2(o["center"], mid) for o in cs}, target, "min", "distance to midpoint of refs")
            tx = byid[target]["center"][0]
            if not (min(a[0], b[0]) < tx < max(a[0], b[0])):
                err(gid, "target not between refs in x")
        elif k == "above":
            ref = byid[spec["ref"]]
            cs = [o for o in cands if o["center"][2] > spec["min_z"]]
            margin_check(gid, {o["id"]: d2(o["center"], ref["center"]) for o in cs}, target, "min", "horizontal distance to ref among upper units")
            to = byid[target]
            inside = all(abs(ref["center"][j] - to["center"][j]) <= to["size"][j] / 2 for j in (0, 1))
            if not inside or to["center"][2] <= ref["center"][2]:
                err(gid, "ref not under target footprint")
        elif k == "left":
            v = byid[spec["view_from"]]["center"]
            fx, fy = spec["facing"]
            lx, ly = -fy, fx
            sc = {o["id"]: (o["center"][0] - v[0]) * lx + (o["center"][1] - v[1]) * ly for o in cands}
            margin_check(gid, sc, target, "max", "leftward offset from viewer")
            if sc[target] <= 0 or any(s > 0 for i2, s in sc.items() if i2 != target):
                err(gid, "left/right split not clean")
        else:
            err(gid, f"unknown kind {k}")
    # ---- style
    w = gr["w"]
    if len(w) != 6 or len({q.lower() for q in w}) != 6:
        err(gid, "not 6 distinct wordings")
    for q in w:
        all_queries[q.lower()] += 1
    if not w[0].startswith(IMPERATIVES):
        err(gid, "w1 not imperative")
    if not (w[1].startswith("Could you ") and w[1].endswith("?")):
        err(gid, "w2 not a Could you question")
    ww = w[2].replace(",", " ").split()
    if len(ww) > 6 or any(x.lower() in ARTICLES for x in ww):
        err(gid, f"w3 telegraphic rule: {w[2]!r}")
    if not any(m in w[3] for m in REASON):
        err(gid, "w4 no reason/contrast marker")
    sents = [s for s in re.split(r"(?<=[.?!])\s+", w[4].strip()) if s]
    if not w[4].startswith("This is ") or len(sents) != 2:
        err(gid, f"w5 shape: {sents}")
    typo, right = gr["typo"]
    w6 = words(w[5])
    if w[5] != w[5].lower():
        err(gid, "w6 not lower case")
    if w6.count(typo) != 1 or typo == right or typo in STOP or right in w6:
        err(gid, f"w6 typo {typo!r}->{right!r} not found exactly once")
    # label use (same rule as validate.py)
    labels = {byid[a]["label"].lower() for a in accept}
    uses = sum(any(re.search(r"\b" + re.escape(lb) + r"(s|es)?\b", q.lower()) for lb in labels) for q in w)
    if uses > 2:
        err(gid, f"label used in {uses} wordings")
    notes.append(f"{gid} {t} {Path(gr['map']).name}: label {sorted(labels)} in {uses} wordings; typo {typo}->{right}")

for q, n in all_queries.items():
    if n > 1:
        errors.append(f"query repeated across suite: {q!r}")
if len(rows) != 288:
    errors.append(f"{len(rows)} lines, want 288")
want = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
if dict(per_type) != want:
    errors.append(f"per type {dict(per_type)} != {want}")
fam = Counter()
for m, n in per_map.items():
    fam["caption" if "caption" in m else "flat" if m.startswith("flat") else "scan" if m.startswith("scan") else "apartment"] += n
s_maps = Counter(Path(gr["map"]).name for gr in G if gr["type"] == "s")
for line in notes:
    print("  ", line)
print("groups per type", dict(per_type))
print("groups per map", dict(per_map))
print("groups per map family", dict(fam))
print("s groups per map", dict(s_maps))
print(f"{len(errors)} errors")
for e in errors:
    print("ERROR", e)
sys.exit(1 if errors else 0)
