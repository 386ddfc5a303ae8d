"""Re-derive o/or accept sets and check every spatial claim of round49 numerically.
Reads scripts/spec.json (written by emit.py), the suite, and the maps."""
import json, math, sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SUITE_DIR = ROOT / "evals/blind"
MARGIN = 0.2
errors = []


def load(mp):
    d = json.loads((SUITE_DIR / mp).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return {o["id"]: o for o in d["objects"]}, {r["label"]: r for r in d.get("rooms", [])}, True
    objs = {}
    for k, v in d.items():
        objs[int(k)] = {"id": int(k), "label": v["category"], "room": v["room_cat"]}
    return objs, {}, False


def lo(o, i): return o["center"][i] - o["size"][i] / 2
def hi(o, i): return o["center"][i] + o["size"][i] / 2
def dxy(a, b): return math.dist(a["center"][:2], b["center"][:2])
def inside_xy(p, o): return lo(o, 0) - 1e-6 <= p["center"][0] <= hi(o, 0) + 1e-6 and lo(o, 1) - 1e-6 <= p["center"][1] <= hi(o, 1) + 1e-6
def rests_on(a, b): return inside_xy(a, b) and abs(lo(a, 2) - hi(b, 2)) <= 0.1


def fail(g, msg): errors.append(f"{g}: {msg}")


def main():
    spec = json.loads((ROOT / "scripts/blind_writers/_specs_round49.json").read_text())
    for g, s in spec.items():
        objs, rooms, geo = load(s["map"])
        t = s["target"]
        if t not in objs:
            fail(g, "target missing"); continue
        typ = s["type"]
        if typ == "o":
            want = sorted(i for i, o in objs.items() if o["label"] == s["label"])
            if want != sorted(s["accept"]): fail(g, f"o accept {s['accept']} != {want}")
        elif typ == "or":
            want = sorted(i for i, o in objs.items() if o["label"] == s["label"] and o.get("room") == s["room"])
            if want != sorted(s["accept"]): fail(g, f"or accept {s['accept']} != {want}")
        elif typ in ("od", "ord", "ard"):
            if s["accept"] != [t]: fail(g, "single-id accept expected")
            lab = objs[t]["label"]
            print(f"{g} {typ}: target {t} ({lab}); note: {s.get('note')}")
        elif typ == "s":
            if not geo: fail(g, "spatial on a caption map"); continue
            same = [o for o in objs.values() if o["label"] == s["label"]]
            if objs[t]["label"] != s["label"]: fail(g, "target label mismatch")
            T = objs[t]
            c = s["check"]
            if c == "nearest":
                ref = objs[s["ref"]]
                ds = sorted((dxy(o, ref), o["id"]) for o in same)
                if ds[0][1] != t or ds[1][0] - ds[0][0] < MARGIN: fail(g, f"nearest fails {ds[:3]}")
                print(f"{g} nearest to {s['ref']}: {[(round(d,2), i) for d, i in ds[:3]]}")
                if "also_nearest_other" in s:
                    other, ref2 = s["also_nearest_other"]
                    ds2 = sorted((dxy(o, objs[ref2]), o["id"]) for o in same)
                    if ds2[0][1] != other or ds2[1][0] - ds2[0][0] < MARGIN: fail(g, f"contrast nearest fails {ds2}")
                    print(f"{g} contrast nearest to {ref2}: {[(round(d,2), i) for d, i in ds2]}")
                if "near_obj" in s:
                    tabs = sorted((dxy(T, o), o["id"]) for o in objs.values() if o["label"] == objs[s["near_obj"]]["label"])
                    if tabs[0][1] != s["near_obj"] or tabs[1][0] - tabs[0][0] < MARGIN: fail(g, f"at-table fails {tabs}")
                    print(f"{g} target at {s['near_obj']}: {[(round(d,2), i) for d, i in tabs]}")
            elif c == "under":
                ref = objs[s["ref"]]
                ok = inside_xy(ref, T) and hi(T, 2) <= lo(ref, 2) + 0.05
                others = [o["id"] for o in same if o["id"] != t and inside_xy(ref, o) and hi(o, 2) <= lo(ref, 2) + 0.05]
                if not ok or others: fail(g, f"under fails ok={ok} others={others}")
                print(f"{g} under: target top {hi(T,2):.2f} ref bottom {lo(ref,2):.2f}; others under: {others}")
            elif c == "between":
                a, b = (objs[i] for i in s["refs"])
                ax = 0 if abs(a["center"][0] - b["center"][0]) > abs(a["center"][1] - b["center"][1]) else 1
                lo_, hi_ = sorted([a["center"][ax], b["center"][ax]])
                ok = lo_ + MARGIN <= T["center"][ax] <= hi_ - MARGIN
                on = objs[s["on"]]
                cands = [o["id"] for o in same if rests_on(o, on) or (inside_xy(o, on) and lo(o, 2) >= lo(on, 2))]
                if not ok or sorted(cands) != sorted([t] + s["refs"]): fail(g, f"between fails ok={ok} on-sofa={cands}")
                print(f"{g} between: {lo_}<{T['center'][ax]}<{hi_}; pillows on sofa {cands}")
            elif c == "lowest":
                tops = sorted((hi(o, 2), o["id"]) for o in same)
                if tops[0][1] != t or tops[1][0] - tops[0][0] < MARGIN - 1e-9: fail(g, f"lowest fails {tops}")
                print(f"{g} tops: {tops}")
            elif c == "supports":
                ref = objs[s["ref"]]
                hold = [o["id"] for o in same if rests_on(ref, o)]
                oth = [o["id"] for o in same if rests_on(objs[s["other_ref"]], o)]
                if hold != [t] or not oth or t in oth: fail(g, f"supports fails {hold} {oth}")
                print(f"{g} {s['ref']} rests on {hold}; {s['other_ref']} rests on {oth}")
            elif c == "on":
                ref = objs[s["ref"]]
                on = [o["id"] for o in same if rests_on(o, ref)]
                if on != [t]: fail(g, f"on fails {on}")
                print(f"{g} on {s['ref']}: {on}; where others rest: " + str({o['id']: [p['id'] for p in objs.values() if p is not o and rests_on(o, p)] for o in same}))
            elif c == "corner":
                poly = rooms[s["room"]]["polygon"]
                inroom = [o for o in same if o.get("room") == s["room"]]
                ds = sorted((min(math.dist(o["center"][:2], p) for p in poly), o["id"]) for o in inroom)
                if ds[0][1] != t or ds[1][0] - ds[0][0] < MARGIN: fail(g, f"corner fails {ds}")
                print(f"{g} corner distances {[(round(d,2), i) for d, i in ds]}")
            elif c == "higher":
                among = [objs[i] for i in s["among"]]
                zs = sorted(((o["center"][2], o["id"]) for o in among), reverse=True)
                shelf = objs[s["in_obj"]]
                inside = all(inside_xy(o, shelf) and lo(o, 2) >= lo(shelf, 2) and hi(o, 2) <= hi(shelf, 2) for o in among)
                inshelf = sorted(o["id"] for o in same if inside_xy(o, shelf))
                if zs[0][1] != t or zs[0][0] - zs[1][0] < MARGIN or not inside or inshelf != sorted(s["among"]):
                    fail(g, f"higher fails {zs} inside={inside} inshelf={inshelf}")
                print(f"{g} heights {zs}; books in shelf {inshelf}")
            else:
                fail(g, f"unknown check {c}")
    # suite consistency with spec
    for line in (SUITE_DIR / "round49.jsonl").read_text().splitlines():
        r = json.loads(line)
        s = spec[r["group"]]
        if (r["type"], r["map"], r["target"], sorted(r["accept"])) != (s["type"], s["map"], s["target"], sorted(s["accept"])):
            fail(r["id"], "line differs from spec")
    print("\n".join(errors) if errors else "check.py: all accept sets and spatial claims OK")
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
