"""Load every map of the suite into one shape: id -> dict(label, alt, room, center, size, text, color)."""
import json, re
from pathlib import Path
BLIND = Path(__file__).resolve().parents[2] / "evals/blind"

def map_path(name):
    p = (BLIND / name).resolve()
    if not p.is_file() and "/" not in name:
        p = Path(__file__).resolve().parents[2] / "map_store" / f"{name}.json"
    return p

def parse_caption(s):
    """The caption string of a caption map: JSON, sometimes with a trailing comma."""
    try:
        return json.loads(s)
    except ValueError:
        return json.loads(re.sub(r",\s*}\s*$", "}", s))

def load(name):
    d = json.loads(map_path(name).read_text(encoding="utf-8"))
    objs = {}
    if isinstance(d, dict) and "objects" in d:
        rooms = {r["id"]: r["label"] for r in d.get("rooms", [])}
        for o in d["objects"]:
            room = o.get("room")
            if isinstance(room, int):
                room = rooms.get(room)
            tags = o.get("tags") or {}
            objs[int(o["id"])] = dict(label=o["label"], alt=o.get("alt_labels") or [], room=room,
                                      center=o["center"], size=o["size"], caption=o.get("caption", ""),
                                      color=str(tags.get("color", "")), tags=tags,
                                      text=(o.get("caption", "") + " " + " ".join(map(str, tags.values()))).lower())
        return objs, True
    for k, v in d.items():
        cap = parse_caption(v["caption"])
        room = v.get("room_cat") or cap.get("room_cat")
        objs[int(k)] = dict(label=v["category"], alt=[], room=room, center=None, size=None,
                            caption=cap.get("captions", ""), color=str(cap.get("color", "")), tags={},
                            raw=v["caption"],
                            text=(cap.get("captions", "") + " " + str(cap.get("color", "")) + " " + str(cap.get("material", ""))).lower())
    return objs, False
