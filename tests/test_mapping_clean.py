"""Geometry cleaning before projection (mapping/clean.py) and the cell-support filter."""

import numpy as np

from iesm_agent.config import MappingConfig
from iesm_agent.mapping.clean import clean_masks, depth_edges, smooth_depth
from iesm_agent.mapping.project import project_candidates


def _box_scene():
    """A 20 x 20 frame: a box at 1 m in rows/cols 5-14 in front of a wall at 3 m; the mask of the
    box leaks two pixels onto the wall on every side."""
    depth = np.full((20, 20), 3.0, np.float32)
    depth[5:15, 5:15] = 1.0
    mask = np.zeros((1, 20, 20), bool)
    mask[0, 3:17, 3:17] = True
    return depth, mask


def test_depth_edges_mark_both_sides_of_a_jump_only():
    depth, _ = _box_scene()
    edge = depth_edges(depth, 0.1)
    assert edge[5, 5:15].all() and edge[4, 5:15].all()      # box rim and the wall pixel beside it
    assert not edge[10, 10] and not edge[0, 0]
    depth[0, 0] = 0.0                                       # a missing reading is no jump
    assert not depth_edges(depth, 0.1)[0, 1]


def test_depth_edge_pixels_leave_the_mask():
    depth, mask = _box_scene()
    out = clean_masks(mask, depth, edge_jump=0.1)
    assert not out[0][5, 5:15].any() and not out[0][4, 5:15].any()   # both sides of the box rim
    assert out[0][10, 10] and out[0][3, 3]
    assert mask[0].sum() == 14 * 14                                   # the input is left alone


def test_erosion_and_edges_shrink_but_never_erase_a_small_mask():
    depth, mask = _box_scene()
    eroded = clean_masks(mask, depth, erode_px=2)
    assert eroded[0].sum() == 10 * 10
    tiny = np.zeros((1, 20, 20), bool)
    tiny[0, 9:11, 9:11] = True
    assert clean_masks(tiny, depth, erode_px=1, min_pixels=2)[0].sum() == 4


def test_off_settings_return_the_masks_unchanged():
    depth, mask = _box_scene()
    assert clean_masks(mask, depth) is mask


def test_min_cell_points_drops_thinly_supported_cells_and_empty_candidates():
    pose = np.eye(4)
    depth = np.ones((10, 10), np.float32)
    masks = np.zeros((2, 10, 10), bool)
    masks[0, :5, :5] = True
    masks[0, 9, 9] = True                                    # a lone pixel far from the rest
    masks[1, 9, 0] = True
    k = (10.0, 10.0, 4.5, 4.5)
    every = project_candidates(depth, masks, *k, pose, 0.5)     # 0.5 m cells: 5 x 5 pixels each
    supported = project_candidates(depth, masks, *k, pose, 0.5, min_cell_points=2)
    assert len(every) == 2 and len(supported) == 1            # mask 1's one cell has one point
    assert len(every.cells(0)[0]) == 2 and len(supported.cells(0)[0]) == 1
    assert supported.area_px.tolist() == [26]


def test_paper_and_uncleaned_turn_cleaning_off():
    for cfg in (MappingConfig.paper(), MappingConfig.uncleaned()):
        assert cfg.mask_erode_px == 0 and cfg.depth_edge_jump is None
        assert cfg.min_cell_points == 1 and cfg.depth_smooth_px == 0
    assert MappingConfig().depth_smooth_px > 0
    assert MappingConfig.paper().delta_geo_strong is None


def test_smoothing_averages_noise_on_a_surface_but_keeps_edges_and_holes():
    """Two walls at 2 m and 3 m with per-pixel noise growing as depth squared (a structured-light
    sensor), and a hole: the noise falls, the step between the walls stays sharp, the hole stays."""
    rng = np.random.default_rng(0)
    exact = np.full((60, 80), 3.0, np.float32)
    exact[:, 40:] = 2.0
    noisy = exact + rng.standard_normal(exact.shape).astype(np.float32) * 0.003 * exact ** 2
    noisy[20:25, 10:15] = 0.0
    out = smooth_depth(noisy, 7, 0.01)
    seen = noisy > 0
    assert (out[~seen] == 0).all() and (out[seen] > 0).all()
    before, after = np.abs(noisy - exact)[seen].mean(), np.abs(out - exact)[seen].mean()
    assert after < before / 2
    assert np.abs(out - exact)[:, 37:43].max() < 0.15          # no blur across the 1 m step
    assert np.array_equal(smooth_depth(exact, 7, 0.01) > 0, exact > 0)
