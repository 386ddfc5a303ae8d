"""The spatial expert where the request names a landmark the map lacks: a point to be near or far
from is read as the map label its name stands for (by the sentence encoder, here a fixed table);
the expert abstains as before when no label is near enough, no encoder is installed, or the thing
is one to be on or with (a part a caption may name), unless another relation the map can answer
is stated: then those rank."""

import pytest

from iesm_agent.providers.offline import OfflineModel
from iesm_agent.understanding.spatial import parse_query

from test_grounding import TableEncoder, unit
from test_spatial_relations import box, make_store, spatial

ENC = TableEncoder({
    "door": unit((0, 1.0)), "stool": unit((1, 1.0)), "plant": unit((2, 1.0)),
    "archway": unit((0, 1.0), (3, 0.4)),     # a door, said otherwise
    "cushion": unit((2, 1.0), (6, 0.5)),     # nearest the plants, but a part of a thing when said with "with"
})


class TableModel(OfflineModel):
    """The offline model with the table above for its sentence encoder."""

    def encoder(self):
        return ENC


# A 5 m x 4 m workshop: a door on the east wall, a stool near it and one far from it, two plants.
SHOP = [
    box(1, "door", (4.98, 1.0, 1.0), (0.05, 0.9, 2.0), room="workshop"),
    box(2, "stool", (4.1, 1.2, 0.35), (0.4, 0.4, 0.7), room="workshop"),
    box(3, "stool", (0.8, 3.0, 0.35), (0.4, 0.4, 0.7), room="workshop"),
    box(4, "plant", (4.4, 3.6, 0.5), (0.4, 0.4, 1.0), room="workshop"),
    box(5, "plant", (0.5, 0.4, 0.5), (0.4, 0.4, 1.0), room="workshop"),
]


@pytest.fixture(scope="module")
def shop(tmp_path_factory):
    return make_store(tmp_path_factory.mktemp("shop"), SHOP)


def test_a_landmark_kind_the_map_lacks_is_the_label_its_name_is_nearest_to(shop):
    query = "which stool stands nearest to the archway here"
    assert parse_query(query).relations[0].landmarks == [("doorway",)]  # a kind of its own in the lexicon
    assert spatial(shop, query) == []  # no encoder: no guess
    assert spatial(shop, query, provider=TableModel()) == [2, 3]  # the stool by the door first


def test_a_name_near_no_label_still_gives_no_ranking(shop):
    assert spatial(shop, "the stool that is closest to the harpsichord", provider=TableModel()) == []


def test_a_part_said_with_with_is_not_read_as_another_label(shop):
    query = "a stool with a cushion"
    assert [r.kind for r in parse_query(query).relations] == ["with"]
    assert spatial(shop, query, provider=TableModel()) == []  # a caption's part, not a plant beside it


@pytest.mark.parametrize("query", [
    "the stool beside the piano that is nearest the door",  # a point to be near, and no piano here
    "the stool with a cushion, nearest the door",            # a part to be with, and no cushion here
])
def test_a_relation_to_a_missing_landmark_leaves_the_others_to_rank(shop, query):
    assert len(parse_query(query).relations) == 2
    assert spatial(shop, query) == [2, 3]  # by the door, the one relation the map can answer


def test_no_relation_the_map_can_answer_still_gives_no_ranking(shop):
    assert spatial(shop, "the stool beside the piano") == []
