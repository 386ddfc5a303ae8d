"""Round 53 self-check: re-derive o/or accept sets from the maps, check every single-id claim
(numerically for spatial groups), the wording style rules and the counts."""
import json, math, re, sys
from collections import Counter
from pathlib import Path

BASE = Path(__file__).resolve().parents[2] / "evals/blind"
SUITE = BASE / "round53.jsonl"
WORDS = {w.strip().lower() for w in open("/usr/share/dict/words", encoding="utf-8")}
# real words or British spellings missing from the system word list
WORDS |= {"l-shaped", "rec", "tv", "usb", "motorised", "colour", "coloured", "centre", "favourite", "wastebasket",
          "lounger", "spyhole", "workspace", "stargazing", "nightstand", "nightstands", "two-seater",
          "whiteboard", "cream-coloured", "odd-coloured"}

def load(mapname):
    p = (BASE / mapname).resolve()
    if not p.is_file():
        p = Path(__file__).resolve().parents[2] / "map_store" / f"{mapname}.json"
    d = json.loads(p.read_text())
    objs = {}
    if isinstance(d, dict) and "objects" in d:
        rooms = {str(r["id"]): r["label"] for r in d["rooms"]}
        for o in d["objects"]:
            room = str(o.get("room", ""))
            room = rooms.get(room, room)
            tags = o.get("tags") or {}
            text = " ".join([o["label"], o.get("caption", ""), " ".join(map(str, tags.values()))]).lower()
            objs[o["id"]] = dict(label=o["label"], room=room, text=text, c=o["center"], s=o["size"], geo=True)
    else:
        for k, v in d.items():
            raw = v["caption"]
            try:
                cj = json.loads(re.sub(r",\s*}\s*$", "}", raw))
            except ValueError:
                cj = {"captions": raw}
            text = " ".join([v["category"], str(cj.get("color", "")), str(cj.get("material", "")), cj.get("captions", "")]).lower()
            objs[int(k)] = dict(label=v["category"], room=v.get("room_cat"), room_id=v.get("room_id"), text=text, geo=False)
    return objs

def has(*words):
    return lambda o: all(w in o["text"] for w in words)

def dist(a, b):
    return math.hypot(a["c"][0] - b["c"][0], a["c"][1] - b["c"][1])

# per group: kind labels, room (None = any), and for single-id types a predicate or spatial score
SPEC = {
 "b53-g01": dict(kind={"book"}),
 "b53-g02": dict(kind={"easy chair"}, room="bedroom"),
 "b53-g03": dict(kind={"couch", "sofa"}, pred=has("l-shaped", "chaise")),
 "b53-g04": dict(kind={"doorway", "door frame", "door/window frame"}, pred=has("peephole")),
 "b53-g05": dict(kind={"easy chair", "chair", "folded chair"}, room="bathroom", pred=has("beige", "velvet")),
 "b53-g06": dict(ard=lambda o: "pet" in o["label"] and o["room"] == "bathroom"),
 "b53-g07": dict(ard=lambda o: o["label"] in {"keyboard", "laptop", "computer"} and o["room"] == "bedroom"),
 "b53-g08": dict(kind={"curtain"}),
 "b53-g09": dict(kind={"window"}, room="rec room"),
 "b53-g10": dict(kind={"pillow", "cushion"}, pred=has("navy", "velvet")),
 "b53-g11": dict(kind={"desk"}, room="rec room", pred=lambda o: o["text"].split()[1] == "white" or "white wooden desk" in o["text"]),
 "b53-g12": dict(ard=lambda o: o["label"] == "clock" and o["room"] == "rec room"),
 "b53-g13": dict(kind={"lamp"}),
 "b53-g14": dict(kind={"armchair"}, room="living room", pred=has("gray")),
 "b53-g15": dict(ard=lambda o: "clock" in o["label"] and o["room"] == "bedroom"),
 "b53-g16": dict(kind={"chair", "office chair"}, near=("label", "refrigerator")),
 "b53-g17": dict(kind={"chair"}, room="studio"),
 "b53-g18": dict(kind={"stool"}, pred=has("black", "metal")),
 "b53-g19": dict(ard=lambda o: o["label"] in {"bench", "chair", "stool", "sofa bed", "sofa"} and o["room"] == "entrance hall"),
 "b53-g20": dict(kind={"rug"}, under=10),  # rug whose centre is under the low table (id 2)
 "b53-g21": dict(kind={"rug"}),
 "b53-g22": dict(kind={"chair"}, room="kitchen", pred=has("yellow")),
 "b53-g23": dict(ard=lambda o: o["label"] == "telescope" and o["room"] == "porch"),
 "b53-g24": dict(kind={"armchair"}, near=("label", "fireplace")),
 "b53-g25": dict(kind={"nightstand"}, room="master bedroom"),
 "b53-g26": dict(kind={"armchair"}, pred=has("leather", "studs")),
 "b53-g27": dict(kind={"chair"}, room="dining room", pred=has("rattan")),
 "b53-g28": dict(kind={"towel"}, high=+1),
 "b53-g29": dict(kind={"mirror"}),
 "b53-g30": dict(kind={"chair"}, room="kitchen"),
 "b53-g31": dict(kind={"lamp"}, pred=has("black", "floor", "arched")),
 "b53-g32": dict(kind={"cabinet"}, room="bathroom", pred=has("gray")),
 "b53-g33": dict(ard=lambda o: o["label"] == "printer" and o["room"] == "office"),
 "b53-g34": dict(kind={"book"}, high=-1),
 "b53-g35": dict(kind={"sofa"}, big=+1),
 "b53-g36": dict(kind={"plant"}, on=("label", "dresser")),
 "b53-g37": dict(kind={"pillow"}),
 "b53-g38": dict(ard=lambda o: o["label"] == "clock"),
 "b53-g39": dict(kind={"nightstand"}, left_facing=(0, 1)),
 "b53-g40": dict(kind={"cup"}, room="kitchen"),
 "b53-g41": dict(kind={"kitchen cabinet"}, pred=has("gray")),
 "b53-g42": dict(kind={"chair"}, near=("label", "door")),
 "b53-g43": dict(kind={"picture"}),
 "b53-g44": dict(kind={"armchair"}, room="living room", pred=has("green")),
 "b53-g45": dict(kind={"pillow"}, between=True),
 "b53-g46": dict(kind={"monitor"}, room="office"),
 "b53-g47": dict(kind={"bookshelf"}, tall=-1),
 "b53-g48": dict(kind={"trash can"}, far=("label", "door")),
}

def ref(objs, key):
    hits = [o for o in objs.values() if o[key[0]] == key[1]]
    assert len(hits) == 1, key
    return hits[0]

def ranked(scores, target, best_low=True):
    """margin between the target's score and the runner-up; target must be best."""
    order = sorted(scores, key=lambda i: scores[i], reverse=not best_low)
    if order[0] != target:
        return None, order
    return abs(scores[order[1]] - scores[order[0]]), order

def check_group(g, rows, objs, problems, notes):
    r = rows[0]; spec = SPEC[g]; t = r["type"]; target = r["target"]; acc = set(r["accept"])
    def kindset():
        return {i for i, o in objs.items() if o["label"] in spec["kind"]
                and (spec.get("room") is None or o["room"] == spec["room"])}
    if t in ("o", "or"):
        derived = kindset()
        if derived != acc:
            problems.append(f"{g}: accept {sorted(acc)} but map gives {sorted(derived)}")
        if t == "or" and not spec.get("room"):
            problems.append(f"{g}: or group without room")
        return
    if len(acc) != 1:
        problems.append(f"{g}: single-id type with accept {sorted(acc)}")
    if t in ("od", "ord"):
        cands = kindset()
        hits = {i for i in cands if spec["pred"](objs[i])}
        if hits != {target}:
            problems.append(f"{g}: description matches {sorted(hits)} among {sorted(cands)}")
        else:
            notes.append(f"{g}: {t} unique among {len(cands)} of its kind")
        return
    if t == "ard":
        hits = {i for i, o in objs.items() if spec["ard"](o)}
        if hits != {target}:
            problems.append(f"{g}: need met by {sorted(hits)}")
        else:
            notes.append(f"{g}: ard met only by {target}")
        return
    # spatial
    cands = kindset()
    if not all(objs[i]["geo"] for i in cands):
        problems.append(f"{g}: spatial on a map without geometry"); return
    if len(cands) < 2:
        problems.append(f"{g}: spatial with a single object of its kind")
    C = {i: objs[i] for i in cands}
    if "near" in spec or "far" in spec:
        key = spec.get("near") or spec.get("far")
        a = ref(objs, key)
        scores = {i: dist(C[i], a) for i in C}
        m, order = ranked(scores, target, best_low="near" in spec)
        what = "nearest" if "near" in spec else "farthest"
    elif "under" in spec:
        table = objs[2]
        scores = {i: dist(C[i], table) for i in C}
        m, order = ranked(scores, target)
        tb = C[target]
        ok = (abs(tb["c"][0] - table["c"][0]) < tb["s"][0] / 2 and abs(tb["c"][1] - table["c"][1]) < tb["s"][1] / 2
              and tb["c"][2] + tb["s"][2] / 2 <= table["c"][2] - table["s"][2] / 2 + 0.03)  # a thin rug the legs stand on
        if not ok: problems.append(f"{g}: target not under the table")
        what = "under low table (xy distance)"
    elif "high" in spec:
        scores = {i: C[i]["c"][2] for i in C}
        m, order = ranked(scores, target, best_low=spec["high"] < 0)
        what = "higher" if spec["high"] > 0 else "lower"
    elif "big" in spec:
        scores = {i: max(C[i]["s"]) for i in C}
        m, order = ranked(scores, target, best_low=False)
        vol = {i: C[i]["s"][0] * C[i]["s"][1] * C[i]["s"][2] for i in C}
        if max(vol, key=vol.get) != target: problems.append(f"{g}: target not largest by volume")
        what = "bigger (longest side)"
    elif "tall" in spec:
        scores = {i: C[i]["s"][2] for i in C}
        m, order = ranked(scores, target, best_low=spec["tall"] < 0)
        what = "shortest"
    elif "on" in spec:
        base = ref(objs, spec["on"])
        def gap(o):  # xy distance + vertical gap between o's bottom and base's top
            dz = abs((o["c"][2] - o["s"][2] / 2) - (base["c"][2] + base["s"][2] / 2))
            return dist(o, base) + dz
        scores = {i: gap(C[i]) for i in C}
        m, order = ranked(scores, target)
        if scores[target] > 0.05: problems.append(f"{g}: target not resting on the base")
        what = "on top of base"
    elif "left_facing" in spec:
        fx, fy = spec["left_facing"]; lx, ly = -fy, fx   # left of facing direction
        scores = {i: C[i]["c"][0] * lx + C[i]["c"][1] * ly for i in C}
        m, order = ranked(scores, target, best_low=False)
        what = "left when facing +y"
    elif "between" in spec:
        def off(i):
            others = [C[j] for j in C if j != i]
            mx = sum(o["c"][0] for o in others) / len(others); my = sum(o["c"][1] for o in others) / len(others)
            return math.hypot(C[i]["c"][0] - mx, C[i]["c"][1] - my)
        scores = {i: off(i) for i in C}
        m, order = ranked(scores, target)
        what = "between the others"
    if m is None:
        problems.append(f"{g}: target not best ({what}); order {order}")
    elif m < 0.2:
        problems.append(f"{g}: margin {m:.2f} < 0.2 ({what})")
    else:
        notes.append(f"{g}: s {what}: target {target} score {scores[target]:.2f}, runner-up {order[1]} {scores[order[1]]:.2f}, margin {m:.2f}")

ART = {"a", "an", "the"}
IMPER = ("Go ", "Take ", "Head ", "Find ", "Get ", "Bring ", "Lead ", "Show ")

def toks(q):
    return [t.strip("'") for t in re.findall(r"[a-zA-Z][a-zA-Z'-]*", q)]

def style(g, rows, problems):
    q = {int(r["id"][-1]): r["query"] for r in rows}
    if not q[1].startswith(IMPER) or "?" in q[1]:
        problems.append(f"{g} w1 not a plain imperative")
    if not (q[2].startswith("Could you ") and q[2].endswith("?")):
        problems.append(f"{g} w2 not a Could-you question")
    w3 = q[3].replace(",", " ").split()
    if len(w3) > 6 or any(w.lower() in ART for w in w3) or q[3].endswith("?"):
        problems.append(f"{g} w3 not telegraphic: {len(w3)} words")
    if not (", not " in q[4] or " so " in q[4] or "because" in q[4] or "rather than" in q[4]):
        problems.append(f"{g} w4 has no reason/contrast")
    sents = [s for s in re.split(r"(?<=[.!?])\s+", q[5].strip()) if s]
    if not q[5].startswith("This is ") or len(sents) != 2:
        problems.append(f"{g} w5 not two sentences starting 'This is': {len(sents)}")
    if q[6] != q[6].lower():
        problems.append(f"{g} w6 not all lower case")
    unknown = []
    for t in toks(q[6]):
        parts = [t] if t in WORDS else t.split("-")
        if not all(p in WORDS for p in parts):
            unknown.append(t)
    if len(unknown) != 1:
        problems.append(f"{g} w6 has {len(unknown)} non-dictionary words: {unknown}")
    for i in range(1, 6):
        bad = [t for t in toks(q[i]) if t.lower() not in WORDS and not all(p.lower() in WORDS for p in t.split("-"))]
        if bad:
            problems.append(f"{g} w{i} unknown words {bad}")
    return unknown

def main():
    rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
    groups = {}
    for r in rows:
        groups.setdefault(r["group"], []).append(r)
    problems, notes = [], []
    cache = {}
    per_type, per_map, typos = Counter(), Counter(), {}
    for g, rs in groups.items():
        m = rs[0]["map"]
        objs = cache.setdefault(m, load(m))
        check_group(g, rs, objs, problems, notes)
        typos[g] = style(g, rs, problems)
        names = {objs[a]["label"].lower() for a in rs[0]["accept"]}
        uses = sum(any(re.search(r"\b" + re.escape(n) + r"(s|es)?\b", x["query"].lower()) for n in names) for x in rs)
        if uses > 2:
            problems.append(f"{g}: map label in {uses} wordings")
        per_type[rs[0]["type"]] += 1
        per_map[Path(m).name] += 1
    want_type = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    if dict(per_type) != want_type:
        problems.append(f"type counts {dict(per_type)}")
    if len(groups) != 48 or len(rows) != 288:
        problems.append(f"{len(groups)} groups, {len(rows)} lines")
    cap = per_map["scene_00829_caption.json"] + per_map["scene_office3_caption.json"]
    flats = sum(per_map[f"flat_{x}.json"] for x in "cdfh")
    scans = sum(v for k, v in per_map.items() if k.startswith("scan_"))
    s_maps = Counter(Path(rs[0]["map"]).name for rs in groups.values() if rs[0]["type"] == "s")
    for n in notes:
        print("ok  ", n)
    print("w6 typos:", {g: t for g, t in typos.items()})
    print("types", dict(per_type))
    print("maps", dict(per_map))
    print(f"caption maps {cap}, flats {flats}, apartment {per_map['apartment']}, scans {scans}; s groups by map {dict(s_maps)}")
    for p in problems:
        print("PROBLEM", p)
    print(f"{len(problems)} problems")
    return 1 if problems else 0

if __name__ == "__main__":
    sys.exit(main())
