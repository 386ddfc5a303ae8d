"""Print a map compactly: python3 show.py PATH"""
import json, sys

def load(path):
    d = json.load(open(path))
    if isinstance(d, dict) and "objects" in d:
        return d, True
    return d, False

def caption_text(v):
    c = v.get("caption", "")
    try:
        j = json.loads(c)
        return j.get("captions", c), j.get("color"), j.get("material")
    except Exception:
        return c, None, None

def main(path):
    d, geo = load(path)
    if geo:
        for r in d.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in d["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(o["id"], o["label"], "| c", c, "s", s, "|", o.get("room"), "|", o.get("tags"), "|", o.get("caption", ""))
    else:
        for k, v in sorted(d.items(), key=lambda kv: int(kv[0])):
            cap, col, mat = caption_text(v)
            print(k, v["category"], "|", v["room_cat"], v["room_id"], "|", col, mat, "|", cap)

if __name__ == "__main__":
    main(sys.argv[1])
