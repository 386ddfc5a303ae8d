"""Print a map compactly: python3 show.py NAME"""
import json, sys
from pathlib import Path
B = Path(__file__).resolve().parents[2] / "evals/blind"
MAPS = {
 "flat_b": B/"maps/flat_b.json", "flat_e": B/"maps/flat_e.json", "flat_g": B/"maps/flat_g.json", "flat_i": B/"maps/flat_i.json",
 "apartment": Path(__file__).resolve().parents[2] / "map_store/apartment.json",
 "scan_bedroom": B/"../maps/scan_bedroom.json", "scan_kitchen": B/"../maps/scan_kitchen.json",
 "scan_livingroom": B/"../maps/scan_livingroom.json", "scan_office": B/"../maps/scan_office.json",
 "s829": Path(__file__).resolve().parents[3] / "shared/data/iesm_maps/scene_00829_caption.json",
 "office3": Path(__file__).resolve().parents[3] / "shared/data/iesm_maps/scene_office3_caption.json",
}
name = sys.argv[1]
d = json.loads(MAPS[name].read_text())
if isinstance(d, dict) and "objects" in d:
    for k in d:
        if k not in ("objects",):
            print(k, ":", json.dumps(d[k]))
    for o in d["objects"]:
        extra = {k: v for k, v in o.items() if k not in ("id","label","center","size","room","tags","caption")}
        print(f'{o["id"]:3d} {o["label"]!r:22} c={o.get("center")} s={o.get("size")} room={o.get("room")} tags={o.get("tags")} {extra if extra else ""}\n     {o.get("caption")}')
else:
    for k, v in d.items():
        try:
            c = json.loads(v["caption"])
        except Exception:
            c = {"captions": v["caption"]}
        print(f'{k:>4} {v["category"]!r:22} room={v.get("room_cat")}#{v.get("room_id")} col={c.get("color")} mat={c.get("material")} top5={v.get("top5_categories")}\n      {c.get("captions")}')
