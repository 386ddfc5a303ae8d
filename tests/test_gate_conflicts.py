"""When the evidence in a query conflicts, the experts disagree and the gate's weights decide.

Each case names a category together with a room that holds none of it (the room holds a kind that
serves the same purpose) or with a colour no instance of it has (a kind of the same purpose has
it). The object, room and description experts then put different instances first; MTEFR follows
the gate, which trusts a named category over a contradicting room or colour, and the same
rankings fused under other weights give another answer. Targets are looked up by label and room.
"""

import pytest

from iesm_agent.retrieval import Retriever, fuse
from test_retriever_apartment import the

CASES = [
    # (query, the named category's instance, the expert that disagrees, what it picks instead)
    ("that armchair in the office", ("armchair",), "room", ("chair", "office")),
    ("the sofa in the bedroom", ("sofa",), "room", ("bed",)),
    ("the desk in the kitchen", ("desk",), "room", ("table", "kitchen")),
    ("that red sofa", ("sofa", None, "brown"), "desc", ("chair", "office")),  # no sofa is red: brown looks nearer than grey
    ("that white armchair", ("armchair",), "desc", ("chair", "kitchen", "white")),
]


@pytest.fixture(scope="module")
def mtefr(apartment_store):
    return Retriever(apartment_store, provider="offline")


@pytest.mark.parametrize("query, named, rival_expert, rival", CASES, ids=[c[0] for c in CASES])
def test_fusion_follows_the_gate_when_experts_disagree(mtefr, apartment_store, query, named, rival_expert, rival):
    other = the(apartment_store, *rival)
    res = mtefr.ask(query)
    assert res.failures == []
    # a request naming no instance in particular ("the sofa in the bedroom") is served by any of them
    label, *detail = named
    fits = [i.id for i in apartment_store.scene.instances if i.label == label]
    target = res.experts["obj"][0] if not detail else the(apartment_store, *named)
    assert target in fits
    assert res.experts["obj"][0] == target and res.experts[rival_expert][0] == other, res.explain()
    assert res.gate["obj"] > res.gate[rival_expert]
    assert res.instance_id == target, res.explain()
    assert res.deciding_expert == "obj"
    # the same rankings under weights that trust the rival expert instead give the rival's pick
    flipped = dict(res.gate, obj=res.gate[rival_expert], **{rival_expert: res.gate["obj"]})
    assert fuse(flipped, res.experts, kappa=res.kappa).best == other
    text = res.explain()
    assert "experts disagree on the top pick" in text and "fusion followed" in text and "obj" in text


def test_three_experts_three_picks(mtefr, apartment_store):
    # a named kind, a room with only its relatives, a colour only another kind has
    res = mtefr.ask("the red armchair in the kitchen")
    picks = {e: res.experts[e][0] for e in ("obj", "room", "desc")}
    assert picks["obj"] == the(apartment_store, "armchair")
    assert apartment_store.get_instance(picks["room"])["room"] == "kitchen"
    assert picks["desc"] == the(apartment_store, "chair", "office")
    assert len(set(picks.values())) == 3
    assert res.instance_id == picks["obj"]


def test_uniform_weights_let_the_majority_of_experts_decide(apartment_store):
    # gate off: the room and abstract experts outvote the object expert on a room conflict
    uniform = Retriever(apartment_store, provider="offline", method="mtefr-uniform").ask("that armchair in the office")
    assert len(set(uniform.gate.values())) == 1
    assert uniform.instance_id == the(apartment_store, "chair", "office"), uniform.explain()


def test_consistent_evidence_keeps_the_experts_in_agreement(mtefr, apartment_store):
    res = mtefr.ask("that sink in the bathroom")
    assert {ids[0] for e, ids in res.experts.items() if ids and e != "spatial"} == {the(apartment_store, "sink", "bathroom")}
    assert "experts agree on the top pick" in res.explain()
