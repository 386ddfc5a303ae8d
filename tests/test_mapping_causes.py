"""Causes of unmatched seen objects (evals/mapping_causes.py) on hand-made masks and observations."""

import numpy as np

from iesm_agent.evals.mapping_causes import cause_counts, mask_objects, unmatched_causes
from iesm_agent.frames import Frame, Segmentation


def _entries(masks: dict[int, list[int]]) -> tuple[np.ndarray, np.ndarray]:
    flat = np.concatenate([np.array(c, np.int64) for c in masks.values()])
    ids = np.concatenate([np.full(len(c), i, np.int64) for i, c in masks.items()])
    return flat, ids


def test_each_cause_is_told_apart():
    gt = _entries({1: list(range(0, 10)), 2: list(range(20, 30)), 3: list(range(24, 28)),
                   4: list(range(60, 70)), 5: list(range(80, 90)), 6: list(range(100, 110)),
                   7: list(range(120, 130))})
    pred = _entries({
        11: list(range(0, 10)),                              # matches object 1
        12: list(range(20, 30)),                             # object 2 (a table), holding object 3 (a cup)
        14: list(range(60, 68)) + list(range(140, 160)),     # object 4, inflated (IoU 8/30)
        15: list(range(80, 83)), 16: list(range(86, 89)),     # object 5 in two pieces
        17: list(range(100, 102)),                           # object 6: a sliver
    })
    # (frame, mask) -> object the mask shows; observations: [instance, frame, mask, area, score]
    shows = {(0, 0): 1, (0, 1): 2, (1, 1): 2, (0, 2): 3, (1, 2): 3, (0, 3): 4, (0, 4): 5, (1, 4): 5,
             (0, 5): 6, (1, 7): 7}
    obs = np.array([[11, 0, 0, 1, 1], [12, 0, 1, 1, 1], [12, 1, 1, 1, 1], [12, 0, 2, 1, 1], [12, 1, 2, 1, 1],
                    [14, 0, 3, 1, 1], [15, 0, 4, 1, 1], [16, 1, 4, 1, 1], [17, 0, 5, 1, 1]], np.float64)
    causes = unmatched_causes(pred, gt, np.arange(1, 8), {1, 2}, obs, shows)
    assert causes == {3: "swallowed", 4: "inflated", 5: "split", 6: "partial", 7: "never segmented"}
    assert cause_counts(causes) == {"never segmented": 1, "swallowed": 1, "split": 1, "inflated": 1,
                                    "partial": 1}


def test_an_instance_belongs_to_the_object_most_of_its_masks_show():
    gt = _entries({1: [0, 1, 2, 3], 2: [0, 1]})
    pred = _entries({9: [0, 1, 2, 3, 4, 5, 6, 7, 8, 9]})
    shows = {(0, 0): 1, (1, 0): 1, (2, 0): 2}
    obs = np.array([[9, 0, 0, 1, 1], [9, 1, 0, 1, 1], [9, 2, 0, 1, 1]], np.float64)
    # object 1 owns instance 9 (two masks of three), which is too large: inflated; object 2 swallowed
    assert unmatched_causes(pred, gt, np.array([1, 2]), set(), obs, shows) == {1: "inflated", 2: "swallowed"}


def test_stacked_groups_count_ours_and_the_baselines_names():
    from types import SimpleNamespace

    from iesm_agent.evals.studies.mapping_causes import stacked_groups

    ctx = SimpleNamespace(stacked={3, 4, 5, 6})
    groups = stacked_groups(ctx, right={3: True, 4: False, 9: True}, causes={5: "inflated", 6: "partial"},
                            baseline_right={3: True, 4: True, 5: True, 6: False, 9: True})
    assert groups["named right"] == {"objects": 1, "baseline_right": 1}
    assert groups["named wrong"] == {"objects": 1, "baseline_right": 1}
    assert groups["inflated"] == {"objects": 1, "baseline_right": 1}
    assert groups["partial"] == {"objects": 1, "baseline_right": 0}
    assert sum(g["objects"] for g in groups.values()) == 4        # object 9 is not stacked


def _rect(r0: int, r1: int, c0: int, c1: int) -> np.ndarray:
    """Sorted global cell keys of rows r0..r1, cols c0..c1 (inclusive)."""
    from iesm_agent.mapping.cells import keys_of

    rows, cols = np.meshgrid(np.arange(r0, r1 + 1), np.arange(c0, c1 + 1), indexing="ij")
    return np.sort(keys_of(rows.ravel(), cols.ravel()))


def test_fragment_cause_names_the_rule_that_keeps_two_pieces_apart():
    from iesm_agent.config import MappingConfig
    from iesm_agent.evals.mapping_causes import fragment_cause

    cfg = MappingConfig(delta_geo_strong=0.7)
    chair = _rect(0, 9, 0, 9)
    # a view seen once, half inside the chair's footprint, embedding pulled away (cosine 0.7)
    piece = _rect(5, 14, 0, 9)
    assert fragment_cause(chair, piece, 0.7, cfg) == "overlap, cosine under the thresholds"
    assert fragment_cause(chair, piece, 0.7, MappingConfig()) == "linkable as built"   # the default links it
    beside = _rect(10, 16, 0, 9)                                          # touching, no shared cell
    assert fragment_cause(chair, beside, 0.5, cfg) == "touching, cosine under the continuity threshold"
    assert fragment_cause(chair, beside, 0.9, cfg) == "touching, compact shapes"
    assert fragment_cause(chair, beside, 0.9, MappingConfig.paper()) == "touching, no continuity merge"
    wall, crossing = _rect(0, 1, 0, 39), _rect(2, 41, 0, 1)              # an L
    assert fragment_cause(wall, crossing, 0.95, cfg) == "touching, planar shapes not collinear"
    assert fragment_cause(wall, _rect(0, 1, 42, 79), 0.95, cfg) == "footprints apart"   # a 2-cell gap


def test_same_label_pairs_and_extra_instances_tell_fragments_from_neighbours():
    from iesm_agent.config import MappingConfig
    from iesm_agent.evals.mapping_causes import extra_instances, same_label_pairs
    from iesm_agent.store.model import GridSpec, Instance, InstanceGrid, SceneMap

    grid = GridSpec(cell_size=0.05, height=40, width=40)

    def flat(r0, r1, c0, c1):
        rows, cols = np.meshgrid(np.arange(r0, r1 + 1), np.arange(c0, c1 + 1), indexing="ij")
        return (rows * 40 + cols).ravel()

    cells = {1: flat(0, 9, 0, 9), 2: flat(10, 16, 0, 9), 3: flat(20, 29, 20, 29), 4: flat(0, 4, 30, 34)}
    labels = {1: "armchair", 2: "armchair", 3: "armchair", 4: "pillow"}
    weights = {1: 5.0, 2: 1.0, 3: 4.0, 4: 1.0}
    occ = InstanceGrid.from_entries(np.concatenate(list(cells.values())),
                                    np.concatenate([np.full(len(c), i) for i, c in cells.items()]),
                                    np.concatenate([np.full(len(c), 0.9, np.float32) for c in cells.values()]))
    emb = np.eye(4, dtype=np.float32)
    emb[1] = [0.95, np.sqrt(1 - 0.95 ** 2), 0, 0]                          # the piece: cosine 0.95 with 1
    scene = SceneMap(scene_id="t", grid=grid, occupancy=occ, embeddings=emb,
                     instances=[Instance(id=i, label=labels[i], mean_height=0.5, weight=weights[i], frames=[i])
                                for i in cells])
    # instance 1 and its piece 2 show object 7 (an armchair); 3 another armchair; 4 a sofa's cushion
    main = {1: 7, 2: 7, 3: 8, 4: 7}
    gt_labels = {7: "armchair", 8: "armchair"}
    pairs = {(p["a"], p["b"]): p for p in same_label_pairs(scene, main, gt_labels, MappingConfig())}
    assert set(pairs) == {(1, 2), (1, 3), (2, 3)}
    assert pairs[(1, 2)]["same_object"] and pairs[(1, 2)]["cause"] == "touching, compact shapes"
    assert not pairs[(1, 3)]["same_object"] and pairs[(1, 3)]["cause"] is None and not pairs[(1, 3)]["named_wrong"]
    extras = extra_instances(scene, main, MappingConfig())
    assert [(e["primary"], e["extra"], e["same_label"]) for e in extras] == [(1, 2, True), (1, 4, False)]
    assert extras[1]["cause"] == "footprints apart"


class _Frames:
    """Two frames of 4 x 5 pixels showing objects 3 (left) and 7 (right): the first with one mask
    over the right half, the second with no mask at all (a fresh seed has such a frame)."""

    def __init__(self):
        self.inst = np.zeros((4, 5), np.int32)
        self.inst[:, :2], self.inst[:, 2:] = 3, 7
        self.masks = [np.zeros((1, 4, 5), bool), np.zeros((0, 4, 5), bool)]
        self.masks[0][0, :, 2:] = True

    def __len__(self):
        return 2

    def read(self, i):
        seg = Segmentation(self.masks[i], np.zeros((len(self.masks[i]), 2), np.float32),
                           np.ones(len(self.masks[i]), np.float32))
        return Frame(i, np.zeros((4, 5, 3), np.uint8), np.ones((4, 5), np.float32), np.eye(4), segmentation=seg,
                     instance_ids=self.inst)


def test_mask_objects_reads_frames_without_masks():
    assert mask_objects(_Frames(), min_pixels=5) == {(0, 0): 7}
