"""Print the maps compactly."""
import json, sys
from pathlib import Path
B = str(Path(__file__).resolve().parents[2]) + "/"
OBJ = {"flat_c": B+"evals/blind/maps/flat_c.json", "flat_d": B+"evals/blind/maps/flat_d.json",
       "flat_f": B+"evals/blind/maps/flat_f.json", "flat_h": B+"evals/blind/maps/flat_h.json",
       "apartment": B+"map_store/apartment.json",
       "scan_bedroom": B+"evals/maps/scan_bedroom.json", "scan_kitchen": B+"evals/maps/scan_kitchen.json",
       "scan_livingroom": B+"evals/maps/scan_livingroom.json", "scan_office": B+"evals/maps/scan_office.json"}
CAP = {"scene_00829": B + "../shared/data/iesm_maps/scene_00829_caption.json",
       "scene_office3": B + "../shared/data/iesm_maps/scene_office3_caption.json"}
import re
def parse_caption(t):
    """Caption dict of a caption-map entry (tolerates trailing commas)."""
    try:
        return json.loads(t)
    except Exception:
        try:
            return json.loads(re.sub(r",\s*}", "}", t))
        except Exception:
            return {"raw": t}
def fmt(v): return "[" + ",".join(f"{x:.2f}" for x in v) + "]"
for name in sys.argv[1:]:
    if name in OBJ:
        d = json.load(open(OBJ[name]))
        print("==", name, d.get("comment", ""))
        for r in d.get("rooms", []):
            print("  room", r["id"], r["label"], r["polygon"])
        for o in d["objects"]:
            extra = {k: v for k, v in o.items() if k not in ("id","label","center","size","room","tags","caption")}
            print(f'{o["id"]:3d} {o["label"]:<18} c={fmt(o["center"])} s={fmt(o["size"])} {o.get("room","")} {o.get("tags",{})} {extra if extra else ""}')
            if o.get("caption"): print("      ", o["caption"])
    else:
        d = json.load(open(CAP[name]))
        print("==", name, len(d))
        for k, v in d.items():
            c = parse_caption(v["caption"])
            print(f'{k:>4} {v["category"]:<20} room={v.get("room_cat")}/{v.get("room_id")} col={c.get("color")} mat={c.get("material")}')
            print("       ", c.get("captions", c.get("raw")))
