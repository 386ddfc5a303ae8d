"""Sanity checks for round1.jsonl (blind paraphrase suite). Reads only the suite and its map JSON files."""
import json, os, re, sys
from collections import Counter, defaultdict

HERE = os.path.dirname(os.path.abspath(__file__))
SUITE = os.path.join(HERE, "round1.jsonl")

def load_map(path):
    d = json.load(open(path))
    if isinstance(d, dict) and "objects" in d:
        return {int(o["id"]): o["label"] for o in d["objects"]}
    return {int(k): v["category"] for k, v in d.items()}

maps, rows, errors = {}, [], []
for n, line in enumerate(open(SUITE), 1):
    try:
        rows.append(json.loads(line))
    except Exception as e:
        errors.append(f"line {n}: does not parse: {e}")
need = {"id", "map", "query", "type", "target", "accept", "group"}
ids = Counter(r["id"] for r in rows)
errors += [f"duplicate id {i}" for i, c in ids.items() if c > 1]
groups = defaultdict(list)
for r in rows:
    if set(r) != need:
        errors.append(f"{r.get('id')}: fields {sorted(r)}")
    p = os.path.normpath(os.path.join(HERE, r["map"]))
    if p not in maps:
        if not os.path.exists(p):
            errors.append(f"{r['id']}: map missing {p}"); continue
        maps[p] = load_map(p)
    m = maps[p]
    if not isinstance(r["target"], int) or r["target"] not in m:
        errors.append(f"{r['id']}: target {r['target']} not in map")
    if r["target"] not in r["accept"]:
        errors.append(f"{r['id']}: target not in accept")
    for a in r["accept"]:
        if not isinstance(a, int) or a not in m:
            errors.append(f"{r['id']}: accept id {a} not in map")
    groups[r["group"]].append(r)

type_g, map_g = Counter(), Counter()
for g, rs in groups.items():
    if len(rs) != 6:
        errors.append(f"group {g}: {len(rs)} lines")
    if len({(r['type'], r['map'], r['target'], tuple(r['accept'])) for r in rs}) != 1:
        errors.append(f"group {g}: type/map/target/accept differ inside the group")
    if len({r['query'].lower() for r in rs}) != len(rs):
        errors.append(f"group {g}: repeated wording")
    type_g[rs[0]["type"]] += 1
    map_g[os.path.basename(rs[0]["map"])] += 1
    # at most 2 of 6 wordings may contain a raw map label of an accepted instance verbatim
    m = maps[os.path.normpath(os.path.join(HERE, rs[0]["map"]))]
    labels = {m[a].lower() for a in rs[0]["accept"]}
    hits = sum(any(re.search(r"\b" + re.escape(l) + r"(s|es)?\b", r["query"].lower()) for l in labels) for r in rs)
    if hits > 2:
        errors.append(f"group {g}: {hits}/6 wordings use the raw label {sorted(labels)}")

print(f"{len(rows)} lines, {len(groups)} groups")
print("groups per type:", dict(type_g))
print("groups per map:", dict(map_g))
hm3d = map_g["scene_00829_caption.json"] + map_g["scene_office3_caption.json"]
print("HM3D groups:", hm3d)
if hm3d < 12: errors.append("fewer than 12 HM3D groups")
if map_g["apartment.json"] < 8: errors.append("fewer than 8 apartment groups")
if any(type_g[t] != 8 for t in ["o", "or", "od", "ord", "ard", "s"]): errors.append(f"type counts {dict(type_g)}")
for e in errors: print("ERROR", e)
sys.exit(1 if errors else 0)
