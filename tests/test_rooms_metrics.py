"""Room metrics on tiny hand-computed maps, grid resampling and the obstacle map."""

from __future__ import annotations

import numpy as np
import pytest

from iesm_agent.nav import ObstacleConfig, inflate, obstacle_map
from iesm_agent.rooms import CellLabels
from iesm_agent.evals.rooms import baseline_scores, resample, score_room_map
from iesm_agent.sim.layouts import grid_layout
from iesm_agent.store.model import GridSpec


def test_label_and_overlap_metrics_by_hand():
    gt = np.array([[0, 0, 1, 1],
                   [0, 0, 1, 1],
                   [-1, -1, -1, -1]])
    pred = np.array([[0, 0, 0, 1],
                     [0, 0, 0, 1],
                     [1, 1, 1, 1]])          # the bottom row is outside GT rooms: ignored
    got = score_room_map(pred, ["kitchen", "bedroom"], gt, {0: "kitchen", 1: "bedroom"})
    assert got["acc"] == pytest.approx(6 / 8)
    assert got["macc"] == pytest.approx((4 / 4 + 2 / 4) / 2)
    assert got["miou"] == pytest.approx((4 / 6 + 2 / 4) / 2)
    assert got["precision"] == pytest.approx((4 / 6 + 2 / 2) / 2)   # pred 0 spills into GT 1
    assert got["recall"] == pytest.approx((4 / 4 + 2 / 4) / 2)


def test_wrong_label_costs_acc_but_not_overlap():
    gt = np.array([[0, 0, 1, 1]])
    got = score_room_map(gt.copy(), ["bedroom", "bedroom"], gt, {0: "kitchen", 1: "bedroom"})
    assert got["acc"] == 0.5 and got["precision"] == 1.0 and got["recall"] == 1.0
    assert got["miou"] == pytest.approx((0 + 2 / 4) / 2)


def test_unassigned_cells_count_as_wrong():
    gt = np.array([[0, 0, 0, 0]])
    got = score_room_map(np.array([[-1, -1, 0, 0]]), ["kitchen"], gt, {0: "kitchen"})
    assert got["acc"] == 0.5 and got["recall"] == 0.5 and got["precision"] == 1.0


def test_baseline_rooms_are_label_components():
    gt = np.array([[0, 0, 0, 1, 1, 1]])
    labels = CellLabels(np.array([[0, 1, 0, 1, 1, -1]]), ["kitchen", "bedroom"])
    got = baseline_scores(labels, gt, {0: "kitchen", 1: "bedroom"})
    # scored on the cells the labels cover (the unlabelled one is not charged) ...
    assert got["rooms_pred"] == 4 and got["acc"] == pytest.approx(4 / 5) and got["cells"] == 5
    # ... unless the evaluated cells are given
    every = baseline_scores(labels, gt, {0: "kitchen", 1: "bedroom"}, np.ones_like(gt, bool))
    assert every["acc"] == pytest.approx(4 / 6) and every["cells"] == 6


def test_resample_between_grids():
    src = GridSpec(cell_size=0.1, origin=(0.0, 0.0), height=2, width=2)
    dst = GridSpec(cell_size=0.05, origin=(-0.05, 0.0), height=4, width=5)
    out = resample(np.array([[1, 2], [3, 4]]), src, dst)
    assert out[:, 0].tolist() == [-1] * 4                       # left of the source grid
    assert out[0, 1:].tolist() == [1, 1, 2, 2] and out[3, 1:].tolist() == [3, 3, 4, 4]


def test_obstacles_by_height_or_label_and_inflation():
    layout = grid_layout(1, 1)
    scene = layout.scene
    walls = obstacle_map(scene, ObstacleConfig(h_min=5, h_max=6))             # labels only
    assert walls[0].all() and walls.sum() > 0
    by_height = obstacle_map(scene, ObstacleConfig(h_min=0.4, h_max=0.6, labels=()))
    sofa = next(i for i in scene.instances if i.label == "sofa")
    assert by_height.sum() == sofa.footprint_cells
    assert not obstacle_map(scene, ObstacleConfig(h_min=2, h_max=3, labels=())).any()
    grown = inflate(by_height, 0.1, 0.05)
    assert grown.sum() > by_height.sum() and (grown | ~by_height).all()
    rows, cols = np.nonzero(by_height)
    assert grown[rows.min() - 2, cols.min() + 1] and not grown[rows.min() - 3, cols.min() + 1]
