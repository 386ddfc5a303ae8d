"""A simulated agent that follows a planned path against the simulator's true occupancy, and the
paper's navigation success (N-SR): the final position lies within `success_radius` (1 m) of the
ground-truth instance (distance to the nearest cell centre of its true footprint)."""

from __future__ import annotations

from typing import Optional

import numpy as np
from pydantic import BaseModel, ConfigDict

from ..nav.obstacles import ObstacleConfig, inflate
from ..nav.planner import PlanningGrid
from ..store.model import GridSpec, InstanceGrid, SceneMap


class TrialOutcome(BaseModel):
    """One navigation trial. `status` is the planner's ("ok", "unreachable", ...) or
    "no_ground_truth" (then `success` is None: the trial cannot be judged); `collided` when the
    true occupancy stopped the agent before the end of its path; distances in metres."""

    model_config = ConfigDict(extra="forbid")

    success: Optional[bool]
    status: str
    message: str = ""
    final_xy: Optional[tuple[float, float]] = None
    distance_m: Optional[float] = None
    path_length_m: Optional[float] = None
    collided: bool = False


def follow(waypoints: np.ndarray, blocked: np.ndarray, grid: GridSpec, step: float = 0.025) -> tuple[np.ndarray, bool]:
    """Walk the (K, 2) polyline `waypoints` (m) in `step` m increments over the (H, W) `blocked`
    grid; returns (final (x, y), collided): the agent stops at the last free sample before a
    blocked one (leaving the grid counts as blocked)."""
    if len(waypoints) < 2:
        return waypoints[0], False
    seg = np.diff(waypoints, axis=0)
    lengths = np.hypot(seg[:, 0], seg[:, 1])
    distance = np.arange(0.0, lengths.sum() + step, step).clip(max=lengths.sum())
    cum = np.concatenate([[0.0], np.cumsum(lengths)])
    k = np.clip(np.searchsorted(cum, distance, side="right") - 1, 0, len(seg) - 1)
    frac = np.where(lengths[k] > 0, (distance - cum[k]) / np.maximum(lengths[k], 1e-12), 0.0)
    samples = waypoints[k] + frac[:, None] * seg[k]
    col = np.floor((samples[:, 0] - grid.origin[0]) / grid.cell_size).astype(np.int64)
    row = np.floor((samples[:, 1] - grid.origin[1]) / grid.cell_size).astype(np.int64)
    inside = (row >= 0) & (row < grid.height) & (col >= 0) & (col < grid.width)
    hit = ~inside
    hit[inside] = blocked[row[inside], col[inside]]
    if not hit.any():
        return samples[-1], False
    first = int(np.argmax(hit))
    return samples[max(first - 1, 0)], True


def footprint_distance(xy: np.ndarray, cells: InstanceGrid, grid: GridSpec, instance_id: int) -> Optional[float]:
    """Distance (m) from point `xy` to the nearest cell centre of `instance_id` in `cells`; None if absent."""
    flat, ids, _ = cells.entries()
    own = flat[ids == instance_id]
    if len(own) == 0:
        return None
    row, col = np.divmod(own, grid.width)
    x = grid.origin[0] + (col + 0.5) * grid.cell_size
    y = grid.origin[1] + (row + 0.5) * grid.cell_size
    return float(np.hypot(x - xy[0], y - xy[1]).min())


class NavTrials:
    """Navigation trials on one built map against simulator ground truth: plan on the built map's
    obstacle map, walk against the true occupancy (grown by `body_radius` m), judge against the true
    footprint of the ground-truth instance matched to the built instance (`to_gt`: built id -> gt id).
    Maps imported from the ground-truth object list share its ids: pass the identity."""

    def __init__(self, scene: SceneMap, gt, to_gt: dict[int, int], config: ObstacleConfig = ObstacleConfig(),
                 body_radius: float = 0.1, success_radius: float = 1.0):
        self.planner = PlanningGrid(scene, config)
        self.gt = gt
        self.to_gt = to_gt
        self.success_radius = success_radius
        self.true_blocked = inflate(gt.occupancy, body_radius, gt.grid.cell_size)

    @classmethod
    def for_map(cls, scene: SceneMap, gt, frames_dir=None, **kwargs) -> "NavTrials":
        """Trials for a map built from the frames whose ground truth is `gt`, ids paired by
        `evals.mapping_causes.built_instances` (the paper's top-down IoU > 0.5, against the observed
        footprints when `frames_dir`, the frame directory, is given; then an object's own instances),
        as the queries written from that ground truth are."""
        from .mapping_causes import built_instances
        from .observed import observed_masks

        instances, _ = built_instances(scene, gt, frames_dir, observed_masks(frames_dir, gt))
        return cls(scene, gt, {pred: gt_id for gt_id, preds in instances.items() for pred in preds}, **kwargs)

    def run(self, instance_id: int, start_xy: tuple[float, float], judge_id: Optional[int] = None) -> TrialOutcome:
        """Go to built instance `instance_id` from `start_xy`; success is judged against the
        ground truth of `judge_id` (default: the same instance)."""
        gt_id = self.to_gt.get(instance_id if judge_id is None else judge_id)
        plan = self.planner.plan(instance_id, start_xy)
        if not plan.reachable:
            return TrialOutcome(success=False if gt_id is not None else None, status=plan.status,
                                message=plan.message)
        final, collided = follow(np.array(plan.waypoints), self.true_blocked, self.gt.grid)
        if gt_id is None:
            return TrialOutcome(success=None, status="no_ground_truth", final_xy=tuple(final.tolist()),
                                message=f"built instance {judge_id or instance_id} matches no ground-truth instance",
                                path_length_m=plan.length_m, collided=collided)
        distance = footprint_distance(final, self.gt.cells, self.gt.grid, gt_id)
        return TrialOutcome(success=distance is not None and distance <= self.success_radius, status=plan.status,
                            final_xy=(round(float(final[0]), 4), round(float(final[1]), 4)),
                            distance_m=distance, path_length_m=plan.length_m, collided=collided)


def record_fields(trials: Optional[NavTrials], start: Optional[tuple[float, float]],
                  predicted: Optional[int]) -> dict:
    """The eval-record fields of one trial: {"nav_success", "path_length_m"} (None when the query
    has no start, the map no ground truth, or nothing was retrieved)."""
    if trials is None or start is None or predicted is None:
        return {}
    outcome = trials.run(predicted, start)
    return {"nav_success": outcome.success, "path_length_m": outcome.path_length_m}
