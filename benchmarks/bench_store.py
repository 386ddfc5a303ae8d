"""Map store benchmark: an HM3D-floor-sized synthetic map (600 x 600 cells at 0.05 m, 300 box
instances, some stacked, 512-d float32 embeddings, ~150-char captions).

Prints the `.iesm` file size (target <= 1 MB), load time (median of 20, target <= 50 ms),
MapStore construction time and `search` latency (median over 200 queries, goal < 1 ms).
Run: python benchmarks/bench_store.py
"""

from __future__ import annotations

import statistics
import tempfile
import time
from pathlib import Path

import numpy as np

from iesm_agent.store import GridSpec, Instance, InstanceGrid, MapStore, Room, SceneMap, load_map, save_map

CATEGORIES = ["chair", "table", "sofa", "bed", "cabinet", "lamp", "book", "cup", "plant", "picture", "shelf",
              "desk", "monitor", "towel", "sink", "toilet", "mirror", "rug", "pillow", "door"]
COLORS = ["red", "blue", "white", "black", "brown", "gray", "green", "yellow"]
MATERIALS = ["wood", "metal", "fabric", "leather", "glass", "plastic", "ceramic"]
ROOMS = ["living room", "kitchen", "bedroom", "bathroom", "office", "hallway", "dining room", "closet"]


def build(seed: int = 0, n: int = 300, size: int = 600, dim: int = 512) -> SceneMap:
    rng = np.random.default_rng(seed)
    cells, ids, tops, instances = [], [], [], []
    room_map = np.full((size, size), -1, np.int32)
    for k in range(len(ROOMS)):  # 4 x 2 blocks of rooms
        r0, c0 = (k // 4) * size // 2, (k % 4) * size // 4
        room_map[r0 + 5:r0 + size // 2 - 5, c0 + 5:c0 + size // 4 - 5] = k
    prev_rc, ph, pw = (0, 0), 0, 0  # the previous instance's box, for the stacked ones
    for i in range(n):
        stacked = i % 5 == 4  # every fifth instance sits on the previous one
        if stacked:
            prev = instances[-1]
            r, c = prev_rc
            h, w = max(2, ph // 3), max(2, pw // 3)
            z0 = prev.mean_height * 2
        else:
            h, w = rng.integers(4, 40, 2)
            r, c = rng.integers(0, size - h), rng.integers(0, size - w)
            z0 = 0.0
        dz = float(rng.uniform(0.05, 1.5))
        rr, cc = np.meshgrid(np.arange(r, r + h), np.arange(c, c + w), indexing="ij")
        flat = (rr * size + cc).ravel()
        cells.append(flat)
        ids.append(np.full(len(flat), i))
        tops.append(np.full(len(flat), z0 + dz, np.float32))
        room = int(room_map[r + h // 2, c + w // 2])
        label = CATEGORIES[rng.integers(len(CATEGORIES))]
        color, material = COLORS[rng.integers(len(COLORS))], MATERIALS[rng.integers(len(MATERIALS))]
        caption = (f"A {color} {material} {label} with a slightly worn surface, placed near the wall of the "
                   f"{ROOMS[room] if room >= 0 else 'corridor'}, next to a window with light curtains.")[:150]
        instances.append(Instance(id=i, label=label, room_id=room if room >= 0 else None,
                                  room_label=ROOMS[room] if room >= 0 else None, caption=caption,
                                  tags={"color": color, "material": material}, alt_labels=["object"],
                                  mean_height=z0 + dz / 2, centroid=(c * 0.05, r * 0.05, z0 + dz / 2),
                                  footprint_cells=len(flat), frames=list(range(i % 7))))
        prev_rc, ph, pw = (r, c), h, w
    occ = InstanceGrid.from_entries(np.concatenate(cells), np.concatenate(ids), np.concatenate(tops))
    emb = rng.normal(size=(n, dim)).astype(np.float32)
    emb /= np.linalg.norm(emb, axis=1, keepdims=True)
    return SceneMap(scene_id="bench", grid=GridSpec(cell_size=0.05, height=size, width=size), instances=instances,
                    rooms=[Room(id=k, label=lab) for k, lab in enumerate(ROOMS)], occupancy=occ, room_map=room_map,
                    obstacles=room_map < 0, embeddings=emb, embedding_model="bench-512")


def median_ms(fn, repeat: int) -> float:
    times = []
    for _ in range(repeat):
        t = time.perf_counter()
        fn()
        times.append(time.perf_counter() - t)
    return statistics.median(times) * 1e3


def main() -> None:
    scene = build()
    print(f"map: {len(scene.instances)} instances, grid {scene.grid.height}x{scene.grid.width}, "
          f"{len(scene.occupancy.ids)} occupancy entries, {scene.occupancy.multi_occupancy_cells} stacked cells")
    with tempfile.TemporaryDirectory() as tmp:
        for label, dtype in (("float32 embeddings", None), ("float16 embeddings on disk", "float16")):
            path = Path(tmp) / "bench.iesm"
            size = save_map(scene, path, embeddings_dtype=dtype)
            load = median_ms(lambda: load_map(path), 20)
            print(f"{label:28s} file {size / 1e6:.3f} MB (target <= 1 MB)   load {load:.1f} ms median of 20 "
                  f"(target <= 50 ms)")
        assert load_map(path).occupancy == scene.occupancy
    build_ms = median_ms(lambda: MapStore(scene), 5)
    store = MapStore(scene)
    queries = [f"the {c} {k} in the {r}" for c, k, r in zip(COLORS * 25, CATEGORIES * 10, ROOMS * 25)][:200]
    for q in queries:  # warm the token cache, as a long-running server would be
        store.search(q)
    search_ms = median_ms(lambda: [store.search(q) for q in queries], 5) / len(queries)
    find_ms = median_ms(lambda: store.find_instances(category="chair", room="kitchen"), 50)
    print(f"MapStore build {build_ms:.1f} ms; search {search_ms * 1e3:.0f} us/query (lexical, median); "
          f"find_instances {find_ms * 1e3:.0f} us")


if __name__ == "__main__":
    main()
