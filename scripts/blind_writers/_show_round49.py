"""Print a map compactly: python3 show.py PATH"""
import json, sys

def parse_cap(c):
    try:
        d = json.loads(c)
        return d
    except Exception:
        return {"captions": c}

def main(p):
    d = json.load(open(p))
    if isinstance(d, dict) and "objects" in d:
        for r in d.get("rooms", []):
            print("ROOM", r["id"], r["label"], r["polygon"])
        for o in d["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            alt = o.get("alt_labels", "")
            print(f'{o["id"]:3d} {o["label"]:18s} c={c} s={s} room={o.get("room")} tags={o.get("tags")} alt={alt}')
            if o.get("caption"):
                print("      ", o["caption"])
    else:
        for k, v in d.items():
            cap = parse_cap(v["caption"])
            print(f'{k:>4} {v["category"]:16s} room={v["room_cat"]}#{v["room_id"]} color={cap.get("color")} mat={cap.get("material")}')
            print("      ", cap.get("captions"))

if __name__ == "__main__":
    main(sys.argv[1])
