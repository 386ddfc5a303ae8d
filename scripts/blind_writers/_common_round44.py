"""Shared map loading for check.py and copycheck.py."""
import json
from pathlib import Path

BLIND = Path(__file__).resolve().parents[2] / "evals" / "blind"


def load_map(name):
    p = (BLIND / name).resolve()
    d = json.loads(p.read_text(encoding="utf-8"))
    if isinstance(d, dict) and "objects" in d:
        return {"geo": True, "objs": {int(o["id"]): o for o in d["objects"]}}
    objs = {}
    for k, v in d.items():
        cap = v.get("caption") or ""
        try:
            cap = json.loads(cap).get("captions", cap)
        except Exception:
            pass
        objs[int(k)] = {"id": int(k), "label": v["category"], "room": v["room_cat"], "caption": cap,
                        "raw": v.get("caption") or ""}
    return {"geo": False, "objs": objs}


def load_suite():
    rows = [json.loads(l) for l in (BLIND / "round44.jsonl").read_text(encoding="utf-8").splitlines() if l.strip()]
    groups = {}
    for r in rows:
        groups.setdefault(r["group"], []).append(r)
    return rows, groups
