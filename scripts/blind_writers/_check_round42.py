"""Re-derive o/or accept sets and check spatial claims numerically for round42 (groups in emit.py).
python3 check.py  -> prints problems, exit 1 if any."""
import json, math, sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).resolve().parent))
from _build_round42 import G, MAPS

BLIND = Path(__file__).resolve().parents[2] / "evals" / "blind"
MARGIN = 0.2


def load(key):
    m = MAPS[key]
    p = BLIND / m if (BLIND / m).is_file() else None
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        return {"geo": True, "rooms": d.get("rooms", []), "objs": {o["id"]: o for o in d["objects"]}}
    return {"geo": False, "objs": {int(k): v for k, v in d.items()}}


def inside(pt, poly):
    x, y = pt; n = len(poly); c = False
    for i in range(n):
        x1, y1 = poly[i]; x2, y2 = poly[(i + 1) % n]
        if (y1 > y) != (y2 > y) and x < (x2 - x1) * (y - y1) / (y2 - y1) + x1:
            c = not c
    return c


def room_of(M, oid):
    o = M["objs"][oid]
    if not M["geo"]:
        return o.get("room_cat")
    rs = [r["label"] for r in M["rooms"] if inside(o["center"][:2], r["polygon"])]
    return rs[0] if len(rs) == 1 else (o.get("room") if not rs else rs)


def label(M, oid):
    o = M["objs"][oid]
    return o["label"] if M["geo"] else o["category"]


def d2(a, b):
    return math.hypot(a["center"][0] - b["center"][0], a["center"][1] - b["center"][1])


def measure(o, axis, how):
    c, s = o["center"][axis], o["size"][axis]
    return {"c": c, "top": c + s / 2, "bottom": c - s / 2}[how]


def xy_overlap(a, b):
    return all(abs(a["center"][i] - b["center"][i]) < (a["size"][i] + b["size"][i]) / 2 for i in (0, 1))


def xy_within(a, b):  # centre of a inside footprint of b
    return all(abs(a["center"][i] - b["center"][i]) <= b["size"][i] / 2 for i in (0, 1))


def main():
    probs = []
    cache = {}
    for gi, (mk, typ, target, accept, words, spec) in enumerate(G, 1):
        g = f"g{gi:02d}"
        M = cache.setdefault(mk, load(mk))
        objs = M["objs"]
        if target not in accept or any(a not in objs for a in accept):
            probs.append(f"{g}: target/accept missing")
            continue
        if typ in ("o", "or"):
            if spec[0] == "label":
                want = sorted(i for i in objs if label(M, i) == spec[1])
            else:
                want = sorted(i for i in objs if label(M, i) == spec[1] and room_of(M, i) == spec[2])
                # also compare with the stored room field on geometry maps
                if M["geo"]:
                    alt = sorted(i for i in objs if label(M, i) == spec[1] and objs[i].get("room") == spec[2])
                    if alt != want:
                        probs.append(f"{g}: polygon rooms {want} vs room field {alt}")
            if want != sorted(accept):
                probs.append(f"{g}: accept {sorted(accept)} but map gives {want}")
            else:
                print(f"{g} {typ} ok: {spec[1:]} -> {want}")
        elif typ in ("od", "ord", "ard"):
            if len(accept) > 1:
                labs = {label(M, a) for a in accept}
                print(f"{g} {typ} set accept {accept} labels {labs}; all of label: {sorted(i for i in objs if label(M, i) in labs)}")
            else:
                print(f"{g} {typ} target {target} {label(M, target)} room {room_of(M, target)}")
        elif typ == "s":
            if not M["geo"]:
                probs.append(f"{g}: spatial on caption map"); continue
            kind, cands = spec[0], spec[1]
            if target not in cands:
                probs.append(f"{g}: target not among candidates")
            if len({label(M, c) for c in cands}) != 1 or len(cands) < 2:
                probs.append(f"{g}: candidates {cands} not >=2 of one label")
            t = objs[target]
            others = [objs[c] for c in cands if c != target]
            if kind in ("nearest", "farthest"):
                refs = [objs[r] for r in spec[2]]
                dist = {c: min(d2(objs[c], r) for r in refs) for c in cands}
                best = dist[target]
                rest = [dist[c] for c in cands if c != target]
                gap = (min(rest) - best) if kind == "nearest" else (best - max(rest))
                ok = gap >= MARGIN
                print(f"{g} s {kind}: dists {{{', '.join(f'{c}:{dist[c]:.2f}' for c in cands)}}} gap {gap:.2f} {'ok' if ok else 'FAIL'}")
                if not ok: probs.append(f"{g}: {kind} margin {gap:.2f}")
            elif kind in ("max", "min"):
                axis, how = spec[2], spec[3]
                val = {c: measure(objs[c], axis, how) for c in cands}
                rest = [val[c] for c in cands if c != target]
                gap = (val[target] - max(rest)) if kind == "max" else (min(rest) - val[target])
                ok = gap >= MARGIN
                print(f"{g} s {kind} axis {axis} {how}: {val} gap {gap:.2f} {'ok' if ok else 'FAIL'}")
                if not ok: probs.append(f"{g}: {kind} margin {gap:.2f}")
            elif kind == "on":
                sup = objs[spec[2]]
                def on(o):
                    return xy_within(o, sup) and abs(measure(o, 2, "bottom") - measure(sup, 2, "top")) <= 0.05
                ok = on(t) and not any(on(o) for o in others)
                print(f"{g} s on {spec[2]}: target {on(t)} others {[on(o) for o in others]} {'ok' if ok else 'FAIL'}")
                if not ok: probs.append(f"{g}: on check")
            elif kind == "under":
                ab = objs[spec[2]]
                def under(o):
                    return xy_within(ab, o) and measure(o, 2, "top") <= measure(ab, 2, "bottom") + 0.05
                ok = under(t) and not any(under(o) for o in others)
                print(f"{g} s under {spec[2]}: target {under(t)} others {[under(o) for o in others]} {'ok' if ok else 'FAIL'}")
                if not ok: probs.append(f"{g}: under check")
            else:
                probs.append(f"{g}: unknown spec {kind}")
    for p in probs:
        print("PROBLEM", p)
    print(f"{len(G)} groups checked, {len(probs)} problems")
    return 1 if probs else 0


if __name__ == "__main__":
    sys.exit(main())
