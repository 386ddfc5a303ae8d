"""Print a map compactly: python3 show.py PATH"""
import json, re, sys

def cap_fields(v):
    """Parse a caption-map entry's caption (a JSON-ish string) into a dict."""
    c = v.get("caption")
    if isinstance(c, dict):
        return c
    out = {}
    for key in ("color", "material", "captions"):
        m = re.search(r'"%s"\s*:\s*"([^"]*)"' % key, c or "")
        out[key] = m.group(1) if m else ""
    return out

if __name__ == "__main__":
    d = json.load(open(sys.argv[1]))
    if isinstance(d, dict) and "objects" in d:
        for r in d.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in d["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(o["id"], o["label"], c, s, o.get("room"), o.get("tags", ""), "|", o.get("caption", ""))
    else:
        for k, v in d.items():
            f = cap_fields(v)
            print(k, "|", v["category"], "|", v.get("room_cat"), v.get("room_id"), "|", f["color"], "|", f["material"], "|", f["captions"])
