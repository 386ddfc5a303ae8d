"""Check round34 against its maps: o/or accept sets re-derived from labels (and rooms), every spatial
claim checked numerically from centres and sizes (margin >= 0.2 m for distance/height claims),
plus the wording-style rules. Exit 1 on any failure."""
import json
import math
import re
import sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from emit import GROUPS  # noqa: E402

SUITE_DIR = Path(__file__).resolve().parents[1] / "evals" / "blind"
MARGIN = 0.2
fails = []


def load(mp):
    d = json.loads((SUITE_DIR / mp).resolve().read_text())
    if isinstance(d, dict) and "objects" in d:
        return {int(o["id"]): o for o in d["objects"]}, True
    return {int(k): {"label": v["category"], "room": v["room_cat"], "caption": v["caption"]} for k, v in d.items()}, False


def box(o):
    c, s = o["center"], o["size"]
    return [c[i] - s[i] / 2 for i in range(3)], [c[i] + s[i] / 2 for i in range(3)]


def xy_overlap(a, b):
    (alo, ahi), (blo, bhi) = box(a), box(b)
    return all(alo[i] < bhi[i] and blo[i] < ahi[i] for i in range(2))


def dist2(a, b):
    return math.dist(a["center"][:2], b["center"][:2])


def fail(g, msg):
    fails.append(f"{g}: {msg}")


def cands(objs, label, room):
    return [i for i, o in objs.items() if o["label"] == label and (room is None or o["room"] == room)]


def check_spatial(g, objs, target, spec):
    rel, ref, label, room = spec
    cs = cands(objs, label, room)
    t = objs[target]
    if target not in cs or len(cs) < 2:
        return fail(g, f"target not among >=2 candidates {cs}")
    others = [c for c in cs if c != target]
    if rel == "nearest":
        d = {c: dist2(objs[c], objs[ref]) for c in cs}
        gap = min(d[c] for c in others) - d[target]
        info = f"nearest to {ref}: target {d[target]:.2f}, gap {gap:.2f}"
        if gap < MARGIN:
            fail(g, info)
    elif rel in ("above", "under"):
        base = objs[ref]
        blo, bhi = box(base)
        ok = []
        for c in cs:
            lo, hi = box(objs[c])
            vert = lo[2] > bhi[2] - 0.01 if rel == "above" else hi[2] < blo[2] + 0.01
            ok.append(c) if (vert and xy_overlap(objs[c], base)) else None
        info = f"{rel} {ref}: satisfied by {ok}"
        if ok != [target]:
            fail(g, info)
    elif rel == "left" or rel == "right_lamp":
        # viewer at the foot of bed `ref` looking toward its head (the end with nightstands/pillows: +y here)
        bed = objs[ref]
        lo, hi = box(bed)
        foot = (bed["center"][0], lo[1])
        fwd = (0.0, 1.0)
        # confirm the head end is +y: every nightstand in the room lies north of the bed centre
        head_objs = [o for o in objs.values() if o["label"] == "nightstand" and o["room"] == bed["room"]]
        if not head_objs or any(o["center"][1] <= bed["center"][1] for o in head_objs):
            return fail(g, "head end of the bed is not +y")
        left = (-fwd[1], fwd[0])
        lat = {c: (objs[c]["center"][0] - foot[0]) * left[0] + (objs[c]["center"][1] - foot[1]) * left[1] for c in cs}
        want_left = rel == "left"
        sel = [c for c in cs if (lat[c] > MARGIN if want_left else lat[c] < -MARGIN)]
        info = f"{rel} of bed {ref} (head at +y, head y={hi[1]:.2f}): lateral {lat}"
        if sel != [target]:
            fail(g, info)
    elif rel == "higher":
        z = {c: objs[c]["center"][2] for c in cs}
        gap = z[target] - max(z[c] for c in others)
        info = f"higher: {z}, gap {gap:.2f}"
        if gap < MARGIN:
            fail(g, info)
    elif rel == "shortest":
        h = {c: objs[c]["size"][2] for c in cs}
        gap = min(h[c] for c in others) - h[target]
        info = f"shortest: {h}, gap {gap:.2f}"
        if gap < MARGIN:
            fail(g, info)
    elif rel in ("between", "between_on"):
        if rel == "between_on":
            base = objs[ref]
            cs = [c for c in cs if xy_overlap(objs[c], base)]
            others = [c for c in cs if c != target]
        if len(others) != 2:
            return fail(g, f"between needs exactly 2 others, got {others}")
        a, b = (objs[c]["center"][:2] for c in others)
        p = t["center"][:2]
        ab = (b[0] - a[0], b[1] - a[1])
        L = math.hypot(*ab)
        u = ((p[0] - a[0]) * ab[0] + (p[1] - a[1]) * ab[1]) / L
        perp = abs((p[0] - a[0]) * ab[1] - (p[1] - a[1]) * ab[0]) / L
        info = f"between {others}: along {u:.2f} of {L:.2f}, off-line {perp:.2f}"
        if not (MARGIN <= u <= L - MARGIN and perp < 0.3):
            fail(g, info)
    else:
        return fail(g, f"unknown relation {rel}")
    print(f"  {g} ok: {info}")


def words(s):
    return re.findall(r"[a-z0-9']+", s.lower())


def main():
    cache = {}
    for gid, mp, typ, target, accept, spec, ws in GROUPS:
        if mp not in cache:
            cache[mp] = load(mp)
        objs, geo = cache[mp]
        if target not in accept or any(a not in objs for a in accept):
            fail(gid, "target/accept ids")
            continue
        if typ in ("o", "or"):
            label, room = spec
            want = sorted(cands(objs, label, room))
            if want != sorted(accept):
                fail(gid, f"accept {sorted(accept)} != derived {want}")
            else:
                print(f"  {gid} ok: {typ} {label!r} in {room} -> {want}")
        elif typ == "s":
            if not geo:
                fail(gid, "spatial on caption map")
            else:
                check_spatial(gid, objs, target, spec)
        elif typ in ("od", "ord") and len(accept) != 1:
            fail(gid, "described type needs a single id")
        # style rules
        w1, w2, w3, w4, w5, w6 = ws
        if not w1.startswith("Go to") and " go to " not in w1.lower():
            fail(gid, "w1 not a plain imperative")
        if not (w2.startswith("Could you") and w2.endswith("?")):
            fail(gid, "w2 not a polite question")
        if set(words(w3)) & {"a", "an", "the"} or len(words(w3)) > 7:
            fail(gid, "w3 not telegraphic")
        if not (w5.startswith("This is") and len(re.findall(r"[.!?](\s|$)", w5)) == 2):
            fail(gid, "w5 not two sentences starting 'This is'")
        if w6 != w6.lower():
            fail(gid, "w6 not lower case")
        if len({w.lower() for w in ws}) != 6:
            fail(gid, "duplicate wordings")
        labels = {objs[a]["label"].lower() for a in accept}
        uses = sum(any(re.search(r"\b" + re.escape(l) + r"(s|es)?\b", w.lower()) for l in labels) for w in ws)
        if uses > 2:
            fail(gid, f"label used in {uses} wordings")
    print("FAIL\n" + "\n".join(fails) if fails else "all checks passed")
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
