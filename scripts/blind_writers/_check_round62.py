"""Check round62.jsonl against the maps and the brief's rules.

- o/or: accept re-derived from the map (every object whose label is one of the group's kinds, in the room for or).
- od/ord: the description keywords occur in the target's text and in no other object of its kind (in its room for ord).
- ard: the need keywords pick exactly one object of the map (and it lies in the named room); no wording names the kind.
- s: the spatial claim recomputed from centres/sizes with a margin >= 0.2 m over the runner-up.
- style: w1 imperative, w2 "Could you ...?", w3 <= 6 words and no articles, w4 reason/contrast,
  w5 two sentences starting "This is", w6 all lower case with exactly one typo (one non-dictionary word = the typo).
- map label in at most 2 wordings per group; counts per type and per map.
"""
import json
import math
import re
import sys
from collections import Counter
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _maps_round62 import load, BLIND
from _groups_round62 import GROUPS

MARGIN = 0.2
errors, notes = [], []
err = errors.append
rows = [json.loads(x) for x in (BLIND / "round62.jsonl").read_text(encoding="utf-8").splitlines()]
by_group = {}
for r in rows:
    by_group.setdefault(r["group"], []).append(r)

DICT = {w.strip().lower() for w in open("/usr/share/dict/words", encoding="utf-8", errors="ignore")}
DICT |= {"tv", "led", "l-shaped", "i", "i'm", "don't", "doesn't", "that's", "it's", "kids'", "dog's", "people's", "rec", "stripy"}
IMPERATIVE = {"take", "go", "bring", "lead", "head", "guide", "show", "get", "find", "walk"}
ARD_KIND_WORDS = {192: ["bed"], 3: ["sofa", "couch", "settee"], 18: ["kettle"], 35: ["desk", "table"],
                  11: ["ironing", "board", "iron"], 54: ["printer"], 30: ["mirror"], 17: ["mirror"]}


def wb(word, text):
    return re.search(r"\b" + re.escape(word) + r"\b", text) is not None


def words(q):
    return re.findall(r"[A-Za-z][A-Za-z'\-]*", q)


def dist2d(a, b):
    return math.hypot(a["center"][0] - b["center"][0], a["center"][1] - b["center"][1])


def footprint_gap(o, ref):
    """horizontal distance from o's centre to ref's footprint (0 if inside)."""
    dx = max(0.0, abs(o["center"][0] - ref["center"][0]) - ref["size"][0] / 2)
    dy = max(0.0, abs(o["center"][1] - ref["center"][1]) - ref["size"][1] / 2)
    return math.hypot(dx, dy)


def check_spatial(spec, objs, gid):
    byid = {o["id"]: o for o in objs}
    cand = [o for o in objs if o["label"] in spec["kinds"]]
    if spec.get("room"):
        cand = [o for o in cand if o["room"] == spec["room"]]
    if spec.get("filt"):
        k, v = spec["filt"]
        cand = [o for o in cand if o["tags"].get(k) == v]
    rel = spec["spatial"]
    t = byid[spec["target"]]
    if t not in cand:
        return err(f"{gid}: target not among candidates")
    if len(cand) < 2:
        return err(f"{gid}: spatial group with a single candidate")
    if rel[0] == "nearest":
        refs = rel[1] if isinstance(rel[1], list) else [rel[1]]
        d = {o["id"]: min(dist2d(o, byid[r]) for r in refs) for o in cand}
        order = sorted(d, key=d.get)
        ok = order[0] == t["id"] and d[order[1]] - d[order[0]] >= MARGIN
        notes.append(f"{gid}: nearest to {refs}: " + ", ".join(f"{i}={d[i]:.2f}" for i in order))
    elif rel[0] == "extreme":
        axis, sign = rel[1], rel[2]
        v = {o["id"]: sign * o["center"][axis] for o in cand}
        order = sorted(v, key=v.get, reverse=True)
        ok = order[0] == t["id"] and v[order[0]] - v[order[1]] >= MARGIN
        notes.append(f"{gid}: {rel[3]}: " + ", ".join(f"{i}={sign * v[i]:.2f}" for i in order))
    elif rel[0] in ("on", "above"):
        ref = byid[rel[1]]
        top = ref["center"][2] + ref["size"][2] / 2

        def bottom(o):
            return o["center"][2] - o["size"][2] / 2

        gaps = {o["id"]: footprint_gap(o, ref) for o in cand}
        others = [g for i, g in gaps.items() if i != t["id"]]
        ok = gaps[t["id"]] == 0 and bottom(t) >= top - 0.05 and min(others) >= MARGIN
        if rel[0] == "on":
            ok = ok and bottom(t) - top <= 0.1
        notes.append(f"{gid}: {rel[0]} {rel[1]} (top {top:.2f}): target bottom {bottom(t):.2f}; "
                     + ", ".join(f"{i} gap={g:.2f}" for i, g in sorted(gaps.items())))
    else:
        return err(f"{gid}: unknown relation {rel}")
    if not ok:
        err(f"{gid}: spatial claim {rel} fails or margin < {MARGIN}")


def check_style(gid, spec, qs, labels):
    w1, w2, w3, w4, w5, w6 = qs
    if words(w1)[0].lower() not in IMPERATIVE:
        err(f"{gid} w1 not an imperative: {w1}")
    if not (w2.startswith("Could you ") and w2.endswith("?")):
        err(f"{gid} w2 not 'Could you ...?'")
    ws3 = w3.split()
    if len(ws3) > 6 or any(re.sub(r"\W", "", w).lower() in {"a", "an", "the"} for w in ws3):
        err(f"{gid} w3 too long or has an article: {w3}")
    if not (re.search(r"\b(so|because|since)\b", w4) or ", not " in w4):
        err(f"{gid} w4 has no reason/contrast: {w4}")
    sents = [s for s in re.split(r"(?<=[.!?])\s+", w5.strip()) if s]
    if len(sents) != 2 or not sents[0].startswith("This is "):
        err(f"{gid} w5 not two sentences starting 'This is': {w5}")
    if w6 != w6.lower():
        err(f"{gid} w6 not all lower case")
    typo, meant = spec["typo"]
    toks = [t.lower().strip("'-") for t in words(w6)]
    unknown = [t for t in toks if t not in DICT]
    if unknown != [typo]:
        err(f"{gid} w6 non-dictionary words {unknown}, expected exactly [{typo!r}]")
    if meant.lower() not in DICT:
        err(f"{gid} typo's intended word {meant!r} not a dictionary word")
    # label rule (same test as validate.py)
    uses = sum(any(re.search(r"\b" + re.escape(lb) + r"(s|es)?\b", q.lower()) for lb in labels) for q in qs)
    if uses > 2:
        err(f"{gid}: map label in {uses} wordings")
    if len({q.lower() for q in qs}) != 6:
        err(f"{gid}: wordings not distinct")


per_type, per_map = Counter(), Counter()
for n, spec in enumerate(GROUPS, 1):
    gid = f"b62-g{n:02d}"
    rs = by_group.get(gid, [])
    if [r["id"] for r in rs] != [f"{gid}-w{i}" for i in range(1, 7)]:
        err(f"{gid}: lines missing or out of order")
        continue
    if any((r["map"], r["type"], r["target"], r["accept"]) != (spec["map"], spec["type"], spec["target"], sorted(spec["accept"])) for r in rs):
        err(f"{gid}: jsonl differs from the spec")
    objs = load(spec["map"])
    byid = {o["id"]: o for o in objs}
    t = byid[spec["target"]]
    typ = spec["type"]
    per_type[typ] += 1
    per_map[spec["map"]] += 1
    qs = [r["query"] for r in rs]
    if typ in ("o", "or"):
        derived = sorted(o["id"] for o in objs if o["label"] in spec["kinds"]
                         and (typ == "o" or o["room"] == spec["room"]))
        if derived != sorted(spec["accept"]):
            err(f"{gid}: accept {sorted(spec['accept'])} but map gives {derived}")
        if typ == "or" and not all(spec["room"].split()[0] in q.lower() or "lounge" in q.lower() or "games" in q.lower()
                                   or "recreation" in q.lower() or "conference" in q.lower() for q in qs):
            notes.append(f"{gid}: some wordings name the room by a synonym only")
    else:
        if spec["accept"] != [spec["target"]]:
            err(f"{gid}: single-id group with accept {spec['accept']}")
    if typ in ("od", "ord"):
        if t["label"] not in spec["kinds"]:
            err(f"{gid}: target label {t['label']} not in kinds")
        comp = [o for o in objs if o["label"] in spec["kinds"] and (typ == "od" or o["room"] == spec["room"])]
        if typ == "ord" and t["room"] != spec["room"]:
            err(f"{gid}: target not in {spec['room']}")
        has = [o["id"] for o in comp if all(wb(k, o["text"]) for k in spec["desc"])]
        if has != [t["id"]]:
            err(f"{gid}: description {spec['desc']} matches {has} among {[o['id'] for o in comp]}")
        notes.append(f"{gid}: {spec['desc']} singles out {has} among {len(comp)} of its kind")
    if typ == "ard":
        if t["room"] != spec["room"]:
            err(f"{gid}: target not in {spec['room']}")
        has = [o["id"] for o in objs if all(wb(k, o["text"]) for k in spec["desc"])]
        if has != [t["id"]]:
            err(f"{gid}: need keywords {spec['desc']} match {has}")
        for q in qs:
            for kw in ARD_KIND_WORDS[t["id"]]:
                if wb(kw, q.lower()):
                    err(f"{gid}: ard wording names the kind ({kw}): {q}")
    if typ == "s":
        if t["center"] is None:
            err(f"{gid}: spatial group on a caption map")
        else:
            check_spatial(spec, objs, gid)
    labels = {byid[a]["label"].lower() for a in spec["accept"]}
    check_style(gid, spec, qs, labels)

want_types = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
if dict(per_type) != want_types:
    err(f"type counts {dict(per_type)} != {want_types}")
if len(rows) != 288 or len(by_group) != 48:
    err(f"{len(rows)} lines / {len(by_group)} groups")
fam = Counter()
for m, c in per_map.items():
    fam["caption" if "iesm" in m else "apartment" if m == "apartment" else "scan" if "scan_" in m else "flat"] += c
s_fam = Counter(("apartment" if g["map"] == "apartment" else "scan" if "scan_" in g["map"] else "flat")
                for g in GROUPS if g["type"] == "s")
for line in notes:
    print("note:", line)
print("groups per type", dict(per_type))
print("groups per map", {Path(m).name: c for m, c in per_map.items()})
print("groups per family", dict(fam), "; s groups per family", dict(s_fam))
for e in errors:
    print("ERROR:", e)
print(f"check: {len(errors)} errors")
sys.exit(1 if errors else 0)
