"""Shared helpers for round 58: map paths, map loading, text tokenising."""
import json
import re
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
BLIND = ROOT / "evals/blind"
SUITE = BLIND / "round58.jsonl"

# map key -> (suite "map" field, path from the repository root)
MAPS = {
    "flat_b": ("maps/flat_b.json", BLIND / "maps/flat_b.json"),
    "flat_e": ("maps/flat_e.json", BLIND / "maps/flat_e.json"),
    "flat_g": ("maps/flat_g.json", BLIND / "maps/flat_g.json"),
    "flat_i": ("maps/flat_i.json", BLIND / "maps/flat_i.json"),
    "apartment": ("apartment", ROOT / "map_store/apartment.json"),
    "scan_bedroom": ("../maps/scan_bedroom.json", ROOT / "evals/maps/scan_bedroom.json"),
    "scan_kitchen": ("../maps/scan_kitchen.json", ROOT / "evals/maps/scan_kitchen.json"),
    "scan_livingroom": ("../maps/scan_livingroom.json", ROOT / "evals/maps/scan_livingroom.json"),
    "scan_office": ("../maps/scan_office.json", ROOT / "evals/maps/scan_office.json"),
    "scene_00829": ("../../../shared/data/iesm_maps/scene_00829_caption.json",
                    ROOT / "../shared/data/iesm_maps/scene_00829_caption.json"),
    "scene_office3": ("../../../shared/data/iesm_maps/scene_office3_caption.json",
                      ROOT / "../shared/data/iesm_maps/scene_office3_caption.json"),
}
FIELD_TO_KEY = {v[0]: k for k, v in MAPS.items()}


def load(key):
    """id -> dict(label, room, caption(s) list, tags, center, size) for either map format."""
    data = json.loads(MAPS[key][1].read_text())
    out = {}
    if isinstance(data, dict) and "objects" in data:
        for o in data["objects"]:
            room = o.get("room")
            if not isinstance(room, str):  # apartment object 3 has a room id
                room = {r["id"]: r["label"] for r in data["rooms"]}.get(int(room))
            out[int(o["id"])] = dict(label=o["label"], room=room, captions=[o.get("caption") or ""],
                                     tags=o.get("tags") or {}, center=o["center"], size=o["size"], geo=True)
        return out, data.get("rooms", [])
    for k, v in data.items():
        caps = [v.get("caption", "")]
        m = re.search(r'"captions":\s*"(.*?)"', v.get("caption", ""), re.S)
        if m:
            caps.append(m.group(1))
        col = re.search(r'"color":\s*"(.*?)"', v.get("caption", ""))
        mat = re.search(r'"material":\s*"(.*?)"', v.get("caption", ""))
        out[int(k)] = dict(label=v["category"], room=v.get("room_cat"), captions=caps,
                           tags={"color": col.group(1) if col else None, "material": mat.group(1) if mat else None},
                           center=None, size=None, geo=False)
    return out, []


def words(text):
    return re.findall(r"[a-z0-9']+", text.lower().replace("-", " "))
