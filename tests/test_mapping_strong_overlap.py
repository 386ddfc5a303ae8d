"""The strong-overlap link (MappingConfig.delta_geo_strong / delta_sem_weak) next to the paper's
rule: nearly coinciding top-down masks fuse on a weaker embedding agreement, a cup on a table
(max-overlap 1, unrelated embedding) does not, and `MappingConfig.paper()` is the paper's rule."""

from __future__ import annotations

import numpy as np
import pytest
from pydantic import ValidationError

from iesm_agent.config import MappingConfig, load_settings
from iesm_agent.mapping.association import linkable, select_matches
from iesm_agent.mapping.cells import keys_of
from iesm_agent.mapping.dictionary import InstanceDictionary
from iesm_agent.mapping.project import TopDownCandidates


def _cand(cols, height: float) -> TopDownCandidates:
    cols = np.asarray(list(cols))
    keys = keys_of(np.zeros(len(cols), np.int64), cols)
    return TopDownCandidates(mask_index=np.array([0]), offsets=np.array([0, len(keys)]), keys=keys,
                             top=np.full(len(keys), height, np.float32), near=np.ones(len(keys), np.float32),
                             mean_height=np.array([height]),
                             area_px=np.array([100]), bbox=np.array([[0, 0, cols.min(), cols.max()]]))


def _unit(angle_deg: float) -> np.ndarray:
    """A 2-D unit embedding whose cosine with [1, 0] is cos(angle)."""
    a = np.radians(angle_deg)
    return np.array([[np.cos(a), np.sin(a)]])


def test_default_links_strong_overlap_on_weaker_semantics_and_paper_does_not():
    geo, sem = np.array([0.9, 0.9, 0.5, 0.9, 0.3]), np.array([0.7, 0.5, 0.7, 0.9, 0.9])
    # an overlap of half (a view seen once, its embedding pulled towards another category) links
    # by default on cosine 0.7; the paper's rule needs 0.85; no overlap above 0.4 never links
    assert linkable(geo, sem, MappingConfig()).tolist() == [True, False, True, True, False]
    assert linkable(geo, sem, MappingConfig.paper()).tolist() == [False, False, False, True, False]
    assert not linkable(np.array([0.5]), np.array([0.7]), MappingConfig(delta_geo_strong=0.7))[0]
    # thresholds are strict, as the paper's
    cfg = MappingConfig()
    assert not linkable(np.array([cfg.delta_geo_strong]), np.array([0.8]), cfg)[0]
    assert not linkable(np.array([0.95]), np.array([cfg.delta_sem_weak]), cfg)[0]


def test_the_largest_phi_still_chooses_among_linkable_instances():
    # candidate 0: instance 0 (geo .95, sem .7) links only by strong overlap, phi .875;
    # instance 1 (geo .5, sem .95) by the paper's rule, phi .635: the larger phi wins
    a, b = np.array([0, 0]), np.array([0, 1])
    geo, sem = np.array([0.95, 0.5]), np.array([0.7, 0.95])
    assert select_matches(a, b, geo, sem, 1, MappingConfig()).tolist() == [0]
    assert select_matches(a, b, geo, sem, 1, MappingConfig.paper()).tolist() == [1]


def test_a_second_view_with_scattered_embedding_fuses_but_a_cup_on_the_table_stays_apart():
    d = InstanceDictionary(2, MappingConfig())
    f0 = _unit(0)
    d.integrate(_cand(range(20), 0.75), f0, np.array([1.0]), frame_index=0)          # a table
    # the same table from another view: 18 of 20 cells, cosine 0.77 (< delta_sem 0.85)
    d.integrate(_cand(range(2, 20), 0.75), _unit(40), np.array([1.0]), frame_index=1)
    assert len(d) == 1 and d.weights.tolist() == [2]
    # a cup on it: max-overlap 1 (its 2 cells are inside the table), cosine 0.17
    d.integrate(_cand(range(5, 7), 0.85), _unit(80), np.array([1.0]), frame_index=2)
    assert len(d) == 2
    # the paper's rule keeps the second view of the table apart
    p = InstanceDictionary(2, MappingConfig.paper())
    p.integrate(_cand(range(20), 0.75), f0, np.array([1.0]), frame_index=0)
    p.integrate(_cand(range(2, 20), 0.75), _unit(40), np.array([1.0]), frame_index=1)
    assert len(p) == 2
    # nor does the second pass merge them under the paper's rule, while it would under the default
    merged, merges = p.second_pass()
    assert (len(merged), merges) == (2, 0)
    p.cfg = MappingConfig()
    merged, merges = p.second_pass()
    assert (len(merged), merges) == (1, 1)


def test_settings_can_switch_the_link_off():
    off = {"mapping.delta_geo_strong": None, "mapping.continuity_gap": None}
    assert load_settings(overrides=off).mapping == MappingConfig.paper(mask_erode_px=1, depth_smooth_px=7,
                                                                       top_fill_max_cos=0.3,
                                                                       size_prior_temperature=0.035)
    off |= {"mapping.mask_erode_px": 0, "mapping.depth_smooth_px": 0, "mapping.top_fill_max_cos": None,
            "mapping.size_prior_temperature": None}
    assert load_settings(overrides=off).mapping == MappingConfig.paper()
    assert MappingConfig.paper(delta_sem=0.8).delta_sem == 0.8
    with pytest.raises(ValidationError):
        MappingConfig(delta_geo_strong=1.5)
