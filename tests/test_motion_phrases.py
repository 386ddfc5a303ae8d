"""Motion phrases are not spatial relations: the spatial expert abstains, its gate weight goes to
the experts that answered, and MTEFR answers the named object. Real relations (a target and a
distinct landmark) still let the spatial expert decide. Wordings here were written for this test."""

from __future__ import annotations

import pytest

from iesm_agent.embeddings import encoder_name
from iesm_agent.providers.offline.spatial_parse import parse_query
from iesm_agent.retrieval import Retriever
from iesm_agent.store import MapStore, open_map


@pytest.fixture(scope="module")
def retriever():
    return Retriever(MapStore(open_map("apartment")), provider="offline")


#: known gaps, kept visible (strict xfail: they fail today and flip when fixed): the shared query
#: reading still takes "round" after a motion verb as a shape, "sit" in "go sit by" as the function
#: asked for, and an unknown verb ("zip") as the target
_GAP = pytest.mark.xfail(strict=True, reason="known gap in the shared query reading (see comment above)")
#: the unknown verb is taken as the target only when the sentence encoder grounds it (the `embeddings`
#: extra); without the encoder the query is answered right
_ENCODER_GAP = pytest.mark.xfail(encoder_name() is not None, strict=True,
                                 reason="known gap in the shared query reading (see comment above)")
MOTION = [("make your way over to the bookshelf, thanks", "bookshelf"),
          ("could you pull up to the desk", "desk"),
          ("stop by the refrigerator for me", "refrigerator"),
          pytest.param("come round to the bed", "bed", marks=_GAP),
          ("walk up to the wardrobe", "wardrobe"),
          pytest.param("zip over to the printer", "printer", marks=_ENCODER_GAP),
          pytest.param("go sit by the bathtub", "bathtub", marks=_GAP),
          ("take me across to the mirror in the hallway", "mirror")]
MOTION_PARSE = [getattr(m, "values", m) for m in MOTION]  # the parse is right in every case


@pytest.mark.parametrize("query, label", MOTION_PARSE)
def test_motion_particles_are_not_relations(query, label):
    sq = parse_query(query)
    assert sq.relations == [] and sq.target, query


@pytest.mark.parametrize("query, label", MOTION)
def test_spatial_expert_abstains_on_motion_phrases_and_mtefr_answers_the_named_object(retriever, query, label):
    res = retriever.ask(query)
    assert res.experts.get("spatial", []) == []
    assert "spatial" in res.abstained and res.gate["spatial"] == 0.0
    assert any(note.startswith("spatial abstained") for note in res.notes)
    assert res.label == label


def test_a_landmark_named_alone_is_the_target_not_a_landmark():
    for query in ("the nearest sofa", "beside the bed", "just next to the toilet"):
        sq = parse_query(query)
        assert sq.relations == [] and sq.target, query


RELATIONS = [pytest.param("the lamp standing on the nightstand", 34, marks=pytest.mark.xfail(
                 strict=True, reason="known gap: 'lamp standing' is read as the category 'lamp stand'")),
             ("the lamp on the nightstand", 34), ("the picture that hangs over the sofa", 6),
             ("the cabinet under the bathroom sink", 42), ("which plant is closest to the bed", 39),
             ("the lamp next to the desk", 56)]


@pytest.mark.parametrize("query, expected", RELATIONS)
def test_real_relations_still_let_the_spatial_expert_decide(retriever, query, expected):
    res = retriever.ask(query)
    assert res.experts["spatial"][0] == expected
    assert res.gate["spatial"] == max(res.gate.values()) > 0
    assert res.instance_id == expected and "spatial" not in res.abstained


def test_a_relation_after_a_motion_phrase_is_still_read():
    sq = parse_query("head over to the lamp on the nightstand")
    assert sq.target and sq.target[0] == "lamp"
    assert [(r.kind, r.landmarks[0][0]) for r in sq.relations] == [("on", "nightstand")]
