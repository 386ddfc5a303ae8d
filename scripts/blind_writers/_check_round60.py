"""Check round60.jsonl against the maps and the brief's rules.

    python3 scripts/check.py evals/blind/round60.jsonl

- o / or: re-derive the accept set from the map (every object whose label is in the group's kind
  labels, and, for or, whose room matches) and compare it with the suite's accept set.
- od / ord: among objects of the kind (in the room for ord), the target must be the only one whose
  label+caption+tags contain every claim keyword.
- ard: among all objects of the map (in the room if one is named), the target must be the only one
  whose label is in the set of labels that can serve the need; the wordings must not name the
  target's kind (forbidden words).
- s: recompute the spatial claim from centres and sizes; the target must win with a margin >= 0.2 m
  over the runner-up (or the claim's own test, e.g. xy containment, must single it out).
- style: w1 imperative, w2 "Could you ...?", w3 <= 6 words without articles, w4 reason/contrast,
  w5 two sentences starting "This is", w6 all lower case with exactly one non-dictionary word
  (the annotated typo of a dictionary content word); the map label in at most 2 wordings.
- counts per type and map.
"""
import json
import math
import re
import sys
from collections import Counter, defaultdict
from pathlib import Path

HERE = Path(__file__).resolve().parent
ROOT = HERE.parents[1]
SUITE_DIR = ROOT / "evals" / "blind"
sys.path.insert(0, str(HERE))
from _build_round60 import GROUPS  # only for the w6 typo annotations  # noqa: E402

MARGIN = 0.2
DOORS = {"doorway", "door frame", "door/window frame"}

# ---------------------------------------------------------------- o / or specs: kind labels, room
KIND = {
    "b60-g01": ({"couch", "sofa"}, None),
    "b60-g02": ({"easy chair", "armchair"}, "bedroom"),
    "b60-g07": ({"pillow", "cushion"}, None),
    "b60-g08": ({"desk"}, "rec room"),
    "b60-g13": ({"lamp"}, None),
    "b60-g14": ({"nightstand"}, "bedroom"),
    "b60-g17": ({"sink"}, "bathroom"),
    "b60-g21": ({"bicycle"}, None),
    "b60-g25": ({"mug", "cup"}, None),
    "b60-g29": ({"plant"}, None),
    "b60-g30": ({"book"}, "living room"),
    "b60-g31": ({"mirror"}, "bathroom"),
    "b60-g40": ({"trash can"}, None),
    "b60-g43": ({"side table"}, "living room"),
}

# ---------------------------------------------------------------- od / ord specs: kind, room, keywords
DESC = {
    "b60-g03": (DOORS, None, ["peephole"]),
    "b60-g04": ({"set of towels", "hand towel"}, None, ["embroidered", "'h'"]),
    "b60-g05": (DOORS, "bathroom", ["electronic lock"]),
    "b60-g09": ({"pillow"}, None, ["orange", "stripes"]),
    "b60-g10": ({"window", "window /outside"}, "rec room", ["clock above"]),
    "b60-g15": ({"armchair", "office chair", "chair"}, "study", ["green"]),
    "b60-g18": ({"chair"}, "dining room", ["black", "metal"]),
    "b60-g22": ({"chair", "armchair", "office chair"}, None, ["red checked"]),
    "b60-g26": ({"lamp"}, "bedroom", ["rattan"]),
    "b60-g32": ({"picture"}, None, ["lighthouse"]),
    "b60-g33": ({"chair", "armchair"}, "kitchen", ["white", "spindle"]),
    "b60-g37": ({"pillow"}, None, ["red"]),
    "b60-g44": ({"armchair"}, "living room", ["green"]),
    "b60-g46": ({"keyboard"}, None, ["white"]),
}

# ---------------------------------------------------------------- ard specs: labels that serve the need, room, forbidden words
NEED = {
    "b60-g06": ({"bed for pet"}, "bathroom", ["bed", "beds"]),
    "b60-g11": ({"clock"}, "rec room", ["clock", "clocks"]),
    "b60-g12": ({"remote-control"}, "rec room", ["remote", "control", "controller"]),
    "b60-g19": ({"dryer"}, "utility room", ["dryer", "drier"]),
    "b60-g23": ({"ironing board"}, "laundry room", ["board", "ironing board"]),
    "b60-g27": ({"printer"}, "studio", ["printer"]),
    "b60-g34": ({"washing machine"}, "bathroom", ["machine", "washer", "washing machine"]),
    "b60-g41": ({"coffee maker"}, None, ["maker", "machine", "coffee maker"]),
}


# ---------------------------------------------------------------- geometry helpers
def c(o):
    return o["center"]


def dxy(a, b):
    return math.hypot(a[0] - b[0], a[1] - b[1])


def top(o):
    return o["center"][2] + o["size"][2] / 2


def bottom(o):
    return o["center"][2] - o["size"][2] / 2


def xy_overlap(a, b):
    return all(abs(a["center"][k] - b["center"][k]) < (a["size"][k] + b["size"][k]) / 2 for k in (0, 1))


def inside_xy(p, box):
    return all(abs(p[k] - box["center"][k]) <= box["size"][k] / 2 for k in (0, 1))


def rank(cands, score, higher=False):
    """Sorted (score, id) list, best first."""
    s = sorted(((score(o), o["id"]) for o in cands), reverse=higher)
    return s


# each s spec: (kind labels, room or None, extra filter, scoring, higher_is_better, note)
def s_specs(objs):
    by = {o["id"]: o for o in objs}
    return {
        "b60-g16": ({"lamp"}, "bedroom", None, lambda o: dxy(c(o), c(by[36])), False, "xy distance to bedroom window 36"),
        "b60-g20": ({"plant"}, None, None, lambda o: dxy(c(o), c(by[8])), False, "xy distance to TV 8"),
        "b60-g24": ({"mirror"}, None, lambda o: bottom(o) > top(by[40]), lambda o: dxy(c(o), c(by[40])), False,
                    "above sink 40: bottom higher than sink top, xy distance"),
        "b60-g28": ({"desk"}, "studio", None, lambda o: c(o)[0], True, "x (right when facing north)"),
        "b60-g35": ({"sofa"}, None, None, lambda o: dxy(c(o), c(by[4])), False, "xy distance to TV 4"),
        "b60-g36": ({"book"}, "living room", None, lambda o: c(o)[2], True, "z height on the living room shelf"),
        "b60-g38": ({"lamp"}, None, None, lambda o: c(o)[0], False, "x (left when facing north from the foot of the bed)"),
        "b60-g39": ({"pillow"}, None, None,
                    lambda o: dxy(c(o), (c(by[1])[0], c(by[1])[1] - by[1]["size"][1] / 2)), False,
                    "xy distance to the middle of the bed's foot edge (south, y min)"),
        "b60-g42": ({"kitchen cabinet"}, None, lambda o: top(o) <= bottom(by[10]) + 0.05,
                    lambda o: dxy(c(o), c(by[10])), False, "under sink 10: top at/below sink bottom, xy distance"),
        "b60-g45": ({"pillow"}, None, lambda o: o["tags"].get("color") == "red", lambda o: c(o)[0], True,
                    "x (left when standing in front of the south-wall sofa facing south)"),
        "b60-g47": ({"monitor"}, None, None, lambda o: dxy(c(o), c(by[1])), False,
                    "xy distance to white table 1 (target must also lie inside its footprint)"),
        "b60-g48": ({"plant"}, None, None, lambda o: o["size"][2], True, "height"),
    }


# ---------------------------------------------------------------- map loading
def map_path(name):
    p = (SUITE_DIR / name).resolve()
    if not p.is_file() and "/" not in name:
        p = ROOT / "map_store" / f"{name}.json"
    return p


def load(name):
    data = json.loads(map_path(name).read_text(encoding="utf-8"))
    if isinstance(data, dict) and "objects" in data:
        objs = []
        for o in data["objects"]:
            o = dict(o)
            o["room"] = str(o.get("room", ""))
            o["text"] = " ".join([o["label"], o.get("caption", "") or "",
                                  " ".join(str(v) for v in (o.get("tags") or {}).values())]).lower()
            objs.append(o)
        return objs, True
    objs = []
    for k, v in data.items():
        raw = v.get("caption", "")
        objs.append({"id": int(k), "label": v["category"], "room": str(v.get("room_cat")),
                     "text": (v["category"] + " " + raw).lower(), "tags": {}})
    return objs, False


# ---------------------------------------------------------------- style
DICT = {w.strip().lower() for w in open("/usr/share/dict/words", encoding="utf-8", errors="ignore")}
EXTRA_OK = {"tv", "h", "i", "a3", "rec"}  # "rec" as in the map's room name "rec room"
IMPERATIVE = ("go ", "take ", "head ", "walk ", "bring ", "lead ", "show ", "find ", "guide ")


def in_dict(w):
    if w in DICT or w in EXTRA_OK:
        return True
    for suf in ("s", "es", "'s"):
        if w.endswith(suf) and w[: -len(suf)] in DICT:
            return True
    return False


def tokens(q):
    return re.findall(r"[a-z0-9]+(?:'[a-z]+)?", q.lower())


def style_errors(rows, typo):
    errs = []
    q = {int(r["id"].rsplit("w", 1)[1]): r["query"] for r in rows}
    w1, w2, w3, w4, w5, w6 = (q[i] for i in range(1, 7))
    if not w1.lower().startswith(IMPERATIVE) or w1.endswith("?"):
        errs.append("w1 not a plain imperative")
    if not (w2.startswith("Could you ") and w2.endswith("?")):
        errs.append("w2 not 'Could you ...?'")
    w3w = tokens(w3)
    if len(w3.split()) > 6 or {"a", "an", "the"} & set(w3w):
        errs.append(f"w3 telegraphic rule broken: {w3!r}")
    if not re.search(r"\b(so|because|since|as|not)\b", w4.lower()):
        errs.append("w4 lacks a reason/contrast marker")
    sents = [s for s in re.split(r"(?<=[.!?])\s+", w5.strip()) if s]
    if not w5.startswith("This is ") or len(sents) != 2 or not w5.rstrip().endswith((".", "?", "!")):
        errs.append(f"w5 not two sentences starting 'This is': {w5!r}")
    if w6 != w6.lower():
        errs.append("w6 not all lower case")
    bad = [t for t in tokens(w6) if not in_dict(t)]
    t_word, fixed = typo
    if bad != [t_word]:
        errs.append(f"w6 non-dictionary words {bad}, expected exactly [{t_word!r}]")
    if not in_dict(fixed) or in_dict(t_word):
        errs.append(f"w6 typo annotation {typo} odd")
    if len({x.lower() for x in q.values()}) != 6:
        errs.append("duplicate wordings")
    return errs


def label_uses(rows, labels):
    names = {lab.lower() for lab in labels}
    return sum(any(re.search(r"\b" + re.escape(n) + r"(s|es)?\b", r["query"].lower()) for n in names) for r in rows)


def main(path):
    rows = [json.loads(x) for x in Path(path).read_text(encoding="utf-8").splitlines()]
    groups = defaultdict(list)
    for r in rows:
        groups[r["group"]].append(r)
    typos = {f"b60-g{i:02d}": g[5] for i, g in enumerate(GROUPS, 1)}
    maps = {}
    errors, notes = [], []
    per_type, per_map = Counter(), Counter()
    for gid, grs in sorted(groups.items()):
        r0 = grs[0]
        if r0["map"] not in maps:
            maps[r0["map"]] = load(r0["map"])
        objs, geom = maps[r0["map"]]
        by = {o["id"]: o for o in objs}
        typ, target, accept = r0["type"], r0["target"], sorted(r0["accept"])
        per_type[typ] += 1
        per_map[Path(r0["map"]).name] += 1
        if typ in ("o", "or"):
            labels, room = KIND[gid]
            if (typ == "or") != (room is not None):
                errors.append(f"{gid}: or/o room mismatch in spec")
            derived = sorted(o["id"] for o in objs if o["label"] in labels and (room is None or o["room"] == room))
            if derived != accept:
                errors.append(f"{gid}: accept {accept} but map gives {derived}")
            notes.append(f"{gid} {typ}: kind {sorted(labels)} room {room} -> {derived}")
        else:
            if accept != [target]:
                errors.append(f"{gid}: single-id type with accept {accept}")
        if typ in ("od", "ord"):
            labels, room, kws = DESC[gid]
            if (typ == "ord") != (room is not None):
                errors.append(f"{gid}: od/ord room mismatch in spec")
            cands = [o for o in objs if o["label"] in labels and (room is None or o["room"] == room)]
            hits = [o["id"] for o in cands if all(k in o["text"] for k in kws)]
            if hits != [target]:
                errors.append(f"{gid}: keywords {kws} match {hits} among {[o['id'] for o in cands]}")
            notes.append(f"{gid} {typ}: {kws} among {len(cands)} of kind -> {hits}")
        if typ == "ard":
            labels, room, forbidden = NEED[gid]
            hits = [o["id"] for o in objs if o["label"] in labels]
            in_room = [i for i in hits if room is None or by[i]["room"] == room]
            if in_room != [target]:
                errors.append(f"{gid}: need labels {labels} give {hits} (in room {room}: {in_room})")
            for r in grs:
                for f in forbidden + [by[target]["label"]]:
                    if re.search(r"\b" + re.escape(f.lower()) + r"\b", r["query"].lower()):
                        errors.append(f"{gid}: {r['id']} names the kind ({f!r})")
            notes.append(f"{gid} ard: serving labels {sorted(labels)} -> {hits}")
        if typ == "s":
            if not geom:
                errors.append(f"{gid}: spatial group on a map without geometry")
                continue
            labels, room, filt, score, higher, what = s_specs(objs)[gid]
            cands = [o for o in objs if o["label"] in labels and (room is None or o["room"] == room)]
            passing = [o for o in cands if filt is None or filt(o)]
            ranked = rank(passing, score, higher)
            if not ranked or ranked[0][1] != target:
                errors.append(f"{gid}: best by {what} is {ranked[:2]}, not {target}")
            elif len(ranked) > 1 and abs(ranked[0][0] - ranked[1][0]) < MARGIN:
                errors.append(f"{gid}: margin {abs(ranked[0][0]-ranked[1][0]):.2f} < {MARGIN} ({ranked[:2]})")
            if gid == "b60-g47" and not inside_xy(c(by[target]), by[1]):
                errors.append(f"{gid}: target not on table 1")
            if gid == "b60-g47":
                on = [o["id"] for o in cands if inside_xy(c(o), by[1]) and bottom(o) >= top(by[1]) - 0.05]
                if on != [target]:
                    errors.append(f"{gid}: monitors on the white table {on}")
            if gid == "b60-g42" and not xy_overlap(by[target], by[10]):
                errors.append(f"{gid}: target does not overlap the sink in xy")
            rest = [(round(s, 2), i) for s, i in ranked]
            notes.append(f"{gid} s: {what}; candidates {len(cands)} kept {len(passing)}: {rest}")
        for e in style_errors(grs, typos[gid]):
            errors.append(f"{gid}: {e}")
        uses = label_uses(grs, {by[a]["label"] for a in accept})
        if uses > 2:
            errors.append(f"{gid}: map label in {uses} wordings")
        if len(grs) != 6:
            errors.append(f"{gid}: {len(grs)} lines")
    want = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    if dict(per_type) != want:
        errors.append(f"type counts {dict(per_type)} != {want}")
    if len(rows) != 288 or len(groups) != 48:
        errors.append(f"{len(rows)} lines, {len(groups)} groups")
    for n in notes:
        print(n)
    print(f"per type {dict(per_type)}")
    print(f"per map {dict(per_map)}")
    for e in errors:
        print("ERROR", e)
    print(f"{len(errors)} errors")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1] if len(sys.argv) > 1 else str(SUITE_DIR / "round60.jsonl")))
