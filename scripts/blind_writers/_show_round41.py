"""Print a map compactly: python3 show.py PATH"""
import json, re, sys

def cap_text(v):
    c = v.get("caption", "")
    m = re.search(r'"captions"\s*:\s*"(.*?)"\s*,?\s*\n', c)
    return m.group(1) if m else c

def field(v, name):
    m = re.search(r'"%s"\s*:\s*"(.*?)"' % name, v.get("caption", ""))
    return m.group(1) if m else ""

d = json.load(open(sys.argv[1]))
if isinstance(d, dict) and "objects" in d:
    for r in d.get("rooms", []):
        print("ROOM", r["id"], r["label"], r.get("polygon"))
    for o in d["objects"]:
        c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
        print(o["id"], "|", o["label"], "|", o.get("room"), "|", c, s, "|", o.get("tags"), "|", o.get("caption"))
else:
    for k, v in sorted(d.items(), key=lambda kv: int(kv[0])):
        print(k, "|", v.get("category"), "|", v.get("room_cat"), v.get("room_id"), "|", field(v, "color"), "|", field(v, "material"), "|", cap_text(v))
