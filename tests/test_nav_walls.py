"""Walls from room polygons (issue 21): imported maps with room polygons but no wall instances get
walls with door gaps; maps with neither say the path ignores walls."""

from __future__ import annotations

import asyncio
import json

import numpy as np
import pytest

from iesm_agent.cli import run
from iesm_agent.nav import PlanningGrid
from iesm_agent.nav.walls import NO_WALLS, shared_segments
from iesm_agent.server import MapService
from iesm_agent.sim.layouts import grid_layout
from iesm_agent.store import Room
from iesm_agent.store.importers import import_map
from iesm_agent.store.refs import open_map


def crossings(waypoints, x_wall: float) -> list[float]:
    """y (m) where the polyline `waypoints` crosses the vertical line x = x_wall."""
    ys = []
    for (x0, y0), (x1, y1) in zip(waypoints[:-1], waypoints[1:]):
        if (x0 - x_wall) * (x1 - x_wall) < 0:
            ys.append(y0 + (x_wall - x0) * (y1 - y0) / (x1 - x0))
    return ys


def touches(planning: PlanningGrid, waypoints, mask: np.ndarray) -> bool:
    """Whether the polyline passes through a cell of `mask` (sampled every 1 cm)."""
    grid = planning.grid
    for a, b in zip(np.array(waypoints[:-1]), np.array(waypoints[1:])):
        t = np.linspace(0, 1, int(np.hypot(*(b - a)) / 0.01) + 2)[:, None]
        rows, cols = np.transpose([grid.cell_of(x, y) for x, y in a + t * (b - a)])
        if mask[rows, cols].any():
            return True
    return False


def test_apartment_kitchen_to_living_room_goes_through_the_door():
    scene = open_map("apartment")
    planning = PlanningGrid(scene)
    assert planning.walls.source == "room polygons" and planning.walls.cells.any()
    door = next(d for d in planning.walls.doors if set(d.rooms) == {1, 2})  # living room | kitchen, x = 5
    assert door.x == pytest.approx(5.0) and door.width == pytest.approx(0.9)
    start = (6.0, 3.6)  # kitchen, by the trash can; the sofa (1) lies south-west in the living room
    with_walls = planning.plan(1, start)
    assert with_walls.reachable and with_walls.walls.startswith("room polygons")
    ys = crossings(with_walls.waypoints, 5.0)
    assert ys and all(door.y - door.width / 2 <= y <= door.y + door.width / 2 for y in ys)
    assert not touches(planning, with_walls.waypoints, planning.walls.cells)
    # the same map without room polygons: the straight line through the wall, and the output says so
    bare = scene.model_copy(update={"rooms": [Room(id=r.id, label=r.label) for r in scene.rooms]})
    without = PlanningGrid(bare).plan(1, start)
    assert without.reachable and without.walls == NO_WALLS and "ignores walls" in without.walls
    (y_bare,) = crossings(without.waypoints, 5.0)  # through the wall beside the door
    assert abs(y_bare - door.y) > door.width / 2
    assert with_walls.length_m > without.length_m + 0.1  # 3.68 m against 3.44 m


def test_apartment_doors_open_where_the_wall_is_clear():
    planning = PlanningGrid(open_map("apartment"))
    doors = {frozenset(d.rooms): d for d in planning.walls.doors}
    assert len(doors) == 8  # every pair of rooms sharing an edge
    bathroom = doors[frozenset({4, 6})]  # hallway | bathroom along y = 5.5; a washing machine at x 4.7-5.3
    assert bathroom.y == pytest.approx(5.5) and bathroom.x - 0.45 >= 5.3
    # every door is passable: the hallway reaches every room
    for room_id, target in ((1, 1), (2, 16), (3, 32), (4, 46), (5, 47)):
        assert planning.plan(target, (9.0, 5.0)).reachable, room_id
    # wall cells sit on the polygon outlines only; object cells stay blocked
    assert planning.obstacles[planning.scene.cells_of([45])].all()


def test_shared_segments_of_partly_overlapping_edges():
    rooms = [Room(id=1, label="a", polygon=[(0, 0), (4, 0), (4, 3), (0, 3)]),
             Room(id=2, label="b", polygon=[(4, 1), (8, 1), (8, 5), (4, 5)]),
             Room(id=3, label="c", polygon=[(0, 3), (2, 3), (2, 6), (0, 6)])]
    found = {(a, b): (tuple(p0), tuple(p1)) for a, b, p0, p1 in shared_segments(rooms)}
    assert found[(1, 2)] == ((4.0, 1.0), (4.0, 3.0))
    assert sorted(found[(1, 3)]) == [(0.0, 3.0), (2.0, 3.0)]
    assert (2, 3) not in found and (1, 3) in found


def two_rooms(tmp_path, doors=None, rooms=True, name="two.json"):
    data = {"scene_id": "two", "objects": [
        {"id": 1, "label": "table", "center": [6.0, 1.5, 0.4], "size": [1.0, 0.8, 0.8]},
        {"id": 2, "label": "cabinet", "center": [4.3, 2.5, 0.5], "size": [0.4, 0.6, 1.0]}]}
    if rooms:
        data["rooms"] = [{"id": 1, "label": "office", "polygon": [[0, 0], [4, 0], [4, 3], [0, 3]]},
                         {"id": 2, "label": "kitchen", "polygon": [[4, 0], [8, 0], [8, 3], [4, 3]]}]
    if doors is not None:
        data["doors"] = doors
    path = tmp_path / name
    path.write_text(json.dumps(data))
    return path


def test_declared_doors_replace_the_automatic_gaps(tmp_path):
    auto = PlanningGrid(import_map(two_rooms(tmp_path)))
    (door,) = auto.walls.doors
    assert door.x == pytest.approx(4.0) and door.y - 0.45 >= 0 and door.y + 0.45 <= 2.2 - 0.2  # clear of the cabinet
    ys = crossings(auto.plan(1, (1.0, 2.5)).waypoints, 4.0)
    assert ys and all(abs(y - door.y) <= 0.45 for y in ys)

    # a declared door 1.2 m wide at y = 2.4, beside the cabinet (x 4.1-4.5, y 2.2-2.8): its cells stay blocked
    scene = import_map(two_rooms(tmp_path, doors=[{"position": [4.0, 2.4], "width": 1.2}], name="d.json"))
    assert json.loads(scene.meta["doors"]) == [{"position": [4.0, 2.4], "width": 1.2}]
    planning = PlanningGrid(scene)
    assert "declared" in planning.walls.description and len(planning.walls.doors) == 1
    assert planning.obstacles[scene.cells_of([2])].all()
    result = planning.plan(1, (1.0, 0.5))
    ys = crossings(result.waypoints, 4.0)
    assert result.reachable and ys and all(1.8 <= y <= 3.0 for y in ys)

    closed = PlanningGrid(import_map(two_rooms(tmp_path, doors=[], name="closed.json")))
    assert closed.walls.doors == [] and closed.plan(1, (1.0, 0.5)).status == "unreachable"


def test_doors_need_room_polygons_and_sane_widths(tmp_path, capsys):
    for bad, words in ((two_rooms(tmp_path, doors=[{"position": [4, 1]}], rooms=False, name="a.json"),
                        "no room has a polygon"),
                       (two_rooms(tmp_path, doors=[{"position": [4, 1], "width": -1}], name="b.json"),
                        "greater than 0"),
                       (two_rooms(tmp_path, doors=[{"position": [4, None]}], name="c.json"), "doors[0].position")):
        assert run(["import", str(bad), "-o", str(tmp_path / "x.iesm")]) == 2
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and err[0].startswith("iesm: error: ") and words in err[0], err
    assert not (tmp_path / "x.iesm").exists()


def test_map_without_walls_or_polygons_says_so(tmp_path, capsys):
    path = two_rooms(tmp_path, rooms=False)  # the grid spans the two boxes: x 3.85-6.75, y 0.85-3.05
    assert run(["path", str(path), "--to", "1", "--start", "4.5,1.5"]) == 0
    out = capsys.readouterr().out
    assert "walls: none: the map has no walls or room polygons; the path ignores walls" in out
    assert run(["path", str(path), "--to", "1", "--start", "4.5,1.5", "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["walls"] == NO_WALLS
    service = MapService.open([str(path)])
    result = asyncio.run(service.call_tool("plan_path", {"instance_id": 1, "start": [4.5, 1.5]}))
    assert result["reachable"] and "ignores walls" in result["walls"]


def test_maps_with_wall_instances_keep_their_walls():
    layout = grid_layout(2, 1, labels=("bedroom", "kitchen"))
    planning = PlanningGrid(layout.scene)
    assert planning.walls.source == "instances" and not planning.walls.cells.any()
    assert planning.walls.description.startswith("instances: ")
