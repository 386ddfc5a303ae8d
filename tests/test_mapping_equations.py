"""The mapping equations (paper Sec. 3.1 and 4.1) on tiny hand-made cases."""

from __future__ import annotations

import numpy as np
import pytest

from iesm_agent.config import MappingConfig
from iesm_agent.mapping.association import iou, phi_geo, phi_sem, select_matches
from iesm_agent.mapping.categorize import category_scores, ranked_labels
from iesm_agent.mapping.cells import intersections, keys_of, union_cells
from iesm_agent.mapping.dictionary import InstanceDictionary
from iesm_agent.evals.mapping_metrics import auc_top, auc_top_all, gt_ranks, label_map_scores, topk_curve
from iesm_agent.mapping.project import TopDownCandidates, project_candidates

CFG = MappingConfig.paper()  # the paper's equations exactly (no strong-overlap link)


def row_keys(row: int, cols) -> np.ndarray:
    return keys_of(np.full(len(cols), row), np.asarray(cols))


def test_max_overlap_matches_a_truncated_view_that_iou_would_reject():
    # the instance covers 10 cells; a truncated view sees 6 cells, 4 of them inside the instance
    inst = row_keys(0, range(10))
    view = row_keys(0, range(6, 12))
    a, b, inter = intersections(view, np.zeros(6, np.int64), inst, np.zeros(10, np.int64))
    assert (a.tolist(), b.tolist(), inter.tolist()) == ([0], [0], [4])
    assert iou(inter, 6, 10)[0] == pytest.approx(4 / 12)          # 0.33 < delta_geo 0.4
    assert phi_geo(inter, 6, 10)[0] == pytest.approx(4 / 6)       # max(4/6, 4/10) = 0.67 > 0.4
    # a candidate fully inside the instance: max-overlap 1 whatever the size ratio
    assert phi_geo(np.array([3]), np.array([3]), np.array([100]))[0] == 1.0


def test_intersections_counts_every_sharing_pair():
    keys_a = np.concatenate([row_keys(0, [0, 1, 2]), row_keys(5, [0, 1])])
    owner_a = np.array([0, 0, 0, 1, 1])
    keys_b = np.concatenate([row_keys(0, [1, 2, 3]), row_keys(0, [2]), row_keys(9, [9])])
    owner_b = np.array([7, 7, 7, 3, 4])
    a, b, n = intersections(keys_a, owner_a, keys_b, owner_b)
    assert list(zip(a.tolist(), b.tolist(), n.tolist())) == [(0, 3, 1), (0, 7, 2)]


def test_phi_sem_is_cosine():
    f = np.array([[2.0, 0.0], [1.0, 1.0]])
    g = np.array([[1.0, 0.0], [-1.0, 1.0]])
    assert phi_sem(f, g) == pytest.approx([1.0, 0.0])


def test_both_thresholds_must_pass_and_the_largest_phi_wins():
    #            candidate 0: (geo .9, sem .8) fails sem, (geo .5, sem .9) passes -> instance 1
    #            candidate 1: (geo .3, sem .99) fails geo -> new instance
    #            candidate 2: phi(inst 3) = .7*.5 + .3*.95 = .635 > phi(inst 4) = .7*.45 + .3*.99 = .612
    a = np.array([0, 0, 1, 2, 2])
    b = np.array([0, 1, 2, 3, 4])
    geo = np.array([0.9, 0.5, 0.3, 0.5, 0.45])
    sem = np.array([0.8, 0.9, 0.99, 0.95, 0.99])
    assert select_matches(a, b, geo, sem, 3, CFG).tolist() == [1, -1, 3]
    # exactly at a threshold is not above it
    assert select_matches(np.array([0]), np.array([0]), np.array([0.4]), np.array([0.9]), 1, CFG).tolist() == [-1]


def test_union_keeps_the_higher_top_and_the_nearer_reading_per_cell():
    f32 = np.float32
    keys, top, near = union_cells(row_keys(0, [1, 2]), np.array([0.5, 0.7], f32), np.array([2.0, 4.5], f32),
                                  row_keys(0, [2, 3]), np.array([0.9, 0.1], f32), np.array([3.0, 1.0], f32))
    assert keys.tolist() == row_keys(0, [1, 2, 3]).tolist()
    assert top.tolist() == pytest.approx([0.5, 0.9, 0.1])
    assert near.tolist() == pytest.approx([2.0, 3.0, 1.0])


def _one(keys: np.ndarray, top: float, height: float, area: int) -> TopDownCandidates:
    rows, cols = keys // (1 << 21) - (1 << 20), keys % (1 << 21) - (1 << 20)
    return TopDownCandidates(mask_index=np.array([0]), offsets=np.array([0, len(keys)]), keys=keys,
                             top=np.full(len(keys), top, np.float32), near=np.ones(len(keys), np.float32),
                             mean_height=np.array([height]),
                             area_px=np.array([area]), bbox=np.array([[rows.min(), rows.max(), cols.min(), cols.max()]]))


def test_weighted_fusion_of_embedding_height_and_weight():
    d = InstanceDictionary(2, CFG)
    cells = row_keys(0, range(4))
    # the semantic threshold is lowered here so that these orthogonal-ish embeddings fuse
    d.cfg = MappingConfig(delta_sem=-1.0)
    d.integrate(_one(cells, 1.0, 1.0, 50), np.array([[1.0, 0.0]]), np.array([0.9]), frame_index=0)
    d.integrate(_one(row_keys(0, range(2, 6)), 2.0, 0.0, 80), np.array([[0.0, 1.0]]), np.array([0.8]), frame_index=1)
    assert len(d) == 1
    assert d.embeddings[0] == pytest.approx([0.5, 0.5])            # (1 * f + f_c) / (1 + 1)
    assert d.weights[0] == 2 and d.mean_heights[0] == pytest.approx(0.5)
    d.integrate(_one(row_keys(0, [0]), 0.5, 3.0, 20), np.array([[0.0, 1.0]]), np.array([0.7]), frame_index=2)
    assert d.embeddings[0] == pytest.approx([1 / 3, 2 / 3])        # (2 * [.5, .5] + [0, 1]) / 3
    assert d.weights[0] == 3 and d.mean_heights[0] == pytest.approx(4 / 3)   # (2 * 0.5 + 3) / 3
    assert d.keys[0].tolist() == row_keys(0, range(6)).tolist()     # mask OR
    assert d.tops[0].tolist() == pytest.approx([1.0, 1.0, 2.0, 2.0, 2.0, 2.0])
    from iesm_agent.mapping.scene import frames_by_area

    assert frames_by_area(d.observations[0]) == [1, 0, 2]           # by mask area, largest first


def test_unmatched_candidates_become_new_entries_and_the_second_pass_merges_duplicates():
    d = InstanceDictionary(2, CFG)
    f = np.array([[1.0, 0.0]])
    d.integrate(_one(row_keys(0, range(10)), 1.0, 1.0, 50), f, np.array([1.0]), 0)        # entry 0: 0..9
    # overlap 3 of 10 cells (0.3 <= delta_geo): a new entry although it is the same object
    d.integrate(_one(row_keys(0, range(7, 17)), 1.0, 1.0, 50), f, np.array([1.0]), 1)     # entry 1: 7..16
    # a different category on the same cells: semantics keep it apart
    d.integrate(_one(row_keys(0, range(7, 17)), 1.0, 1.0, 50), np.array([[0.0, 1.0]]), np.array([1.0]), 2)
    assert len(d) == 3
    # 5..12 overlaps entry 0 by 5/8 and entry 1 by 6/8: the larger phi (entry 1) takes it
    d.integrate(_one(row_keys(0, range(5, 13)), 1.0, 1.0, 40), f, np.array([1.0]), 3)
    assert d.weights.tolist() == [1, 2, 1]
    assert d.keys[1].tolist() == row_keys(0, range(5, 17)).tolist()
    # now entries 0 and 1 overlap by 5 / min(10, 12) = 0.5: the second pass merges them
    merged, merges = d.second_pass()
    assert merges == 1 and len(merged) == 2
    assert merged.weights.tolist() == [3, 1]                       # heaviest first; weights add
    assert merged.keys[0].tolist() == row_keys(0, range(17)).tolist()
    assert [o[0] for o in merged.observations[0]] == [1, 3, 0]


def test_categorisation_is_argmax_of_f_e_transpose():
    f = np.array([[0.9, 0.1, 0.0], [0.2, 0.1, 0.95]])
    e = np.eye(3)
    assert category_scores(f, e) == pytest.approx(f)
    assert ranked_labels(category_scores(f, e), ["chair", "table", "cup"], n_alt=2) == [
        ("chair", ["table", "cup"]), ("cup", ["chair", "table"])]


def test_auc_top_worked_example():
    # J = 4 categories; 3 matched pairs whose ground-truth category ranks 1st, 2nd and 4th;
    # |P| = 5 predictions, |G| = 4 ground-truth instances.
    ranking = np.array([[2, 0, 1, 3], [1, 3, 0, 2], [0, 1, 2, 3]])
    ranks = gt_ranks(ranking, np.array([2, 3, 3]))
    assert ranks.tolist() == [1, 2, 4]
    # f_match(k), k = 0..4: 0, 1/3, 2/3, 2/3, 3/3 on x = 0, .25, .5, .75, 1
    assert topk_curve(ranks, 4, 3) == pytest.approx([0, 1 / 3, 2 / 3, 2 / 3, 1])
    # trapezoids: .25 * [(0 + 1/3)/2 + (1/3 + 2/3)/2 + (2/3 + 2/3)/2 + (2/3 + 1)/2] = .25 * 13/6 = 13/24
    assert auc_top(ranks, 4, 3) == pytest.approx(13 / 24)
    scores = auc_top_all(ranks, 4, n_pred=5, n_gt=4)
    assert scores["pred"] == pytest.approx(13 / 24 * 3 / 5)         # = 13/40
    assert scores["gt"] == pytest.approx(13 / 24 * 3 / 4)           # = 13/32
    assert scores["top1_match"] == pytest.approx(1 / 3)
    # a ground-truth label outside the list never counts
    assert gt_ranks(ranking[:1], np.array([-1])).tolist() == [5]


def test_label_map_scores_by_hand():
    gt = np.array([0, 0, 0, 1, 1, -1])
    pred = np.array([0, 0, 1, 1, -1, 0])     # last cell has no ground truth: ignored
    s = label_map_scores(gt, pred)
    assert s["acc"] == pytest.approx(3 / 5)
    assert s["macc"] == pytest.approx((2 / 3 + 1 / 2) / 2)
    # IoU class 0: 2 / (3 + 2 - 2) = 2/3; class 1: 1 / (2 + 2 - 1) = 1/3
    assert s["miou"] == pytest.approx(0.5)
    assert s["fmiou"] == pytest.approx(3 / 5 * 2 / 3 + 2 / 5 * 1 / 3)


def test_back_projection_of_a_downward_camera():
    # camera 2 m above (x, y) = (1.0, 1.0), looking straight down: x_cam = x_world, y_cam = -y_world
    pose = np.array([[1, 0, 0, 1.0], [0, -1, 0, 1.0], [0, 0, -1, 2.0], [0, 0, 0, 1]], float)
    depth = np.full((20, 20), 2.0, np.float32)
    depth[:, :10] = 1.5                            # left half: a 0.5 m tall surface
    masks = np.zeros((2, 20, 20), bool)
    masks[0, 8:12, 2:6] = True                     # on the raised surface
    masks[1, 0:1, 15:16] = True                    # a single pixel: dropped by min_pixels
    c = project_candidates(depth, masks, fx=20.0, fy=20.0, cx=9.5, cy=9.5, pose=pose, cell_size=0.05,
                           min_pixels=2)
    assert c.mask_index.tolist() == [0]
    assert c.area_px.tolist() == [16]
    assert c.mean_height[0] == pytest.approx(0.5) and np.allclose(c.top, 0.5)
    # u = 2..5 -> x = 1 + (u - 9.5) * 1.5 / 20 in [0.4375, 0.6625]; v = 8..11 -> y = 1 - (v - 9.5) * 0.075
    rows, cols = np.divmod(c.keys - ((1 << 20) * (1 << 21) + (1 << 20)), 1 << 21)
    assert cols.min() == int(np.floor(0.4375 / 0.05)) and cols.max() == int(np.floor(0.6625 / 0.05))
    assert rows.min() == int(np.floor((1 - 1.5 * 0.075) / 0.05)) and rows.max() == int(np.floor(1.1125 / 0.05))
    assert c.bbox[0].tolist() == [rows.min(), rows.max(), cols.min(), cols.max()]


def test_a_frame_without_masks_adds_nothing():
    pose = np.eye(4)
    c = project_candidates(np.ones((4, 5), np.float32), np.zeros((0, 4, 5), bool), 5.0, 5.0, 2.0, 2.0, pose, 0.05)
    assert len(c) == 0 and c.offsets.tolist() == [0]
    d = InstanceDictionary(3, CFG)
    assert d.integrate(c, np.zeros((0, 3)), np.zeros(0), 0).tolist() == [] and len(d) == 0
