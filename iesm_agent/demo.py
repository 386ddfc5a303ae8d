"""`make demo`: the whole system of the paper on a simulated apartment, with the offline model.

Simulate an apartment (RGB-D frames, masks, ground truth), build the instance-level 2.5D map,
segment rooms, caption every instance, evaluate the map against ground truth, generate a query
suite from ground truth, evaluate MTEFR against SPR, keyword and the ablations, answer three
example queries with explanations and plan a path to a retrieved goal. Pictures go to
`out/demo/` (override with IESM_DEMO_DIR): instance_map.png, room_map.png, path.png, results.png,
and two self-contained pages: eval/report.html (every query with its evidence) and map.html
(the map viewer).

Each step runs the real `iesm` command line (printed first, so it can be copied) in this process,
so the embedding model loads once.
"""

from __future__ import annotations

import json
import os
import shlex
import shutil
import sys
import time
from pathlib import Path

#: the simulated scene; seed 0 of `--size small`
SEED = 0
#: query types of the suite: the paper's five and the spatial type
TYPES = "o,or,od,ord,ard,s"
#: example queries: the first generated query of each of these types
EXAMPLE_TYPES = ("ord", "ard", "s")
METHODS = "mtefr,mtefr-uniform,spr,keyword,experts:obj,experts:obj,desc,experts:obj,room"


class StepFailed(Exception):
    pass


def _run(args: list[str], step: str) -> None:
    from .cli import run

    print(f"\n== {step}\n$ iesm {shlex.join(args)}", flush=True)
    t0 = time.perf_counter()
    status = run(args)
    print(f"   ({time.perf_counter() - t0:.1f} s)", flush=True)
    if status != 0:
        raise StepFailed(f"{step}: `iesm {shlex.join(args)}` exited with status {status}")


def _examples(suite: Path) -> list[str]:
    """The first query of each EXAMPLE_TYPES type in the suite (types it lacks are skipped)."""
    first: dict[str, str] = {}
    for line in filter(str.strip, suite.read_text(encoding="utf-8").split("\n")):  # JSON Lines: "\n" only
        row = json.loads(line)
        first.setdefault(row["type"], row["query"])
    return [first[t] for t in EXAMPLE_TYPES if t in first]


def _start_far_from(map_path: Path, goal: int) -> tuple[float, float]:
    """A free cell (x, y) in metres near the centre of the largest room that does not hold `goal`."""
    import numpy as np

    from .store import load_map

    scene = load_map(map_path)
    goal_room = scene.instance(goal).room_id
    free = ~scene.obstacles if scene.obstacles is not None else np.ones((scene.grid.height, scene.grid.width), bool)
    best, best_area = None, 0
    for room in scene.rooms:
        mask = (scene.room_map == room.id) & free
        if room.id != goal_room and mask.sum() > best_area:
            best, best_area = mask, int(mask.sum())
    if best is None:
        best = free
    cells = np.argwhere(best)
    r, c = cells[np.argmin(((cells - cells.mean(0)) ** 2).sum(1))]
    return scene.grid.center_of(int(r), int(c))


def main() -> int:
    out = Path(os.environ.get("IESM_DEMO_DIR", "out/demo"))
    out.mkdir(parents=True, exist_ok=True)
    frames, scene = out / "scene", out / "scene.iesm"
    suite, run_dir = out / "suite.jsonl", out / "eval"
    t0 = time.perf_counter()
    try:
        _run(["sim", "--seed", str(SEED), "--out", str(frames), "--size", "small", "--force"],
             "1. simulate an apartment: RGB-D frames, poses, masks + embeddings, ground truth")
        _run(["build-map", str(frames), "-o", str(scene)], "2. build the instance-level 2.5D map (paper Sec. 3.1)")
        _run(["rooms", str(scene), "--frames", str(frames), "-o", str(scene)],
             "3. segment rooms, label them, obstacle map (Sec. 3.2)")
        _run(["caption", str(scene), "--frames", str(frames), "-o", str(scene)],
             "4. caption every instance from its keyframes (Sec. 3.3; offline captioner)")
        _run(["info", str(scene)], "5. the saved map")
        _run(["eval-map", str(scene), "--gt", str(frames)], "6. the map against ground truth (Sec. 4.1, 4.2)")
        _run(["render", str(scene), "-o", str(out / "instance_map.png")], "7. pictures: instance map")
        _run(["render", str(scene), "--layer", "rooms", "-o", str(out / "room_map.png")], "   room map")
        _run(["gen-queries", str(scene), "--gt", str(frames), "--types", TYPES, "--per-type", "10",
              "--seed", "0", "-o", str(suite)], "8. a query suite written from ground truth")
        shutil.rmtree(run_dir, ignore_errors=True)  # a fresh run each time
        _run(["eval", str(suite), "--method", METHODS, "--gt", str(frames), "--keep-prompts", "-o", str(run_dir)],
             "9. MTEFR against SPR, keyword and the ablations (Sec. 4.3)")
        shutil.copyfile(run_dir / "osr_by_type.png", out / "results.png")
        _run(["view", str(scene), "-o", str(out / "map.html")], "   pages: the map viewer (the eval wrote report.html)")
        for query in _examples(suite):
            _run(["ask", str(scene), query, "--explain"], "10. an example query, explained")
        from .retrieval import Retriever
        from .store import MapStore

        goal_query = _examples(suite)[0]
        goal = Retriever(MapStore.load(scene), provider="offline").ask(goal_query).instance_id
        if goal is None:
            raise StepFailed(f"11. no goal retrieved for {goal_query!r}")
        x, y = _start_far_from(scene, goal)
        _run(["path", str(scene), "--to", str(goal), "--start", f"{x:.2f},{y:.2f}", "--png", str(out / "path.png")],
             f"11. plan a path to the goal of {goal_query!r}")
    except StepFailed as exc:
        print(f"\ndemo failed at {exc}", file=sys.stderr)
        return 1
    print(f"\nDemo finished in {time.perf_counter() - t0:.0f} s. Outputs in {out}/: instance_map.png, room_map.png, "
          f"path.png, results.png, {run_dir.name}/report.md, {run_dir.name}/report.html, map.html, {scene.name}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
