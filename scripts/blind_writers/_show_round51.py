"""Print a map compactly: object maps (id label room centre size tags caption) or caption maps."""
import json, sys
from pathlib import Path

MAPS = {
    "flat_c": str(Path(__file__).resolve().parents[2] / "evals/blind/maps/flat_c.json"),
    "flat_d": str(Path(__file__).resolve().parents[2] / "evals/blind/maps/flat_d.json"),
    "flat_f": str(Path(__file__).resolve().parents[2] / "evals/blind/maps/flat_f.json"),
    "flat_h": str(Path(__file__).resolve().parents[2] / "evals/blind/maps/flat_h.json"),
    "apartment": str(Path(__file__).resolve().parents[2] / "map_store/apartment.json"),
    "scan_bedroom": str(Path(__file__).resolve().parents[2] / "evals/maps/scan_bedroom.json"),
    "scan_kitchen": str(Path(__file__).resolve().parents[2] / "evals/maps/scan_kitchen.json"),
    "scan_livingroom": str(Path(__file__).resolve().parents[2] / "evals/maps/scan_livingroom.json"),
    "scan_office": str(Path(__file__).resolve().parents[2] / "evals/maps/scan_office.json"),
    "c829": str(Path(__file__).resolve().parents[3] / "shared/data/iesm_maps/scene_00829_caption.json"),
    "coff3": str(Path(__file__).resolve().parents[3] / "shared/data/iesm_maps/scene_office3_caption.json"),
}

def show(name):
    d = json.load(open(MAPS[name]))
    if isinstance(d, dict) and "objects" in d:
        print("##", name, d.get("comment", ""))
        for r in d.get("rooms", []):
            print("  room", r["id"], r["label"], r["polygon"])
        for o in d["objects"]:
            extra = {k: v for k, v in o.items() if k not in ("id", "label", "center", "size", "room", "tags", "caption")}
            print(f'{o["id"]:>3} {o["label"]:<18} {o.get("room",""):<12} c={o["center"]} s={o["size"]} {o.get("tags",{})} {extra}')
            if o.get("caption"):
                print("      ", o["caption"])
    else:
        print("##", name)
        for k, v in d.items():
            cap = v.get("caption", "")
            try:
                c = json.loads(cap)
            except Exception:
                c = {"captions": cap}
            print(f'{k:>4} {v["category"]:<20} {v.get("room_cat")}({v.get("room_id")}) col={c.get("color")} mat={c.get("material")}')
            print("       ", c.get("captions"))
            extra = {kk: vv for kk, vv in v.items() if kk not in ("category", "room_cat", "room_id", "category_idx", "top5_categories", "caption")}
            if extra: print("       extra:", extra)

for n in (sys.argv[1:] or MAPS):
    show(n)
