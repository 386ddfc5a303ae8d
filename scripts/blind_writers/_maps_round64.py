"""Load any suite map into a uniform list of objects."""
import json
import re
from pathlib import Path
BLIND = Path(__file__).resolve().parents[2] / "evals" / "blind"

def path_of(mp):
    p = (BLIND / mp).resolve()
    if not p.is_file() and "/" not in mp:
        p = BLIND.parents[1] / "map_store" / f"{mp}.json"
    return p

def load(mp):
    d = json.loads(path_of(mp).read_text())
    objs = []
    if isinstance(d, dict) and "objects" in d:
        for o in d["objects"]:
            tags = o.get("tags") or {}
            objs.append(dict(id=o["id"], label=o["label"].lower(), alt=[a.lower() for a in o.get("alt_labels") or []],
                             room=str(o["room"]).lower(), center=o["center"], size=o["size"],
                             caption=o.get("caption", "") or "",
                             text=(" ".join([o.get("caption", "") or ""] + [str(v) for v in tags.values()])).lower()))
        return objs, True
    for k, v in d.items():
        cap = v.get("caption", "")
        objs.append(dict(id=int(k), label=v["category"].lower(), alt=[], room=str(v.get("room_cat")).lower(),
                         center=None, size=None, caption=cap, text=cap.lower()))
    return objs, False

def captions(mp):
    """Every caption sentence text of a map (for caption maps, the 'captions' field and the whole string)."""
    objs, geo = load(mp)
    out = []
    for o in objs:
        c = o["caption"]
        if not c:
            continue
        out.append(c)
        m = re.search(r'"captions"\s*:\s*"([^"]*)"', c)
        if m:
            out.append(m.group(1))
    return out
