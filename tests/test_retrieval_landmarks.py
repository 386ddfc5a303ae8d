"""Queries that pick an instance by a landmark ("the lamp next to the bed"): the landmark is not
the target, and captions that mention it are the evidence. Targets are found by label and room."""

import pytest

from iesm_agent.providers.offline import OfflineModel
from iesm_agent.retrieval import Retriever

CASES = [
    ("the lamp next to the bed", "lamp", "bedroom"),
    ("the plant on the dresser", "plant", "bedroom"),
    ("the mirror above the washbasin", "mirror", "bathroom"),
    ("the towel by the bathtub", "towel", "bathroom"),
    ("the chair at the desk", "chair", "office"),
    ("the cup on the coffee table", "cup", "living room"),
]


@pytest.fixture(scope="module")
def retriever(apartment_store):
    return Retriever(apartment_store, provider=OfflineModel(use_embeddings=False))


@pytest.mark.parametrize("query, label, room", CASES)
def test_landmark_picks_the_instance_beside_it(retriever, apartment_store, query, label, room):
    (expected,) = [i.id for i in apartment_store.scene.instances if i.label == label and i.room_label == room]
    others = [i.id for i in apartment_store.scene.instances if i.label == label and i.id != expected]
    result = retriever.ask(query)
    assert result.instance_id == expected, result.explain()
    assert result.label == label  # the landmark itself is not taken for the target
    assert others == [] or result.scores[expected] > max(result.scores.get(i, 0.0) for i in others)
