"""Print a map compactly: python3 show.py PATH"""
import json, sys

def caption_text(c):
    try:
        d = json.loads(c)
        return f"[{d.get('color','')}/{d.get('material','')}] {d.get('captions','')}"
    except Exception:
        return c

def main(p):
    data = json.load(open(p))
    if isinstance(data, dict) and "objects" in data:
        for r in data.get("rooms", []):
            print("ROOM", r["id"], r["label"], r.get("polygon"))
        for o in data["objects"]:
            c = o["center"]; s = o["size"]
            print(f'{o["id"]:3d} {o["label"]:<16} c=({c[0]:.2f},{c[1]:.2f},{c[2]:.2f}) s=({s[0]:.2f},{s[1]:.2f},{s[2]:.2f}) '
                  f'{o.get("room","")} | {o.get("tags",{})} | {o.get("alt_labels","")} | {o.get("caption","")}')
    else:
        for k, v in sorted(data.items(), key=lambda kv: (kv[1]["room_id"] if kv[1]["room_id"] is not None else -1, kv[1]["category"], int(kv[0]))):
            print(f'{int(k):4d} {v["category"]:<18} r{v["room_id"]} {str(v["room_cat"]):<14} {caption_text(v["caption"])}')

if __name__ == "__main__":
    main(sys.argv[1])
