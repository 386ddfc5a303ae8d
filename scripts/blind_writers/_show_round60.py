"""Print a map compactly: python3 show.py <path>"""
import json
import sys
p = sys.argv[1]
d = json.load(open(p))
if isinstance(d, dict) and "objects" in d:
    print(d.get("comment", ""))
    print("rooms:", json.dumps(d.get("rooms"))[:2000])
    for o in d["objects"]:
        c = [round(v, 2) for v in o["center"]]
        s = [round(v, 2) for v in o["size"]]
        print(f'{o["id"]:3d} {o["label"]:<18} {o.get("room","")!s:<14} c={c} s={s} alt={o.get("alt_labels","")} tags={o.get("tags",{})}')
        if o.get("caption"):
            print("      ", o["caption"])
else:
    for k, v in d.items():
        try:
            cap = json.loads(v["caption"])
        except Exception:
            cap = {"captions": v["caption"]}
        extra = {kk: vv for kk, vv in cap.items() if kk not in ("category", "room_cat", "captions")}
        print(f'{k:>4} {v["category"]:<20} room={v.get("room_cat")}#{v.get("room_id")} {extra}')
        print("      ", cap.get("captions"))
