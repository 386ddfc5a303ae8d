"""The obstacle map and navigation on it: `plan_to_instance(scene, instance_id, start_xy) -> PathResult`."""

from .obstacles import ObstacleConfig, inflate, obstacle_map, with_obstacles
from .planner import PathResult, PlanningGrid, plan_to_instance

__all__ = ["ObstacleConfig", "PathResult", "PlanningGrid", "inflate", "obstacle_map", "plan_to_instance",
           "with_obstacles"]
