"""Print a map compactly: object maps (id label center size room tags caption) or caption maps."""
import json, sys
from pathlib import Path

def show(path):
    data = json.loads(Path(path).read_text())
    if isinstance(data, dict) and "objects" in data:
        for r in data.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in data["objects"]:
            c = ",".join(f"{v:.2f}" for v in o["center"]); s = ",".join(f"{v:.2f}" for v in o["size"])
            print(f'{o["id"]:>3} {o["label"]:<16} c=[{c}] s=[{s}] {o.get("room","")} {o.get("tags",{})} {o.get("alt_labels","")} | {o.get("caption","")}')
    else:
        for k, v in data.items():
            cap = v.get("caption", "")
            try:
                cj = json.loads(cap); cap = f'[{cj.get("color")}/{cj.get("material")}] {cj.get("captions")}'
            except Exception:
                pass
            print(f'{k:>4} {v["category"]:<16} {v["room_cat"]}#{v["room_id"]} | {cap}')

if __name__ == "__main__":
    for p in sys.argv[1:]:
        print("=====", p); show(p)
