"""Print a map compactly: python3 show.py <map path>"""
import json, sys

def caption_text(v):
    c = v.get("caption", "")
    try:
        d = json.loads(c)
        return f"{d.get('color','')}/{d.get('material','')} :: {d.get('captions','')}"
    except Exception:
        return c

def main(p):
    data = json.load(open(p))
    if isinstance(data, dict) and "objects" in data:
        for r in data.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in data["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(o["id"], o["label"], "|", o.get("room"), c, s, o.get("tags", {}), "|", o.get("caption", ""))
    else:
        for k, v in sorted(data.items(), key=lambda kv: (kv[1]["room_id"] if kv[1]["room_id"] is not None else -1, kv[1]["category"], int(kv[0]))):
            print(k, v["category"], "|", v["room_cat"], v["room_id"], "|", caption_text(v))

if __name__ == "__main__":
    main(sys.argv[1])
