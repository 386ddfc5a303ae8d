"""Re-derive o/or accept sets and check spatial claims numerically for round40 (run from anywhere)."""
import json, math, sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).resolve().parent))
from _build_round40 import GROUPS

BLIND = Path(__file__).resolve().parents[2] / "evals" / "blind"
MARGIN = 0.2


def load(mp):
    data = json.loads((BLIND / mp).resolve().read_text())
    if isinstance(data, dict) and "objects" in data:
        objs = {o["id"]: o for o in data["objects"]}
        return objs, data.get("rooms", []), True
    objs = {int(k): {"id": int(k), "label": v["category"], "room": v["room_cat"]} for k, v in data.items()}
    return objs, [], False


def dist(a, b):
    return math.dist(a["center"], b["center"])


def dist2(a, b):
    return math.dist(a["center"][:2], b["center"][:2])


def inside_xy(a, b, tol=0.0):
    return all(abs(a["center"][i] - b["center"][i]) <= b["size"][i] / 2 + tol for i in (0, 1))


def bottom(o):
    return o["center"][2] - o["size"][2] / 2


def top(o):
    return o["center"][2] + o["size"][2] / 2


def spatial(meta, target, objs, rooms):
    rel, among = meta["rel"], meta["among"]
    t = objs[target]
    others = [objs[i] for i in among if i != target]
    labels = {objs[i]["label"] for i in among}
    msgs = [] if len(labels) == 1 else [f"candidates of mixed labels {labels}"]
    if rel == "nearest":
        ref = objs[meta["ref"]]
        for f in (dist, dist2):
            d = f(t, ref)
            m = min(f(o, ref) for o in others)
            if m - d < MARGIN:
                msgs.append(f"nearest margin {m - d:.2f} ({f.__name__})")
        return msgs, f"d={dist2(t, objs[meta['ref']]):.2f} next={min(dist2(o, objs[meta['ref']]) for o in others):.2f}"
    if rel == "above":
        ref = objs[meta["ref"]]
        if not inside_xy(t, ref) or bottom(t) - top(ref) < MARGIN:
            msgs.append("target not above ref")
        for o in others:
            if inside_xy(o, ref) and bottom(o) > top(ref):
                msgs.append(f"{o['id']} also above ref")
        return msgs, f"gap={bottom(t) - top(ref):.2f}"
    if rel == "on":
        ref = objs[meta["ref"]]
        if not inside_xy(t, ref) or abs(bottom(t) - top(ref)) > 0.05:
            msgs.append("target not on ref")
        for o in others:
            if inside_xy(o, ref) and abs(bottom(o) - top(ref)) <= 0.05:
                msgs.append(f"{o['id']} also on ref")
        return msgs, f"bottom={bottom(t):.2f} reftop={top(ref):.2f}"
    if rel == "higher":
        for o in others:
            if t["center"][2] - o["center"][2] < MARGIN or bottom(t) - bottom(o) < MARGIN:
                msgs.append(f"not higher than {o['id']} by margin")
        return msgs, f"z={t['center'][2]:.2f} others={[o['center'][2] for o in others]}"
    if rel in ("right_facing_north", "left_facing_north"):
        sign = 1 if rel.startswith("right") else -1
        for o in others:
            if sign * (t["center"][0] - o["center"][0]) < MARGIN:
                msgs.append(f"x order vs {o['id']} fails")
        return msgs, f"x={t['center'][0]:.2f} others={[o['center'][0] for o in others]}"
    if rel == "between":
        a, b = (objs[i] for i in meta["refs"])

        def between(o):
            ax, ay = a["center"][:2]; bx, by = b["center"][:2]; px, py = o["center"][:2]
            vx, vy = bx - ax, by - ay
            L2 = vx * vx + vy * vy
            s = ((px - ax) * vx + (py - ay) * vy) / L2
            perp = abs((px - ax) * vy - (py - ay) * vx) / math.sqrt(L2)
            return 0.2 < s < 0.8 and perp < 0.5 * math.sqrt(L2), s, perp
        ok, s, perp = between(t)
        if not ok:
            msgs.append("target not between refs")
        for o in others:
            if o["id"] in meta["refs"]:
                continue
            if between(o)[0]:
                msgs.append(f"{o['id']} also between")
        return msgs, f"s={s:.2f} perp={perp:.2f}"
    if rel == "corner":
        corners = [tuple(p) for r in rooms for p in r["polygon"]]

        def dc(o):
            return min(math.dist(o["center"][:2], c) for c in corners)
        m = min(dc(o) for o in others)
        if m - dc(t) < MARGIN:
            msgs.append(f"corner margin {m - dc(t):.2f}")
        return msgs, f"dcorner={dc(t):.2f} next={m:.2f}"
    return [f"unknown rel {rel}"], ""


def main():
    bad = 0
    for g, (typ, mp, target, accept, meta, words) in enumerate(GROUPS, 1):
        objs, rooms, geo = load(mp)
        msgs, info = [], ""
        if target not in objs or any(a not in objs for a in accept) or target not in accept:
            msgs.append("ids missing")
        elif typ in ("o", "or"):
            want = sorted(i for i, o in objs.items() if o["label"] == meta["label"]
                          and (typ == "o" or o["room"] == meta["room"]))
            if want != sorted(accept):
                msgs.append(f"accept {sorted(accept)} != derived {want}")
            info = f"label={meta['label']} derived={want}"
        elif typ in ("od", "ord", "ard", "s"):
            if len(accept) != 1 and typ != "ard":
                msgs.append("single id expected")
            if typ == "ord" and objs[target]["room"] != meta["room"]:
                msgs.append(f"target room {objs[target]['room']} != {meta['room']}")
            if typ == "s":
                if not geo:
                    msgs.append("spatial on caption map")
                else:
                    m2, info = spatial(meta, target, objs, rooms)
                    msgs += m2
            info = info or f"target={target} {objs[target]['label']} ({objs[target]['room']})"
        status = "OK " if not msgs else "BAD"
        bad += bool(msgs)
        print(f"{status} g{g:02d} {typ:<3} {Path(mp).name:<28} {info} {'; '.join(msgs)}")
    # style: w2 polite question, w3 no articles, w5 two sentences starting "This is", w6 lower case
    import re
    for g, (typ, mp, target, accept, meta, words) in enumerate(GROUPS, 1):
        w = words
        probs = []
        if not (w[1].startswith("Could you") and w[1].endswith("?")): probs.append("w2")
        if re.search(r"\b(the|a|an)\b", w[2].lower()): probs.append("w3 article")
        if not w[4].startswith("This is") or w[4].count(". ") + 1 != 2: probs.append("w5")
        if w[5] != w[5].lower(): probs.append("w6 case")
        if probs:
            bad += 1
            print(f"BAD g{g:02d} style {probs}")
    print("problems:", bad)
    return 1 if bad else 0


if __name__ == "__main__":
    sys.exit(main())
