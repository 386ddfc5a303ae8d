"""Path planning on the obstacle map (paper Sec. 3.4.1): grid A* (pyastar2d, C++ core) on the
obstacle map inflated by the robot radius, to the nearest reachable free cell next to the goal
instance, then shortened by line of sight. Lengths and waypoints are in metres."""

from __future__ import annotations

from typing import Literal, Optional

import numpy as np
from pydantic import BaseModel, ConfigDict, Field

from .obstacles import ObstacleConfig, inflate, obstacle_map
from .walls import map_walls
from ..store.model import GridSpec, SceneMap

Status = Literal["ok", "unknown_instance", "start_outside_map", "start_in_obstacle", "no_free_space",
                 "unreachable"]


class PathResult(BaseModel):
    """Outcome of one plan. `reachable` is True only for status "ok"; `waypoints` are (x, y) in
    metres from start to goal (line-of-sight shortened); `length_m` their Euclidean length;
    `goal_cell` (row, col) the free cell chosen next to the instance; `goal_distance_m` its distance
    to the instance's nearest cell; `message` says why when not reachable; `walls` where the walls
    planned around came from (the map's wall instances, its room polygons with door gaps, or
    "none: ..." when the path ignores walls)."""

    model_config = ConfigDict(extra="forbid")

    status: Status
    reachable: bool
    message: str = ""
    instance_id: int
    start: tuple[float, float]
    length_m: Optional[float] = None
    waypoints: list[tuple[float, float]] = Field(default_factory=list)
    goal_cell: Optional[tuple[int, int]] = None
    goal_distance_m: Optional[float] = None
    walls: str = ""


class PlanningGrid:
    """The inflated obstacle grid of one map, prepared once for many plans.

    `blocked` (H, W) bool: obstacle cells grown by the robot radius; `obstacles` (H, W) bool the
    obstacle cells themselves (the map's stored obstacle map, else computed from its instances)
    plus, for a map with room polygons but no wall instances, the walls drawn from the polygons
    (`walls.map_walls`; `self.walls` says which).
    A goal counts as reachable when a reachable free cell lies within `max_goal_distance` m of the
    instance (the N-SR radius).
    """

    def __init__(self, scene: SceneMap, config: ObstacleConfig = ObstacleConfig(), max_goal_distance: float = 1.0):
        self.scene = scene
        self.max_goal_distance = max_goal_distance
        self.grid: GridSpec = scene.grid
        self.config = config
        obstacles = scene.obstacles if scene.obstacles is not None else obstacle_map(scene, config)
        self.walls = map_walls(scene, obstacles, config.robot_radius)
        self.obstacles = obstacles | self.walls.cells
        self.blocked = inflate(self.obstacles, config.robot_radius, scene.grid.cell_size)
        self.weights = np.where(self.blocked, np.inf, 1.0).astype(np.float32)
        self._ids = {inst.id for inst in scene.instances}
        self._components: Optional[np.ndarray] = None

    def components(self) -> np.ndarray:
        """(H, W) int32 8-connected component id of each unblocked cell (0 = blocked), computed once."""
        import cv2

        if self._components is None:
            self._components = cv2.connectedComponents((~self.blocked).astype(np.uint8), connectivity=8)[1]
        return self._components

    def plan(self, instance_id: int, start_xy: tuple[float, float]) -> PathResult:
        """Plan from world point `start_xy` (m) to instance `instance_id`; never raises for
        unknown ids, bad starts or unreachable goals (the status says which)."""
        import cv2
        import pyastar2d

        start = (float(start_xy[0]), float(start_xy[1]))

        def fail(status: Status, message: str) -> PathResult:
            return PathResult(status=status, reachable=False, message=message, instance_id=instance_id, start=start,
                              walls=self.walls.description)

        if instance_id not in self._ids:
            return fail("unknown_instance", f"no instance with id {instance_id} in map {self.scene.scene_id}")
        if self.blocked.all():
            return fail("no_free_space", "the map has no free cell for a robot of radius "
                                         f"{self.config.robot_radius} m")
        row, col = self.grid.cell_of(*start)
        if not self.grid.contains(row, col):
            return fail("start_outside_map", f"start ({start[0]:.2f}, {start[1]:.2f}) lies outside the map")
        if self.obstacles[row, col]:
            return fail("start_in_obstacle", f"start ({start[0]:.2f}, {start[1]:.2f}) lies inside an obstacle")
        if self.blocked[row, col]:  # within the robot radius of an obstacle: step to the nearest free cell
            free = np.argwhere(~self.blocked)
            near = free[np.argmin(np.hypot(free[:, 0] - row, free[:, 1] - col))]
            if np.hypot(near[0] - row, near[1] - col) * self.grid.cell_size > self.config.robot_radius + self.grid.cell_size:
                return fail("start_in_obstacle", f"start ({start[0]:.2f}, {start[1]:.2f}) is hemmed in by obstacles")
            row, col = int(near[0]), int(near[1])
        target = self.scene.cells_of([instance_id])
        if not target.any():
            return fail("unreachable", f"instance {instance_id} occupies no cell of the map")
        # only cells within max_goal_distance of the instance can be goals: work in that window
        rows, cols = np.nonzero(target)
        pad = int(np.ceil(self.max_goal_distance / self.grid.cell_size)) + 1
        r0, c0 = max(rows.min() - pad, 0), max(cols.min() - pad, 0)
        r1, c1 = rows.max() + pad + 1, cols.max() + pad + 1
        component = self.components()
        reachable = component[r0:r1, c0:c1] == component[row, col]
        to_target = cv2.distanceTransform((~target[r0:r1, c0:c1]).astype(np.uint8), cv2.DIST_L2,
                                          cv2.DIST_MASK_PRECISE)
        candidates = np.where(reachable, to_target, np.inf)
        best = float(candidates.min())
        if not np.isfinite(best) or best * self.grid.cell_size > self.max_goal_distance:
            closest = f" (the closest reachable cell is {best * self.grid.cell_size:.2f} m away)" \
                if np.isfinite(best) else ""
            return fail("unreachable", f"instance {instance_id} cannot be reached from "
                                       f"({start[0]:.2f}, {start[1]:.2f}){closest}")
        ties = np.argwhere(candidates <= best + 1e-6) + (r0, c0)
        goal = ties[np.argmin(np.hypot(ties[:, 0] - row, ties[:, 1] - col))]
        path = pyastar2d.astar_path(self.weights, (row, col), (int(goal[0]), int(goal[1])), allow_diagonal=True)
        if path is None:  # cannot happen within one component; kept as a clear answer
            return fail("unreachable", f"no path to instance {instance_id}")
        corners = shorten(path, self.blocked)
        s, (ox, oy) = self.grid.cell_size, self.grid.origin
        waypoints = [start] + [(ox + (c + 0.5) * s, oy + (r + 0.5) * s) for r, c in corners[1:].tolist()]
        points = np.array(waypoints)
        length = float(np.hypot(*np.diff(points, axis=0).T).sum()) if len(points) > 1 else 0.0
        return PathResult(status="ok", reachable=True, instance_id=instance_id, start=start, length_m=length,
                          waypoints=[(round(x, 4), round(y, 4)) for x, y in waypoints],
                          goal_cell=(int(goal[0]), int(goal[1])), goal_distance_m=best * s,
                          walls=self.walls.description)


def line_of_sight(a: np.ndarray, b: np.ndarray, blocked: np.ndarray) -> bool:
    """True when the straight segment between cells `a` and `b` (row, col) crosses no blocked cell
    (sampled every quarter cell)."""
    steps = int(np.ceil(4 * np.abs(b - a).max())) + 1
    t = np.linspace(0.0, 1.0, steps)[:, None]
    cells = np.rint(a + t * (b - a)).astype(np.int64)
    return not blocked[cells[:, 0], cells[:, 1]].any()


def shorten(path: np.ndarray, blocked: np.ndarray) -> np.ndarray:
    """(K, 2) cells of a (N, 2) grid path reduced to its turns, then greedily to the farthest turn
    in line of sight of each kept one (start and goal kept)."""
    if len(path) <= 2:
        return path
    step = np.diff(path, axis=0)
    turn = np.any(step[1:] != step[:-1], axis=1)
    corners = np.concatenate([path[:1], path[1:-1][turn], path[-1:]])
    kept = [0]
    while kept[-1] < len(corners) - 1:
        i = kept[-1]
        j = len(corners) - 1
        while j > i + 1 and not line_of_sight(corners[i], corners[j], blocked):
            j -= 1
        kept.append(j)
    return corners[kept]


def plan_to_instance(scene: SceneMap, instance_id: int, start_xy: tuple[float, float],
                     config: ObstacleConfig = ObstacleConfig()) -> PathResult:
    """One plan from `start_xy` (m) to instance `instance_id` of `scene` (builds the planning grid;
    keep a `PlanningGrid` for many plans on the same map)."""
    return PlanningGrid(scene, config).plan(instance_id, start_xy)
