import json
import re
from pathlib import Path
BLIND = Path(__file__).resolve().parents[2] / "evals/blind"
ROOT = Path(__file__).resolve().parents[2]

def map_path(m):
    p = (BLIND / m).resolve()
    if not p.is_file() and "/" not in m:
        p = ROOT / "map_store" / f"{m}.json"
    return p

def load(m):
    """list of dicts: id,label,room,text,center,size (None for caption maps), captions list"""
    d = json.loads(map_path(m).read_text())
    objs = []
    if isinstance(d, dict) and "objects" in d:
        rooms = {r["id"]: r["label"] for r in d.get("rooms", [])}
        for o in d["objects"]:
            room = o.get("room")
            if isinstance(room, int) or (isinstance(room, str) and room.isdigit()):
                room = rooms[int(room)]
            tags = o.get("tags") or {}
            text = " ".join([o["label"], o.get("caption", "")] + [str(v) for v in tags.values()])
            objs.append(dict(id=o["id"], label=o["label"], room=room, text=text.lower(),
                             center=o["center"], size=o["size"], caption=o.get("caption", "")))
    else:
        for k, v in d.items():
            cap = v["caption"]
            try:
                cj = json.loads(cap)
            except Exception:
                try:
                    cj = json.loads(re.sub(r",\s*}", "}", cap))
                except Exception:
                    cj = {"captions": cap}
            text = " ".join(str(cj.get(x, "")) for x in ("category", "color", "material", "captions"))
            objs.append(dict(id=int(k), label=v["category"], room=v.get("room_cat"), text=text.lower(),
                             center=None, size=None, caption=str(cj.get("captions", cap))))
    return objs

def words(s):
    return re.findall(r"[a-z0-9]+", s.lower())
