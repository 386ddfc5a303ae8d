"""Print a map compactly: object maps (id label room center size tags caption) or caption maps."""
import json, sys
from pathlib import Path
p = Path(sys.argv[1])
d = json.loads(p.read_text())
if isinstance(d, dict) and "objects" in d:
    for r in d.get("rooms", []):
        print("ROOM", r["id"], r["label"], r.get("polygon"))
    for o in d["objects"]:
        c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
        print(o["id"], "|", o["label"], "|", o.get("room"), "|", c, s, "|", o.get("tags"), "|", o.get("alt_labels", ""), "|", o.get("caption", ""))
else:
    for k, v in d.items():
        cap = v["caption"]
        try:
            cj = json.loads(cap); cap = f"[{cj.get('color')}/{cj.get('material')}] {cj.get('captions')}"
        except Exception:
            pass
        print(k, "|", v["category"], "|", v["room_cat"], v["room_id"], "|", cap)
