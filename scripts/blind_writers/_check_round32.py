"""Re-derive o/or accept sets from the maps, check every spatial claim numerically, and check the
wording styles and the group/type/map spread of round 32.

    python3 scripts/check.py
"""
import json, math, re, sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import emit  # noqa: E402

SUITE_DIR = Path(__file__).resolve().parents[1] / "evals" / "blind"
MARGIN = 0.2
errors = []


def load(map_):
    p = (SUITE_DIR / map_).resolve()
    return json.loads(p.read_text(encoding="utf-8"))


def in_poly(x, y, poly):
    inside = False
    n = len(poly)
    for i in range(n):
        x1, y1 = poly[i]; x2, y2 = poly[(i + 1) % n]
        if (y1 > y) != (y2 > y) and x < (x2 - x1) * (y - y1) / (y2 - y1) + x1:
            inside = not inside
    return inside


def room_of(data, o):
    """Room label of an object from the room polygons (centre), falling back to its room field."""
    hits = [r["label"] for r in data.get("rooms", []) if in_poly(o["center"][0], o["center"][1], r["polygon"])]
    if len(hits) == 1:
        return hits[0]
    return str(o.get("room"))


def expected_accept(grp):
    data = load(grp["map"])
    if "objects" in data:
        objs = {o["id"]: o for o in data["objects"]}
        ids = [i for i, o in objs.items() if o["label"] == grp["label"]]
        if grp["type"] == "or":
            for i in ids:
                if room_of(data, objs[i]) != objs[i].get("room") and str(objs[i].get("room")) not in ("1",):
                    errors.append(f"{grp['map']} id {i}: polygon room {room_of(data, objs[i])} != field {objs[i].get('room')}")
            ids = [i for i in ids if room_of(data, objs[i]) == grp["room"]]
    else:
        ids = [int(k) for k, v in data.items() if v["category"] == grp["label"]]
        if grp["type"] == "or":
            ids = [i for i in ids if data[str(i)]["room_cat"] == grp["room"]]
    return sorted(ids)


def box(o):
    c, s = o["center"], o["size"]
    return [c[i] - s[i] / 2 for i in range(3)], [c[i] + s[i] / 2 for i in range(3)]


def xy_in(o, sup):
    lo, hi = box(sup)
    return lo[0] <= o["center"][0] <= hi[0] and lo[1] <= o["center"][1] <= hi[1]


def dist(a, b):
    return math.hypot(a["center"][0] - b["center"][0], a["center"][1] - b["center"][1])


def check_claim(gid, objs, claim):
    kind = claim[0]
    if kind == "nearest":
        _, t, anchor, cands = claim
        d = {c: dist(objs[c], objs[anchor]) for c in cands}
        others = [d[c] for c in cands if c != t]
        ok = all(d[t] + MARGIN <= x for x in others)
        msg = f"nearest {t} to {anchor}: " + ", ".join(f"{c}={d[c]:.2f}" for c in cands)
    elif kind == "between":
        _, t, a, b, axis, cands = claim
        k = "xyz".index(axis)
        lo, hi = sorted([objs[a]["center"][k], objs[b]["center"][k]])
        v = objs[t]["center"][k]
        ok = lo + MARGIN <= v <= hi - MARGIN and all(
            not (lo < objs[c]["center"][k] < hi) for c in cands if c not in (t, a, b))
        msg = f"between {t} on {axis}: {lo:.2f} < {v:.2f} < {hi:.2f}"
    elif kind == "on":
        _, t, sups, cands = claim
        def on(i):
            lo, _ = box(objs[i])
            return any(xy_in(objs[i], objs[s]) and abs(lo[2] - box(objs[s])[1][2]) <= 0.05 for s in sups)
        ok = on(t) and not any(on(c) for c in cands if c != t)
        msg = f"on {t} over {sups}: target bottom {box(objs[t])[0][2]:.2f}; others on: {[c for c in cands if c != t and on(c)]}"
    elif kind == "above":
        _, t, base, cands = claim
        top = box(objs[base])[1][2]
        def above(i):
            return xy_in(objs[base], objs[i]) or xy_in(objs[i], objs[base])
        ok = above(t) and box(objs[t])[0][2] >= top + MARGIN and not any(above(c) for c in cands if c != t)
        msg = f"above {t} over {base}: bottom {box(objs[t])[0][2]:.2f} vs top {top:.2f}; others above: {[c for c in cands if c != t and above(c)]}"
    elif kind == "higher":
        _, t, cands = claim
        z = {c: objs[c]["center"][2] for c in cands}
        ok = all(z[t] >= z[c] + MARGIN for c in cands if c != t)
        msg = "higher: " + ", ".join(f"{c}={z[c]:.2f}" for c in cands)
    elif kind == "left":
        _, t, viewer, facing, cands = claim
        vx, vy = objs[viewer]["center"][:2] if isinstance(viewer, int) else viewer
        fx, fy = objs[facing]["center"][:2] if isinstance(facing, int) else facing
        dx, dy = fx - vx, fy - vy
        n = math.hypot(dx, dy); lx, ly = -dy / n, dx / n  # unit vector to the viewer's left
        lat = {c: (objs[c]["center"][0] - vx) * lx + (objs[c]["center"][1] - vy) * ly for c in cands}
        ok = lat[t] >= MARGIN and all(lat[c] <= lat[t] - MARGIN for c in cands if c != t)
        msg = "left offsets: " + ", ".join(f"{c}={lat[c]:.2f}" for c in cands)
    else:
        ok, msg = False, f"unknown claim {kind}"
    print(f"  {gid} {'OK ' if ok else 'BAD'} {msg}")
    if not ok:
        errors.append(f"{gid}: spatial claim fails: {msg}")


ARTICLES = re.compile(r"\b(a|an|the)\b", re.I)
per_type, per_map = Counter(), Counter()
for n, grp in enumerate(emit.G, 1):
    gid = f"b32-g{n:02d}"
    per_type[grp["type"]] += 1
    per_map[Path(grp["map"]).name] += 1
    data = load(grp["map"])
    ids = {o["id"] for o in data["objects"]} if "objects" in data else {int(k) for k in data}
    if grp["target"] not in grp["accept"] or not set(grp["accept"]) <= ids:
        errors.append(f"{gid}: target/accept not in map")
    if grp["type"] in ("o", "or"):
        exp = expected_accept(grp)
        print(f"  {gid} {grp['type']} {grp['label']!r} {grp['room']!r}: derived {exp} vs written {grp['accept']}")
        if exp != grp["accept"]:
            errors.append(f"{gid}: accept {grp['accept']} != derived {exp}")
    else:
        if len(grp["accept"]) != 1 and grp["type"] != "ard":
            errors.append(f"{gid}: {grp['type']} should have a single id")
    if grp["type"] == "s":
        if "objects" not in data:
            errors.append(f"{gid}: spatial on a caption map")
        elif not grp["claims"]:
            errors.append(f"{gid}: spatial group without claims")
        else:
            objs = {o["id"]: o for o in data["objects"]}
            for cl in grp["claims"]:
                check_claim(gid, objs, cl)
    q = grp["q"]
    if not q[0].startswith("Go to"):
        errors.append(f"{gid} w1 not a plain imperative")
    if not (q[1].startswith("Could you") and q[1].endswith("?")):
        errors.append(f"{gid} w2 not a polite question")
    if ARTICLES.search(q[2]) or len(q[2].split()) > 8:
        errors.append(f"{gid} w3 not telegraphic: {q[2]!r}")
    if not q[4].startswith("This is") or len(re.findall(r"[.!?](\s|$)", q[4])) != 2:
        errors.append(f"{gid} w5 not two sentences starting 'This is': {q[4]!r}")
    if q[5] != q[5].lower():
        errors.append(f"{gid} w6 not lower case")
    if len({s.lower() for s in q}) != 6:
        errors.append(f"{gid}: duplicate wordings")

print("groups per type", dict(per_type))
print("groups per map", dict(per_map))
cap = per_map["scene_00829_caption.json"] + per_map["scene_office3_caption.json"]
flats = sum(v for k, v in per_map.items() if k.startswith("flat_"))
scan_s = sum(1 for grp in emit.G if grp["type"] == "s" and "scan_" in grp["map"])
want = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
if dict(per_type) != want:
    errors.append(f"type counts {dict(per_type)} != {want}")
if len(emit.G) != 48 or cap < 12 or flats < 14 or scan_s < 4:
    errors.append(f"spread: groups {len(emit.G)}, caption {cap}, flats {flats}, spatial on scans {scan_s}")
print(f"caption-map groups {cap}, flat groups {flats}, spatial groups on scans {scan_s}")
for e in errors:
    print("ERROR", e)
print("check.py:", "FAIL" if errors else "all checks passed")
sys.exit(1 if errors else 0)
