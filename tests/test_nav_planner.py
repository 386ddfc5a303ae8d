"""Path planning on hand-made grids: A* through door gaps, line-of-sight shortening, Euclidean
length, and clear answers for unknown ids, bad starts, walled-off goals and maps without free space;
the simulated agent against a true occupancy that differs from the map."""

from __future__ import annotations

import numpy as np
import pytest

from iesm_agent.nav import PlanningGrid, plan_to_instance
from iesm_agent.evals.navigation import follow, footprint_distance
from iesm_agent.nav.planner import line_of_sight, shorten
from iesm_agent.nav import ObstacleConfig
from iesm_agent.sim.layouts import grid_layout
from iesm_agent.store.model import GridSpec, Instance, InstanceGrid, SceneMap


def instance_id(scene, label):
    return next(i.id for i in scene.instances if i.label == label)


def test_straight_path_in_one_room_has_euclidean_length():
    scene = grid_layout(1, 1, labels=("bedroom",)).scene      # bed over cells rows 20-35, cols 20-39
    planning = PlanningGrid(scene, ObstacleConfig(robot_radius=0.2))
    res = planning.plan(instance_id(scene, "bed"), (3.5, 1.5))
    assert res.reachable and res.status == "ok"
    assert len(res.waypoints) == 2                              # straight: one leg after shortening
    assert 0.2 < res.goal_distance_m <= 0.25                     # the nearest cell outside the safety margin
    assert not planning.blocked[res.goal_cell]
    x, y = res.waypoints[-1]
    assert 2.0 + 0.15 < x < 2.3 and 1.0 < y < 1.9                # beside the bed's right edge (x = 2.0 m)
    assert res.length_m == pytest.approx(np.hypot(3.5 - x, 1.5 - y), abs=1e-6)


def test_path_goes_through_the_door_and_is_longer_than_the_straight_line():
    scene = grid_layout(2, 1, labels=("bedroom", "kitchen")).scene
    start = (1.0, 0.5)                                          # the straight line to the fridge hits the wall
    res = plan_to_instance(scene, instance_id(scene, "refrigerator"), start)
    assert res.reachable
    wps = np.array(res.waypoints)
    door_y = 2.0
    crossing = [(a, b) for a, b in zip(wps[:-1], wps[1:]) if (a[0] - 4.05) * (b[0] - 4.05) < 0]
    assert len(crossing) == 1
    (a, b), = crossing
    y_at_wall = a[1] + (b[1] - a[1]) * (4.05 - a[0]) / (b[0] - a[0])
    assert abs(y_at_wall - door_y) < 0.45
    assert res.length_m > np.hypot(*(wps[-1] - np.array(start))) + 0.3


def test_shorten_keeps_only_visible_turns():
    path = np.array([(r, 2) for r in range(2, 18)] + [(17, c) for c in range(3, 18)])
    free = np.zeros((20, 20), bool)
    assert shorten(path, free).tolist() == [[2, 2], [17, 17]]
    blocked = free.copy()
    blocked[5:15, 10] = True                                    # hides the goal from the start
    assert shorten(path, blocked).tolist() == [[2, 2], [17, 2], [17, 17]]
    assert not line_of_sight(np.array([10, 2]), np.array([10, 18]), blocked)


def test_unknown_id_start_in_obstacle_outside_and_unreachable_goal():
    scene = grid_layout(2, 1, labels=("bedroom", "kitchen")).scene
    planning = PlanningGrid(scene)
    assert planning.plan(999, (1, 1)).status == "unknown_instance"
    bed = instance_id(scene, "bed")
    assert planning.plan(bed, (1.5, 1.5)).status == "start_in_obstacle"      # inside the bed
    assert planning.plan(bed, (-3, 1)).status == "start_outside_map"
    near_wall = planning.plan(bed, (0.15, 3.0))                              # within the robot radius of the wall
    assert near_wall.reachable
    # wall off the kitchen completely: its fridge becomes unreachable from the bedroom
    wall = np.zeros((scene.grid.height, scene.grid.width), bool)
    wall[:, 80:83] = True
    closed = scene.model_copy(update={"obstacles": planning.obstacles | wall})
    res = plan_to_instance(closed, instance_id(scene, "refrigerator"), (1.0, 3.5))
    assert not res.reachable and res.status == "unreachable" and "cannot be reached" in res.message
    for r in (planning.plan(999, (1, 1)), res):
        assert r.length_m is None and r.waypoints == []


def test_map_without_free_space():
    grid = GridSpec(cell_size=0.05, height=10, width=10)
    flat = np.arange(100)
    scene = SceneMap(scene_id="full", grid=grid, instances=[Instance(id=1, label="wall", mean_height=1.0)],
                     occupancy=InstanceGrid.from_entries(flat, np.ones(100, np.int64)))
    res = plan_to_instance(scene, 1, (0.2, 0.2))
    assert res.status == "no_free_space" and not res.reachable


def test_agent_stops_at_an_obstacle_the_map_missed():
    grid = GridSpec(cell_size=0.1, height=10, width=30)
    truth = np.zeros((10, 30), bool)
    truth[:, 15] = True
    final, collided = follow(np.array([[0.5, 0.5], [2.5, 0.5]]), truth, grid)
    assert collided and 1.3 < final[0] < 1.5
    final, collided = follow(np.array([[0.5, 0.5], [1.2, 0.5]]), truth, grid)
    assert not collided and final[0] == pytest.approx(1.2)


def test_footprint_distance():
    grid = GridSpec(cell_size=0.1, height=10, width=10)
    cells = InstanceGrid.from_entries(np.array([55]), np.array([7]))       # cell (5, 5): centre (0.55, 0.55)
    assert footprint_distance(np.array([0.55, 1.55]), cells, grid, 7) == pytest.approx(1.0)
    assert footprint_distance(np.array([0.0, 0.0]), cells, grid, 8) is None
