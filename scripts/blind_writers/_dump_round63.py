import json
import sys
p=sys.argv[1]
d=json.load(open(p))
if isinstance(d,dict) and "objects" in d:
    for r in d.get("rooms",[]):
        print("ROOM",r["id"],r["label"],r["polygon"])
    for o in d["objects"]:
        extra={k:v for k,v in o.items() if k not in("id","label","center","size","room","tags","caption")}
        print(o["id"],o["label"],o["center"],o["size"],o.get("room"),o.get("tags"),extra or "")
        if o.get("caption"):
            print("    C:",o["caption"])
else:
    for k,v in d.items():
        c=v["caption"]
        try:
            cj=json.loads(c)
            s=f'{cj.get("color")} | {cj.get("material")} | {cj.get("captions")}'
        except Exception:
            s=c
        print(k,v["category"],"|",v.get("room_cat"),v.get("room_id"),"|",s)
