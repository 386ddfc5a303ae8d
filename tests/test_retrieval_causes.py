"""One cause per wrong retrieval answer on a built map (evals/retrieval_causes.py), on hand-made
instances of a kitchen with two stoves and a bedroom."""

import pytest

from iesm_agent.evals.retrieval_causes import CAUSES, GtObject, classify, gt_objects, read_wrongly, said
from iesm_agent.evals.vocab import Vocabulary
from iesm_agent.store.model import Instance

STOVE = GtObject(1, "stove", "kitchen", {"color": "black", "material": "metal"})
WHITE_STOVE = GtObject(2, "stove", "kitchen", {"color": "white", "material": "metal"})
PILLOW = GtObject(3, "pillow", "bedroom", {"color": "white", "material": "cotton"})
HINTS = {"obj": "stove", "desc": "black", "room": "kitchen"}


@pytest.fixture(scope="module")
def vocab():
    return Vocabulary.load()


def _inst(i: int, label: str, room: str, colour: str) -> Instance:
    return Instance(id=i, label=label, room_label=room, caption=f"a {colour} {label} in the {room}",
                    tags={"color": colour})


def _cause(vocab, qtype, query, target_insts, picked, picked_gt, hints=HINTS, target=STOVE):
    return classify(qtype, query, hints, target, target_insts, target_insts, picked, picked_gt, vocab)[0]


def test_gt_objects_and_said(vocab):
    objs = gt_objects([{"id": 1, "label": "stove", "room": 2, "tags": {"color": "black", "material": "metal"}}],
                      [{"id": 2, "label": "Kitchen_1"}], vocab)
    assert objs[1] == STOVE
    assert said("the black stove", STOVE, vocab) == {"color": {"black"}}
    assert set(said("the black metal stove", STOVE, vocab)) == {"color", "material"}
    assert said("the stove", STOVE, vocab) == {}


def test_map_causes_in_order(vocab):
    right, white = _inst(10, "stove", "kitchen", "black"), _inst(11, "stove", "kitchen", "white")
    assert _cause(vocab, "od", "the black stove", [], white, WHITE_STOVE) == CAUSES[0]
    assert _cause(vocab, "od", "the black stove", [_inst(10, "toilet", "kitchen", "black")], white,
                  WHITE_STOVE) == CAUSES[1]
    assert _cause(vocab, "ord", "the black stove in the kitchen", [_inst(10, "stove", "bedroom", "black")],
                  white, WHITE_STOVE) == CAUSES[2]
    # the caption misnames the colour; material is never named by a colour-only caption
    assert _cause(vocab, "od", "the black stove", [_inst(10, "stove", "kitchen", "grey")], white,
                  WHITE_STOVE) == CAUSES[3]
    assert _cause(vocab, "od", "the metal stove", [right], white, WHITE_STOVE) == CAUSES[3]
    # the pick is labelled stove but holds a pillow
    assert _cause(vocab, "od", "the black stove", [right], _inst(12, "stove", "bedroom", "white"), PILLOW) == CAUSES[4]
    assert _cause(vocab, "or", "the stove in the kitchen", [right], _inst(13, "stove", "kitchen", "white"),
                  GtObject(2, "stove", "bedroom", {"color": "white"})) == CAUSES[5]
    assert _cause(vocab, "od", "the black stove", [right], _inst(11, "stove", "kitchen", "black"),
                  WHITE_STOVE) == CAUSES[6]
    assert _cause(vocab, "od", "the black stove", [right], _inst(11, "stove", "kitchen", "black"),
                  GtObject(2, "stove", "kitchen", {"color": "black"})) == CAUSES[7]


def test_reading_and_other(vocab):
    right, white = _inst(10, "stove", "kitchen", "black"), _inst(11, "stove", "kitchen", "white")
    assert _cause(vocab, "od", "the black stove", [right], white, WHITE_STOVE,
                  hints={"obj": "stove", "desc": "white"}) == CAUSES[8]
    assert _cause(vocab, "o", "the stove", [right], _inst(14, "pillow", "bedroom", "white"), PILLOW,
                  hints={"obj": "pillow"}) == CAUSES[8]
    assert _cause(vocab, "od", "the black stove", [right], white, WHITE_STOVE) == CAUSES[9]


def test_read_wrongly(vocab):
    wanted = {"color": {"black"}}
    assert read_wrongly("od", HINTS, "stove", None, wanted, vocab) is None
    assert "room" in read_wrongly("ord", {**HINTS, "room": "bedroom"}, "stove", "kitchen", wanted, vocab)
    assert "category" in read_wrongly("od", {**HINTS, "obj": "sofa"}, "stove", None, wanted, vocab)
    assert read_wrongly("ard", {"desc": "black", "room": "kitchen"}, "stove", "kitchen", wanted, vocab) is None


def test_names_abstract():
    from iesm_agent.evals.retrieval_causes import names_abstract

    assert names_abstract({"abs": "counter, stove"}, "stove")
    assert not names_abstract({"abs": "heater"}, "microwave")
    assert not names_abstract({}, "microwave")
