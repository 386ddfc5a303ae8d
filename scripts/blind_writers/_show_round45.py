"""Print a map compactly: python3 show.py PATH"""
import json, re, sys


def cap_fields(s):
    out = {}
    for k in ("color", "material", "captions"):
        m = re.search(r'"%s"\s*:\s*"((?:[^"\\]|\\.)*)"' % k, s or "")
        out[k] = m.group(1) if m else ""
    return out


def main():
    p = sys.argv[1]
    d = json.load(open(p))
    if isinstance(d, dict) and "objects" in d:
        for r in d.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in d["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(o["id"], o["label"], "|", o.get("room"), "| c", c, "s", s, "|", json.dumps(o.get("tags", {})), "|", o.get("caption", ""))
    else:
        for k, v in d.items():
            f = cap_fields(v.get("caption"))
            print(k, v["category"], "|", v.get("room_cat"), v.get("room_id"), "|", f["color"], "/", f["material"], "|", f["captions"])


if __name__ == "__main__":
    main()
