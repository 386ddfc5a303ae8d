import json, os, collections
B = os.path.dirname(os.path.abspath(__file__))
def ids_of(p):
    d = json.load(open(os.path.join(B, p)))
    if isinstance(d, dict) and "objects" in d:
        return {int(o["id"]) for o in d["objects"]}
    return {int(k) for k in d}
rows = [json.loads(l) for l in open(os.path.join(B, "round2.jsonl"))]
assert len({r["id"] for r in rows}) == len(rows), "dup ids"
cache = {}
groups = collections.defaultdict(list)
for r in rows:
    for k in ("id","map","query","type","target","accept","group"): assert k in r, (r, k)
    ids = cache.setdefault(r["map"], ids_of(r["map"]))
    assert isinstance(r["target"], int) and r["target"] in ids, r
    assert all(isinstance(a, int) and a in ids for a in r["accept"]) and r["target"] in r["accept"], r
    groups[r["group"]].append(r)
for g, rs in groups.items():
    assert len(rs) == 6, g
    assert len({(r["type"], r["map"], tuple(sorted(r["accept"])), r["target"]) for r in rs}) == 1, g
    assert len({r["query"].lower() for r in rs}) == 6, g
geo = ("map_store/apartment.json", "evals/maps/", "maps/flat_c.json", "../maps/")
for g, rs in groups.items():
    if rs[0]["type"] == "s": assert not rs[0]["map"].endswith("_caption.json"), g
tc = collections.Counter(rs[0]["type"] for rs in groups.values())
mc = collections.Counter(os.path.basename(rs[0]["map"]) for rs in groups.values())
print("lines", len(rows), "groups", len(groups))
print("groups per type", dict(tc))
print("groups per map", dict(mc))
assert len(rows) == 252 and len(groups) == 42 and all(v == 7 for v in tc.values()) and len(tc) == 6
print("OK")
