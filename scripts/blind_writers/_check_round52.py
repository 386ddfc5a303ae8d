"""Independent checks of evals/blind/round52.jsonl against the maps and groups.py specs.

1. o/or accept sets re-derived from the map (label set, room label), compared with the suite.
2. od/ord: target matches every key; no other candidate of the kind (in the room, for ord) does.
3. ard: exactly one object in the map (room) can serve the need (its label set).
4. s: numeric check from centres/sizes, margin >= 0.2 m over the runner-up.
5. style rules per wording slot; map label in <= 2 wordings; w6 has exactly one non-dictionary word (the typo).
6. counts per type / per map-family.
"""
import json, math, re, sys
from collections import Counter, defaultdict
from pathlib import Path
sys.path.insert(0, str(Path(__file__).parent))
from _groups_round52 import G, M

BLIND = Path(__file__).resolve().parents[2] / "evals/blind"
SUITE = BLIND / "round52.jsonl"
problems = []


def bad(msg):
    problems.append(msg)


def map_path(key):
    m = M[key]
    return Path(__file__).resolve().parents[2] / "map_store/apartment.json" if m == "apartment" else (BLIND / m).resolve()


def load(key):
    d = json.loads(map_path(key).read_text())
    objs = {}
    if isinstance(d, dict) and "objects" in d:
        rooms = {r["id"]: r["label"] for r in d.get("rooms", [])}
        for o in d["objects"]:
            room = o.get("room")
            if isinstance(room, int):
                room = rooms[room]
            text = " ".join([o["label"], json.dumps(o.get("tags") or {}), o.get("caption") or ""])
            objs[o["id"]] = dict(label=o["label"], room=room, text=text, caption=o.get("caption") or "",
                                 c=o["center"], s=o["size"])
    else:
        for k, v in d.items():
            cap = v["caption"]
            try:
                cj = json.loads(cap)
                capt = cj.get("captions", "")
                extra = f'{cj.get("color")} {cj.get("material")}'
            except ValueError:
                mm = re.search(r'"captions":\s*"(.*?)"', cap, re.S)
                capt = mm.group(1) if mm else cap
                extra = cap
            objs[int(k)] = dict(label=v["category"], room=v.get("room_cat"), text=v["category"] + " " + extra + " " + capt,
                                caption=capt, c=None, s=None)
    return objs


def xy_dist(a, b):
    return math.hypot(a["c"][0] - b["c"][0], a["c"][1] - b["c"][1])


def box_gap(a, b):
    dx = max(0, abs(a["c"][0] - b["c"][0]) - (a["s"][0] + b["s"][0]) / 2)
    dy = max(0, abs(a["c"][1] - b["c"][1]) - (a["s"][1] + b["s"][1]) / 2)
    return math.hypot(dx, dy)


def check_s(name, objs, spec, target):
    cands = {i: o for i, o in objs.items() if o["label"] in spec["cands"]}
    if target not in cands:
        return bad(f"{name}: target not among candidates")
    rel = spec["rel"]
    if rel == "nearest":
        ref = objs[spec["ref"]]
        for metric in (xy_dist, box_gap):
            order = sorted(cands, key=lambda i: metric(cands[i], ref))
            d = [metric(cands[i], ref) for i in order]
            if order[0] != target or len(d) > 1 and d[1] - d[0] < 0.2:
                bad(f"{name}: nearest({metric.__name__}) order {order} dists {[round(x, 2) for x in d]}")
            else:
                print(f"  {name}: nearest[{metric.__name__}] {order[0]} {d[0]:.2f} vs {order[1] if len(d) > 1 else '-'} {d[1] if len(d) > 1 else float('nan'):.2f}")
        if "other" in spec:  # the contrast in w4 ("not the one by the door/window")
            ref2 = objs[spec["other"]["ref"]]
            order = sorted(cands, key=lambda i: xy_dist(cands[i], ref2))
            if order[0] != spec["other"]["target"]:
                bad(f"{name}: contrast object is not nearest to {spec['other']['ref']}")
    elif rel == "side":
        near = objs[spec["near"]]
        cs = {i: o for i, o in cands.items() if box_gap(o, near) <= spec["near_dist"]}
        fx, fy = spec["facing"]
        rx, ry = fy, -fx  # right-hand vector when facing (fx, fy)
        lat = {i: o["c"][0] * rx + o["c"][1] * ry for i, o in cs.items()}
        order = sorted(lat, key=lambda i: lat[i], reverse=(spec["side"] == "right"))
        vals = [lat[i] for i in order]
        if order[0] != target or len(vals) < 2 or abs(vals[0] - vals[1]) < 0.2:
            bad(f"{name}: side order {order} {vals}")
        else:
            print(f"  {name}: {spec['side']} of {sorted(cs)} -> {order[0]}, lateral margin {abs(vals[0] - vals[1]):.2f}")
    elif rel == "under":
        ref = objs[spec["ref"]]
        def overlaps(o):
            return all(abs(o["c"][k] - ref["c"][k]) < (o["s"][k] + ref["s"][k]) / 2 for k in (0, 1))
        def below(o):
            return o["c"][2] + o["s"][2] / 2 <= ref["c"][2] - ref["s"][2] / 2 + 0.1
        ok = [i for i, o in cands.items() if overlaps(o) and below(o)]
        dists = sorted((xy_dist(o, ref), i) for i, o in cands.items())
        if ok != [target] or dists[0][1] != target or dists[1][0] - dists[0][0] < 0.2:
            bad(f"{name}: under -> {ok}, dists {dists[:3]}")
        else:
            print(f"  {name}: under {spec['ref']} -> {ok}, xy offset {dists[0][0]:.2f} vs next {dists[1][0]:.2f}")
    elif rel == "between":
        if len(cands) != 3:
            return bad(f"{name}: between needs three candidates")
        score = {}
        for i, o in cands.items():
            others = [cands[j] for j in cands if j != i]
            mid = [(others[0]["c"][k] + others[1]["c"][k]) / 2 for k in (0, 1)]
            score[i] = math.hypot(o["c"][0] - mid[0], o["c"][1] - mid[1])
        order = sorted(score, key=score.get)
        if order[0] != target or score[order[1]] - score[order[0]] < 0.2:
            bad(f"{name}: between scores {score}")
        else:
            print(f"  {name}: between -> {order[0]}, offset {score[order[0]]:.2f} vs {score[order[1]]:.2f}")
    else:
        bad(f"{name}: unknown relation {rel}")


# ---------------------------------------------------------------- style helpers
RAW = [w.strip() for w in open("/usr/share/dict/words", encoding="utf-8", errors="ignore")]
DICT = {w.lower() for w in RAW}
LOWER = {w for w in RAW if w == w.lower()} | {"i", "i'm", "tv"}  # common words only, no proper names
EXTRA_OK = {"rec"}  # "rec room" is the map's own room name


def known(w):
    w = w.strip("'")
    if not w or w in DICT or w in EXTRA_OK:
        return True
    for suf in ("s", "es", "'s", "ed", "ing"):
        if w.endswith(suf) and w[: -len(suf)] in DICT:
            return True
    return False


IMPERATIVE = {"go", "take", "head", "bring", "lead", "guide", "show", "walk", "find", "get", "navigate"}
ARTICLES = {"a", "an", "the"}


def style(name, rows, grp, labels):
    q = [r["query"] for r in rows]
    if q[0].split()[0].lower() not in IMPERATIVE:
        bad(f"{name} w1 not imperative: {q[0]}")
    if not (q[1].startswith("Could you ") and q[1].endswith("?")):
        bad(f"{name} w2 not a 'Could you ...?' question")
    w3 = q[2].split()
    if len(w3) > 6 or any(re.sub(r"[^a-z]", "", t.lower()) in ARTICLES for t in w3):
        bad(f"{name} w3 not telegraphic: {q[2]}")
    if not re.search(r"\b(not|so|because|since|rather than|instead)\b", q[3]):
        bad(f"{name} w4 has no reason/contrast marker")
    sents = [s for s in re.split(r"(?<=[.!?])\s+", q[4].strip()) if s]
    if not q[4].startswith("This is ") or len(sents) != 2:
        bad(f"{name} w5 not two sentences starting 'This is': {sents}")
    if q[5] != q[5].lower():
        bad(f"{name} w6 not lower case")
    toks = re.findall(r"[a-z']+", q[5])
    unknown = [t for t in toks if t.strip("'") not in LOWER and t not in EXTRA_OK]
    typo, right = grp["typo"]
    if unknown != [typo] or right not in LOWER or typo not in toks:
        bad(f"{name} w6 typo check: unknown={unknown}, declared={grp['typo']}")
    # no unintended non-words elsewhere
    for i in range(5):
        unk = [t for t in re.findall(r"[a-z']+", q[i].lower()) if not known(t)]
        unk = [t for t in unk if t not in {"tv", "a3", "led", "stabilisers", "stripy", "teeny", "settee", "settees",
                                          "credenza", "dry-erase", "gilt", "bedside", "nightstand", "workstation",
                                          "workstations", "houseplant", "spindle-back", "kids'", "grown-ups'"}]
        if unk:
            print(f"  note {name} w{i + 1}: words not in dictionary {unk}")
    uses = sum(any(re.search(r"\b" + re.escape(l) + r"(s|es)?\b", x.lower()) for l in labels) for x in q)
    if uses > 2:
        bad(f"{name}: map label in {uses} wordings")
    if len({x.lower() for x in q}) != 6:
        bad(f"{name}: duplicate wordings")


# ---------------------------------------------------------------- main
rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
by_group = defaultdict(list)
for r in rows:
    by_group[r["group"]].append(r)
if len(rows) != 288 or len(by_group) != 48:
    bad(f"{len(rows)} lines / {len(by_group)} groups")

cache = {}
per_type, per_map, per_family, s_family = Counter(), Counter(), Counter(), Counter()
FAMILY = {"B": "flats", "E": "flats", "G": "flats", "I": "flats", "APT": "apartment", "SB": "scans", "SK": "scans",
          "SL": "scans", "SO": "scans", "C829": "caption", "O3": "caption"}
for n, grp in enumerate(G, 1):
    name = f"b52-g{n:02d}"
    rs = sorted(by_group[name], key=lambda r: r["id"])
    if [r["id"] for r in rs] != [f"{name}-w{w}" for w in range(1, 7)]:
        bad(f"{name}: ids")
    objs = cache.setdefault(grp["map"], load(grp["map"]))
    spec, typ, tgt = grp["spec"], grp["type"], grp["target"]
    for r in rs:
        if (r["type"], r["target"], r["accept"], r["map"]) != (typ, tgt, sorted(grp["accept"]), M[grp["map"]]):
            bad(f"{r['id']}: row differs from the group spec")
    room = spec.get("room")
    if typ in ("o", "or"):
        derived = sorted(i for i, o in objs.items() if o["label"] in spec["labels"] and (typ == "o" or o["room"] == room))
        if typ == "or" and not room:
            bad(f"{name}: or without room")
        if derived != sorted(grp["accept"]) or tgt not in derived:
            bad(f"{name}: accept {sorted(grp['accept'])} but map gives {derived}")
    elif typ in ("od", "ord"):
        cands = {i: o for i, o in objs.items() if o["label"] in spec["labels"] and (typ == "od" or o["room"] == room)}
        if typ == "ord" and (not room or objs[tgt]["room"] != room):
            bad(f"{name}: ord target not in room {room}")
        hits = [i for i, o in cands.items() if all(re.search(k, o["text"], re.I) for k in spec["keys"])]
        if hits != [tgt] or grp["accept"] != [tgt]:
            bad(f"{name}: description keys {spec['keys']} match {hits} among {sorted(cands)}")
        else:
            print(f"  {name}: keys {spec['keys']} single out {tgt} among {sorted(cands)}")
    elif typ == "ard":
        serve = [i for i, o in objs.items() if o["label"] in spec["labels"] and (not room or o["room"] == room)]
        if serve != [tgt] or grp["accept"] != [tgt]:
            bad(f"{name}: need served by {serve}")
    elif typ == "s":
        if objs[tgt]["c"] is None:
            bad(f"{name}: spatial group on a map without geometry")
        else:
            check_s(name, objs, spec, tgt)
    labels = {objs[a]["label"].lower() for a in grp["accept"]}
    style(name, rs, grp, labels)
    per_type[typ] += 1
    per_map[M[grp["map"]]] += 1
    per_family[FAMILY[grp["map"]]] += 1
    if typ == "s":
        s_family[FAMILY[grp["map"]]] += 1

want = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
if dict(per_type) != want:
    bad(f"type counts {dict(per_type)} != {want}")
if s_family["caption"]:
    bad("spatial group on a caption map")
print("per type", dict(per_type))
print("per family", dict(per_family), "s per family", dict(s_family))
print("per map", dict(per_map))
print("\n".join(problems) if problems else "check.py: no problems")
sys.exit(1 if problems else 0)
