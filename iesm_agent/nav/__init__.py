"""Navigation on the obstacle map: `plan_to_instance(scene, instance_id, start_xy) -> PathResult`,
and simulated trials for N-SR (`NavTrials`)."""

from .agent import NavTrials, TrialOutcome
from .planner import PathResult, PlanningGrid, plan_to_instance

__all__ = ["NavTrials", "PathResult", "PlanningGrid", "TrialOutcome", "plan_to_instance"]
