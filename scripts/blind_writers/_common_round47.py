"""Shared loading for check.py and copycheck.py: resolve a suite map field and load its objects."""
import json
import re
from pathlib import Path

SUITE_DIR = Path(__file__).resolve().parents[2] / "evals" / "blind"


def map_path(field):
    return (SUITE_DIR / field).resolve()


def caption_text(raw):
    """The 'captions' sentence of a caption-map entry (its caption is a JSON string, sometimes with a trailing comma)."""
    try:
        return json.loads(re.sub(r",\s*}", "}", raw)).get("captions", raw)
    except ValueError:
        return raw


def load(field):
    """{id: dict(label, room, center, size, caption)} and whether the map has geometry."""
    data = json.loads(map_path(field).read_text(encoding="utf-8"))
    if isinstance(data, dict) and "objects" in data:
        rooms = {str(r["id"]): r["label"] for r in data.get("rooms", [])}
        polys = {r["label"]: r["polygon"] for r in data.get("rooms", [])}
        objs = {}
        for o in data["objects"]:
            room = str(o.get("room"))
            room = rooms.get(room, room)  # the apartment gives one room as its id
            objs[int(o["id"])] = dict(label=o["label"], room=room, center=o["center"], size=o["size"],
                                      caption=o.get("caption", ""), tags=o.get("tags", {}))
        return objs, True, polys
    objs = {int(k): dict(label=v["category"], room=v["room_cat"], caption=caption_text(v["caption"]),
                         raw=v["caption"]) for k, v in data.items()}
    return objs, False, {}
