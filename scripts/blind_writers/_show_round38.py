"""Print a map compactly: python3 show.py PATH  (object list with geometry or caption dictionary)."""
import json, sys

def caption_text(v):
    c = v.get("caption", "")
    try:
        d = json.loads(c)
        return f"color={d.get('color')} mat={d.get('material')} :: {d.get('captions')}"
    except Exception:
        return c

def main(path):
    data = json.load(open(path))
    if isinstance(data, dict) and "objects" in data:
        for r in data.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in data["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(f'{o["id"]:3d} {o["label"]:18s} c={c} s={s} room={o.get("room")} tags={o.get("tags")} alt={o.get("alt_labels","")}')
            if o.get("caption"):
                print("      ", o["caption"])
    else:
        for k, v in sorted(data.items(), key=lambda kv: (kv[1]["room_id"] if kv[1]["room_id"] is not None else -1, int(kv[0]))):
            print(f'{k:>4s} {v["category"]:16s} room={v["room_id"]}:{v["room_cat"]} | {caption_text(v)}')

if __name__ == "__main__":
    main(sys.argv[1])
