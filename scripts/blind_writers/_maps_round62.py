"""Load a suite map (object list or caption dictionary) into uniform records."""
import json
import re
from pathlib import Path

BLIND = Path(__file__).resolve().parents[2] / "evals" / "blind"


def map_path(name):
    p = (BLIND / name).resolve()
    if not p.is_file() and "/" not in name:
        p = BLIND.parents[1] / "map_store" / f"{name}.json"
    return p


def load(name):
    """list of dicts: id, label, room, center, size (None on caption maps), text (caption + tags), caption."""
    data = json.loads(map_path(name).read_text(encoding="utf-8"))
    out = []
    if isinstance(data, dict) and "objects" in data:
        for o in data["objects"]:
            tags = o.get("tags") or {}
            cap = o.get("caption", "") or ""
            text = " ".join([o["label"], " ".join(o.get("alt_labels", [])), cap] + [str(v) for v in tags.values()])
            out.append(dict(id=int(o["id"]), label=o["label"], room=o.get("room"), center=o["center"],
                            size=o["size"], tags=tags, caption=cap, text=text.lower()))
    else:
        for k, v in data.items():
            raw = v.get("caption", "")
            try:
                c = json.loads(raw)
                cap, color, mat = c.get("captions", ""), c.get("color"), c.get("material")
            except ValueError:
                m = re.search(r'"captions":\s*"(.*?)"', raw, re.S)
                cap = m.group(1) if m else raw
                color = (re.search(r'"color":\s*"(.*?)"', raw) or [None, None])[1]
                mat = (re.search(r'"material":\s*"(.*?)"', raw) or [None, None])[1]
            tags = {"color": color, "material": mat}
            text = " ".join([v["category"], cap, str(color), str(mat)])
            out.append(dict(id=int(k), label=v["category"], room=v.get("room_cat"), center=None, size=None,
                            tags=tags, caption=cap, text=text.lower()))
    return out
