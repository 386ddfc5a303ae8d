"""Audit evals/blind/round55.jsonl against the maps and the brief's rules.

- re-derives every o/or accept set from the map (all objects whose label is in the group's kind,
  and for `or` whose room -- the object's room field, and its polygon for object maps -- is the room);
- od/ord/ard: the target is the only candidate (kind, in the room for ord; every object in the room
  or map for ard) whose text (label, tags, caption) matches every key;
- s: the spatial claim, numerically, with a margin of at least 0.2 m over the runner-up;
- style: w1 imperative, w2 "Could you ...?", w3 <= 6 words and no articles, w4 reason/contrast,
  w5 "This is ..." + exactly two sentences, w6 lower case with exactly one non-dictionary word
  (the declared typo of a content word); map label in <= 2 wordings; no label in ard wordings;
- counts per type and per map.
"""
import json, math, re, sys
from collections import Counter, defaultdict
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _groups_round55 import G
from _common_round55 import load

SUITE = Path(__file__).resolve().parents[2] / "evals/blind/round55.jsonl"
WANT_TYPES = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
IMPERATIVES = {"go", "take", "head", "bring", "lead", "show", "guide", "find", "get", "navigate", "walk"}
ARTICLES = {"a", "an", "the"}
STOP = {"a", "an", "the", "to", "of", "in", "on", "at", "by", "for", "with", "and", "or", "but", "so",
        "not", "me", "my", "i", "you", "it", "is", "be", "there", "where", "here", "this", "that", "one",
        "can", "do", "please", "your", "from", "as", "if", "up", "out"}
WORDS = {w.strip().lower() for w in open("/usr/share/dict/words", encoding="utf-8", errors="ignore")}
# everyday words missing from /usr/share/dict/words (checked by hand, not typos)
WORDS |= {"rec", "worktop", "loveseat", "nightstand"}
MARGIN = 0.2

errors, notes = [], []
maps = {}


def M(name):
    if name not in maps:
        maps[name] = load(name)
    return maps[name]


def in_room(o, room, geometry):
    if room is None:
        return True
    if geometry:
        return o["room"] == room and room in o["poly_rooms"]
    return o["room"] == room


def has(text, key):
    return re.search(r"(?<![a-z])" + re.escape(key) + r"(?![a-z])", text) is not None


def xy(o):
    return o["center"][0], o["center"][1]


def dist(a, b):
    return math.dist(a, b)


def rank(scores, target, what):
    """scores: id -> value, larger is better; the target must win by MARGIN."""
    best = sorted(scores.items(), key=lambda kv: -kv[1])
    if best[0][0] != target:
        return f"{what}: winner {best[0][0]} not target {target} ({best})"
    if len(best) > 1 and best[0][1] - best[1][1] < MARGIN:
        return f"{what}: margin {best[0][1] - best[1][1]:.2f} < {MARGIN}"
    notes.append(f"{what}: target {target} wins, margin {best[0][1] - best[1][1] if len(best) > 1 else float('inf'):.2f} m "
                 f"({', '.join(f'{k}:{v:.2f}' for k, v in best)})")
    return None


def check_spatial(gid, g, objs):
    spec, t = g["spec"], g["target"]
    cands = {i: o for i, o in objs.items() if o["label"] in spec["kind"] and in_room(o, spec.get("room"), True)}
    c = spec["claim"]
    if "among" in c:
        cands = {i: o for i, o in cands.items() if i in c["among"]}
    if t not in cands or len(cands) < 2:
        return f"{gid}: target not a candidate or no rival ({sorted(cands)})"
    rel = c["rel"]
    if rel == "side":
        fx, fy = c["facing"]; sx, sy = c["stand"]
        rx, ry = fy, -fx  # right-hand direction when facing (fx, fy)
        sign = 1 if c["side"] == "right" else -1
        for i, o in cands.items():  # all candidates must be in front of the viewer
            if (o["center"][0] - sx) * fx + (o["center"][1] - sy) * fy <= 0:
                return f"{gid}: candidate {i} is behind the viewpoint"
        sc = {i: sign * ((o["center"][0] - sx) * rx + (o["center"][1] - sy) * ry) for i, o in cands.items()}
        return rank(sc, t, f"{gid} {c['side']} of viewer at {c['stand']} facing {c['facing']}")
    if rel == "nearest":
        a = xy(objs[c["anchor"]])
        sc = {i: -dist(xy(o), a) for i, o in cands.items()}
        return rank(sc, t, f"{gid} nearest to {c['anchor']} ({objs[c['anchor']]['label']})")
    if rel == "higher":
        sc = {i: o["center"][2] for i, o in cands.items()}
        return rank(sc, t, f"{gid} higher (centre z)")
    if rel == "under":
        top = objs[c["top"]]
        tb = top["center"][2] - top["size"][2] / 2
        o = cands[t]
        inside = all(abs(top["center"][k] - o["center"][k]) <= o["size"][k] / 2 for k in (0, 1))
        touching = abs((o["center"][2] + o["size"][2] / 2) - tb) <= 0.1
        if not (inside and touching):
            return f"{gid}: {c['top']} does not stand on {t} (inside={inside}, touching={touching})"
        sc = {i: -dist(xy(o), xy(top)) for i, o in cands.items()}
        return rank(sc, t, f"{gid} under {c['top']} ({top['label']})")
    if rel == "above":
        base = objs[c["base"]]
        btop = base["center"][2] + base["size"][2] / 2
        above = {i: o for i, o in cands.items() if o["center"][2] - o["size"][2] / 2 >= btop}
        o = cands[t]
        if t not in above:
            return f"{gid}: target not above base"
        overlap = all(abs(base["center"][k] - o["center"][k]) < (base["size"][k] + o["size"][k]) / 2 for k in (0, 1))
        if not overlap:
            return f"{gid}: target footprint does not overlap base"
        sc = {i: -dist(xy(o), xy(base)) for i, o in above.items()}
        return rank(sc, t, f"{gid} above {c['base']} ({base['label']}), candidates above it {sorted(above)}")
    if rel == "between":
        if len(cands) != 3:
            return f"{gid}: between needs 3 candidates, got {sorted(cands)}"
        sc = {}
        for i, o in cands.items():
            others = [xy(p) for j, p in cands.items() if j != i]
            mid = ((others[0][0] + others[1][0]) / 2, (others[0][1] + others[1][1]) / 2)
            sc[i] = -dist(xy(o), mid)
        return rank(sc, t, f"{gid} between the other two")
    return f"{gid}: unknown relation {rel}"


def check_style(gid, g):
    w = g["w"]
    errs = []
    if len(w) != 6:
        return [f"{gid}: {len(w)} wordings"]
    toks = lambda s: re.findall(r"[A-Za-z0-9'-]+", s)
    if toks(w[0])[0].lower() not in IMPERATIVES or w[0].startswith("Could"):
        errs.append(f"{gid} w1 not a plain imperative: {w[0]}")
    if not (w[1].startswith("Could you ") and w[1].endswith("?")):
        errs.append(f"{gid} w2 not 'Could you ...?': {w[1]}")
    t3 = [x.lower() for x in toks(w[2])]
    if len(t3) > 6 or ARTICLES & set(t3):
        errs.append(f"{gid} w3 telegraphic rule: {w[2]}")
    if not re.search(r"\b(so|because|since|as)\b|\bnot\b|rather than|instead", w[3].lower()):
        errs.append(f"{gid} w4 has no reason or contrast: {w[3]}")
    sents = [s for s in re.split(r"(?<=[.!?])\s+", w[4].strip()) if s]
    if not (w[4].startswith("This is ") and len(sents) == 2):
        errs.append(f"{gid} w5 not 'This is ...' + 2 sentences: {w[4]}")
    if w[5] != w[5].lower():
        errs.append(f"{gid} w6 not lower case: {w[5]}")
    bad = []
    for tok in toks(w[5]):
        for part in tok.strip("'-").split("-"):
            p = part.strip("'")
            p = re.sub(r"'s$", "", p)
            if p and not p.isdigit() and p not in WORDS and p.capitalize() not in WORDS:
                bad.append(p)
    typo, right = g["typo"]
    if bad != [typo]:
        errs.append(f"{gid} w6 non-dictionary words {bad}, declared typo {typo!r}: {w[5]}")
    if right not in WORDS or right in STOP or typo in WORDS:
        errs.append(f"{gid} w6 typo {typo!r}->{right!r} not a content-word misspelling")
    # edit distance <= 2 between typo and its correction
    a, b = typo, right
    d = [[i + j if i * j == 0 else 0 for j in range(len(b) + 1)] for i in range(len(a) + 1)]
    for i in range(1, len(a) + 1):
        for j in range(1, len(b) + 1):
            d[i][j] = min(d[i - 1][j] + 1, d[i][j - 1] + 1, d[i - 1][j - 1] + (a[i - 1] != b[j - 1]))
            if i > 1 and j > 1 and a[i - 1] == b[j - 2] and a[i - 2] == b[j - 1]:
                d[i][j] = min(d[i][j], d[i - 2][j - 2] + 1)
    if d[-1][-1] > 2:
        errs.append(f"{gid} w6 typo {typo!r} too far from {right!r}")
    if len({x.lower() for x in w}) != 6:
        errs.append(f"{gid}: wordings not distinct")
    return errs


def main():
    rows = [json.loads(l) for l in SUITE.read_text(encoding="utf-8").splitlines()]
    by_group = defaultdict(list)
    for r in rows:
        by_group[r["group"]].append(r)
    if len(rows) != 288 or len(by_group) != 48 or len(G) != 48:
        errors.append(f"counts: {len(rows)} lines, {len(by_group)} groups in suite, {len(G)} in groups.py")
    per_type, per_map = Counter(), Counter()
    all_queries = Counter(r["query"].lower() for r in rows)
    for q, n in all_queries.items():
        if n > 1:
            errors.append(f"query repeated across the suite: {q}")
    for gi, g in enumerate(G, 1):
        gid = f"b55-g{gi:02d}"
        rs = sorted(by_group[gid], key=lambda r: r["id"])
        if [r["query"] for r in rs] != g["w"] or any(r["map"] != g["map"] or r["type"] != g["type"]
                                                      or r["target"] != g["target"] for r in rs):
            errors.append(f"{gid}: suite lines differ from groups.py")
        objs, geometry, _ = M(g["map"])
        spec, t, typ = g["spec"], g["target"], g["type"]
        per_type[typ] += 1
        per_map[Path(g["map"]).name] += 1
        accept = rs[0]["accept"] if rs else []
        # accept sets
        if typ in ("o", "or"):
            room = spec.get("room") if typ == "or" else None
            if typ == "or" and not room:
                errors.append(f"{gid}: or without room")
            derived = sorted(i for i, o in objs.items() if o["label"] in spec["kind"] and in_room(o, room, geometry))
            if derived != sorted(accept):
                errors.append(f"{gid}: accept {sorted(accept)} != derived {derived}")
            if len(derived) < 2:
                notes.append(f"{gid}: {typ} with a single instance {derived}")
            notes.append(f"{gid} {typ} kind={spec['kind']} room={room}: accept {derived}")
        else:
            if accept != [t]:
                errors.append(f"{gid}: single-id type with accept {accept}")
        if typ in ("od", "ord", "ard"):
            if typ == "ard":
                cands = {i: o for i, o in objs.items() if in_room(o, spec.get("room"), geometry)}
            else:
                cands = {i: o for i, o in objs.items() if o["label"] in spec["kind"]
                         and in_room(o, spec.get("room") if typ == "ord" else None, geometry)}
                if typ == "ord" and not spec.get("room"):
                    errors.append(f"{gid}: ord without room")
                if sum(1 for o in objs.values() if o["label"] in spec["kind"]) < 2:
                    notes.append(f"{gid}: {typ} kind has a single instance in the map")
            if t not in cands:
                errors.append(f"{gid}: target not among candidates")
            match = sorted(i for i, o in cands.items() if all(any(has(o["text"], k) for k in alts) for alts in spec["keys"]))
            if match != [t]:
                errors.append(f"{gid}: keys {spec['keys']} match {match}, want [{t}]")
            else:
                notes.append(f"{gid} {typ}: keys {spec['keys']} single out {t} among {len(cands)} candidates")
            if typ == "ard":
                lab = objs[t]["label"].lower()
                for k, q in enumerate(g["w"], 1):
                    if re.search(r"\b" + re.escape(lab) + r"(s|es)?\b", q.lower()):
                        errors.append(f"{gid} w{k}: ard wording names the kind {lab!r}")
        if typ == "s":
            if not geometry:
                errors.append(f"{gid}: s on a caption map")
            else:
                e = check_spatial(gid, g, objs)
                if e:
                    errors.append(e)
        errors.extend(check_style(gid, g))
        names = {objs[a]["label"].lower() for a in accept if a in objs}
        uses = sum(any(re.search(r"\b" + re.escape(n) + r"(s|es)?\b", q.lower()) for n in names) for q in g["w"])
        if uses > 2:
            errors.append(f"{gid}: map label in {uses} wordings")
    if dict(per_type) != WANT_TYPES:
        errors.append(f"type counts {dict(per_type)} != {WANT_TYPES}")
    cap = per_map["scene_00829_caption.json"] + per_map["scene_office3_caption.json"]
    flats = sum(per_map[f"flat_{x}.json"] for x in "cdfh")
    scans = sum(v for k, v in per_map.items() if k.startswith("scan_"))
    spread = dict(caption=cap, flats=flats, apartment=per_map["apartment"], scans=scans)
    s_maps = Counter(Path(g["map"]).name for g in G if g["type"] == "s")
    for n in notes:
        print("note:", n)
    for e in errors:
        print("ERROR:", e)
    print(f"types {dict(per_type)}")
    print(f"maps {dict(per_map)}")
    print(f"spread {spread}; s groups per map {dict(s_maps)}")
    print(f"{len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
