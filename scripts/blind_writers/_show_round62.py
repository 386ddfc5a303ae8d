"""Print a map compactly: objects (id, label, room, centre, size, tags, caption) or caption dict."""
import json
import sys
p = sys.argv[1]
d = json.load(open(p))
if isinstance(d, dict) and "objects" in d:
    for r in d.get("rooms", []):
        print("ROOM", r["id"], r["label"], r["polygon"])
    for o in d["objects"]:
        c = [round(v, 2) for v in o["center"]]
        s = [round(v, 2) for v in o["size"]]
        print(o["id"], "|", o["label"], "|", o.get("alt_labels", ""), "|", o.get("room"), "|", c, s, "|", o.get("tags"), "|", o.get("caption", ""))
else:
    for k, v in sorted(d.items(), key=lambda kv: int(kv[0])):
        try:
            cap = json.loads(v["caption"])
        except Exception:
            cap = {"captions": v["caption"]}
        print(k, "|", v["category"], "|", v["room_cat"], v["room_id"], "|", cap.get("color"), "|", cap.get("material"), "|", cap.get("captions"))
