"""Print a map compactly: python3 show.py PATH [--full]"""
import json, sys

def load(path):
    d = json.load(open(path))
    return d

def main():
    path = sys.argv[1]
    d = load(path)
    if isinstance(d, dict) and "objects" in d:
        for r in d.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in d["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(f'{o["id"]:>3} {o["label"]:<16} c={c} s={s} room={o.get("room")} tags={o.get("tags")} alt={o.get("alt_labels","")}')
            if o.get("caption"):
                print("      ", o["caption"])
    else:
        for k, v in d.items():
            cap = v["caption"]
            try:
                cj = json.loads(cap)
                cap = f'[{cj.get("color")}|{cj.get("material")}] {cj.get("captions")}'
            except Exception:
                pass
            print(f'{k:>4} {v["category"]:<20} {v["room_cat"]}#{v["room_id"]}: {cap}')

main()
