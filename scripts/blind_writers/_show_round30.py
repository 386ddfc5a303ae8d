"""Print a map (object list with geometry, or caption dictionary) compactly.
    python3 scripts/show.py PATH [--captions]"""
import json, re, sys


def cap_text(v):
    """The description sentence inside a caption-map entry's raw caption string."""
    c = str(v.get("caption", ""))
    m = re.search(r'"captions"\s*:\s*"(.*?)"\s*,?\s*\n', c)
    return m.group(1) if m else c


def cap_field(v, name):
    m = re.search(r'"%s"\s*:\s*"(.*?)"' % name, str(v.get("caption", "")))
    return m.group(1) if m else ""


if __name__ == "__main__":
    p = sys.argv[1]; caps = "--captions" in sys.argv
    d = json.load(open(p))
    if isinstance(d, dict) and "objects" in d:
        for r in d.get("rooms", []):
            print("ROOM", r.get("id"), r.get("label"), r.get("polygon"))
        for o in sorted(d["objects"], key=lambda o: (str(o.get("room")), o["label"])):
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(o["id"], o["label"], "room=%s" % o.get("room"), "c=%s" % c, "s=%s" % s,
                  "tags=%s" % o.get("tags", ""), ("| " + str(o.get("caption", ""))) if caps else "")
    else:
        for k, v in sorted(d.items(), key=lambda kv: (str(kv[1].get("room_cat")), str(kv[1].get("room_id")), kv[1]["category"])):
            print(k, v["category"], "|", v.get("room_cat"), v.get("room_id"), "|", cap_field(v, "color"), "/",
                  cap_field(v, "material"), ("| " + cap_text(v)) if caps else "")
