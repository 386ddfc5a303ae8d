"""Load any of the round-51 maps into uniform records (id, label, room, color, material, caption, center, size)."""
import json, re
from pathlib import Path

BLIND = Path(__file__).resolve().parents[2] / "evals/blind"


def map_path(name):
    if "/" not in name:
        return Path(__file__).resolve().parents[2] / "map_store" / f"{name}.json"
    return (BLIND / name).resolve()


def _caption_fields(raw):
    try:
        c = json.loads(raw)
        return c.get("captions", ""), str(c.get("color", "")), str(c.get("material", ""))
    except Exception:
        def grab(key):
            m = re.search(r'"%s":\s*"((?:[^"\\]|\\.)*)"' % key, raw)
            return m.group(1) if m else ""
        return grab("captions"), grab("color"), grab("material")


def load(name):
    """(records by id, has_geometry)."""
    data = json.loads(map_path(name).read_text(encoding="utf-8"))
    recs = {}
    if isinstance(data, dict) and "objects" in data:
        rooms = {str(r["id"]): r["label"] for r in data.get("rooms", [])}
        for o in data["objects"]:
            room = str(o.get("room", ""))
            room = rooms.get(room, room)  # apartment id 3 uses a room id ("1")
            tags = o.get("tags", {})
            recs[int(o["id"])] = dict(id=int(o["id"]), label=o["label"], room=room,
                                      color=str(tags.get("color", "")), material=str(tags.get("material", "")),
                                      caption=o.get("caption", "") or "", alt=o.get("alt_labels", []),
                                      center=o["center"], size=o["size"], tags=tags)
        return recs, True
    for k, v in data.items():
        cap, col, mat = _caption_fields(v.get("caption", ""))
        recs[int(k)] = dict(id=int(k), label=v["category"], room=v.get("room_cat") or "", color=col,
                            material=mat, caption=cap, alt=[], center=None, size=None, tags={})
    return recs, False


def captions(name):
    recs, _ = load(name)
    return [r["caption"] for r in recs.values() if r["caption"]]
