"""Far readings out of the footprints, not out of the map (`MappingConfig.reliable_depth`,
`InstanceDictionary.reliable_footprints`): a cell only a far view placed leaves the footprint of an
instance that nearer readings placed elsewhere; the far view still votes for the label; an instance
seen only from far keeps its cells."""

import numpy as np

from iesm_agent.config import MappingConfig
from iesm_agent.frames import Frame, Intrinsics, Segmentation
from iesm_agent.mapping.build import MapBuilder

F, CX, CY = 160.0, 159.5, 119.5
INTR = Intrinsics(width=320, height=240, fx=F, fy=F, cx=CX, cy=CY)
CELL = 0.05


def _frame(index: int, y: float, views: list[tuple[int, int, float, float]], embeddings: np.ndarray) -> tuple:
    """A frame from world (0, `y`), 1.35 m up, level, looking along world +y (depth = world y - `y`);
    mask k covers rows 100-139 of columns views[k][0] to views[k][1] - 1, its upper half read at
    views[k][2] m, its lower half at views[k][3] m."""
    pose = np.array([[1, 0, 0, 0], [0, 0, 1, y], [0, -1, 0, 1.35], [0, 0, 0, 1]], np.float64)
    depth = np.zeros((240, 320), np.float32)
    masks = np.zeros((len(embeddings), 240, 320), bool)
    for k, (c0, c1, upper, lower) in enumerate(views):
        cols = slice(c0, c1)
        masks[k, 100:140, cols] = True
        depth[100:120, cols], depth[120:140, cols] = upper, lower
    seg = Segmentation(masks, embeddings.astype(np.float32), np.ones(len(embeddings), np.float32))
    return Frame(index, np.zeros((240, 320, 3), np.uint8), depth, pose), seg


def _built(reliable_depth):
    """The map of two views: object 0 read at 2 m from y = 0, and from y = -2.5 at 4.5 m (upper
    half) and 4.76 m (lower half: a far reading 0.26 m off); object 1 read only from y = -2.5, at 4.5 m.
    Returns the map and {label: the world rows (y / CELL) of its footprint}."""
    near_view = np.array([[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]])
    far_view = np.array([[0.8, 0.6, 0.0], [0.0, 0.0, 1.0]])   # the far view's own vote for object 0
    cfg = MappingConfig(reliable_depth=reliable_depth, depth_smooth_px=0, mask_erode_px=0, top_fill_max_cos=None,
                        continuity_gap=None, cell_size=CELL)
    builder = MapBuilder(INTR, cfg)
    builder.add(*_frame(0, 0.0, [(130, 190, 2.0, 2.0)], near_view[:1]))             # x -0.37..0.37 m
    builder.add(*_frame(1, -2.5, [(147, 173, 4.5, 4.76), (250, 300, 4.5, 4.5)], far_view))
    scene = builder.finish(["a", "b", "c"], np.eye(3, dtype=np.float32), scene_id="s", embedding_space="hash-384")
    rows = {}
    for inst in scene.instances:
        r, _c = np.nonzero(scene.cells_of([inst.id]))
        rows[inst.label] = sorted({int(v) + round(scene.grid.origin[1] / CELL) for v in r})
    return scene, rows


def test_far_cells_leave_a_footprint_that_nearer_readings_placed():
    _scene, every = _built(None)
    assert every == {"a": [40, 45], "c": [40]}     # the far view's lower half lands 0.25 m behind object 0
    scene, cut = _built(4.0)
    assert cut == {"a": [40], "c": [40]}           # object 1, seen only from 4.5 m, keeps its cells
    assert [i.label for i in scene.instances] == ["a", "c"]


def test_the_far_view_still_votes_for_the_label():
    scene, _rows = _built(4.0)
    a = next(i for i in scene.instances if i.label == "a")
    assert a.weight == 2 and sorted(a.frames) == [0, 1]
    assert scene.embeddings[a.id - 1][1] > 0.2    # the mean of both views' embeddings, not the near view's


def test_off_in_the_papers_rules_and_uncleaned():
    assert MappingConfig.paper().reliable_depth is None and MappingConfig.uncleaned().reliable_depth is None
