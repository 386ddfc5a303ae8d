"""Validate round5.jsonl (blind helper)."""
import json, os, re, collections
BASE = os.path.dirname(os.path.abspath(__file__))
rows = [json.loads(l) for l in open(os.path.join(BASE, "round5.jsonl"))]
def load(m):
    d = json.load(open(os.path.normpath(os.path.join(BASE, m))))
    if "objects" in d:
        return {int(o["id"]): o["label"] for o in d["objects"]}, True
    return {int(k): v["category"] for k, v in d.items()}, False
maps = {}
ids = set(); groups = collections.defaultdict(list); err = 0
for r in rows:
    assert set(r) == {"id", "map", "query", "type", "target", "accept", "group"}, r
    assert r["id"] not in ids, r["id"]; ids.add(r["id"])
    if r["map"] not in maps: maps[r["map"]] = load(r["map"])
    labels, geo = maps[r["map"]]
    assert isinstance(r["target"], int) and r["target"] in labels, r
    assert r["target"] in r["accept"], r
    for a in r["accept"]: assert a in labels, (r["id"], a)
    assert r["type"] in {"o", "or", "od", "ord", "ard", "s"}
    if r["type"] == "s": assert geo, r["id"]
    groups[r["group"]].append(r)
tc = collections.Counter(); mc = collections.Counter()
for gname, rs in groups.items():
    assert len(rs) == 6, gname
    assert len({(r["type"], r["map"], tuple(r["accept"]), r["target"]) for r in rs}) == 1, gname
    assert len({r["query"].lower() for r in rs}) == 6, gname
    labels, _ = maps[rs[0]["map"]]
    labs = {labels[a].lower() for a in rs[0]["accept"]}
    n = sum(any(re.search(r"\b" + re.escape(l) + r"(s|es)?\b", r["query"].lower()) for l in labs) for r in rs)
    if n > 2: print("LABEL-USE", gname, n, labs); err += 1
    tc[rs[0]["type"]] += 1; mc[os.path.basename(rs[0]["map"])] += 1
print("lines", len(rows), "groups", len(groups))
print("types", dict(tc)); print("maps", dict(mc))
assert len(rows) == 288 and len(groups) == 48 and all(v == 8 for v in tc.values())
hm = mc["scene_00829_caption.json"] + mc["scene_office3_caption.json"]
assert hm >= 14 and mc["apartment.json"] >= 8, (hm, mc)
print("OK" if not err else f"{err} label warnings")
