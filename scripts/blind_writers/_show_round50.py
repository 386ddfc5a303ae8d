"""Print the maps compactly: rooms and objects (id, label, alt labels, room, centre, size, tags, caption)."""
import json, sys
from pathlib import Path
B = Path(__file__).resolve().parents[2]
MAPS = {
 "maps/flat_b.json": B/"evals/blind/maps/flat_b.json",
 "maps/flat_e.json": B/"evals/blind/maps/flat_e.json",
 "maps/flat_g.json": B/"evals/blind/maps/flat_g.json",
 "maps/flat_i.json": B/"evals/blind/maps/flat_i.json",
 "apartment": B/"map_store/apartment.json",
 "../maps/scan_bedroom.json": B/"evals/maps/scan_bedroom.json",
 "../maps/scan_kitchen.json": B/"evals/maps/scan_kitchen.json",
 "../maps/scan_livingroom.json": B/"evals/maps/scan_livingroom.json",
 "../maps/scan_office.json": B/"evals/maps/scan_office.json",
 "../../../shared/data/iesm_maps/scene_00829_caption.json": (B.parent / "shared/data/iesm_maps/scene_00829_caption.json"),
 "../../../shared/data/iesm_maps/scene_office3_caption.json": (B.parent / "shared/data/iesm_maps/scene_office3_caption.json"),
}
def show(name):
    d = json.loads(MAPS[name].read_text())
    print("=====", name)
    if "objects" in d:
        print(d.get("comment"))
        for r in d.get("rooms", []): print("ROOM", r)
        for o in d["objects"]:
            print(f'{o["id"]:3} {o["label"]!r} alt={o.get("alt_labels")} room={o.get("room")} c={o["center"]} s={o["size"]} tags={o.get("tags")}')
            if o.get("caption"): print("      ", o["caption"])
            extra = {k:v for k,v in o.items() if k not in ("id","label","alt_labels","room","center","size","tags","caption")}
            if extra: print("      extra", extra)
    else:
        for k, v in d.items():
            try: cap = json.loads(v["caption"])
            except Exception: cap = {"raw": v["caption"]}
            print(f'{k:>4} {v["category"]!r} room={v.get("room_cat")}#{v.get("room_id")} top5={v.get("top5_categories")}')
            print("      ", {kk:vv for kk,vv in cap.items() if kk not in ("category","room_cat")})
for n in (sys.argv[1:] or MAPS): show(n)
