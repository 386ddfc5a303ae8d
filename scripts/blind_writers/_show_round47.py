"""Print a map compactly: caption maps (id, category, room, colour/material, caption) or object maps
(id, label, room, centre, size, tags, caption).  python3 show.py PATH"""
import json
import re
import sys


def caption_text(raw):
    try:
        c = json.loads(re.sub(r",\s*}", "}", raw))
        return c.get("color", ""), c.get("material", ""), c.get("captions", "")
    except Exception:
        return "", "", raw


def main(path):
    data = json.load(open(path))
    if isinstance(data, dict) and "objects" in data:
        for r in data.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in data["objects"]:
            c = [round(v, 2) for v in o["center"]]
            s = [round(v, 2) for v in o["size"]]
            print(o["id"], "|", o["label"], "|", o.get("alt_labels", ""), "|", o.get("room"), "| c", c, "s", s,
                  "|", o.get("tags", {}), "|", o.get("caption", ""))
    else:
        for k, v in sorted(data.items(), key=lambda kv: int(kv[0])):
            col, mat, cap = caption_text(v["caption"])
            print(k, "|", v["category"], "|", v["room_cat"], v["room_id"], "|", col, "|", mat, "|", cap)


if __name__ == "__main__":
    main(sys.argv[1])
