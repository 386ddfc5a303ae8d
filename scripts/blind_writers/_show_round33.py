"""Print a map compactly: python3 show.py <map path>"""
import json, sys

def caption_text(c):
    try:
        d = json.loads(c)
        return d.get("captions", c), d.get("color", ""), d.get("material", "")
    except Exception:
        return c, "", ""

def main(p):
    data = json.load(open(p))
    if isinstance(data, dict) and "objects" in data:
        for r in data.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in data["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(o["id"], "|", o["label"], o.get("alt_labels", ""), "|", o.get("room"), "| c", c, "s", s,
                  "|", o.get("tags", {}), "|", o.get("caption", ""))
    else:
        for k, v in data.items():
            cap, col, mat = caption_text(v["caption"])
            print(k, "|", v["category"], "|", v["room_cat"], v["room_id"], "|", col, "/", mat, "|", cap)

if __name__ == "__main__":
    main(sys.argv[1])
