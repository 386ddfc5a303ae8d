"""Check the footprint ranges of `mapping.plausibility.SIZE_PRIORS` against the IESM paper's published maps.

    python scripts/published_footprints.py /work/shared/data/iesm_maps

For each instance of `scene_<s>_caption.json` whose HM3D category has a counterpart among our categories
(`COUNTERPARTS`, a loose name mapping), its footprint is the number of distinct (x, y) cells of its vertices in
`scene_<s>_ours_map_with_id.ply` times 0.025^2 m^2 (the project page's cell size). Prints, per category, how
many footprints lie inside the range and within a factor 2 of it. The published heights are one binned value
per instance, not metric tops, so only footprints are checked.
"""

from __future__ import annotations

import json
import sys
from collections import defaultdict
from pathlib import Path

import numpy as np

from iesm_agent.mapping.plausibility import SIZE_PRIORS
from iesm_agent.store.importers.iesm import read_ply_vertices

CELL_M = 0.025
COUNTERPARTS = {
    "chair": "chair", "folded chair": "chair", "easy chair": "armchair", "couch": "sofa", "sofa": "sofa", "bed": "bed",
    "pillow": "pillow", "book": "book", "toilet": "toilet", "table": "dining table", "desk": "desk",
    "counter desk": "desk", "bath sink": "bathroom sink", "sink": "bathroom sink", "kitchen sink": "bathroom sink",
    "mirror frame": "mirror", "window": "window", "window /outside": "window", "door": "door", "doorway": "door",
    "door frame": "door", "cup": "cup", "clock": "clock", "laptop": "laptop", "monitor": "monitor", "screen": "monitor",
    "remote-control": "remote control", "bench": "bench", "garden bench": "bench", "sideboard": "sideboard",
    "side table": "nightstand", "bed table": "nightstand", "bowl with sweets": "bowl", "decorative bowl": "bowl",
    "wall tv": "television", "keyboard": "keyboard", "art frame": "picture", "cabinet kitchen": "cabinet",
    "storage shelving": "shelf", "book rack": "bookshelf", "hand towel": "towel", "set of towels": "towel",
}


def footprints(folder: Path) -> dict[str, list[float]]:
    """Our category -> footprints (m^2) of the published instances named as its counterpart."""
    out: dict[str, list[float]] = defaultdict(list)
    for captions in sorted(folder.glob("scene_*_caption.json")):
        scene = captions.name[:-len("_caption.json")]
        entries = json.loads(captions.read_text(encoding="utf-8"))
        v = read_ply_vertices(folder / f"{scene}_ours_map_with_id.ply")
        for key, entry in entries.items():
            ours = COUNTERPARTS.get(str(entry.get("category", "")))
            mine = v["instance_id"] == int(key)
            if ours is not None and mine.any():
                cells = np.unique(np.stack([v["x"][mine], v["y"][mine]], axis=1), axis=0)
                out[ours].append(len(cells) * CELL_M ** 2)
    return out


def main(folder: str) -> None:
    inside = within2 = total = 0
    for category, areas in sorted(footprints(Path(folder)).items()):
        lo, hi = SIZE_PRIORS[category][0]
        a = np.array(areas)
        n_in, n_2 = int(((a >= lo) & (a <= hi)).sum()), int(((a >= lo / 2) & (a <= 2 * hi)).sum())
        inside, within2, total = inside + n_in, within2 + n_2, total + len(a)
        print(f"{category:16s} n={len(a):2d} median {np.median(a):.3f} m^2 range [{lo}, {hi}] inside {n_in} "
              f"within 2x {n_2}")
    print(f"{total} instances: inside {inside}, within a factor 2 {within2}")


if __name__ == "__main__":
    main(sys.argv[1] if len(sys.argv) > 1 else "/work/shared/data/iesm_maps")
