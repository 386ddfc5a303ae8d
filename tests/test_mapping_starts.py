"""Robot starts for N-SR in suites written from ground truth: on free floor inside a room, clear
of obstacles, seeded."""

import numpy as np

from iesm_agent.sim.ground_truth import GroundTruth
from iesm_agent.evals.gt_queries import START_CLEARANCE_M, free_starts
from iesm_agent.store import GridSpec, InstanceGrid


def _gt(occupancy: np.ndarray, rooms: np.ndarray) -> GroundTruth:
    grid = GridSpec(cell_size=0.1, origin=(0.0, 0.0), height=rooms.shape[0], width=rooms.shape[1])
    return GroundTruth("g", [], [], grid, rooms, occupancy, InstanceGrid.empty())


def test_starts_lie_on_clear_floor_inside_rooms_and_repeat_with_the_seed():
    rooms = np.full((30, 40), -1, np.int32)
    rooms[:, :20] = 1                      # the right half is outside every room
    occupancy = np.zeros((30, 40), bool)
    occupancy[10:20, 5:15] = True          # a big table
    gt = _gt(occupancy, rooms)
    starts = free_starts(gt, 50, seed=3)
    assert len(starts) == 50 and starts == free_starts(gt, 50, seed=3) and starts != free_starts(gt, 50, seed=4)
    for x, y in starts:
        r, c = gt.grid.cell_of(x, y)
        assert rooms[r, c] == 1
        # the table spans x 0.5-1.5 m, y 1.0-2.0 m: the start keeps the clearance from it
        dx = max(0.5 - x, 0.0, x - 1.5)
        dy = max(1.0 - y, 0.0, y - 2.0)
        assert np.hypot(dx, dy) >= START_CLEARANCE_M - 0.1


def test_no_free_floor_means_no_starts():
    rooms = np.ones((10, 10), np.int32)
    assert free_starts(_gt(np.ones((10, 10), bool), rooms), 5, seed=0) == []
