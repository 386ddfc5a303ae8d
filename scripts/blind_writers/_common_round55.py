"""Load the round-55 maps into one shape: id -> dict(label, room, center, size, text)."""
import json, re
from pathlib import Path

BLIND = Path(__file__).resolve().parents[2] / "evals/blind"


def map_path(name: str) -> Path:
    p = (BLIND / name).resolve()
    if not p.is_file() and "/" not in name:
        p = Path(__file__).resolve().parents[2] / "map_store" / f"{name}.json"
    return p


def parse_caption(t: str) -> dict:
    try:
        return json.loads(t)
    except Exception:
        try:
            return json.loads(re.sub(r",\s*}", "}", t))
        except Exception:
            return {"captions": t}


def in_poly(x, y, poly):
    inside = False
    n = len(poly)
    for i in range(n):
        x1, y1 = poly[i]; x2, y2 = poly[(i + 1) % n]
        if (y1 > y) != (y2 > y) and x < (x2 - x1) * (y - y1) / (y2 - y1) + x1:
            inside = not inside
    return inside


def load(name: str):
    """(objects, geometry?, captions) of map `name`."""
    data = json.loads(map_path(name).read_text())
    objs, caps = {}, []
    if isinstance(data, dict) and "objects" in data:
        rooms = data.get("rooms", [])
        for o in data["objects"]:
            cx, cy = o["center"][0], o["center"][1]
            poly_rooms = [r["label"] for r in rooms if in_poly(cx, cy, r["polygon"])]
            text = " ".join([o["label"], " ".join(o.get("alt_labels", [])),
                             " ".join(str(v) for v in o.get("tags", {}).values()), o.get("caption", "")])
            objs[int(o["id"])] = dict(label=o["label"], room=str(o.get("room")), poly_rooms=poly_rooms,
                                      center=o["center"], size=o["size"], text=text.lower())
            if o.get("caption"):
                caps.append(o["caption"])
        return objs, True, caps
    for k, v in data.items():
        c = parse_caption(v["caption"])
        text = " ".join([v["category"], str(c.get("color", "")), str(c.get("material", "")), str(c.get("captions", ""))])
        objs[int(k)] = dict(label=v["category"], room=v.get("room_cat"), poly_rooms=[v.get("room_cat")],
                            center=None, size=None, text=text.lower())
        if c.get("captions"):
            caps.append(str(c["captions"]))
        caps.append(v["caption"])
    return objs, False, caps
