"""Tops seen at grazing incidence (mapping/tops.py): filled where a top face must be, nowhere else."""

import numpy as np

from iesm_agent.config import MappingConfig
from iesm_agent.frames import Intrinsics
from iesm_agent.mapping.build import MapBuilder
from iesm_agent.mapping.cells import rowcol_of
from iesm_agent.mapping.project import project_candidates, world_points
from iesm_agent.mapping.tops import TOP_PERCENTILE, fill_tops

F, CX, CY, CAM_Z = 160.0, 159.5, 119.5, 1.35
# camera looking along world +y, level: camera x = world x, camera y (down) = world -z, camera z = world y
POSE = np.array([[1, 0, 0, 0], [0, 0, 1, 0], [0, -1, 0, CAM_Z], [0, 0, 0, 1]], np.float64)
FRONT_Y, TOP_Z, BOTTOM_Z, BACK_Y = 2.0, 1.2, 0.9, 2.3   # a box 0.3 m deep, its front face 2 m away


def _box_frame(wall_y: float = 3.0):
    """(depth (240, 320) m, true depth, mask (1, 240, 320)): a box below the camera, its front face
    read, its top face (seen at grazing incidence) without readings, in columns 140-179; above it
    (smaller rows) a wall `wall_y` m away, read."""
    rows = np.arange(240, dtype=np.float64)[:, None]
    b = (rows - CY) / F + np.zeros((1, 320))           # ray: world z drops by b per metre of depth
    front = (CAM_Z - FRONT_Y * b >= BOTTOM_Z) & (CAM_Z - FRONT_Y * b <= TOP_Z)
    with np.errstate(divide="ignore"):
        t_top = (CAM_Z - TOP_Z) / b
    top = (b > 0) & (t_top >= FRONT_Y) & (t_top <= BACK_Y) & ~front
    cols = np.zeros((1, 320), bool)
    cols[0, 140:180] = True
    box = (front | top) & cols
    wall = (rows < np.argmax(box, axis=0)[None, :]) & cols & ~box
    truth = np.where(front & cols, FRONT_Y, np.where(top & cols, t_top, np.where(wall, wall_y, 0.0))).astype(np.float32)
    depth = np.where(front & cols, FRONT_Y, np.where(wall, wall_y, 0.0)).astype(np.float32)
    return depth, truth, box[None]


def _fill(depth, masks, max_cos=0.3, max_ratio=1.1):
    return fill_tops(depth, masks, F, F, CX, CY, POSE, max_cos=max_cos, max_ratio=max_ratio, min_readings=20)


def test_top_face_pixels_get_the_depth_of_the_top_plane():
    depth, truth, masks = _box_frame()
    top = masks[0] & (depth == 0)
    assert top.sum() >= 40                                  # the test box shows a top face
    out = _fill(depth, masks)
    filled = out != depth
    assert filled.any() and not (filled & ~top).any()      # only top-face pixels, never a reading
    assert depth[top].max() == 0                            # the input is left alone
    assert (out[filled] >= FRONT_Y).all() and (out[filled] <= 1.1 * FRONT_Y).all()
    pix = np.flatnonzero(filled)
    z = world_points(out, pix, F, F, CX, CY, POSE)[2]
    read = np.flatnonzero(masks[0] & (depth > 0))
    h = np.percentile(world_points(depth, read, F, F, CX, CY, POSE)[2], TOP_PERCENTILE)
    np.testing.assert_allclose(z, h, atol=1e-4)             # on the plane of the mask's top
    assert abs(h - TOP_Z) < 0.02
    np.testing.assert_allclose(out[filled], truth[filled], rtol=0.05)


def test_top_cells_join_the_footprint():
    depth, truth, masks = _box_frame()
    cells = {}
    for name, d in (("read", depth), ("filled", _fill(depth, masks)), ("true", truth)):
        cands = project_candidates(d, masks, F, F, CX, CY, POSE, 0.05)
        cells[name] = set(cands.cells(0)[0].tolist())
    rows = {int(r) for r in rowcol_of(np.array(sorted(cells["filled"])))[0]}
    assert cells["read"] < cells["filled"]                  # the top adds cells behind the front face ...
    assert rows <= set(range(int(FRONT_Y / 0.05), int(BACK_Y / 0.05)))   # ... all of them on the box
    assert 2 * len(cells["filled"] - cells["read"]) >= len(cells["true"] - cells["read"])   # a row of 2


def test_no_fill_without_grazing_incidence_beyond_the_ratio_or_below_a_reading():
    depth, _truth, masks = _box_frame()
    assert np.array_equal(_fill(depth, masks, max_cos=0.01), depth)    # the top plane seen too steeply
    assert np.array_equal(_fill(depth, masks, max_ratio=1.0), depth)   # no depth behind the front edge allowed
    holed = depth.copy()
    holed[140, 150] = 0.0                                   # a hole in the front face, readings above it
    assert _fill(holed, masks)[140, 150] == 0.0


def test_no_fill_behind_what_is_seen_beyond_the_object():
    depth, _truth, masks = _box_frame()
    filled = _fill(depth, masks) != depth
    assert filled.any()
    near, _truth, _masks = _box_frame(wall_y=2.1)           # a wall 0.1 m behind the front face
    out = _fill(near, masks)
    assert (out[filled & (out != near)] < 2.1).all() and (out != near).sum() < filled.sum()
    unseen = depth.copy()
    unseen[depth == 3.0] = 0.0                              # nothing read above the box
    assert np.array_equal(_fill(unseen, masks), unseen)


def test_no_fill_for_a_top_above_the_camera_or_too_few_readings():
    depth, _truth, masks = _box_frame()
    up = depth[::-1].copy()                                 # the image upside down: a face above the camera
    above = up == FRONT_Y
    rows = np.flatnonzero(above.any(axis=1))
    above[rows[0] - 3:rows[0]] = above[rows[0]]             # with three rows of holes above its readings
    assert np.array_equal(_fill(up, above[None], max_ratio=10.0), up)
    assert not np.array_equal(_fill(depth, masks, max_ratio=10.0), depth)
    assert np.array_equal(fill_tops(depth, masks, F, F, CX, CY, POSE, max_cos=0.3, max_ratio=1.1,
                                    min_readings=10 ** 6), depth)


def test_the_builder_fills_tops_by_default_and_uncleaned_does_not():
    from iesm_agent.frames import Frame, Segmentation

    depth, _truth, masks = _box_frame()
    frame = Frame(0, np.zeros((240, 320, 3), np.uint8), depth, POSE)
    seg = Segmentation(masks, np.ones((1, 4), np.float32), np.ones(1, np.float32))
    intr = Intrinsics(width=320, height=240, fx=F, fy=F, cx=CX, cy=CY)
    sizes = {}
    for name, cfg in (("ours", MappingConfig(depth_smooth_px=0, mask_erode_px=0)),
                      ("uncleaned", MappingConfig.uncleaned())):
        builder = MapBuilder(intr, cfg)
        builder.add(frame, seg)
        sizes[name] = int(builder.dictionary.sizes[0])
    assert MappingConfig.uncleaned().top_fill_max_cos is None and MappingConfig.paper().top_fill_max_cos is None
    assert sizes["ours"] > 2 * sizes["uncleaned"]
