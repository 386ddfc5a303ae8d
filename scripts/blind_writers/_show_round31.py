"""Print a map (caption dict or object list) compactly: python3 show.py MAPPATH"""
import json, sys

def main(p):
    d = json.load(open(p))
    if isinstance(d, dict) and "objects" in d:
        for r in d.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in d["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(o["id"], o["label"], "|", o.get("room"), "| c", c, "s", s, "|", o.get("tags", {}),
                  "|", o.get("alt_labels", ""), "|", o.get("caption", ""))
    else:
        for k, v in d.items():
            try:
                cap = json.loads(v["caption"])
            except Exception:
                cap = {"captions": v["caption"]}
            print(k, v["category"], "|", v["room_cat"], v["room_id"], "|", cap.get("color"), cap.get("material"),
                  "|", cap.get("captions"))

if __name__ == "__main__":
    main(sys.argv[1])
