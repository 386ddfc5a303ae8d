"""Print a map compactly: python3 show.py PATH"""
import json
import sys
p = sys.argv[1]
d = json.load(open(p))
if isinstance(d, dict) and "objects" in d:
    print("COMMENT:", d.get("comment"))
    for r in d["rooms"]:
        print("ROOM", r["id"], r["label"], r["polygon"])
    for o in d["objects"]:
        c = [round(v, 2) for v in o["center"]]
        s = [round(v, 2) for v in o["size"]]
        alt = o.get("alt_labels")
        print(f'{o["id"]:>3} {o["label"]!r} alt={alt} room={o["room"]} c={c} s={s}')
        print("     tags:", json.dumps(o.get("tags")))
        if o.get("caption"):
            print("     cap:", o["caption"])
else:
    for k, v in d.items():
        cap = v["caption"]
        try:
            cj = json.loads(cap)
            cap = json.dumps({a: b for a, b in cj.items() if a not in ("category", "room_cat", "room_id")})
        except Exception:
            pass
        print(f'{k:>4} {v["category"]!r} room={v["room_cat"]}/{v["room_id"]} top5={v.get("top5_categories")}')
        print("      cap:", cap)
