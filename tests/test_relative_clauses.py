"""Relative clauses whose preposition has no object ("the cabinet the printer sits on", "the sink
with the mirror above it"): the clause's noun is the landmark, the noun before it the target, and
the relation is read from the target's side. Wordings here were written for this test."""

from __future__ import annotations

import pytest

from iesm_agent.retrieval import Retriever
from iesm_agent.store import MapStore, open_map
from iesm_agent.understanding import analyse_query
from iesm_agent.understanding.clauses import clause_final_words, is_stranded
from iesm_agent.understanding.spatial import parse_query


@pytest.fixture(scope="module")
def retriever():
    return Retriever(MapStore(open_map("apartment")), provider="offline")


# (query, target category, relation kind seen from the target, landmark category)
CLAUSES = [("the cabinet that the printer is sitting on", "cabinet", "with", "printer"),
           ("bring me to the dresser a plant has been put on", "dresser", "with", "plant"),
           ("the sink with a mirror hanging right above it", "sink", "below", "mirror"),
           ("which plant has the dresser underneath it", "plant", "above", "dresser"),
           ("the armchair with a lamp to the left of it", "armchair", "right", "lamp"),
           ("find the tv stand that the tv sits on", "tv stand", "with", "tv")]


@pytest.mark.parametrize("query, target, kind, landmark", CLAUSES)
def test_the_clause_noun_is_the_landmark_and_the_relation_is_turned_round(query, target, kind, landmark):
    sq = parse_query(query)
    assert sq.target == (target,)
    assert [(r.kind, r.landmarks) for r in sq.relations] == [(kind, [(landmark,)])]
    info = analyse_query(query)
    assert info.targets[target] == 1.0 and landmark not in info.targets and info.landmarks[landmark] < 1.0


def test_the_clause_verb_is_not_the_target_use():
    # "hangs" would ask for something to hang things on; here it is what the clock does
    sq = parse_query("the one the clock hangs over")
    assert sq.target == () and [(r.kind, r.landmarks) for r in sq.relations] == [("below", [("clock",)])]
    assert analyse_query("the one the clock hangs over").afford == {}


@pytest.mark.parametrize("query, expected", [("the cabinet the printer sits on", 53),
                                             ("take me to the nightstand a lamp is standing on", 33),
                                             ("the sink that has the mirror over it", 41),
                                             ("the table the cup sits on", 3)])
def test_mtefr_answers_the_object_the_clause_is_about(retriever, query, expected):
    res = retriever.ask(query)
    assert res.instance_id == expected, (query, res.experts)


@pytest.mark.parametrize("query, relations", [
    ("the lamp on the right", [("right", [])]),                 # a side word, not a stranded preposition
    ("the cushion with the stripes on it", []),                 # the clause's noun is not a known landmark
    ("the cup on the table", [("on", [("table",)])]),            # an ordinary relation keeps its direction
    ("facing the bed, the lamp on the left", [("left", [])])])
def test_ordinary_relations_and_side_words_are_left_alone(query, relations):
    assert [(r.kind, r.landmarks) for r in parse_query(query).relations] == relations


def test_a_preposition_is_stranded_at_a_clause_end_or_before_a_pronoun():
    toks = ["cabinet", "printer", "sits", "on", "please"]
    assert is_stranded(toks, 4, clause_final_words("the cabinet the printer sits on, please"))
    assert not is_stranded(toks, 4, clause_final_words("the cabinet the printer sits on please"))
    assert is_stranded(["sink", "mirror", "above", "it"], 3, frozenset())
    assert not is_stranded(["lamp", "on", "right"], 3, frozenset({"right"}))  # "on the right"
