"""The one cell-region tracer (rooms/outline.py), used by rooms and the simulator's floor plans."""

import numpy as np
import pytest

from iesm_agent.rooms.outline import cells_polygon
from iesm_agent.rooms.scene import room_polygon
from iesm_agent.store.model import GridSpec, InstanceGrid, SceneMap


def _area(poly):
    xy = np.asarray(poly, np.float64)
    return float(np.dot(xy[:, 0], np.roll(xy[:, 1], -1)) - np.dot(xy[:, 1], np.roll(xy[:, 0], -1))) / 2


def test_outline_runs_through_cell_corners_and_skips_holes_and_small_blobs():
    mask = np.zeros((10, 12), bool)
    mask[1:8, 1:9] = True
    mask[3:5, 3:5] = False          # a hole
    mask[9, 11] = True              # a one-cell blob elsewhere
    poly = cells_polygon(mask, 0.5)
    assert sorted(poly) == sorted([(0.5, 0.5), (4.5, 0.5), (4.5, 4.0), (0.5, 4.0)])
    assert _area(poly) == pytest.approx(7 * 8 * 0.25)          # counter-clockwise: positive
    assert cells_polygon(np.zeros((3, 3), bool), 1.0) == []


def test_room_polygon_is_the_outline_in_world_metres():
    grid = GridSpec(cell_size=0.1, origin=(2.0, -1.0), height=10, width=10)
    scene = SceneMap(scene_id="s", grid=grid, instances=[], occupancy=InstanceGrid.empty())
    mask = np.zeros((10, 10), bool)
    mask[2:6, 3:9] = True
    assert sorted(room_polygon(mask, scene)) == sorted([(2.3, -0.8), (2.9, -0.8), (2.9, -0.4), (2.3, -0.4)])
    assert room_polygon(np.zeros((10, 10), bool), scene) is None
