"""Print a map compactly: python3 show.py PATH"""
import json, sys

def load(path):
    d = json.load(open(path))
    return d

def main(path):
    d = load(path)
    if isinstance(d, dict) and "objects" in d:
        for r in d.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in d["objects"]:
            c = [round(v, 2) for v in o["center"]]; s = [round(v, 2) for v in o["size"]]
            print(o["id"], o["label"], o.get("alt_labels", ""), c, s, o.get("room"), o.get("tags", {}), "|", o.get("caption", ""))
    else:
        for k, v in sorted(d.items(), key=lambda kv: int(kv[0])):
            try:
                cap = json.loads(v["caption"])
                txt = f'{cap.get("color")} / {cap.get("material")} | {cap.get("captions")}'
            except Exception:
                txt = v["caption"]
            print(k, v["category"], "|", v["room_cat"], v["room_id"], "|", txt)

if __name__ == "__main__":
    main(sys.argv[1])
