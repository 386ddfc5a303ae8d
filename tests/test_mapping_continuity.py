"""The continuity merge (MappingConfig.continuity_gap / delta_sem_continuous,
`InstanceDictionary.merge_continuous`): a wall seen in stretches that never overlap ends as one
instance; two walls meeting at a corner, two objects side by side and two wall pieces on either
side of a door gap stay apart, even with equal embeddings; `MappingConfig.paper()` leaves the
dictionary as it is."""

from __future__ import annotations

import numpy as np

from iesm_agent.config import MappingConfig
from iesm_agent.mapping.association import continues, continuous_link, planar_line
from iesm_agent.mapping.cells import dilate, keys_of, rowcol_of
from iesm_agent.mapping.dictionary import InstanceDictionary


def _rect(r0: int, r1: int, c0: int, c1: int) -> np.ndarray:
    """Sorted keys of the cells rows r0..r1, cols c0..c1 (inclusive)."""
    rows, cols = np.meshgrid(np.arange(r0, r1 + 1), np.arange(c0, c1 + 1), indexing="ij")
    return np.sort(keys_of(rows.ravel(), cols.ravel()))


def _unit(angle_deg: float) -> np.ndarray:
    """A 2-D unit embedding whose cosine with [1, 0] is cos(angle)."""
    a = np.radians(angle_deg)
    return np.array([np.cos(a), np.sin(a)])


def _dictionary(parts: list[tuple[tuple[int, int, int, int], float, float]],
                cfg: MappingConfig | None = None) -> InstanceDictionary:
    """Entries from (rectangle (r0, r1, c0, c1), embedding angle in degrees, weight)."""
    d = InstanceDictionary(2, cfg or MappingConfig())
    for k, ((r0, r1, c0, c1), angle, weight) in enumerate(parts):
        keys = _rect(r0, r1, c0, c1)
        d.add(keys, np.full(len(keys), 2.6, np.float32), np.ones(len(keys), np.float32), _unit(angle), 1.3, weight,
              np.array([r0, r1, c0, c1]), [(k, 0, 100, 1.0)])
    return d


def test_a_wall_seen_in_three_stretches_that_never_overlap_becomes_one_instance():
    # a 3 m wall (60 cells of 5 cm, 2 cells thick) seen as three 1 m stretches; view-to-view
    # cosines 0.94-0.98 (above delta_sem_continuous), max-overlap 0 (the paper's rule never links them)
    d = _dictionary([((0, 1, 0, 19), 0, 3), ((0, 1, 20, 39), 15, 2), ((0, 1, 40, 59), 5, 4)])
    merged, merges = d.merge_continuous()
    assert (len(merged), merges) == (1, 2)
    assert merged.weights.tolist() == [9] and merged.sizes.tolist() == [120]
    assert sorted(o[0] for o in merged.observations[0]) == [0, 1, 2]
    # the embedding is the weight-averaged one, as every fusion
    expected = (3 * _unit(0) + 2 * _unit(15) + 4 * _unit(5)) / 9
    assert np.allclose(merged.embeddings[0], expected)


def test_a_light_stretch_between_two_heavy_ones_joins_all_three():
    # heaviest first: the two ends do not touch each other, the middle one touches both; the
    # pass is repeated until nothing fuses, so one instance remains
    d = _dictionary([((0, 1, 0, 19), 0, 5), ((0, 1, 40, 59), 10, 5), ((0, 1, 20, 39), 5, 1)])
    merged, merges = d.merge_continuous()
    assert (len(merged), merges) == (1, 2)


def test_two_walls_meeting_at_a_corner_stay_apart_even_with_equal_embeddings():
    # an L: a wall along x (rows 0-1) and a wall along y (cols 0-1) that touch at the corner
    d = _dictionary([((0, 1, 0, 39), 0, 3), ((2, 41, 0, 1), 0, 3)])
    assert not continues(d.keys[0], d.keys[1], 0.05)
    merged, merges = d.merge_continuous()
    assert (len(merged), merges) == (2, 0)


def test_objects_side_by_side_and_a_door_gap_stay_apart():
    # two nightstands (40 x 40 cm) touching side by side, equal embeddings: two compact footprints
    # never continue each other (one object seen in two parts looks the same from above)
    d = _dictionary([((0, 7, 0, 7), 0, 3), ((0, 7, 8, 15), 0, 3)])
    assert d.merge_continuous()[0].weights.tolist() == [3, 3]
    # two parallel walls 0.5 m apart touching an end wall: not collinear
    d = _dictionary([((0, 1, 0, 39), 0, 3), ((10, 11, 0, 39), 0, 3)])
    assert not continues(d.keys[0], d.keys[1], 0.05)
    # two wall pieces either side of a 90 cm door gap, same embedding: they do not touch
    d = _dictionary([((0, 1, 0, 39), 0, 3), ((0, 1, 58, 99), 0, 3)])
    assert len(d.merge_continuous()[0]) == 2
    # a 10 cm gap (2 empty cells) is bridged only with continuity_gap >= 0.1 m
    d = _dictionary([((0, 1, 0, 39), 0, 3), ((0, 1, 42, 79), 0, 3)])
    assert len(d.merge_continuous()[0]) == 2
    d.cfg = MappingConfig(continuity_gap=0.1)
    assert len(d.merge_continuous()[0]) == 1


def test_a_compact_piece_continues_a_wall_but_a_different_object_does_not():
    # a stretch of wall whose mask leaked into the floor (6 x 8 cells) beside a clean stretch
    d = _dictionary([((0, 1, 0, 39), 0, 3), ((0, 5, 40, 47), 20, 1)])
    assert len(d.merge_continuous()[0]) == 1
    # the same shapes with unrelated embeddings (a cabinet against the wall: cosine 0.34)
    d = _dictionary([((0, 1, 0, 39), 0, 3), ((0, 5, 40, 47), 70, 1)])
    assert len(d.merge_continuous()[0]) == 2


def test_the_papers_rule_has_no_continuity_merge():
    d = _dictionary([((0, 1, 0, 19), 0, 3), ((0, 1, 20, 39), 0, 2)], MappingConfig.paper())
    merged, merges = d.merge_continuous()
    assert merged is d and merges == 0


def test_continuous_link_takes_the_largest_cosine_that_is_not_a_corner():
    cfg = MappingConfig()
    wall = _rect(0, 1, 0, 39)
    entry_keys = [_rect(0, 1, 40, 79), _rect(2, 41, 0, 1), _rect(0, 1, 80, 99)]
    # entry 1 (a crossing wall) has the largest cosine but meets `wall` at a corner; entry 2 is collinear
    assert continuous_link(wall, np.array([0, 1]), np.array([0.8, 0.99]), entry_keys, cfg) == 0
    assert continuous_link(wall, np.array([0, 2]), np.array([0.8, 0.9]), entry_keys, cfg) == 2
    assert continuous_link(wall, np.array([0, 2]), np.array([cfg.delta_sem_continuous, 0.2]), entry_keys, cfg) == -1


def test_planar_line_and_dilate():
    assert planar_line(_rect(0, 7, 0, 7), 0.05) is None                  # a square is not planar
    centre, axis = planar_line(_rect(0, 1, 0, 39), 0.05)
    assert np.allclose(np.abs(axis), [1, 0]) and np.allclose(centre, [0.975, 0.025])  # (x, y) m
    rows, cols = rowcol_of(dilate(keys_of(np.array([5]), np.array([5])), 1))
    assert sorted(zip(rows.tolist(), cols.tolist())) == [(r, c) for r in (4, 5, 6) for c in (4, 5, 6)]
