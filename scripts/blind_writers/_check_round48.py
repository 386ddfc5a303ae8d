"""Re-derive every o/or accept set from the maps, check single-id groups, check every spatial claim
numerically (centres and sizes, margin >= 0.2 m for distance/height claims), and check the wording
styles and spread rules of the brief. Exit 1 on any failure."""
import json
import math
import re
import sys
from collections import Counter, defaultdict

from _common_round48 import ROOT, load_map

MARGIN = 0.2
fails = []


def fail(msg):
    fails.append(msg)


def lo(o, i):
    return o["center"][i] - o["size"][i] / 2


def hi(o, i):
    return o["center"][i] + o["size"][i] / 2


def d2(a, b):
    return math.dist(a["center"][:2], b["center"][:2])


def in_footprint(p, o, tol=0.02):
    return all(lo(o, i) - tol <= p[i] <= hi(o, i) + tol for i in (0, 1))


def is_on(a, b):
    return in_footprint(a["center"], b) and abs(lo(a, 2) - hi(b, 2)) <= 0.05


def cands(objs, label, room=None):
    return [o for o in objs.values() if o["label"] == label and (room is None or o["room"] == room)]


def margin_pick(gid, what, target, scores, best_low=True):
    """scores: {id: value}; target must be best by >= MARGIN."""
    others = [v for k, v in scores.items() if k != target]
    if not others:
        fail(f"{gid}: {what}: no other candidates"); return
    t = scores[target]
    gap = (min(others) - t) if best_low else (t - max(others))
    ok = gap >= MARGIN
    print(f"  {gid} {what}: target {target}={t:.2f} others {sorted(round(v, 2) for v in others)} gap {gap:.2f} {'OK' if ok else 'FAIL'}")
    if not ok:
        fail(f"{gid}: {what} margin {gap:.2f}")


def check_claim(gid, c, objs):
    kind = c[0]
    if kind == "on":
        _, a, b, label = c
        ok = is_on(objs[a], objs[b])
        others = [o["id"] for o in cands(objs, label) if o["id"] != a and is_on(o, objs[b])]
        print(f"  {gid} on({a},{b}) {ok} other {label}s on it: {others}")
        if not ok or others:
            fail(f"{gid}: on({a},{b}) fails or not unique")
    elif kind == "on_any":
        _, a, bs, label = c
        ok = any(is_on(objs[a], objs[b]) for b in bs)
        others = [o["id"] for o in cands(objs, label) if o["id"] != a and any(is_on(o, objs[b]) for b in bs)]
        print(f"  {gid} on_any({a},{bs}) {ok} others {others}")
        if not ok or others:
            fail(f"{gid}: on_any fails or not unique")
    elif kind in ("nearest", "farthest"):
        _, t, ref, label, *room = c
        cs = cands(objs, label, room[0] if room else None)
        scores = {o["id"]: d2(o, objs[ref]) for o in cs}
        margin_pick(gid, f"{kind} to {ref} among {label}", t, scores, best_low=(kind == "nearest"))
    elif kind == "lowest":
        _, t, label = c
        margin_pick(gid, f"lowest {label}", t, {o["id"]: o["center"][2] for o in cands(objs, label)})
    elif kind == "near":
        _, a, b, lim = c
        ok = d2(objs[a], objs[b]) <= lim
        print(f"  {gid} near({a},{b}) d={d2(objs[a], objs[b]):.2f} <= {lim} {ok}"); ok or fail(f"{gid}: near")
    elif kind == "east_of":
        _, a, b = c
        ok = objs[a]["center"][0] >= objs[b]["center"][0] + MARGIN
        print(f"  {gid} east_of({a},{b}) {ok}"); ok or fail(f"{gid}: east_of")
    elif kind == "west_of":
        _, a, b = c
        ok = objs[a]["center"][0] + MARGIN <= objs[b]["center"][0]
        print(f"  {gid} west_of({a},{b}) {ok}"); ok or fail(f"{gid}: west_of")
    elif kind == "east_wall":
        _, a = c
        xmax = max(o["center"][0] for o in objs.values() if o["room"] == objs[a]["room"])
        ok = objs[a]["center"][0] >= xmax - 0.01
        print(f"  {gid} east_wall({a}) {ok}"); ok or fail(f"{gid}: east_wall")
    elif kind == "between":
        _, t, a, b, label = c
        pa, pb, pt = (objs[i]["center"][:2] for i in (a, b, t))
        v = (pb[0] - pa[0], pb[1] - pa[1]); L2 = v[0] ** 2 + v[1] ** 2
        s = ((pt[0] - pa[0]) * v[0] + (pt[1] - pa[1]) * v[1]) / L2
        perp = abs((pt[0] - pa[0]) * v[1] - (pt[1] - pa[1]) * v[0]) / math.sqrt(L2)
        ids = sorted(o["id"] for o in cands(objs, label))
        ok = 0.2 <= s <= 0.8 and perp <= 0.3 and ids == sorted([t, a, b])
        print(f"  {gid} between({t};{a},{b}) s={s:.2f} perp={perp:.2f} all {label}={ids} {'OK' if ok else 'FAIL'}")
        ok or fail(f"{gid}: between")
    elif kind == "east_end_short":
        _, t, *rest = c
        ok = all(objs[t]["center"][0] >= objs[r]["center"][0] + MARGIN and hi(objs[t], 2) + MARGIN <= hi(objs[r], 2) for r in rest)
        print(f"  {gid} east_end_short({t}) {ok}"); ok or fail(f"{gid}: east_end_short")
    elif kind == "under":
        _, t, ref, label = c
        def under(o):
            return in_footprint(objs[ref]["center"], o) and lo(objs[ref], 2) >= hi(o, 2) - 0.05
        others = [o["id"] for o in cands(objs, label) if o["id"] != t and under(o)]
        ok = under(objs[t]) and not others
        print(f"  {gid} under({t},{ref}) {under(objs[t])} others {others}"); ok or fail(f"{gid}: under")
    elif kind in ("left_from_foot", "nearest_foot"):
        _, t, bed, label = c
        B = objs[bed]
        # headboard side = the bed end nearer the nightstands
        ns = cands(objs, "nightstand")
        north = sum(o["center"][1] for o in ns) / len(ns) > B["center"][1]
        print(f"  {gid} headboard at {'north' if north else 'south'} (viewer at foot faces {'+y' if north else '-y'})")
        if not north:
            fail(f"{gid}: expected headboard north"); return
        if kind == "left_from_foot":   # facing +y, left is -x
            margin_pick(gid, f"leftmost {label} from foot", t, {o["id"]: o["center"][0] for o in cands(objs, label)})
        else:
            foot = [B["center"][0], lo(B, 1)]
            margin_pick(gid, f"{label} nearest foot {foot}", t,
                        {o["id"]: math.dist(o["center"][:2], foot) for o in cands(objs, label)})
    elif kind == "above":
        _, t, ref, label = c
        def above(o):
            R = objs[ref]
            xo = min(hi(o, 0), hi(R, 0)) - max(lo(o, 0), lo(R, 0))
            return xo > 0 and lo(o, 2) >= hi(R, 2) + MARGIN and abs(o["center"][1] - R["center"][1]) <= 0.6
        others = [o["id"] for o in cands(objs, label) if o["id"] != t and above(o)]
        ok = above(objs[t]) and not others
        print(f"  {gid} above({t},{ref}) {above(objs[t])} others {others}"); ok or fail(f"{gid}: above")
    else:
        fail(f"{gid}: unknown claim {kind}")


def main():
    specs = json.loads((ROOT / "scripts/blind_writers/_specs_round48.json").read_text())
    rows = [json.loads(l) for l in (ROOT / "evals/blind/round48.jsonl").read_text().splitlines()]
    groups = defaultdict(list)
    for r in rows:
        groups[r["group"]].append(r)
    per_type, per_map, s_scan = Counter(), Counter(), 0
    for gid, sp in specs.items():
        kind, objs, _ = load_map(sp["map"])
        typ = sp["type"]
        per_type[typ] += 1
        mname = sp["map"].split("/")[-1]
        cls = "caption" if kind == "cap" else ("flat" if mname.startswith("flat_") else ("scan" if mname.startswith("scan_") else "apartment"))
        per_map[cls] += 1
        if sp["target"] not in objs or any(a not in objs for a in sp["accept"]):
            fail(f"{gid}: ids missing")
        lab = (lambda i: objs[i]["category"]) if kind == "cap" else (lambda i: objs[i]["label"])
        room = (lambda i: objs[i]["room_cat"]) if kind == "cap" else (lambda i: objs[i]["room"])
        if typ in ("o", "or"):
            derived = sorted(i for i in objs if lab(i) == sp["label"] and (typ == "o" or room(i) == sp["room"]))
            ok = derived == sorted(sp["accept"]) and sp["target"] in derived
            print(f"{gid} {typ} {mname} label={sp['label']!r} room={sp.get('room')!r} derived={derived} {'OK' if ok else 'FAIL'}")
            ok or fail(f"{gid}: accept {sp['accept']} != derived {derived}")
            if typ == "or":
                outside = sorted(i for i in objs if lab(i) == sp["label"] and room(i) != sp["room"])
                print(f"   (same label elsewhere: {outside})")
        else:
            if sp["accept"] != [sp["target"]]:
                fail(f"{gid}: single-id type with accept {sp['accept']}")
            print(f"{gid} {typ} {mname} target={sp['target']} ({lab(sp['target'])}, {room(sp['target'])}) why: {sp.get('why', '')}")
        if typ == "s":
            if kind != "geo":
                fail(f"{gid}: spatial on caption map")
            if cls == "scan":
                s_scan += 1
            n_kind = sum(1 for i in objs if lab(i) == lab(sp["target"]))
            if n_kind < 2:
                fail(f"{gid}: spatial target has no others of its kind")
        for c in sp.get("claims", []):
            check_claim(gid, c, objs)
        # wording styles
        ws = {int(r["id"].rsplit("-w", 1)[1]): r["query"] for r in groups[gid]}
        if sorted(ws) != [1, 2, 3, 4, 5, 6]:
            fail(f"{gid}: wordings {sorted(ws)}")
            continue
        if not re.match(r"^(Go|Take|Bring|Head|Find|Show)\b", ws[1]):
            fail(f"{gid} w1 not imperative: {ws[1]}")
        if not (ws[2].startswith("Could you") and ws[2].endswith("?")):
            fail(f"{gid} w2 not a polite question: {ws[2]}")
        w3 = re.findall(r"[a-z0-9'-]+", ws[3].lower())
        if len(w3) > 6 or set(w3) & {"a", "an", "the"}:
            fail(f"{gid} w3 not telegraphic: {ws[3]}")
        if not (ws[5].startswith("This is") and len(re.findall(r"[.!?](\s|$)", ws[5])) == 2):
            fail(f"{gid} w5 not two sentences: {ws[5]}")
        if ws[6] != ws[6].lower():
            fail(f"{gid} w6 not lower case: {ws[6]}")
        names = {lab(a).lower() for a in sp["accept"]}
        uses = sum(any(re.search(r"\b" + re.escape(n) + r"(s|es)?\b", q.lower()) for n in names) for q in ws.values())
        if uses > 2:
            fail(f"{gid}: exact label in {uses} wordings")
    need = {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}
    print("per type", dict(per_type), "per map class", dict(per_map), "spatial on scans", s_scan)
    if dict(per_type) != need:
        fail(f"type counts {dict(per_type)}")
    if per_map["caption"] < 12 or per_map["flat"] < 14 or s_scan < 4 or len(specs) != 48:
        fail("spread rules")
    print("\nw6 wordings (typo review):")
    for gid in specs:
        print(" ", gid, [r["query"] for r in groups[gid] if r["id"].endswith("-w6")][0])
    print("\nFAILURES:" if fails else "\nALL CHECKS PASSED")
    for f in fails:
        print(" ", f)
    return 1 if fails else 0


if __name__ == "__main__":
    sys.exit(main())
