"""Shared helpers for the round-65 check scripts: map loading and caption text."""
import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BLIND = ROOT / "evals" / "blind"
STORE = ROOT / "map_store"


def map_path(name: str) -> Path:
    p = (BLIND / name).resolve()
    if not p.is_file() and "/" not in name:
        p = STORE / f"{name}.json"
    return p


def caption_text(v: dict) -> str:
    """The free-text caption of a caption-map entry (its 'captions' field, even if the JSON is broken)."""
    c = v.get("caption", "")
    try:
        return str(json.loads(c).get("captions", ""))
    except Exception:
        m = re.search(r'"captions"\s*:\s*"((?:[^"\\]|\\.)*)"', c)
        return m.group(1) if m else c


def caption_attrs(v: dict) -> str:
    """colour/material text of a caption-map entry."""
    c = v.get("caption", "")
    try:
        j = json.loads(c)
        return f"{j.get('color', '')} {j.get('material', '')}"
    except Exception:
        col = re.search(r'"color"\s*:\s*"([^"]*)"', c)
        mat = re.search(r'"material"\s*:\s*"([^"]*)"', c)
        return f"{col.group(1) if col else ''} {mat.group(1) if mat else ''}"


def load_objects(name: str) -> tuple[dict[int, dict], bool]:
    """id -> normalised object {label, room, text, center, size, alt}; and whether it has geometry."""
    data = json.loads(map_path(name).read_text(encoding="utf-8"))
    objs = {}
    if isinstance(data, dict) and "objects" in data:
        for o in data["objects"]:
            tags = " ".join(str(v) for v in o.get("tags", {}).values())
            objs[int(o["id"])] = dict(label=o["label"], room=o["room"], alt=o.get("alt_labels", []),
                                      caption=o.get("caption", ""),
                                      text=f"{o['label']} {tags} {o.get('caption', '')}".lower(),
                                      center=o["center"], size=o["size"])
        return objs, True
    for k, v in data.items():
        cap = caption_text(v)
        objs[int(k)] = dict(label=v["category"], room=v["room_cat"], alt=[], caption=cap,
                            text=f"{v['category']} {caption_attrs(v)} {cap}".lower(),
                            center=None, size=None)
    return objs, False


def captions_of(name: str) -> list[str]:
    objs, _ = load_objects(name)
    return [o["caption"] for o in objs.values() if o["caption"]]


def words(text: str) -> list[str]:
    return re.findall(r"[a-z0-9]+(?:'[a-z]+)?", text.lower())
