"""Check round30 against its maps: o/or accept sets re-derived from labels (and rooms), single-id
types have one accepted id with the stated label/room, and every spatial claim is checked numerically
from centres and sizes (margin >= 0.2 m for distance and height claims).
    python3 scripts/check.py"""
import json, math, sys
from collections import defaultdict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SUITE = ROOT / "evals" / "blind" / "round30.jsonl"
MARGIN = 0.2

CATEGORY = {  # o / or: (label, room or None)
    "g01": ("easy chair", None), "g02": ("side table", "bedroom"), "g03": ("set of towels", "living room"),
    "g08": ("pillow", None), "g09": ("desk", "rec room"),
    "g13": ("lamp", None), "g14": ("mirror", None), "g15": ("mug", None),
    "g16": ("lamp", "bedroom"), "g17": ("chair", "meeting room"),
    "g31": ("plant", None), "g32": ("book", "living room"), "g33": ("chair", "kitchen"),
    "g42": ("monitor", None),
}
SINGLE = {  # od / ord / ard / s: (label of target, room of target or None)
    "g04": ("stand/small table", None), "g05": ("bed curtain", "bedroom"), "g06": ("garden bench", "bathroom"),
    "g07": ("bed for pet", None), "g10": ("monitor", None), "g11": ("pillow", None), "g12": ("clock", None),
    "g18": ("ironing board", None), "g19": ("lamp", None), "g20": ("chair", "dining room"),
    "g21": ("chair", "kitchen"), "g22": ("armchair", "living room"), "g23": ("dryer", None),
    "g24": ("toolbox", None), "g25": ("kettle", None), "g26": ("printer", None),
    "g27": ("lamp", "bedroom"), "g28": ("lamp", None), "g29": ("bicycle", None), "g30": ("monitor", "studio"),
    "g34": ("sofa", None), "g35": ("picture", "hallway"), "g36": ("mirror", "bathroom"),
    "g37": ("microwave", None), "g38": ("washing machine", None),
    "g39": ("book", "living room"), "g40": ("chair", "kitchen"), "g41": ("plant", "bedroom"),
    "g43": ("chair", None), "g44": ("lamp", None), "g45": ("pillow", None), "g46": ("cup", None),
    "g47": ("kitchen cabinet", None), "g48": ("bookshelf", None),
}
# unique-description checks (od/ord): other objects of the label must not share the tag / caption word
DESCR = {
    "g04": ("caption", "honey"), "g05": ("caption", "floral"), "g06": ("caption", "weathered"), "g10": ("caption", "world map"),
    "g11": ("color", "navy blue"), "g18": ("caption", "floral"), "g19": ("caption", "rattan"),
    "g20": ("color", "black"), "g21": ("caption", "red checked"), "g22": ("material", "leather"),
    "g34": ("material", "leather"), "g35": ("caption", "lighthouse"), "g36": ("caption", "oval"),
    "g43": ("color", "red"),
}
# spatial claims: (kind, candidate label, candidate room or None, reference id or axis)
SPATIAL = {
    "g27": ("nearest", "lamp", "bedroom", 35),       # flat_b: bedside lamp nearer the wardrobe
    "g28": ("highest", "lamp", None, None),          # flat_e: the lamp hanging highest
    "g29": ("nearest", "bicycle", None, 4),          # flat_g: bike nearer the workbench
    "g30": ("nearest", "monitor", None, 21),         # flat_i: screen nearer the bookshelf
    "g39": ("highest", "book", "living room", None), # apartment: upper book in the living room
    "g40": ("nearest", "chair", "kitchen", 19),      # apartment: dining chair nearest the stove
    "g41": ("on", "plant", None, 38),                # apartment: plant on the dresser
    "g44": ("nearest", "lamp", None, 14),            # scan_bedroom: lamp nearer the window
    "g45": ("nearest_point", "pillow", None, (2.25, 1.85)),  # scan_bedroom: pillow nearest the foot (south edge) of the bed
    "g46": ("nearest", "cup", None, 10),             # scan_kitchen: cup nearest the sink
    "g47": ("under", "kitchen cabinet", None, 10),   # scan_kitchen: cabinet under the sink
    "g48": ("shortest", "bookshelf", None, None),    # scan_office: shortest bookshelf (top height)
}
EXTRA = {  # additional contrasts stated in the wordings
    "g27": [("nearest", "lamp", "bedroom", 36, "far")],   # not the one by the window -> target is farther from window
    "g44": [("nearest", "lamp", None, 15, "far")],        # not the one by the door
    "g40": [("colour_other", 24, "white")],
}


def load(mp):
    p = (SUITE.parent / mp)
    if not p.is_file():
        p = ROOT / "map_store" / f"{mp}.json"
    d = json.loads(p.read_text())
    if "objects" in d:
        rooms = {r["id"]: r for r in d.get("rooms", [])}
        objs = {}
        for o in d["objects"]:
            room = o.get("room")
            if not isinstance(room, str):  # room given as an id or missing: use the polygon
                room = rooms[room]["label"] if room in rooms else poly_room(o["center"], d.get("rooms", []))
            objs[o["id"]] = dict(label=o["label"], room=room, c=o["center"], s=o["size"], tags=o.get("tags", {}) or {},
                                 caption=o.get("caption", "") or "")
        return objs, True
    import re
    objs = {}
    for k, v in d.items():
        cap = v.get("caption", "")
        m = re.search(r'"color"\s*:\s*"(.*?)"', cap)
        objs[int(k)] = dict(label=v["category"], room=v.get("room_cat"), tags={"color": m.group(1) if m else ""},
                            caption=cap)
    return objs, False


def poly_room(c, rooms):
    x, y = c[0], c[1]
    for r in rooms:
        p = r["polygon"]; inside = False
        for i in range(len(p)):
            (x1, y1), (x2, y2) = p[i], p[(i + 1) % len(p)]
            if (y1 > y) != (y2 > y) and x < (x2 - x1) * (y - y1) / (y2 - y1) + x1:
                inside = not inside
        if inside:
            return r["label"]
    return None


def dist(a, b):
    return math.hypot(a[0] - b[0], a[1] - b[1])


def main():
    rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
    groups = defaultdict(list)
    for r in rows:
        groups[r["group"].split("-")[1]].append(r)
    errs = []
    for g, rs in sorted(groups.items()):
        r = rs[0]; objs, geo = load(r["map"]); t = r["type"]; acc = set(r["accept"]); tgt = r["target"]
        if t in ("o", "or"):
            lab, room = CATEGORY[g]
            want = {i for i, o in objs.items() if o["label"] == lab and (room is None or o["room"] == room)}
            if want != acc:
                errs.append(f"{g}: accept {sorted(acc)} != derived {sorted(want)} ({lab}, {room})")
            continue
        if len(acc) != 1:
            errs.append(f"{g}: {t} should have one id"); continue
        lab, room = SINGLE[g]
        o = objs[tgt]
        if o["label"] != lab or (room and o["room"] != room):
            errs.append(f"{g}: target {tgt} is {o['label']}/{o['room']}, expected {lab}/{room}")
        if g in DESCR:
            field, word = DESCR[g]
            def has(x):
                return word.lower() in (x["caption"] if field == "caption" else str(x["tags"].get(field, ""))).lower()
            if not has(o):
                errs.append(f"{g}: target lacks {field}={word}")
            same = [i for i, x in objs.items() if i != tgt and x["label"] == lab and has(x)
                    and (t != "ord" or x["room"] == room)]
            if same:
                errs.append(f"{g}: description {word} also fits {same}")
        if t == "s":
            kind, clab, croom, ref = SPATIAL[g]
            cands = {i: x for i, x in objs.items() if x["label"] == clab and (croom is None or x["room"] == croom)}
            if tgt not in cands or len(cands) < 2:
                errs.append(f"{g}: target not among {len(cands)} candidates"); continue
            if kind in ("nearest", "nearest_point"):
                rp = ref if kind == "nearest_point" else objs[ref]["c"]
                ds = {i: dist(x["c"], rp) for i, x in cands.items()}
                best = min(ds.values()); others = [v for i, v in ds.items() if i != tgt]
                ok = ds[tgt] == best and min(others) - best >= MARGIN
                print(f"{g} {kind} ref={ref}: " + ", ".join(f"{i}:{v:.2f}" for i, v in sorted(ds.items())), "OK" if ok else "FAIL")
                if not ok: errs.append(f"{g}: nearest claim fails")
            elif kind in ("highest", "shortest"):
                top = {i: x["c"][2] + x["s"][2] / 2 for i, x in cands.items()}
                val = top[tgt]; others = [v for i, v in top.items() if i != tgt]
                ok = (val - max(others) >= MARGIN) if kind == "highest" else (min(others) - val >= MARGIN)
                zc = {i: x["c"][2] for i, x in cands.items()}
                if kind == "highest":
                    ok = ok and zc[tgt] - max(v for i, v in zc.items() if i != tgt) >= MARGIN
                print(f"{g} {kind} tops: " + ", ".join(f"{i}:{v:.2f}" for i, v in sorted(top.items())), "OK" if ok else "FAIL")
                if not ok: errs.append(f"{g}: height claim fails")
            elif kind in ("on", "under"):
                a, b = (o, objs[ref]) if kind == "on" else (objs[ref], o)  # a rests on b
                bottom = a["c"][2] - a["s"][2] / 2; btop = b["c"][2] + b["s"][2] / 2
                inside = all(abs(a["c"][k] - b["c"][k]) <= b["s"][k] / 2 for k in (0, 1))
                ok = abs(bottom - btop) <= 0.05 and inside
                # and no other candidate is in that relation
                for i, x in cands.items():
                    if i == tgt: continue
                    a2, b2 = (x, objs[ref]) if kind == "on" else (objs[ref], x)
                    if abs((a2["c"][2] - a2["s"][2] / 2) - (b2["c"][2] + b2["s"][2] / 2)) <= 0.05 and \
                            all(abs(a2["c"][k] - b2["c"][k]) <= b2["s"][k] / 2 for k in (0, 1)):
                        ok = False
                print(f"{g} {kind} ref={ref}: gap={bottom - btop:.2f} inside={inside}", "OK" if ok else "FAIL")
                if not ok: errs.append(f"{g}: {kind} claim fails")
        for ex in EXTRA.get(g, []):
            if ex[0] == "nearest":
                _, clab, croom, ref, sense = ex
                cands = {i: x for i, x in objs.items() if x["label"] == clab and (croom is None or x["room"] == croom)}
                ds = {i: dist(x["c"], objs[ref]["c"]) for i, x in cands.items()}
                ok = ds[tgt] - max(v for i, v in ds.items() if i != tgt) >= MARGIN
                print(f"{g} contrast ref={ref}: " + ", ".join(f"{i}:{v:.2f}" for i, v in sorted(ds.items())), "OK" if ok else "FAIL")
                if not ok: errs.append(f"{g}: contrast fails")
            elif ex[0] == "colour_other":
                ok = objs[ex[1]]["tags"].get("color") == ex[2]
                if not ok: errs.append(f"{g}: other object colour")
    for e in errs:
        print("ERROR", e)
    print(f"{len(groups)} groups checked, {len(errs)} errors")
    return 1 if errs else 0


if __name__ == "__main__":
    sys.exit(main())
