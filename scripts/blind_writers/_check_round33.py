"""Re-derive accept sets and check spatial claims of round33 from the maps (emit.G)."""
import json, math, sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).resolve().parent))
from emit import G, rows

BLIND = Path(__file__).resolve().parents[1] / "evals" / "blind"
MARGIN = 0.2


def load(mp):
    p = (BLIND / mp).resolve()
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        return {o["id"]: {"label": o["label"], "room": o.get("room"), "c": o["center"], "s": o["size"],
                          "tags": o.get("tags", {})} for o in d["objects"]}, True
    return {int(k): {"label": v["category"], "room": v["room_cat"], "tags": {}} for k, v in d.items()}, False


def dist(a, b):
    return math.dist(a["c"], b["c"])


def main():
    errs, notes = [], []
    cache = {}
    for n, (typ, mp, target, accept, spec, ws) in enumerate(G, 1):
        g = f"g{n:02d}"
        if mp not in cache:
            cache[mp] = load(mp)
        objs, geo = cache[mp]
        acc = set(accept)
        if target not in objs or objs[target]["label"] != spec["label"]:
            errs.append(f"{g}: target {target} label is not {spec['label']!r}")
        if typ == "o":
            want = {i for i, o in objs.items() if o["label"] == spec["label"]}
            if want != acc:
                errs.append(f"{g}: o accept {sorted(acc)} != {sorted(want)}")
        elif typ == "or":
            want = {i for i, o in objs.items() if o["label"] == spec["label"] and o["room"] == spec["room"]}
            if want != acc:
                errs.append(f"{g}: or accept {sorted(acc)} != {sorted(want)}")
            allr = {i for i, o in objs.items() if o["label"] == spec["label"]}
            notes.append(f"{g}: or {spec['label']} in {spec['room']} -> {sorted(want)} (all of label: {sorted(allr)})")
        elif typ in ("od", "ord", "ard"):
            if acc != {target}:
                notes.append(f"{g}: {typ} accept set of {len(acc)}")
            if typ == "ord" and objs[target]["room"] != spec["room"]:
                errs.append(f"{g}: target not in room {spec['room']}")
            same = sorted(i for i, o in objs.items() if o["label"] == spec["label"])
            notes.append(f"{g}: {typ} target {target}; same label on map: {same}")
        elif typ == "s":
            if not geo:
                errs.append(f"{g}: spatial on caption map")
                continue
            cands = [i for i, o in objs.items() if o["label"] == spec["label"]
                     and ("room" not in spec or o["room"] == spec["room"])
                     and ("color" not in spec or o["tags"].get("color") == spec["color"])]
            if len(cands) < 2:
                errs.append(f"{g}: only {len(cands)} candidates")
            for sub in [spec] + ([dict(spec, **spec["also"])] if "also" in spec else []):
                exp = sub.get("expect", target)
                ok, msg = relation(sub, cands, objs, exp)
                notes.append(f"{g}: {sub['rel']} cands {cands} expect {exp}: {msg}")
                if not ok:
                    errs.append(f"{g}: {sub['rel']} fails: {msg}")
    n_lines = len(rows())
    for line in notes:
        print(line)
    print(f"{len(G)} groups, {n_lines} lines; errors: {len(errs)}")
    for e in errs:
        print("ERROR", e)
    return 1 if errs else 0


def relation(sp, cands, objs, exp):
    rel = sp["rel"]
    if rel in ("nearest", "farthest"):
        ref = objs[sp["ref"]]
        ds = sorted((dist(objs[i], ref), i) for i in cands)
        if rel == "farthest":
            ds = ds[::-1]
        best, second = ds[0], ds[1]
        m = abs(best[0] - second[0])
        return best[1] == exp and m >= MARGIN, f"{[(i, round(d, 2)) for d, i in ds]} margin {m:.2f}"
    if rel in ("lowest", "highest"):
        zs = sorted((objs[i]["c"][2], i) for i in cands)
        if rel == "highest":
            zs = zs[::-1]
        m = abs(zs[0][0] - zs[1][0])
        return zs[0][1] == exp and m >= MARGIN, f"{zs} margin {m:.2f}"
    if rel in ("left", "right"):
        # viewer facing sp['facing']; left of facing north is smaller x, etc.
        axis, sign = {"north": (0, -1), "south": (0, 1), "east": (1, 1), "west": (1, -1)}[sp["facing"]]
        key = [(sign * objs[i]["c"][axis] * (1 if rel == "left" else -1), i) for i in cands]
        key.sort(key=lambda t: -t[0])
        m = abs(key[0][0] - key[1][0])
        return key[0][1] == exp and m >= MARGIN, f"{key} margin {m:.2f}"
    if rel == "on":
        ref = objs[sp["ref"]]
        hits = []
        for i in cands:
            o = objs[i]
            inside = all(abs(o["c"][k] - ref["c"][k]) <= ref["s"][k] / 2 for k in (0, 1))
            gap = (o["c"][2] - o["s"][2] / 2) - (ref["c"][2] + ref["s"][2] / 2)
            if inside and abs(gap) <= 0.05:
                hits.append(i)
        return hits == [exp], f"resting on {sp['ref']}: {hits}"
    if rel == "between":
        others = [i for i in cands if i != exp]
        if len(others) != 2:
            return False, "need exactly two others"
        a, b, t = (objs[others[0]]["c"], objs[others[1]]["c"], objs[exp]["c"])
        ab = [b[k] - a[k] for k in range(3)]
        L2 = sum(v * v for v in ab)
        u = sum((t[k] - a[k]) * ab[k] for k in range(3)) / L2
        foot = [a[k] + u * ab[k] for k in range(3)]
        perp = math.dist(foot, t)
        ok = 0.1 < u < 0.9 and perp < 0.5
        return ok, f"t={u:.2f} perp={perp:.2f}"
    return False, "unknown relation"


if __name__ == "__main__":
    sys.exit(main())
