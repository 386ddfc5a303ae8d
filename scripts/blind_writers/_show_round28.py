import json,sys
p=sys.argv[1]
d=json.load(open(p))
if isinstance(d,dict) and "objects" in d:
    for r in d.get("rooms",[]): print("ROOM",r["id"],r["label"],r.get("polygon"))
    for o in d["objects"]:
        c=o["center"]; s=o["size"]
        print(o["id"],"|",o["label"],"|",o.get("room"),"| c",[round(v,2) for v in c],"s",[round(v,2) for v in s],"|",o.get("tags",""),"|",o.get("alt_labels",""),"|",o.get("caption",""))
else:
    for k,v in d.items():
        cap=v["caption"]
        try:
            cj=json.loads(cap); cap="%s/%s: %s"%(cj.get("color"),cj.get("material"),cj.get("captions"))
        except Exception: pass
        print(k,"|",v["category"],"|",v["room_cat"],v["room_id"],"|",cap)
