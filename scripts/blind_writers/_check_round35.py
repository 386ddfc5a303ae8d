"""Re-derive o/or accept sets from the maps and check every spatial claim numerically.
    python3 scripts/check.py   (from /work/blind35)"""
import json, math, sys
from collections import OrderedDict
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SUITE = ROOT / "evals" / "blind" / "round35.jsonl"
MARGIN = 0.2

def load_map(m):
    p = (SUITE.parent / m).resolve()
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        return {int(o["id"]): o for o in d["objects"]}, True
    return {int(k): {"label": v["category"], "room": v["room_cat"], "room_id": v["room_id"]} for k, v in d.items()}, False

# room named in each or / ord group (room_cat on caption maps, room field on geometry maps)
ROOMS = {"b35-g02": "living room", "b35-g03": "bedroom", "b35-g05": "bathroom", "b35-g08": "rec room",
         "b35-g11": "rec room", "b35-g15": "kitchen", "b35-g16": "master bedroom", "b35-g19": "bedroom",
         "b35-g20": "guest bedroom", "b35-g21": "kitchenette", "b35-g30": "living room", "b35-g32": "bathroom",
         "b35-g38": "office", "b35-g40": "kitchen", "b35-g42": "living room"}

def c(o): return o["center"]
def dist2d(a, b): return math.hypot(a[0] - b[0], a[1] - b[1])
def top(o): return o["center"][2] + o["size"][2] / 2
def bottom(o): return o["center"][2] - o["size"][2] / 2
def xy_overlap(a, b):
    return all(abs(a["center"][i] - b["center"][i]) < (a["size"][i] + b["size"][i]) / 2 for i in (0, 1))

def nearest(objs, target, cands, ref, far=False):
    d = {i: dist2d(c(objs[i]), ref) for i in cands}
    order = sorted(d, key=d.get, reverse=far)
    gap = abs(d[order[0]] - d[order[1]])
    return order[0] == target and gap >= MARGIN, f"dists {{{', '.join(f'{i}: {d[i]:.2f}' for i in order)}}} gap {gap:.2f}"

def on(objs, target, cands, support):
    s = objs[support]
    ok = [i for i in cands if xy_overlap(objs[i], s) and abs(bottom(objs[i]) - top(s)) <= 0.1]
    return ok == [target], f"on {support}: {ok}"

def under(objs, target, cands, above):
    a = objs[above]
    ok = [i for i in cands if xy_overlap(objs[i], a) and top(objs[i]) <= bottom(a) + 0.1]
    return ok == [target], f"under {above}: {ok}"

def labels(objs, lab): return [i for i, o in objs.items() if o["label"] == lab]

def spatial(g, objs):
    if g == "b35-g25":  # flat_c chair closest to fridge 13
        return nearest(objs, 20, labels(objs, "chair"), c(objs[13]))
    if g == "b35-g26":  # flat_d chair nearest bookcase 12
        return nearest(objs, 4, labels(objs, "chair"), c(objs[12]))
    if g == "b35-g27":  # flat_f rug under coffee table 5
        return under(objs, 7, labels(objs, "rug"), 5)
    if g == "b35-g28":  # flat_h lamp nearest front door (south end of hallway x 4..6, y 0)
        return nearest(objs, 9, labels(objs, "lamp"), (5.0, 0.0))
    if g == "b35-g35":  # apartment sofa farther from tv 4
        return nearest(objs, 1, labels(objs, "sofa"), c(objs[4]), far=True)
    if g == "b35-g36":  # apartment plant on dresser 38
        return on(objs, 39, labels(objs, "plant"), 38)
    if g == "b35-g37":  # apartment lamp on desk 47
        return on(objs, 56, labels(objs, "lamp"), 47)
    if g == "b35-g44":  # scan_office trash can nearest door 20
        return nearest(objs, 21, labels(objs, "trash can"), c(objs[20]))
    if g == "b35-g45":  # scan_kitchen cabinet under coffee maker 12
        return under(objs, 1, labels(objs, "kitchen cabinet"), 12)
    if g == "b35-g46":  # scan_livingroom red pillow on right of a person sitting on sofa 1 facing TV 14 (north): right = east
        reds = [i for i in labels(objs, "pillow") if objs[i]["tags"].get("color") == "red"]
        assert c(objs[14])[1] > c(objs[1])[1]  # tv is north of the sofa
        on_sofa = all(xy_overlap(objs[i], objs[1]) for i in reds)
        east = max(reds, key=lambda i: c(objs[i])[0])
        gap = abs(c(objs[reds[0]])[0] - c(objs[reds[1]])[0])
        return east == 4 and on_sofa and gap >= MARGIN and len(reds) == 2, f"reds {reds} x-gap {gap:.2f}"
    if g == "b35-g47":  # scan_office shortest bookshelf (top heights)
        bs = labels(objs, "bookshelf")
        tops = sorted(((top(objs[i]), i) for i in bs))
        return tops[0][1] == 16 and tops[1][0] - tops[0][0] >= MARGIN, f"tops {tops}"
    if g == "b35-g48":  # scan_bedroom lamp closest to window 14
        return nearest(objs, 8, labels(objs, "lamp"), c(objs[14]))
    return False, "no spatial check written"

def main():
    rows = [json.loads(l) for l in SUITE.read_text().splitlines()]
    groups = OrderedDict()
    for r in rows:
        groups.setdefault(r["group"], r)
    bad = 0
    for g, r in groups.items():
        objs, geo = load_map(r["map"])
        t, target, acc = r["type"], r["target"], sorted(r["accept"])
        lab = objs[target]["label"]
        room = objs[target]["room"]
        if t == "o":
            want = sorted(labels(objs, lab)); ok = want == acc; info = f"label {lab!r} -> {want}"
        elif t == "or":
            want = sorted(i for i in labels(objs, lab) if objs[i]["room"] == ROOMS[g])
            ok = want == acc and room == ROOMS[g]; info = f"label {lab!r} in {ROOMS[g]} -> {want}"
        elif t in ("od", "ard"):
            ok = acc == [target]; info = f"single {target} ({lab})"
        elif t == "ord":
            ok = acc == [target] and room == ROOMS[g]
            info = f"single {target} ({lab}) in {room}; same label in room: {[i for i in labels(objs, lab) if objs[i]['room'] == room]}"
        elif t == "s":
            ok, info = spatial(g, objs); ok = ok and geo and acc == [target]
        print(("OK  " if ok else "BAD ") + f"{g} {t:3s} {Path(r['map']).name}: {info}")
        bad += not ok
    print(f"{len(groups)} groups, {bad} failing")
    return 1 if bad else 0

if __name__ == "__main__":
    sys.exit(main())
