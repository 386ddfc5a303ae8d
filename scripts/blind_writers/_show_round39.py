"""Print a map compactly: python3 show.py <map path>"""
import json, sys
from pathlib import Path

def load(path):
    d = json.loads(Path(path).read_text())
    if isinstance(d, dict) and "objects" in d:
        return d
    objs = []
    for k, v in d.items():
        cap = v.get("caption", "")
        try:
            c = json.loads(cap); cap = f"[{c.get('color','')}/{c.get('material','')}] {c.get('captions','')}"
        except Exception:
            pass
        objs.append({"id": int(k), "label": v["category"], "room": f"{v['room_cat']}#{v['room_id']}", "caption": cap})
    return {"objects": objs}

if __name__ == "__main__":
    d = load(sys.argv[1])
    for r in d.get("rooms", []):
        print("ROOM", r["id"], r["label"], r["polygon"])
    for o in sorted(d["objects"], key=lambda o: (o["label"], o["id"])):
        geo = ""
        if "center" in o:
            geo = " c=" + ",".join(f"{x:.2f}" for x in o["center"]) + " s=" + ",".join(f"{x:.2f}" for x in o["size"])
        tags = o.get("tags", "")
        print(f"{o['id']:4d} {o['label']:<18} {o.get('room','')}{geo} {tags if tags else ''} | {o.get('caption','')}")
