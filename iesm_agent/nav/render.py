"""PNG of a planned path: obstacles, the robot-radius margin, rooms, the goal instance and the path."""

from __future__ import annotations

from pathlib import Path

import numpy as np

from ..fileio import pyplot, save_figure
from .planner import PathResult, PlanningGrid


def render_path(planning: PlanningGrid, result: PathResult, path: str | Path, dpi: int = 120) -> None:
    """Write the drawing of `result` on `planning`'s grid to `path` (PNG, atomically)."""
    plt = pyplot("--png")
    scene, grid = planning.scene, planning.grid
    image = np.ones((grid.height, grid.width, 3))
    if scene.room_map is not None:
        image[scene.room_map >= 0] = (0.93, 0.95, 1.0)
    image[planning.blocked] = (0.82, 0.82, 0.82)
    image[planning.obstacles] = (0.35, 0.35, 0.35)
    if result.status != "unknown_instance":
        image[scene.cells_of([result.instance_id])] = (0.85, 0.1, 0.1)
    extent = (grid.origin[0], grid.origin[0] + grid.width * grid.cell_size,
              grid.origin[1], grid.origin[1] + grid.height * grid.cell_size)
    fig, ax = plt.subplots(figsize=(8, max(3.0, 8 * grid.height / max(grid.width, 1))))
    ax.imshow(image, origin="lower", extent=extent, interpolation="nearest")
    if result.waypoints:
        xs, ys = np.array(result.waypoints).T
        ax.plot(xs, ys, "-", color="tab:blue", linewidth=2)
    ax.plot(*result.start, "o", color="tab:blue", markersize=8)
    title = (f"to instance {result.instance_id}: {result.length_m:.2f} m" if result.reachable
             else f"to instance {result.instance_id}: {result.message}")
    if planning.walls.source == "none":
        title += "\n(the path ignores walls: the map has none)"
    elif planning.walls.source == "room polygons":
        title += f"\n(walls from the room polygons, {len(planning.walls.doors)} doors)"
    ax.set_title(title, fontsize=9)
    ax.set_xlabel("x (m)")
    ax.set_ylabel("y (m)")
    save_figure(fig, path, dpi)
