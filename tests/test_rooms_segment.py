"""Room segmentation on hand-made walled layouts: LSD boundaries, components, majority labels,
the contextual open-plan split, polygons and per-instance rooms."""

from __future__ import annotations

import numpy as np
import pytest

from iesm_agent.errors import IesmError
from iesm_agent.nav import with_obstacles
from iesm_agent.rooms import CellLabels, RoomConfig, segment_rooms, segment_scene
from iesm_agent.rooms.boundaries import boundary_raster, merge_collinear
from iesm_agent.evals.rooms import baseline_scores, score_room_map
from iesm_agent.sim.layouts import grid_layout, noisy_labels


def scores(layout, seg):
    return score_room_map(seg.room_map, seg.labels, layout.rooms, dict(enumerate(layout.room_labels)))


def test_walled_rooms_are_found_and_labelled_despite_noisy_cells():
    layout = grid_layout(3, 2)
    labels = noisy_labels(layout, accuracy=0.6, seed=1)
    seg = segment_scene(layout.scene, labels)
    assert seg.boundaries.detector == "lsd" and seg.components == 6 and seg.splits == 0
    got = scores(layout, seg)
    base = baseline_scores(labels, layout.rooms, dict(enumerate(layout.room_labels)))
    assert got["acc"] > 0.97 and got["miou"] > 0.95 and got["rooms_pred"] == 6
    assert base["acc"] < 0.7 and got["miou"] > base["miou"] + 0.3
    # each GT room is covered by one predicted room carrying its label
    for gt_id, label in enumerate(layout.room_labels):
        ids, counts = np.unique(seg.room_map[layout.rooms == gt_id], return_counts=True)
        assert seg.labels[ids[np.argmax(counts)]] == label


def test_door_gaps_are_closed_by_merging_collinear_segments():
    layout = grid_layout(2, 1, door=0.9)
    assert segment_scene(layout.scene, noisy_labels(layout, 1.0)).components == 2
    no_merge = RoomConfig(merge_gap=0.0, split=False)
    assert segment_scene(layout.scene, noisy_labels(layout, 1.0), no_merge).components == 1


def test_merge_collinear_joins_a_line_broken_by_a_gap_but_not_parallel_lines():
    segs = np.array([[0, 0, 10, 0], [14, 0.5, 30, 0.5], [0, 20, 30, 20]], np.float32)
    merged = merge_collinear(segs, angle_deg=5, offset=2, gap=6)
    assert len(merged) == 2
    long = merged[np.argmax(np.abs(merged[:, 2] - merged[:, 0]))]
    assert min(long[0], long[2]) == pytest.approx(0, abs=0.6) and max(long[0], long[2]) == pytest.approx(30, abs=0.6)
    assert len(merge_collinear(segs, angle_deg=5, offset=2, gap=2)) == 3


def test_hough_fallback_when_lsd_is_missing(monkeypatch):
    import cv2

    mask = np.zeros((100, 100), bool)
    mask[48:52, 5:95] = True
    monkeypatch.delattr(cv2, "createLineSegmentDetector")
    result = boundary_raster(mask, 0.05)
    assert result.detector == "hough" and "HoughLinesP" in result.notes[0]
    assert result.raster[50, 10:90].all() and not result.raster[10, 50]


@pytest.mark.parametrize("open_walls", [(("v", 0, 0),), (("v", 0, 0), ("h", 1, 0))])
def test_contextual_split_separates_open_plan_rooms(open_walls):
    layout = grid_layout(3, 2, open_walls=open_walls)
    labels = noisy_labels(layout, accuracy=0.6, seed=3)
    plain = segment_scene(layout.scene, labels, RoomConfig(split=False))
    ours = segment_scene(layout.scene, labels)
    assert plain.components == 6 - len(open_walls) and ours.splits == len(open_walls)
    assert scores(layout, ours)["miou"] > scores(layout, plain)["miou"] + 0.15
    assert scores(layout, ours)["miou"] > 0.95


def test_no_split_when_the_labels_do_not_cluster():
    layout = grid_layout(2, 1, open_walls=(("v", 0, 0),), labels=("living room", "living room"))
    labels = noisy_labels(layout, accuracy=0.9, seed=0)
    seg = segment_scene(layout.scene, labels)
    assert seg.splits == 0 and seg.components == 1 and seg.labels == ["living room"]


def test_segment_rooms_writes_rooms_polygons_instance_rooms_and_obstacles():
    layout = grid_layout(2, 2)
    scene = with_obstacles(segment_rooms(layout.scene, noisy_labels(layout, 0.8)))
    assert len(scene.rooms) == 4 and scene.room_map.dtype == np.int32
    for room in scene.rooms:
        xs, ys = np.array(room.polygon).T
        assert 3.0 < xs.max() - xs.min() <= 4.1 and 3.0 < ys.max() - ys.min() <= 4.1
    bed = next(i for i in scene.instances if i.label == "bed")
    assert bed.room_label == "bedroom" and scene.rooms[bed.room_id].label == "bedroom"
    assert scene.obstacles[layout.rooms < 0].mean() > 0.9 and not scene.obstacles[layout.rooms >= 0].all()
    assert (scene.room_map[layout.rooms >= 0] >= 0).mean() > 0.97    # the floor is covered (corners aside)
    assert "lsd" in scene.meta["room_segmentation"]


def test_bad_inputs_are_clear_errors():
    layout = grid_layout(1, 1)
    with pytest.raises(IesmError, match="per-cell labels are"):
        segment_scene(layout.scene, CellLabels(np.zeros((3, 3), np.int32), ["kitchen"]))


def test_no_observed_cells_means_no_rooms():
    layout = grid_layout(2, 1)
    empty = CellLabels(np.full(layout.rooms.shape, -1, np.int32), ["kitchen"])
    seg = segment_scene(layout.scene.model_copy(update={"instances": layout.scene.instances}), empty)
    assert seg.labels == [] and (seg.room_map == -1).all()


def test_thick_mapped_walls_are_shared_by_the_rooms_they_separate():
    layout = grid_layout(2, 1, wall=0.3, labels=("bedroom", "kitchen"))   # interior wall: columns 80-85
    seg = segment_scene(layout.scene, noisy_labels(layout, 1.0))
    wall = seg.room_map[10:30, 80:86]
    left, right = seg.room_map[20, 40], seg.room_map[20, 120]
    assert set(np.unique(wall).tolist()) <= {left, right, -1} and (wall == left).any() and (wall == right).any()
    assert (wall[:, 0] == left).all() and (wall[:, -1] == right).all()
    unshared = segment_scene(layout.scene, noisy_labels(layout, 1.0), RoomConfig(wall_share=0))
    assert (unshared.room_map[10:30, 80:86] == -1).all()


def test_a_wall_mapped_half_a_metre_thick_is_shared_up_to_its_middle():
    layout = grid_layout(2, 1, wall=0.5, labels=("bedroom", "kitchen"))   # interior wall: columns 80-89
    left, right = 0, 1
    for share, unassigned in ((None, 1), (0.15, 7)):   # the default, and the share before it was widened
        config = RoomConfig() if share is None else RoomConfig(wall_share=share)
        wall = segment_scene(layout.scene, noisy_labels(layout, 1.0), config).room_map[20:70, 76:94]
        assert ((wall == -1).sum(axis=1) == unassigned).all()
        assert ((wall == left).sum(axis=1) == (wall == right).sum(axis=1) - 1).all()  # each takes its side


def test_split_parts_with_the_same_label_are_rejoined():
    from iesm_agent.rooms.segment import _merge_alike_parts

    room_map = np.array([[0, 0, 2, 2, 3, -1, 1]])
    parent = [0, 1, 0, 0]                  # rooms 2 and 3 were cut out of component 0
    labels = np.array([4, 1, 2, 4])        # room 3 ended up with component 0's label
    merged, merged_labels = _merge_alike_parts(room_map, labels, parent)
    assert merged.tolist() == [[0, 0, 2, 2, 0, -1, 1]] and merged_labels.tolist() == [4, 1, 2]


def _noisy(truth: np.ndarray, flip: float, n_labels: int, seed: int) -> np.ndarray:
    rng = np.random.default_rng(seed)
    noisy = rng.random(truth.shape) < flip
    return np.where(noisy, rng.integers(0, n_labels, truth.shape), truth).astype(np.int32)


def test_label_parts_cut_an_l_shaped_room_that_no_straight_line_separates():
    from iesm_agent.rooms.segment import _label_parts

    truth = np.zeros((80, 80), np.int32)       # 4 m x 4 m at 5 cm: an L-shaped kitchen (label 1)
    truth[:25] = 1
    truth[:, :25] = 1                          # around a living room (label 0) in the other corner
    labels = _noisy(truth, 0.3, 3, seed=4)
    mask = np.ones_like(truth, bool)
    parts = _label_parts(mask, labels, None, 3, 0.05, RoomConfig())
    assert len(parts) == 2
    for part in parts:
        assert np.bincount(truth[part]).max() / part.sum() > 0.95   # each part is one true room


def test_label_parts_keep_a_room_whole_when_its_labels_are_only_noise():
    from iesm_agent.rooms.segment import _label_parts

    labels = _noisy(np.full((80, 80), 2, np.int32), 0.5, 4, seed=5)
    mask = np.ones(labels.shape, bool)
    assert len(_label_parts(mask, labels, None, 4, 0.05, RoomConfig())) == 1


def test_small_parts_join_the_neighbour_they_share_most_border_with():
    from iesm_agent.rooms.segment import _absorb_small

    parts = np.zeros((10, 10), np.int32)
    parts[:, 5:] = 1
    parts[0:2, 3:5] = 2                        # 4 cells: 4 border cells with part 0, 2 with part 1
    parts[8:10, 0:2] = -1                      # cells without a part, inside part 0
    out = _absorb_small(parts, np.ones_like(parts, bool), min_cells=10)
    assert set(np.unique(out).tolist()) == {0, 1} and (out[8:10, 0:2] == 0).all()
    assert (out[0:2, 3:5] == 0).all()           # 4 border cells with part 0 against 2 with part 1


def test_a_small_room_inside_a_large_one_is_cut_out_only_where_its_objects_stand():
    from iesm_agent.rooms.segment import _label_parts

    truth = np.zeros((120, 120), np.int32)     # a 6 m x 6 m hallway (label 0) ...
    truth[:30, :30] = 1                        # ... with a 1.5 m x 1.5 m bathroom (label 1) in a corner
    labels = _noisy(truth, 0.3, 2, seed=6)
    mask = np.ones_like(truth, bool)
    config = RoomConfig()
    assert len(_label_parts(mask, labels, None, 2, 0.05, config)) == 1    # too little evidence to split
    objects = np.zeros((2, 120, 120), np.float32)
    objects[1, 5:15, 5:15] = 1.0               # a toilet's footprint
    parts = _label_parts(mask, labels, objects, 2, 0.05, config)
    assert len(parts) == 2
    bathroom = next(part for part in parts if part[10, 10])
    assert (truth[bathroom] == 1).mean() > 0.9 and bathroom.sum() > 0.8 * 900


def test_room_labels_weigh_room_typical_objects_with_the_cell_labels():
    from iesm_agent.rooms.segment import _majority_labels

    room_map = np.zeros((10, 10), np.int32)
    labels = np.zeros((10, 10), np.int32)
    labels[:, :6] = 1                          # cells: 60 say bedroom (1), 40 bathroom (0)
    votes = np.zeros((2, 10, 10), np.float32)
    assert _majority_labels(room_map, labels, 1, 2).tolist() == [1]
    assert _majority_labels(room_map, labels, 1, 2, votes).tolist() == [1]
    votes[0, 2:7, 2:7] = 1.0                   # a toilet's and a bathtub's footprint: 25 bathroom votes
    assert _majority_labels(room_map, labels, 1, 2, votes).tolist() == [0]


def test_smoothed_choice_is_the_argmax_of_every_label_smoothed():
    import cv2

    from iesm_agent.rooms.segment import _smoothed_choice

    rng = np.random.default_rng(7)
    labels = rng.integers(0, 4, (60, 70))      # label 4 of 5 has no evidence at all
    evidence = np.stack([(labels == k).astype(np.float32) for k in range(5)])
    evidence[2, 10:20, 10:30] += 0.5 * rng.random((10, 20), dtype=np.float32)
    evidence[:, 40:, :5] = 0                    # cells without evidence: no choice when far enough
    mask = np.ones(labels.shape, bool)
    mask[:3] = False
    for sigma in (0.0, 1.0, 10.0):
        smooth = np.stack([cv2.GaussianBlur(e, (0, 0), sigma) if sigma > 0 else e for e in evidence])
        plain = np.where(mask & (smooth.max(axis=0) > 0), smooth.argmax(axis=0), -1)
        assert np.array_equal(_smoothed_choice(evidence, mask, sigma), plain)


def test_room_boxes_are_each_rooms_cell_count_and_bounds():
    from iesm_agent.rooms.segment import _room_boxes

    rng = np.random.default_rng(3)
    room_map = rng.integers(-1, 6, (40, 50)).astype(np.int32)
    room_map[room_map == 4] = 2                 # room 4 has no cells
    for room, box in enumerate(_room_boxes(room_map, 7)):
        rows, cols = np.nonzero(room_map == room)
        want = (len(rows), rows.min(), rows.max() + 1, cols.min(), cols.max() + 1) if len(rows) else (0, 0, 0, 0, 0)
        assert box == want


def test_room_labels_sum_object_votes_as_the_dense_sum_does():
    from iesm_agent.rooms.segment import _majority_labels

    rng = np.random.default_rng(5)
    room_map = rng.integers(-1, 4, (30, 30)).astype(np.int32)
    labels = rng.integers(-1, 3, (30, 30)).astype(np.int32)
    votes = np.where(rng.random((3, 30, 30)) < 0.05, rng.random((3, 30, 30)), 0).astype(np.float32)
    counts = np.zeros((4, 3))
    for room in range(4):
        counts[room] = np.bincount(labels[(room_map == room) & (labels >= 0)], minlength=3)
        counts[room] += (0.7 * votes[:, room_map == room]).sum(axis=1)
    assert _majority_labels(room_map, labels, 4, 3, votes, 0.7).tolist() == counts.argmax(axis=1).tolist()


def test_a_neighbours_label_seen_through_the_door_is_not_cut_out_as_a_room():
    from iesm_agent.rooms.segment import Neighbours, _label_parts

    truth = np.zeros((100, 100), np.int32)      # a 5 m x 5 m hallway (label 0) whose door side ...
    truth[60:] = 1                              # ... says living room (label 1), as seen from next door
    labels = _noisy(truth, 0.2, 2, seed=8)
    mask = np.ones_like(truth, bool)
    config = RoomConfig(split_min_area=0)
    assert len(_label_parts(mask, labels, None, 2, 0.05, config)) == 2   # alone, the labels would cut it
    near = np.full(truth.shape, -1, np.int32)
    near[90:] = 1                               # a living room behind the wall below, 0.5 m away ...
    distance = np.where(near >= 0, 10.0, 99.0).astype(np.float32)
    strong = np.full(truth.shape, 8000.0)       # ... whose own living-room evidence outweighs the part's
    assert len(_label_parts(mask, labels, None, 2, 0.05, config, lambda: Neighbours(near, distance, strong))) == 1
    weak = np.full(truth.shape, 1000.0)         # a small room that only says living room: no spill-over
    assert len(_label_parts(mask, labels, None, 2, 0.05, config, lambda: Neighbours(near, distance, weak))) == 2
    distance[90:] = 1.0                         # touching the room (no wall): a piece of it
    assert len(_label_parts(mask, labels, None, 2, 0.05, config, lambda: Neighbours(near, distance, strong))) == 2


def test_an_instance_outside_every_room_takes_the_nearest_room_within_reach():
    from iesm_agent.rooms.scene import instance_rooms
    layout = grid_layout(2, 2)
    scene = segment_rooms(layout.scene, noisy_labels(layout, 1.0))
    bed = next(i for i in scene.instances if i.label == "bed")
    flat, ids, _ = scene.occupancy.entries()
    room_map = scene.room_map.copy()
    room_map.ravel()[flat[ids == bed.id]] = -1       # the bed's mapped cells fall outside the room
    assert bed.id not in instance_rooms(scene, room_map)
    assert bed.id not in instance_rooms(scene, room_map, reach=0.5)   # its edge is one cell from the room
    assert instance_rooms(scene, room_map, reach=1.5)[bed.id] == bed.room_id
    others = {k: v for k, v in instance_rooms(scene, room_map, reach=1.5).items() if k != bed.id}
    assert others == {k: v for k, v in instance_rooms(scene, room_map).items()}   # the others keep theirs
