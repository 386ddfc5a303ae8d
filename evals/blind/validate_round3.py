import json, os, re, collections, sys
BASE = os.path.dirname(os.path.abspath(__file__))
def ids_of(path):
    d = json.load(open(os.path.join(BASE, path)))
    if "objects" in d:
        return {int(o["id"]): o["label"] for o in d["objects"]}
    return {int(k): v["category"] for k, v in d.items()}
GEOM = ("map_store/apartment.json", "scan_", "flat_d.json")
rows = [json.loads(l) for l in open(os.path.join(BASE, "round3.jsonl"))]
errs = []
ids = [r["id"] for r in rows]
if len(ids) != len(set(ids)): errs.append("duplicate ids")
cache = {}
groups = collections.defaultdict(list)
for r in rows:
    for k in ("id", "map", "query", "type", "target", "accept", "group"):
        if k not in r: errs.append(f"{r.get('id')}: missing {k}")
    if r["map"] not in cache: cache[r["map"]] = ids_of(r["map"])
    m = cache[r["map"]]
    if r["target"] not in m: errs.append(f"{r['id']}: target {r['target']} not in map")
    if r["target"] not in r["accept"]: errs.append(f"{r['id']}: target not in accept")
    for a in r["accept"]:
        if a not in m: errs.append(f"{r['id']}: accept {a} not in map")
    if r["type"] == "s" and not any(g in r["map"] for g in GEOM): errs.append(f"{r['id']}: spatial on map without geometry")
    groups[r["group"]].append(r)
tc = collections.Counter(); mc = collections.Counter()
for g, rs in groups.items():
    if len(rs) != 6: errs.append(f"{g}: {len(rs)} lines")
    for k in ("type", "map", "target"):
        if len({json.dumps(r[k]) for r in rs}) != 1: errs.append(f"{g}: mixed {k}")
    if len({json.dumps(sorted(r["accept"])) for r in rs}) != 1: errs.append(f"{g}: mixed accept")
    if len({r["query"].lower() for r in rs}) != 6: errs.append(f"{g}: duplicate wording")
    tc[rs[0]["type"]] += 1; mc[os.path.basename(rs[0]["map"])] += 1
    lab = cache[rs[0]["map"]][rs[0]["target"]].lower()
    n = sum(1 for r in rs if re.search(r"\b" + re.escape(lab) + r"s?\b", r["query"].lower()))
    if n > 2: errs.append(f"{g}: exact label '{lab}' used in {n} wordings")
print("lines", len(rows), "groups", len(groups))
print("types", dict(tc)); print("maps", dict(mc))
hm = mc["scene_00829_caption.json"] + mc["scene_office3_caption.json"]
print("HM3D groups", hm, "apartment", mc["apartment.json"])
if any(v != 8 for v in tc.values()) or len(tc) != 6: errs.append("type counts not 8 each")
if hm < 14: errs.append("too few HM3D groups")
if mc["apartment.json"] < 8: errs.append("too few apartment groups")
print("\n".join(errs) if errs else "OK")
sys.exit(1 if errs else 0)
