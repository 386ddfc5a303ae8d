"""Room segmentation and path planning benchmark on hand-made walled layouts.

Room segmentation: a 5 x 5 grid of 10 m rooms at 0.05 m (1002 x 1002 cells), noisy per-cell
labels, the contextual split on; median of 5 runs of `segment_scene` (structural masks, LSD,
components, split, labels; target <= 0.2 s). Path planning: a 3 x 3 grid of 10 m rooms
(602 x 602 cells), one `PlanningGrid` per map, median of 30 plans from a corner room to an
object in the opposite corner (target <= 20 ms); the one-off grid preparation is printed too.
Figures are one-thread CPU time (wall time printed beside it).
Run: python benchmarks/bench_rooms_nav.py
"""

from __future__ import annotations

import statistics
import sys
import time
from pathlib import Path

sys.path.insert(0, str(Path(__file__).parent))
from results_io import record  # noqa: E402

from iesm_agent.nav import PlanningGrid  # noqa: E402
from iesm_agent.rooms import segment_scene  # noqa: E402
from iesm_agent.sim.layouts import grid_layout, noisy_labels  # noqa: E402


def median_time(fn, repeats: int) -> tuple[float, float]:
    """(median wall seconds, median CPU seconds of this process) over `repeats` calls after a warm-up.
    OpenCV runs on one thread here, so CPU time is the single-core work: the figure recorded, as
    wall time on this shared machine includes time other processes held the cores."""
    fn()  # warm-up (imports, caches)
    wall, cpu = [], []
    for _ in range(repeats):
        start, start_cpu = time.perf_counter(), time.process_time()
        fn()
        wall.append(time.perf_counter() - start)
        cpu.append(time.process_time() - start_cpu)
    return statistics.median(wall), statistics.median(cpu)


def main() -> None:
    import cv2

    cv2.setNumThreads(1)
    layout = grid_layout(5, 5, room_size=10.0, open_walls=(("v", 0, 0), ("h", 2, 2)))
    labels = noisy_labels(layout, accuracy=0.7)
    seg = segment_scene(layout.scene, labels)
    shape = layout.rooms.shape
    wall, seconds = median_time(lambda: segment_scene(layout.scene, labels), 7)
    print(f"room segmentation {shape[0]} x {shape[1]}: {seconds:.3f} s CPU median, {wall:.3f} s wall "
          f"({seg.components} components, {seg.splits} splits, {seg.boundaries.detector})")
    record("room_segmentation_s", seconds, "s", "<= 0.2 s", seconds <= 0.2,
           note=f"{shape[0]}x{shape[1]} grid, 25 rooms, 2 open-plan joins; one-thread CPU time "
                f"(wall {wall:.3f} s on the shared machine)")

    nav = grid_layout(3, 3, room_size=10.0)
    start = time.perf_counter()
    planning = PlanningGrid(nav.scene)
    planning.components()
    prep_ms = (time.perf_counter() - start) * 1000
    goal = [i.id for i in nav.scene.instances if i.label != "wall"][-1]
    result = planning.plan(goal, (1.0, 1.0))
    assert result.reachable, result.message
    wall, cpu = median_time(lambda: planning.plan(goal, (1.0, 1.0)), 30)
    ms, wall_ms = cpu * 1000, wall * 1000
    print(f"path planning {nav.rooms.shape[0]} x {nav.rooms.shape[1]}: {ms:.2f} ms CPU median per path, "
          f"{wall_ms:.2f} ms wall ({result.length_m:.1f} m, {len(result.waypoints) - 1} legs); "
          f"grid preparation {prep_ms:.1f} ms once per map")
    record("path_planning_ms", ms, "ms", "<= 20 ms", ms <= 20,
           note=f"{nav.rooms.shape[0]}x{nav.rooms.shape[1]} grid, prepared grid (one-off {prep_ms:.0f} ms); "
                f"one-thread CPU time (wall {wall_ms:.1f} ms)")


if __name__ == "__main__":
    main()
