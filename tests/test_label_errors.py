"""Causes of mislabelled matched instances (evals/label_errors.py) on hand-made masks and embeddings."""

from collections import Counter

import numpy as np

from iesm_agent.evals.label_errors import label_error, near_synonyms

CATEGORIES = ["cup", "table", "chair", "armchair", "wall"]
E = np.eye(5)
LABELS = {1: "cup", 2: "table", 3: "armchair", 4: "wall", 5: "chair"}


def _mask(pixels: dict[int, int], vec: list[float]) -> dict:
    v = np.array(vec, np.float64)
    return {"pixels": Counter(pixels), "category": int(v.argmax()), "embedding": v}


def test_near_synonyms_by_their_words():
    assert near_synonyms("armchair", "chair") and near_synonyms("Chair", "office chair")
    assert near_synonyms("coffee table", "dining table")
    assert not near_synonyms("cup", "chair") and not near_synonyms("chair", "chair")


def test_masks_of_the_support_fused_in_drown_a_cup():
    # two cup masks named cup, three table masks fused in: the instance reads "table"
    masks = [_mask({1: 90, 2: 10}, [1, 0.2, 0, 0, 0])] * 2 + [_mask({2: 100}, [0, 1, 0, 0, 0])] * 3
    err = label_error(1, 0, 1, masks, LABELS, CATEGORIES, E)
    assert err["cause"] == "neighbour"
    assert (err["own_masks"], err["own_right"], err["own_label"], err["other_masks"]) == (2, 2, "cup", 3)
    assert err["neighbour"] == "table" and err["neighbour_share"] == round(320 / 500, 3)


def test_a_cup_mask_spilling_onto_the_table_carries_its_look():
    # every mask mostly shows the cup but a third of its pixels are table, and it reads "table"
    masks = [_mask({1: 60, 2: 30, 0: 10}, [0.4, 1, 0, 0, 0])] * 3
    assert label_error(1, 0, 1, masks, LABELS, CATEGORIES, E)["cause"] == "neighbour"
    # the same masks with a sliver of table (under NEIGHBOUR_SHARE): the segmenter's own view is wrong
    masks = [_mask({1: 95, 2: 5}, [0.4, 1, 0, 0, 0])] * 3
    assert label_error(1, 0, 1, masks, LABELS, CATEGORIES, E)["cause"] == "segmenter"


def test_a_near_synonym_comes_before_the_segmenter():
    masks = [_mask({3: 100}, [0, 0, 1, 0.5, 0])] * 3
    err = label_error(3, 3, 2, masks, LABELS, CATEGORIES, E)
    assert err["cause"] == "near-synonym" and err["own_label"] == "chair" and err["own_right"] == 0
    # an armchair called a chair next to a real chair making up a fifth of the pixels: the neighbour
    masks = [_mask({3: 80, 5: 20}, [0, 0, 1, 0.5, 0])] * 3
    assert label_error(3, 3, 2, masks, LABELS, CATEGORIES, E)["cause"] == "neighbour"


def test_a_category_outside_the_list_is_other():
    masks = [_mask({1: 100}, [1, 0, 0, 0, 0])]
    assert label_error(1, -1, 0, masks, {1: "teapot"}, CATEGORIES, E)["cause"] == "other"
