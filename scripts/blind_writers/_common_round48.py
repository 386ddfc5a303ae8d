"""Shared helpers: load a suite map given its "map" field (relative to evals/blind)."""
import json
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SUITE_DIR = ROOT / "evals/blind"


def map_path(field):
    return (SUITE_DIR / field).resolve()


def load_map(field):
    """('geo', {id: obj}, rooms) for object maps, or ('cap', {id: entry}, None) for caption maps."""
    data = json.loads(map_path(field).read_text(encoding="utf-8"))
    if isinstance(data, dict) and "objects" in data:
        return "geo", {int(o["id"]): o for o in data["objects"]}, data.get("rooms", [])
    return "cap", {int(k): v for k, v in data.items()}, None
