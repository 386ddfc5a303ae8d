"""Print a map compactly: python3 show.py PATH"""
import json, sys

def load(path):
    d = json.load(open(path))
    return d

def main(path):
    d = load(path)
    if isinstance(d, dict) and "objects" in d:
        print(d.get("scene_id"), d.get("comment", ""))
        for r in d.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in d["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(o["id"], "|", o["label"], "|", o.get("room"), "| c", c, "s", s, "|", o.get("tags"), "|", o.get("caption", ""))
    else:
        for k, v in d.items():
            cap = v.get("caption", "")
            try:
                cj = json.loads(cap); cap = f"{cj.get('color')}/{cj.get('material')}: {cj.get('captions')}"
            except Exception:
                pass
            print(k, "|", v["category"], "|", v["room_cat"], v["room_id"], "|", cap)

if __name__ == "__main__":
    main(sys.argv[1])
