"""`project_candidates` against a plain per-mask, per-cell reference (overlapping masks, missing
and far depth, min_pixels; per cell the highest point and the nearest reading), and
`cells.group_ids` on its counting and its sorting path."""

import numpy as np
import pytest

from iesm_agent.mapping.cells import group_ids, rowcol_of
from iesm_agent.mapping.project import pixel_cells, project_candidates


def _reference(depth, masks, k, pose, cell, min_pixels, max_depth):
    """One mask at a time, one cell at a time: dicts over (mask, key)."""
    usable = ((depth > 0) & (depth <= max_depth) & np.isfinite(depth)).ravel()
    out = []
    for m in range(len(masks)):
        pixels = np.flatnonzero(masks[m].ravel() & usable)
        if len(pixels) < max(min_pixels, 1):
            continue
        keys, z = pixel_cells(depth, pixels, *k, pose, cell)
        cells = {key: z[keys == key] for key in np.unique(keys)}
        reading = depth.ravel()[pixels]
        out.append((m, int(masks[m].sum()), sorted(cells),
                    [float(cells[key].max()) for key in sorted(cells)],
                    [float(reading[keys == key].min()) for key in sorted(cells)],
                    float(np.mean([cells[key].mean(dtype=np.float64) for key in cells]))))
    return out


@pytest.mark.parametrize("max_depth", [np.inf, 4.0])
def test_candidates_equal_a_per_mask_reference(max_depth):
    rng = np.random.default_rng(7)
    h, w = 30, 40
    depth = rng.uniform(0.5, 6.0, (h, w)).astype(np.float32)
    depth[rng.random((h, w)) < 0.1] = 0.0
    depth[0, :3] = (np.nan, np.inf, -1.0)
    depth[5, 5] = 400.0                                   # one far reading: a wide cell box
    masks = rng.random((6, h, w)) < 0.3                   # overlapping masks
    masks[4] = False
    masks[4, 0, :3] = True                                # only unusable pixels: dropped
    masks[5] = False
    masks[5, 10, 10:13] = True                            # 3 pixels: dropped by min_pixels=4
    angle = 0.3
    pose = np.array([[np.cos(angle), 0, np.sin(angle), -1.3], [-np.sin(angle), 0, np.cos(angle), 2.2],
                     [0, -1, 0, 1.4], [0, 0, 0, 1]])
    k = (30.0, 30.0, 19.5, 14.5)
    c = project_candidates(depth, masks, *k, pose, 0.1, min_pixels=4, max_depth=max_depth)
    ref = _reference(depth, masks, k, pose, 0.1, 4, max_depth)
    assert c.mask_index.tolist() == [r[0] for r in ref]
    assert c.area_px.tolist() == [r[1] for r in ref]
    for a, (_m, _area, keys, tops, nearest, mean) in enumerate(ref):
        got_keys, got_top, got_near = c.cells(a)
        assert got_keys.tolist() == keys
        assert got_top.tolist() == tops
        assert got_near.tolist() == nearest
        assert c.mean_height[a] == pytest.approx(mean, abs=1e-6)
    rows, cols = rowcol_of(c.keys)
    for a in range(len(c)):
        s, e = c.offsets[a], c.offsets[a + 1]
        assert c.bbox[a].tolist() == [rows[s:e].min(), rows[s:e].max(), cols[s:e].min(), cols[s:e].max()]


@pytest.mark.parametrize("size", [50, 10 ** 9])
def test_group_ids_counts_or_sorts_alike(size):
    values = np.random.default_rng(1).integers(0, 50, 200) * (size // 50)
    distinct, inverse, counts = group_ids(values, size)
    expect, expect_inverse, expect_counts = np.unique(values, return_inverse=True, return_counts=True)
    assert distinct.tolist() == expect.tolist() and counts.tolist() == expect_counts.tolist()
    assert inverse.tolist() == expect_inverse.tolist()
    assert group_ids(np.zeros(0, np.int64), 0)[0].tolist() == []


def test_cells_beyond_the_key_range_are_held_at_its_edge():
    depth = np.full((6, 8), 2.0, np.float32)
    masks = np.ones((1, 6, 8), bool)
    pose = np.eye(4)
    pose[0, 3] = 2e5                                      # 200 km east: past the keys' +-50 km
    c = project_candidates(depth, masks, 8.0, 8.0, 3.5, 2.5, pose, 0.05)
    _rows, cols = rowcol_of(c.keys)
    assert (np.diff(c.keys) > 0).all() and (cols == (1 << 20) - 1).all()
