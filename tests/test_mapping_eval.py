"""The 2D point-wise baseline, matching across grids and the optional evaluation sections."""

from __future__ import annotations

import numpy as np
import pytest

from iesm_agent.config import MappingConfig
from iesm_agent.frames import Frame, Intrinsics, Segmentation
from iesm_agent.evals.baseline2d import PointwiseMap2D
from iesm_agent.evals.matching import cells_in_grid, greedy_pairs
from iesm_agent.evals.mapping_metrics import small_categories, topmost_labels
from iesm_agent.store.model import GridSpec


def test_a_2d_cell_averages_the_features_of_all_its_points():
    # a 2 x 2 image, every pixel lands in one 10 m cell: 3 pixels of mask A, 1 of mask B
    intr = Intrinsics(width=2, height=2, fx=1.0, fy=1.0, cx=0.5, cy=0.5)
    masks = np.zeros((2, 2, 2), bool)
    masks[0].flat[:3] = True
    masks[1].flat[3] = True
    emb = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]], np.float32)
    e = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]])
    pose = np.eye(4)
    pose[:3, 3] = (5.0, 5.0, 0.0)
    frame = Frame(0, np.zeros((2, 2, 3), np.uint8), np.ones((2, 2), np.float32), pose)
    flat = PointwiseMap2D(intr, e, MappingConfig(cell_size=10.0))
    flat.add(frame, Segmentation(masks, emb, np.ones(2, np.float32)))
    flat.add(frame, Segmentation(masks[1:], emb[1:], np.ones(1, np.float32)))   # one more B point
    keys, scores = flat.finish()
    assert len(keys) == 1
    assert scores[0] == pytest.approx([3 / 5, 2 / 5, 0.0])


def test_cells_move_between_grids_by_their_centres():
    src = GridSpec(cell_size=0.05, origin=(0.0, 0.0), height=10, width=10)
    dst = GridSpec(cell_size=0.05, origin=(-0.10, 0.05), height=10, width=10)
    # src cell (row 3, col 4): centre (0.225, 0.175) -> dst row 2, col 6
    assert cells_in_grid(np.array([3 * 10 + 4, 99]), src, dst).tolist() == [2 * 10 + 6, -1]


def test_greedy_pairs_are_one_to_one_and_above_the_threshold():
    g = np.array([1, 1, 2, 3])
    p = np.array([10, 11, 10, 12])
    iou = np.array([0.9, 0.6, 0.7, 0.5])
    assert greedy_pairs(g, p, iou, 0.5) == {1: 10}   # 2 loses 10 to 1; 3 is not above 0.5


def test_top_most_instance_labels_the_cell():
    flat = np.array([0, 0, 1, 2])
    ids = np.array([7, 8, 7, 9])
    top = np.array([0.75, 0.87, 0.75, np.nan], np.float32)
    assert topmost_labels(flat, ids, top, {7: 0, 8: 1, 9: 2}, 4).tolist() == [1, 0, 2, -1]


def test_small_categories_are_those_in_the_bottom_fifth():
    labels = ["cup", "cup", "table", "sofa", "book", "bed"]
    areas = np.array([4, 6, 300, 700, 8, 1300])
    assert small_categories(labels, areas, 0.2) == {"cup"}    # 20th percentile = 6
