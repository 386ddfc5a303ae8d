import json
import sys
p = sys.argv[1]
d = json.load(open(p))
if isinstance(d, dict) and "objects" in d:
    print("ROOMS:", [(r["label"], r["polygon"]) for r in d.get("rooms", [])])
    for o in d["objects"]:
        extra = {k: v for k, v in o.items() if k not in ("id","label","center","size","room","tags","caption")}
        print(o["id"], o["label"], "c=", o["center"], "s=", o["size"], "|", o.get("room"), "|", o.get("tags"), "|", o.get("caption",""), "|", extra if extra else "")
else:
    for k, v in d.items():
        try:
            c = json.loads(v["caption"])
        except Exception:
            c = {"captions": v["caption"]}
        print(k, v["category"], "|", v.get("room_cat"), v.get("room_id"), "|", c.get("color"), "|", c.get("material"), "|", c.get("captions"))
