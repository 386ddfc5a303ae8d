"""Load the suite's maps into one object form: id, label, room, center, size, color, material, caption."""
import json
from pathlib import Path

BLIND = Path(__file__).resolve().parents[2] / "evals/blind"


def map_path(name: str) -> Path:
    p = (BLIND / name).resolve()
    if not p.is_file() and "/" not in name:
        p = BLIND.parents[1] / "map_store" / f"{name}.json"
    return p


def load(name: str) -> dict:
    data = json.loads(map_path(name).read_text(encoding="utf-8"))
    objs = {}
    if isinstance(data, dict) and "objects" in data:
        for o in data["objects"]:
            t = o.get("tags") or {}
            objs[int(o["id"])] = dict(id=int(o["id"]), label=o["label"].lower(), room=str(o.get("room", "")).lower(),
                                      center=o["center"], size=o["size"], color=str(t.get("color", "")).lower(),
                                      material=str(t.get("material", "")).lower(), caption=o.get("caption", "") or "",
                                      alt=[a.lower() for a in o.get("alt_labels", [])], geometry=True)
        return objs
    for k, v in data.items():
        raw = v.get("caption", "")
        try:
            c = json.loads(raw)
        except ValueError:  # a few captions have a trailing comma
            try:
                c = json.loads(raw.rstrip().rstrip("}").rstrip().rstrip(",") + "}")
            except ValueError:
                c = {"captions": raw}
        objs[int(k)] = dict(id=int(k), label=v["category"].lower(), room=str(v.get("room_cat") or "").lower(),
                            center=None, size=None, color=str(c.get("color", "")).lower(),
                            material=str(c.get("material", "")).lower(), caption=str(c.get("captions", raw)),
                            raw_caption=raw, alt=[], geometry=False)
    return objs
