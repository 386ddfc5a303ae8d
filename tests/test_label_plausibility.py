"""Label plausibility from measured geometry (MappingConfig.size_prior_temperature,
`mapping.plausibility`): a small item whose masks look a little more like a coffee table than a cup
is labelled cup when the prior is on (the default) and coffee table when it is off; a coffee table's own size keeps
its label; a category without a prior is never pushed down; the evaluation ranks an instance's own
label first."""

from __future__ import annotations

import numpy as np
import pytest

from iesm_agent.config import MappingConfig
from iesm_agent.mapping.cells import keys_of
from iesm_agent.mapping.dictionary import InstanceDictionary
from iesm_agent.mapping.plausibility import SIZE_PRIORS, size_log_likelihood
from iesm_agent.mapping.scene import to_scene_map

CATEGORIES = ["coffee table", "cup", "wall"]
E = np.eye(3)  # category text embeddings: one axis each


def _entry(d: InstanceDictionary, side_cells: int, top_m: float, f: list[float]) -> None:
    """An entry whose footprint is a square of `side_cells` cells with top height `top_m` everywhere."""
    rows, cols = np.meshgrid(np.arange(side_cells), np.arange(side_cells), indexing="ij")
    keys = np.sort(keys_of(rows.ravel() + 100 * len(d), cols.ravel()))
    d.add(keys, np.full(len(keys), top_m, np.float32), np.ones(len(keys), np.float32), np.asarray(f, np.float64),
          top_m / 2, 1.0, np.array([0, side_cells - 1, 0, side_cells - 1]), [(len(d), 0, 100, 1.0)])


def _labels(cfg: MappingConfig, entries: list[tuple[int, float, list[float]]]) -> list[str]:
    d = InstanceDictionary(3, cfg)
    for entry in entries:
        _entry(d, *entry)
    scene = to_scene_map(d, CATEGORIES, E, cfg=cfg, scene_id="t", embedding_space="test", meta={})
    return [inst.label for inst in scene.instances]


LOOKS_LIKE_A_TABLE = [0.62, 0.58, 0.0]  # cosine 0.73 with coffee table, 0.68 with cup


def test_a_cup_sized_item_on_a_counter_is_a_cup_with_the_prior_and_what_its_masks_say_without():
    small_high = (2, 0.95, LOOKS_LIKE_A_TABLE)  # 2 x 2 cells of 5 cm: 0.01 m^2, top at 0.95 m
    assert _labels(MappingConfig(size_prior_temperature=None), [small_high]) == ["coffee table"]
    assert _labels(MappingConfig(), [small_high]) == ["cup"]


def test_a_coffee_table_sized_instance_keeps_its_label_and_paper_rules_keep_the_prior_off():
    table = (16, 0.45, LOOKS_LIKE_A_TABLE)  # 0.64 m^2, top at 0.45 m
    assert _labels(MappingConfig(size_prior_temperature=0.035), [table]) == ["coffee table"]
    assert MappingConfig.paper().size_prior_temperature is None
    assert MappingConfig.uncleaned(size_prior_temperature=0.05).size_prior_temperature == 0.05
    assert MappingConfig.uncleaned().size_prior_temperature is None


def test_log_likelihood_is_zero_inside_a_range_falls_outside_and_stops_at_the_floor():
    (a_lo, a_hi), (t_lo, t_hi) = SIZE_PRIORS["coffee table"]
    area = np.array([(a_lo * a_hi) ** 0.5, a_hi * 2, a_hi * 1000, (a_lo * a_hi) ** 0.5])
    top = np.array([(t_lo + t_hi) / 2, (t_lo + t_hi) / 2, (t_lo + t_hi) / 2, t_hi + 0.1])
    ll = size_log_likelihood(area, top, ["coffee table", "no such category"], floor=-3.0)
    assert ll[:, 0] == pytest.approx([0.0, -0.5, -3.0, -0.5])
    assert ll[:, 1] == pytest.approx([0.0] * 4)  # no prior: nothing against it


def test_the_evaluation_ranks_the_maps_own_label_first():
    from iesm_agent.evals.mapping import stated_first

    d = InstanceDictionary(3, MappingConfig(size_prior_temperature=0.035))
    _entry(d, 2, 0.95, LOOKS_LIKE_A_TABLE)
    scene = to_scene_map(d, CATEGORIES, E, cfg=d.cfg, scene_id="t", embedding_space="test", meta={})
    by_embedding = np.array([[0, 1, 2]])
    assert stated_first(by_embedding, scene, CATEGORIES).tolist() == [[1, 0, 2]]
