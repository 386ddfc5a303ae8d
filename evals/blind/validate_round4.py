import json, os, re, collections, sys
B = os.path.dirname(os.path.abspath(__file__))
rows = [json.loads(l) for l in open(os.path.join(B, "round4.jsonl"))]
def load(m):
    d = json.load(open(os.path.normpath(os.path.join(B, m))))
    if "objects" in d:
        return {int(o["id"]): o["label"] for o in d["objects"]}
    return {int(k): v["category"] for k, v in d.items()}
maps = {}
ids = set(); errs = []
groups = collections.defaultdict(list)
for r in rows:
    for k in ("id", "map", "query", "type", "target", "accept", "group"):
        if k not in r: errs.append(f"{r.get('id')}: missing {k}")
    if r["id"] in ids: errs.append("dup id " + r["id"])
    ids.add(r["id"])
    if r["map"] not in maps: maps[r["map"]] = load(r["map"])
    objs = maps[r["map"]]
    if r["target"] not in objs: errs.append(f"{r['id']}: target {r['target']} not in map")
    if r["target"] not in r["accept"]: errs.append(f"{r['id']}: target not in accept")
    for a in r["accept"]:
        if a not in objs: errs.append(f"{r['id']}: accept {a} not in map")
    if r["type"] not in {"o", "or", "od", "ord", "ard", "s"}: errs.append(r["id"] + " bad type")
    if r["type"] == "s" and "iesm_maps" in r["map"]: errs.append(r["id"] + " spatial on HM3D map")
    groups[r["group"]].append(r)
qs = collections.Counter(r["query"].strip().lower() for r in rows)
for q, c in qs.items():
    if c > 1: errs.append(f"duplicate query text x{c}: {q}")
for gname, rs in groups.items():
    if len(rs) != 6: errs.append(f"{gname}: {len(rs)} lines")
    if len({(r["type"], r["map"], r["target"], tuple(sorted(r["accept"]))) for r in rs}) != 1:
        errs.append(f"{gname}: inconsistent type/map/target/accept")
    # exact map label of the target used in at most 2 wordings
    lab = maps[rs[0]["map"]][rs[0]["target"]].lower()
    n = sum(1 for r in rs if re.search(r"\b" + re.escape(lab) + r"\b", r["query"].lower()))
    if n > 2: errs.append(f"{gname}: label '{lab}' used in {n} wordings")
print("lines", len(rows), "groups", len(groups))
print("type groups", collections.Counter(rs[0]["type"] for rs in groups.values()))
print("map groups", collections.Counter(os.path.basename(rs[0]["map"]) for rs in groups.values()))
print("\n".join(errs) if errs else "OK: no errors")
sys.exit(1 if errs else 0)
