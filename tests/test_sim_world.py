"""Generated worlds: seeded determinism, floor plans that tile and connect, doors that are open,
furniture clear of walls, stacked objects resting on their supports, a trajectory through every room."""

from __future__ import annotations

import numpy as np
import pytest

from iesm_agent.sim import generate_scene
from iesm_agent.sim.catalog import COLORS, FOOTPRINTS
from iesm_agent.sim.floorplan import DOOR_WIDTH, grow_floor_plan


@pytest.fixture(scope="module")
def small():
    return generate_scene(5, "small", open_plan=True)


def _shoelace(poly) -> float:
    x, y = np.array(poly).T
    return 0.5 * float(np.dot(x, np.roll(y, -1)) - np.dot(y, np.roll(x, -1)))


def _overlap_volume(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Pairwise intersection volumes of boxes a (n, 2, 3) and b (m, 2, 3) -> (n, m)."""
    lo = np.maximum(a[:, None, 0], b[None, :, 0])
    hi = np.minimum(a[:, None, 1], b[None, :, 1])
    return np.prod(np.clip(hi - lo, 0, None), axis=-1)


def test_same_seed_same_world_other_seed_other_world(small):
    again = generate_scene(5, "small", open_plan=True)
    assert np.array_equal(small.boxes, again.boxes) and np.array_equal(small.poses, again.poses)
    assert [vars(i) for i in small.instances] == [vars(i) for i in again.instances]
    other = generate_scene(6, "small", open_plan=True)
    assert other.boxes.shape != small.boxes.shape or not np.allclose(other.boxes, small.boxes)


@pytest.mark.parametrize("seed", range(6))
@pytest.mark.parametrize("open_plan", [False, True])
def test_rooms_tile_the_footprint_and_are_all_reachable(seed, open_plan):
    plan = grow_floor_plan("small", open_plan, np.random.default_rng(seed))
    assert plan.grid.min() >= 1 and set(np.unique(plan.grid)) == set(plan.labels)
    areas = [_shoelace(plan.polygon(r)) for r in plan.labels]
    for room, area in zip(plan.labels, areas):  # one polygon per room, counter-clockwise, its own cells
        assert area == pytest.approx(np.sum(plan.grid == room) * plan.cell ** 2)
    fx, fy = FOOTPRINTS["small"]
    assert sum(areas) == pytest.approx(fx * fy)  # no overlap, no gap
    assert plan.connected()
    assert len(plan.open_pairs) == int(open_plan)
    for door in plan.doors:  # a door fits inside its wall run
        assert door.run.lo < door.center - DOOR_WIDTH / 2 and door.center + DOOR_WIDTH / 2 < door.run.hi


def test_hm3d_plan_is_large_and_connected():
    plan = grow_floor_plan("hm3d", True, np.random.default_rng(0))
    assert len(plan.labels) >= 15 and plan.connected() and plan.grid.shape == (60, 60)


def test_doors_are_passable_and_open_plan_has_no_wall(small):
    walls = small.boxes[np.isin(small.box_instance, [i.id for i in small.instances if i.label == "wall"])]
    for door in small.plan.doors:
        run = door.run
        point = np.array([door.center, run.coord, 1.0] if run.along_x else [run.coord, door.center, 1.0])
        inside = np.all((walls[:, 0] <= point) & (point <= walls[:, 1]), axis=1)
        assert not inside.any()
    (a, b), = small.plan.open_pairs
    shared = [r for r in small.plan.runs if (r.a, r.b) == (a, b)]
    assert sum(r.length for r in shared) >= 1.5
    for run in shared:
        mid = (run.lo + run.hi) / 2
        point = np.array([mid, run.coord, 1.0] if run.along_x else [run.coord, mid, 1.0])
        assert not np.all((walls[:, 0] <= point) & (point <= walls[:, 1]), axis=1).any()


@pytest.mark.parametrize("seed", range(4))
def test_furniture_is_clear_of_walls_doors_windows_and_other_furniture(seed):
    world = generate_scene(seed, "small", open_plan=bool(seed % 2))
    structural = {i.id for i in world.instances if i.structural}
    is_struct = np.isin(world.box_instance, list(structural))
    assert _overlap_volume(world.boxes[~is_struct], world.boxes[is_struct]).max() < 1e-6
    furniture = world.boxes[~is_struct]
    owner = world.box_instance[~is_struct]
    overlap = _overlap_volume(furniture, furniture)
    overlap[owner[:, None] == owner[None, :]] = 0  # boxes of one item may touch each other
    assert overlap.max() < 1e-6


def test_labels_and_colours(small):
    assert all(i.color in COLORS and i.label for i in small.instances)
    labels = {i.label for i in small.instances}
    assert {"wall", "door", "window"} <= labels
    assert all(i.structural == (i.label in ("wall", "door", "window")) for i in small.instances)
    assert 60 <= len(small.instances) <= 120


@pytest.mark.parametrize("seed", [0, 1, 2])
def test_stacked_objects_rest_on_their_support(seed):
    world = generate_scene(seed, "small")
    stacked = [i for i in world.instances if i.on is not None]
    assert len(stacked) >= 8
    for inst in stacked:
        mine = world.boxes[world.box_instance == inst.id]
        bottom = mine[:, 0, 2].min()
        support = world.boxes[world.box_instance == inst.on]
        tops = np.isclose(support[:, 1, 2], bottom, atol=1e-9)
        assert tops.any(), f"{inst.label} {inst.id} floats above {inst.on}"
        lo, hi = mine[:, 0, :2].min(0), mine[:, 1, :2].max(0)
        carriers = support[tops]
        assert np.any(np.all((carriers[:, 0, :2] <= lo + 1e-9) & (hi <= carriers[:, 1, :2] + 1e-9), axis=1))
        assert bottom > 0.02  # off the floor


def test_some_objects_stand_on_shelf_boards_above_others():
    world = generate_scene(1, "hm3d")
    by_id = {i.id: i for i in world.instances}
    on_shelves = [i for i in world.instances if i.on and by_id[i.on].label in ("bookshelf", "shelf")]
    heights = [world.boxes[world.box_instance == i.id][:, 0, 2].min() for i in on_shelves]
    assert on_shelves and max(heights) > 0.8
    assert 300 <= len(world.instances) <= 550 and 250 <= len(world.poses) <= 500


def test_trajectory_visits_every_room_from_free_space(small):
    cams = small.poses[:, :3, 3]
    rows, cols = zip(*(small.grid.cell_of(x, y) for x, y, _ in cams))
    visited = set(small.room_raster[list(rows), list(cols)].tolist())
    assert set(small.plan.labels) <= visited
    inside = np.all((small.boxes[None, :, 0] <= cams[:, None]) & (cams[:, None] <= small.boxes[None, :, 1]), -1)
    assert not inside.any()
    rot = small.poses[:, :3, :3]
    assert np.allclose(np.einsum("nji,njk->nik", rot, rot), np.eye(3), atol=1e-9)
    assert np.all(rot[:, 2, 2] < 0)  # forward axis tilted down: floors are visible
