"""Re-derive o/or accept sets, single-object uniqueness (od/ord/ard) and every spatial claim of round 36
from the maps. Spatial distances are horizontal (x, y) centre distances; margins must be >= 0.2 m."""
import json, math, re, sys
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
from emit import GROUPS, MAPS  # noqa: E402

SUITE_DIR = Path(__file__).resolve().parent.parent / "evals" / "blind"
MARGIN = 0.2


def load(mk):
    path = (SUITE_DIR / MAPS[mk]).resolve()
    d = json.loads(path.read_text())
    objs = {}
    if isinstance(d, dict) and "objects" in d:
        rooms = {str(r["id"]): r["label"] for r in d.get("rooms", [])}
        for o in d["objects"]:
            room = str(o.get("room"))
            room = rooms.get(room, room)
            t = o.get("tags", {})
            objs[int(o["id"])] = dict(label=o["label"], room=room, color=str(t.get("color", "")),
                                      material=str(t.get("material", "")), caption=o.get("caption", ""),
                                      c=o["center"], s=o["size"])
    else:
        for k, v in d.items():
            try:
                cap = json.loads(v["caption"])
            except ValueError:  # a few captions carry a trailing comma
                cap = {}
                for key in ("color", "material", "captions"):
                    m = re.search(r'"%s":\s*"([^"]*)"' % key, v["caption"])
                    cap[key] = m.group(1) if m else ""
            objs[int(k)] = dict(label=v["category"], room=str(v["room_cat"]), color=str(cap.get("color", "")),
                                material=str(cap.get("material", "")), caption=str(cap.get("captions", "")),
                                c=None, s=None)
    return objs


def match(o, f):
    if "label" in f and o["label"] != f["label"]:
        return False
    if "label_in" in f and o["label"] not in f["label_in"]:
        return False
    if "room" in f and o["room"] != f["room"]:
        return False
    for key in ("color", "material"):
        if key in f and f[key] not in o[key].lower():
            return False
    if "caption_has" in f and f["caption_has"].lower() not in o["caption"].lower():
        return False
    return True


def hd(a, b):
    return math.hypot(a["c"][0] - b["c"][0], a["c"][1] - b["c"][1])


def spatial(objs, target, claim):
    kind = claim[0]
    f = claim[-1]
    cands = [i for i, o in objs.items() if match(o, f)]
    t = objs[target]
    if target not in cands:
        return f"target not among candidates {cands}"
    others = [i for i in cands if i != target]
    if not others:
        return f"no competing candidates for {f}"
    if kind == "nearest":
        ref = objs[claim[1]]
        dt = hd(t, ref)
        do = {i: round(hd(objs[i], ref), 2) for i in others}
        if min(do.values()) - dt < MARGIN:
            return f"nearest fails: target {dt:.2f} others {do}"
        return f"ok nearest {dt:.2f} vs {do}"
    if kind == "side":
        facing, which = claim[1], claim[2]
        # facing +y: right is +x, left is -x
        assert facing == "+y"
        sign = 1 if which == "right" else -1
        lt = sign * t["c"][0]
        lo = {i: sign * objs[i]["c"][0] for i in others}
        if lt - max(lo.values()) < MARGIN:
            return f"side fails {lt} vs {lo}"
        return f"ok side {which}: {lt:.2f} vs {lo}"
    if kind == "higher":
        zt = t["c"][2]
        zo = {i: objs[i]["c"][2] for i in others}
        if zt - max(zo.values()) < MARGIN:
            return f"higher fails {zt} vs {zo}"
        return f"ok higher {zt} vs {zo}"
    if kind in ("on", "above"):
        ref = objs[claim[1]]
        top = ref["c"][2] + ref["s"][2] / 2

        def rel(o):
            bottom = o["c"][2] - o["s"][2] / 2
            ox = abs(o["c"][0] - ref["c"][0]) < (o["s"][0] + ref["s"][0]) / 2
            oy = abs(o["c"][1] - ref["c"][1]) < (o["s"][1] + ref["s"][1]) / 2
            if kind == "on":
                inside = (abs(o["c"][0] - ref["c"][0]) <= ref["s"][0] / 2 and
                          abs(o["c"][1] - ref["c"][1]) <= ref["s"][1] / 2)
                return inside and abs(bottom - top) <= 0.05
            return ox and oy and bottom - top >= MARGIN
        if not rel(t):
            return f"{kind} fails for target"
        bad = [i for i in others if rel(objs[i])]
        if bad:
            return f"{kind} also holds for {bad}"
        return f"ok {kind} {claim[1]}"
    return f"unknown claim {kind}"


def main():
    bad = 0
    cache = {}
    for n, (mk, typ, target, accept, spec, _w) in enumerate(GROUPS, 1):
        objs = cache.setdefault(mk, load(mk))
        g = f"g{n:02d} {mk} {typ}"
        msgs = []
        if typ in ("o", "or"):
            f = {"label": spec["label"]}
            if typ == "or":
                f["room"] = spec["room"]
            want = sorted(i for i, o in objs.items() if match(o, f))
            ok = want == sorted(accept) and target in want
            msgs.append(("ok" if ok else "FAIL") + f" accept {sorted(accept)} derived {want}")
            if typ == "o" and "room" in spec:
                ok = False
        elif typ == "s":
            ok = accept == [target]
            for claim in spec["spatial"]:
                r = spatial(objs, target, claim)
                msgs.append(r)
                ok = ok and r.startswith("ok")
        else:
            hits = sorted(i for i, o in objs.items() if match(o, spec["unique"]))
            ok = hits == [target] and accept == [target]
            msgs.append(("ok" if ok else "FAIL") + f" unique {spec['unique']} -> {hits}")
        if not ok:
            bad += 1
        print(("PASS " if ok else "FAIL ") + g + " target " + str(target) + " | " + " ; ".join(msgs))
    print(f"{len(GROUPS) - bad}/{len(GROUPS)} groups pass")
    return 1 if bad else 0


def style():
    """Wording styles: w1 imperative, w2 polite question, w3 no articles, w5 two sentences, w6 lower case."""
    probs = []
    for n, (_mk, _t, _tg, _a, _s, w) in enumerate(GROUPS, 1):
        if not re.match(r"(Go|Take|Stand|Sit)\b", w[0]):
            probs.append(f"g{n:02d} w1 not imperative")
        if not (w[1].startswith("Could you") and w[1].endswith("?")):
            probs.append(f"g{n:02d} w2 not a polite question")
        if re.search(r"\b(a|an|the)\b", w[2].lower()):
            probs.append(f"g{n:02d} w3 has an article")
        if len(re.findall(r"[.!?](\s|$)", w[4])) != 2:
            probs.append(f"g{n:02d} w5 not two sentences")
        if w[5] != w[5].lower():
            probs.append(f"g{n:02d} w6 not lower case")
    for p in probs:
        print("STYLE", p)
    print(f"style problems: {len(probs)}")
    return len(probs)


if __name__ == "__main__":
    sys.exit(1 if (main() | style()) else 0)
