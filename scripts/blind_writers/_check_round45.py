"""Re-derive o/or accept sets and check every spatial claim numerically (margin >= 0.2 m).
Also checks ord rooms, that each group has one type/map/target/accept, and the type/map spread."""
import json, math, sys
from collections import Counter
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import _build_round45 as emit

BLIND = emit.ROOT / "evals" / "blind"
MARGIN = 0.2


def load(mkey):
    d = json.loads((BLIND / emit.MAPS[mkey]).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return {int(o["id"]): {"label": o["label"], "room": o.get("room"), "c": o["center"], "s": o["size"]} for o in d["objects"]}, True
    return {int(k): {"label": v["category"], "room": v.get("room_cat")} for k, v in d.items()}, False


def dist(a, b):
    return math.hypot(a["c"][0] - b["c"][0], a["c"][1] - b["c"][1])


def on(obj, sup):
    x, y = obj["c"][:2]
    inside = abs(x - sup["c"][0]) <= sup["s"][0] / 2 and abs(y - sup["c"][1]) <= sup["s"][1] / 2
    gap = (obj["c"][2] - obj["s"][2] / 2) - (sup["c"][2] + sup["s"][2] / 2)
    return inside and abs(gap) < 0.05


def main():
    errs = []
    per_type, per_map = Counter(), Counter()
    for num, mkey, typ, target, accept, spec, qs in emit.G:
        g = f"g{num:02d}"
        objs, geo = load(mkey)
        per_type[typ] += 1
        per_map[mkey] += 1
        if target not in accept or any(a not in objs for a in accept):
            errs.append(f"{g}: target/accept not in map")
            continue
        if typ == "o":
            want = sorted(i for i, o in objs.items() if o["label"] == spec["label"])
            if want != sorted(accept) or objs[target]["label"] != spec["label"]:
                errs.append(f"{g}: o accept {sorted(accept)} != {want}")
        elif typ == "or":
            want = sorted(i for i, o in objs.items() if o["label"] == spec["label"] and o["room"] == spec["room"])
            if want != sorted(accept):
                errs.append(f"{g}: or accept {sorted(accept)} != {want}")
        elif typ in ("od", "ord", "ard"):
            if typ != "ard" and len(accept) != 1:
                errs.append(f"{g}: {typ} should have a single id")
            if typ == "ord" and objs[target]["room"] != spec["room"]:
                errs.append(f"{g}: ord room {objs[target]['room']} != {spec['room']}")
        elif typ == "s":
            if not geo:
                errs.append(f"{g}: spatial on a map without geometry"); continue
            if accept != [target]:
                errs.append(f"{g}: spatial should be single id")
            rel, cands = spec["rel"], spec["cands"]
            labs = {objs[c]["label"] for c in cands}
            if target not in cands:
                errs.append(f"{g}: target not among candidates")
            others = [c for c in cands if c != target]
            t = objs[target]
            if rel == "on":
                sup = objs[spec["support"]]
                ok = on(t, sup) and not any(on(objs[c], sup) for c in others)
                detail = "on"
            elif rel in ("nearest", "farthest"):
                ref = objs[spec["ref"]]
                dt = dist(t, ref); do = [dist(objs[c], ref) for c in others]
                ok = (min(do) - dt >= MARGIN) if rel == "nearest" else (dt - max(do) >= MARGIN)
                detail = f"d(target)={dt:.2f} others={[round(v, 2) for v in do]}"
            elif rel == "higher":
                zt = t["c"][2]; zo = [objs[c]["c"][2] for c in others]
                ok = zt - max(zo) >= MARGIN
                detail = f"z={zt} others={zo}"
            elif rel == "lowest_top":
                top = lambda o: o["c"][2] + o["s"][2] / 2
                zt = top(t); zo = [top(objs[c]) for c in others]
                ok = min(zo) - zt >= MARGIN
                detail = f"top={zt} others={zo}"
            elif rel == "above":
                ref = objs[spec["ref"]]
                def above(o):
                    return (abs(ref["c"][0] - o["c"][0]) <= o["s"][0] / 2 and abs(ref["c"][1] - o["c"][1]) <= o["s"][1] / 2
                            and o["c"][2] - o["s"][2] / 2 >= ref["c"][2] + ref["s"][2] / 2 + MARGIN)
                ok = above(t) and not any(above(objs[c]) for c in others)
                detail = "above"
            elif rel == "left":
                fx, fy = spec["facing"]; lx, ly = -fy, fx  # left of the facing direction
                sc = lambda o: o["c"][0] * lx + o["c"][1] * ly
                st = sc(t); so = [sc(objs[c]) for c in others]
                ok = st - max(so) >= MARGIN
                detail = f"left score {st} others {so}"
            else:
                ok, detail = False, "unknown relation"
            print(f"{g} s/{rel}: {'OK' if ok else 'FAIL'} {detail} labels={labs}")
            if not ok:
                errs.append(f"{g}: spatial claim {rel} fails ({detail})")
    cap = per_map["c829"] + per_map["off3"]
    flats = sum(per_map[k] for k in ("fc", "fd", "ff", "fh"))
    scans_s = sum(1 for n, m, t, *_ in emit.G if t == "s" and m.startswith("s"))
    want_types = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    if dict(per_type) != want_types:
        errs.append(f"type counts {dict(per_type)}")
    if len(emit.G) != 48 or cap < 12 or flats < 14 or scans_s < 4:
        errs.append(f"spread: groups {len(emit.G)} caption {cap} flats {flats} scan-spatial {scans_s}")
    print(f"types {dict(per_type)}; maps {dict(per_map)}; caption {cap} flats {flats} apt+scans {48 - cap - flats} scan spatial {scans_s}")
    for e in errs:
        print("ERROR", e)
    print("check.py:", "PASS" if not errs else f"{len(errs)} errors")
    return 1 if errs else 0


if __name__ == "__main__":
    sys.exit(main())
