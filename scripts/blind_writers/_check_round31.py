"""Re-derive o/or accept sets from the maps, verify spatial claims numerically, and check the wording styles.
    python3 check.py   (run from anywhere; reads ../evals/blind/round31.jsonl and the maps)"""
import json, math, re, sys
from pathlib import Path
sys.path.insert(0, str(Path(__file__).resolve().parent))
from emit import GROUPS, MAPS, SPATIAL

BLIND = Path(__file__).resolve().parents[1] / "evals" / "blind"
MARGIN = 0.2
errs = []


def load(mk):
    p = (BLIND / MAPS[mk]).resolve()
    if not p.is_file():
        p = BLIND / MAPS[mk]
    d = json.loads(p.read_text())
    if isinstance(d, dict) and "objects" in d:
        return {o["id"]: o for o in d["objects"]}, True
    return {int(k): {"id": int(k), "label": v["category"], "room": (v["room_cat"], v["room_id"])} for k, v in d.items()}, False


def d2(a, b):
    return math.hypot(a["center"][0] - b["center"][0], a["center"][1] - b["center"][1])


def spatial(objs, kind, args):
    if kind in ("nearest", "farthest"):
        ref, cands, exp = args
        ds = sorted(((d2(objs[ref], objs[c]), c) for c in cands), reverse=(kind == "farthest"))
        ok = ds[0][1] == exp and abs(ds[0][0] - ds[1][0]) >= MARGIN
        return ok, f"{kind} to {ref}: " + ", ".join(f"{c}:{d:.2f}" for d, c in ds)
    if kind == "higher":
        cands, exp = args
        hs = sorted(((objs[c]["center"][2], c) for c in cands), reverse=True)
        return hs[0][1] == exp and hs[0][0] - hs[1][0] >= MARGIN, "heights " + str(hs)
    if kind == "on":
        top, sup = objs[args[0]], objs[args[1]]
        inside = all(abs(top["center"][i] - sup["center"][i]) <= sup["size"][i] / 2 for i in (0, 1))
        gap = (top["center"][2] - top["size"][2] / 2) - (sup["center"][2] + sup["size"][2] / 2)
        return inside and abs(gap) <= 0.05, f"{args[0]} on {args[1]}: inside={inside} gap={gap:.3f}"
    if kind == "between":
        o, a, b = (objs[i]["center"] for i in args)
        ax, ay, bx, by = a[0], a[1], b[0], b[1]
        t = ((o[0] - ax) * (bx - ax) + (o[1] - ay) * (by - ay)) / ((bx - ax) ** 2 + (by - ay) ** 2)
        off = abs((o[0] - ax) * (by - ay) - (o[1] - ay) * (bx - ax)) / math.hypot(bx - ax, by - ay)
        return 0.2 < t < 0.8 and off < 0.3, f"between t={t:.2f} off={off:.2f}"
    if kind == "endof":
        c, t = objs[args[0]], objs[args[1]]
        long_ax = 0 if t["size"][0] >= t["size"][1] else 1
        short_ax = 1 - long_ax
        beyond = abs(c["center"][long_ax] - t["center"][long_ax]) > t["size"][long_ax] / 2
        within = abs(c["center"][short_ax] - t["center"][short_ax]) < t["size"][short_ax] / 2
        return beyond and within, f"endof beyond={beyond} within={within}"
    return False, "unknown kind"


counts_t, counts_m = {}, {}
for g, (mk, typ, target, accept, words) in enumerate(GROUPS, 1):
    objs, geo = load(mk)
    counts_t[typ] = counts_t.get(typ, 0) + 1
    counts_m[mk] = counts_m.get(mk, 0) + 1
    lab = objs[target]["label"]
    if typ == "o":
        want = sorted(i for i, o in objs.items() if o["label"] == lab)
        if want != sorted(accept):
            errs.append(f"g{g:02d}: o accept {sorted(accept)} != derived {want}")
    elif typ == "or":
        room = objs[target]["room"]
        want = sorted(i for i, o in objs.items() if o["label"] == lab and o["room"] == room)
        if want != sorted(accept):
            errs.append(f"g{g:02d}: or accept {sorted(accept)} != derived {want}")
    elif typ != "ard" and sorted(accept) != [target]:
        errs.append(f"g{g:02d}: {typ} must have a single id")
    if typ == "s":
        if not geo:
            errs.append(f"g{g:02d}: spatial on a caption map")
        if g not in SPATIAL:
            errs.append(f"g{g:02d}: no spatial claim recorded")
        for kind, args in SPATIAL.get(g, []):
            ok, msg = spatial(objs, kind, args)
            print(f"g{g:02d} {'OK ' if ok else 'BAD'} {msg}")
            if not ok:
                errs.append(f"g{g:02d}: spatial claim fails: {msg}")
    # styles
    w1, w2, w3, w4, w5, w6 = words
    if not w2.startswith("Could you") or not w2.endswith("?"):
        errs.append(f"g{g:02d}: w2 not a polite question")
    if len(w3.split()) > 6 or re.search(r"\b(the|a|an)\b", w3.lower()):
        errs.append(f"g{g:02d}: w3 not telegraphic: {w3}")
    if not w5.startswith("This is") or len(re.findall(r"[.!?](\s|$)", w5)) != 2:
        errs.append(f"g{g:02d}: w5 not two sentences starting 'This is': {w5}")
    if w6 != w6.lower():
        errs.append(f"g{g:02d}: w6 not lower case")
    uses = sum(bool(re.search(r"\b" + re.escape(lab.lower()) + r"(s|es)?\b", w.lower())) for w in words)
    if uses > 2:
        errs.append(f"g{g:02d}: label '{lab}' in {uses} wordings")
    if len({w.lower() for w in words}) != 6:
        errs.append(f"g{g:02d}: duplicate wordings")

print("types", counts_t)
print("maps", counts_m)
cap = counts_m.get("s829", 0) + counts_m.get("off3", 0)
flats = sum(counts_m.get(k, 0) for k in ("fc", "fd", "ff", "fh"))
scans_s = sum(1 for mk, t, *_ in GROUPS if t == "s" and mk in ("sb", "sk", "sl", "so"))
print(f"caption groups {cap} (>=12), flat groups {flats} (>=14), spatial on scans {scans_s} (>=4)")
if cap < 12 or flats < 14 or scans_s < 4:
    errs.append("spread rule broken")
if counts_t != {"o": 7, "or": 7, "od": 7, "ord": 7, "ard": 8, "s": 12}:
    errs.append(f"type counts {counts_t}")
for e in errs:
    print("ERROR", e)
print("check.py:", "FAIL" if errs else "all checks pass")
sys.exit(1 if errs else 0)
