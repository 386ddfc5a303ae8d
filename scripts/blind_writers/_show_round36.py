"""Print a map compactly: python3 show.py PATH"""
import json, sys
p = sys.argv[1]
d = json.load(open(p))
if isinstance(d, dict) and "objects" in d:
    for r in d.get("rooms", []):
        print("ROOM", r["id"], r["label"], r.get("polygon"))
    for o in d["objects"]:
        c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
        print(o["id"], o["label"], "|", o.get("room"), c, s, o.get("tags", {}), o.get("alt_labels", ""), "|", o.get("caption", ""))
else:
    for k, v in d.items():
        try:
            cap = json.loads(v["caption"])
        except Exception:
            cap = {"captions": v["caption"]}
        extra = {a: b for a, b in cap.items() if a not in ("category", "room_cat", "room_id", "captions")}
        print(k, v["category"], "|", v["room_cat"], v["room_id"], extra, "|", cap.get("captions"))
