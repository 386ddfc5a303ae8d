"""The spatial expert on tiny hand-made maps: every relation, ambiguous and missing landmarks,
the reference block outside the candidates, and the gate weighting it."""

import json

import pytest

from iesm_agent.config import RetrievalConfig
from iesm_agent.providers.offline import OfflineModel
from iesm_agent.providers.offline.looks import own_colours
from iesm_agent.retrieval import Retriever
from iesm_agent.store import MapStore
from iesm_agent.store.importers.objects import import_objects
from iesm_agent.understanding import analyse_query
from iesm_agent.understanding.parse import normalise
from iesm_agent.understanding.spatial import parse_query


def box(i, label, center, size, **extra):
    return {"id": i, "label": label, "center": list(center), "size": list(size), "room": "bedroom", **extra}


def make_store(tmp_path, objects, name="tiny"):
    path = tmp_path / f"{name}.json"
    rooms = [{"id": k, "label": label} for k, label in enumerate(dict.fromkeys(o["room"] for o in objects), 1)]
    path.write_text(json.dumps({"scene_id": name, "rooms": rooms, "objects": objects}))
    return MapStore(import_objects(path))


def spatial(store, query, kappa=2, provider=None, **config):
    r = Retriever(store, provider=provider or OfflineModel(use_embeddings=False), method="experts:spatial",
                  config=RetrievalConfig(kappa=kappa, **config))
    return r.ask(query).experts.get("spatial", [])


# A 5 m x 4 m bedroom: bed against the north wall, nightstands either side, lamps on them,
# a desk on the west wall with a box under it, a door on the east wall, tables with cups.
ROOM = [
    box(1, "bed", (2.5, 3.0, 0.3), (1.6, 2.0, 0.6)),
    box(2, "nightstand", (1.3, 3.7, 0.3), (0.4, 0.4, 0.6)),
    box(3, "nightstand", (3.7, 3.7, 0.3), (0.4, 0.4, 0.6)),
    box(4, "lamp", (1.3, 3.7, 0.85), (0.3, 0.3, 0.5)),
    box(5, "lamp", (3.7, 3.7, 0.8), (0.2, 0.2, 0.4)),
    box(6, "desk", (0.4, 1.0, 0.375), (0.8, 1.2, 0.75)),
    box(7, "box", (0.4, 1.0, 0.15), (0.3, 0.3, 0.3)),
    box(8, "box", (2.5, 0.3, 0.15), (0.3, 0.3, 0.3)),
    box(9, "door", (4.98, 1.0, 1.0), (0.05, 0.9, 2.0)),
    box(10, "chair", (4.2, 1.0, 0.45), (0.45, 0.45, 0.9), tags={"color": "red"}),
    box(11, "chair", (3.2, 1.0, 0.45), (0.45, 0.45, 0.9), tags={"color": "blue"}),
    box(12, "chair", (2.2, 1.0, 0.45), (0.45, 0.45, 0.9), tags={"color": "red"}),
    box(13, "picture", (2.5, 3.98, 1.6), (0.8, 0.04, 0.6)),
    box(14, "picture", (0.02, 2.5, 1.6), (0.04, 0.8, 0.6)),
    box(15, "plant", (4.75, 3.75, 0.5), (0.4, 0.4, 1.0)),
    box(16, "plant", (2.5, 2.0, 0.05), (0.3, 0.3, 0.1)),
    box(17, "plant", (1.5, 0.25, 0.4), (0.3, 0.3, 0.8)),
]


@pytest.fixture(scope="module")
def room(tmp_path_factory):
    return make_store(tmp_path_factory.mktemp("room"), ROOM)


@pytest.mark.parametrize("query, best", [
    ("the lamp on the left nightstand, facing the bed", 4),
    ("the box under the desk", 7),
    ("that picture above the bed", 13),
    ("the picture over the desk", 14),
    ("the chair next to the door", 10),
    ("the chair closest to the desk", 12),
    ("that chair farthest from the door", 12),
    ("the chair between the other two chairs", 11),
    ("the red chair near the desk", 12),
    ("the plant in the corner", 15),
    ("the plant in the middle of the room", 16),
    ("the plant against the wall", 17),
    ("the smaller of those two lamps", 5),
    ("the largest lamp", 4),
    ("the tallest plant", 15),
    ("the lowest picture", 13),
    ("the second chair from the door", 11),
    ("when facing the bed, the nightstand on the left", 2),
    ("when facing the bed, the nightstand on the right", 3),
    ("the nightstand with the small lamp on it", 3),
    ("the lamp between the bed and the desk", 4),
])
def test_each_relation_picks_the_intended_instance(room, query, best):
    ranked = spatial(room, query)
    assert ranked and ranked[0] == best, (query, ranked)


def test_on_uses_the_stacking_and_the_box_heights(room):
    assert spatial(room, "that lamp on the nightstand", kappa=3) == [4, 5]  # both stand on one
    assert spatial(room, "the lamp on the nightstand by the door")[0] == 5


def test_ambiguous_landmark_keeps_every_instance_that_satisfies_it(tmp_path):
    store = make_store(tmp_path, [box(1, "table", (1, 1, 0.375), (1, 1, 0.75)),
                                  box(2, "table", (3, 1, 0.375), (1, 1, 0.75)),
                                  box(3, "cup", (1, 1, 0.8), (0.1, 0.1, 0.1)),
                                  box(4, "cup", (3, 1, 0.8), (0.1, 0.1, 0.1)),
                                  box(5, "cup", (2, 3, 0.05), (0.1, 0.1, 0.1))])
    assert sorted(spatial(store, "the cup on the table", kappa=3)[:2]) == [3, 4]


@pytest.mark.parametrize("query", ["the chair next to the piano", "the lamp on the fireplace",
                                   "the chair between the door and the piano"])
def test_missing_landmark_gives_no_ranking(room, query):
    assert spatial(room, query) == []


def test_the_one_candidate_of_its_kind_leaves_the_relation_nothing_to_tell_apart(room):
    assert spatial(room, "the desk beside the door") == []  # the room's one desk: no ranking to impose
    assert spatial(room, "the desk standing by itself") == []
    assert spatial(room, "the box beside the door") == [8, 7]  # two boxes: the relation tells them apart
    result = Retriever(room, provider=OfflineModel(use_embeddings=False)).ask("the desk beside the door")
    assert result.instance_id == 6 and "spatial" in result.abstained
    assert any("one candidate of the target kind" in note for note in result.notes)


@pytest.mark.parametrize("query", ["the red chair", "find the lamp in the bedroom", "the unicorn on the bed"])
def test_no_relation_or_no_target_gives_no_ranking(room, query):
    assert spatial(room, query) == []


def test_landmarks_outside_the_candidates_come_from_the_reference_block(tmp_path):
    chairs = [box(i, "chair", (float(i), 1.0, 0.45), (0.45, 0.45, 0.9)) for i in range(1, 7)]
    store = make_store(tmp_path, chairs + [box(20, "fireplace", (5.0, 2.5, 0.5), (1.2, 0.4, 1.0))])
    # three candidates (chairs 1-3): the fireplace is only a reference object, still resolved
    assert spatial(store, "the chair closest to the fireplace", max_candidates=3) == [3, 2]


def test_gate_weighs_the_spatial_expert_only_for_relations(room):
    r = Retriever(room, provider=OfflineModel(use_embeddings=False))
    rel = r.ask("the chair closest to the desk")
    assert rel.gate["spatial"] > 0.5 and rel.instance_id == 12
    assert all(w <= rel.gate["spatial"] / 4 + 1e-9 for n, w in rel.gate.items() if n != "spatial")
    plain = r.ask("the blue chair")
    # no relation: the spatial expert is not even asked (nor weighed by the gate)
    assert "spatial" not in plain.gate and "spatial" not in plain.experts and plain.instance_id == 11


def test_without_the_spatial_expert_the_relation_is_lost(room):
    r = Retriever(room, provider=OfflineModel(use_embeddings=False), method="experts:abs,desc,obj,room")
    assert r.ask("the chair closest to the desk").instance_id != 12


def test_a_relation_whose_landmark_cannot_be_read_gives_no_ranking(room):
    # "over there" names nothing; "farthest from" with nothing after it has no landmark either
    assert spatial(room, "the chair farthest from") == []
    assert spatial(room, "the lamp over there") == []


@pytest.mark.parametrize("query, best", [
    ("the box that is not under the desk", 8),
    ("the chair across the bed from the desk", 10),
    ("the plant that isn't in the corner", 16),
])
def test_negation_and_opposite(room, query, best):
    assert spatial(room, query)[0] == best


def _relations(text: str) -> list[tuple[str, list[tuple[str, ...]], str]]:
    return [(r.kind, r.landmarks, r.landmark_where) for r in parse_query(text).relations]


@pytest.mark.parametrize("text, expected", [
    # a landmark is what the relation's words govern, not the next noun anywhere after them
    ("the easel in the middle of the studio with a rug under it", [("middle", [], ""), ("above", [("rug",)], "")]),
    # a side of a landmark, through the noun the side word modifies
    ("the stool on the left-hand side of the sideboard", [("left", [("sideboard",)], "")]),
    # the thing placed relative to the target points back to it: the relation seen from the target
    ("this is a sofa. there is a lamp to its right.", [("left", [("lamp",)], "")]),
    # a side word on a landmark says which landmark, not where the target is
    ("the jug on the left shelf", [("on", [("shelf",)], "left")]),
    # a verb's particle is not a place, an intensifier is not a side
    ("turn on the desk lamp", []),
    ("the towel right beside the sink", [("near", [("sink",)], "")]),
    # "at" a thing is by it; at a part of it or at what one looks at is not
    ("the stool at the counter", [("near", [("counter",)], "")]),
    ("the stool at one end of the workbench", []),
    # any relation placing another thing on a re-mentioned target holds from the target's side
    ("this is a shelf. there is a vase on the shelf.", [("with", [("vase",)], "")]),
    # the landmark is the noun the relation's words take as object, not a modifier before it
    ("the candle on the piano bench", [("on", [("bench",)], "")]),
    ("the candle on the sideboard farthest from the piano", [("on", [("sideboard",)], ""),
                                                           ("farthest", [("piano",)], "")]),
])
def test_relations_follow_the_parse(text, expected):
    assert _relations(text) == expected


def test_an_imperative_face_sets_the_viewpoint_a_noun_face_does_not():
    face = parse_query("Face the piano. The stool I mean is on the right.")
    assert face.target == ("stool",) and face.facing == ("piano",)
    assert parse_query("the clock face by the door").facing == ()


def test_a_leading_exclusion_negates_its_own_relations_only():
    jug = parse_query("Not the one on the piano: the jug on the shelf.")
    assert jug.target == ("bottle",)
    assert [(r.kind, r.landmarks, r.negated) for r in jug.relations] == [("on", [("piano",)], True), ("on", [("shelf",)], False)]
    stool = parse_query("Not the green stool, the one by the piano.")
    assert [(r.kind, r.negated) for r in stool.relations] == [("near", False)]


@pytest.mark.parametrize("text, expected", [
    ("the scarf we left on the piano bench", [("on", [("bench",)], "")]),  # a verb with its subject
    ("the hours they have left before dinner", []),
    ("facing the fireplace, the left stool", [("left", [], "")]),         # a side, however tagged
])
def test_a_side_word_said_as_a_verb_is_not_a_relation(text, expected):
    assert _relations(text) == expected


@pytest.mark.parametrize("text, expected", [
    ("the stool behind the piano", [("behind", [("piano",)], "")]),          # "behind" takes its object
    ("the stool right behind the piano", [("behind", [("piano",)], "")]),
    ("the candle right next to the vase", [("near", [("vase",)], "")]),       # "right" intensifies
    ("the candle on the right next to the vase", [("right", [], ""), ("near", [("vase",)], "")]),
])
def test_behind_takes_its_landmark_and_right_before_a_relation_intensifies(text, expected):
    assert _relations(text) == expected


@pytest.mark.parametrize("query, best", [
    ("that middle chair", 11),                   # the middle one of the row of chairs, not the room's
    ("the chair at the middle of those three chairs", 11),
    ("the chair at the middle of the bedroom", 12),  # the room's middle
])
def test_middle_of_the_group_or_of_the_room(room, query, best):
    ranked = spatial(room, query)
    assert ranked and ranked[0] == best, (query, ranked)


def _middles(text: str) -> list[tuple[str, str, list[tuple[str, ...]], str]]:
    return [(r.kind, r.value, r.landmarks, r.landmark_where) for r in parse_query(text).relations]


@pytest.mark.parametrize("text, expected", [
    # the middle one of the target's own kind, said on the target, a stand-in or a row of them
    ("the middle stool", [("middle", "group", [], "")]),
    ("pick the middle one of the jugs", [("middle", "group", [], "")]),
    ("the jug at the centre of a line of jugs", [("middle", "group", [], "")]),
    # said on a landmark it says which landmark
    ("the stool by the middle piano", [("near", "", [("piano",)], "middle")]),
    # the middle of a room is no landmark; a clause on the room keeps its own relation
    ("the easel at the centre of the studio that is farthest from the piano",
     [("middle", "", [], ""), ("farthest", "", [("piano",)], "")]),
])
def test_middle_reads_whose_middle(text, expected):
    assert _middles(text) == expected


@pytest.mark.parametrize("query, best", [
    ("the plant standing by itself", 15),           # its nearest fellow plant is the farthest away
    ("the lone plant", 15),
    ("pick the plant that is on its own", 15),
    ("the plant furthest away from the other two", 15),
    ("the plant closest to the others", 16),         # near both the others
])
def test_apart_from_or_amid_the_others_of_its_kind(room, query, best):
    ranked = spatial(room, query)
    assert ranked and ranked[0] == best, (query, ranked)


@pytest.mark.parametrize("text, expected", [
    ("the mug on its own", [("farthest", "group", [], "")]),
    ("the stools by themselves", [("farthest", "group", [], "")]),
    ("the mug furthest from the rest", [("farthest", "group", [], "")]),
    ("the mug furthest from the kettle", [("farthest", "", [("kettle",)], "")]),  # a landmark is no group
    ("the mug by its own kettle", [("near", "", [("kettle",)], "")]),              # "own" before a noun
    ("the mug by the lone kettle", [("near", "", [("kettle",)], "")]),             # said of the landmark
    ("somewhere I can read on my own", []),                # said of a person
    ("the stain will not lift on its own", []),           # said of a doing
    ("the vase nearest 2 the clock", [("closest", "", [("clock",)], "")]),  # a digit for "to" is no group
])
def test_apart_from_the_group_reads_no_landmark(text, expected):
    assert _middles(text) == expected


@pytest.mark.parametrize("text, expected", [
    ("the lamp alongside the sofa", [("near", [("sofa",)], "")]),
    ("the vase upon the dresser", [("on", [("dresser",)], "")]),
    ("the book amongst the plants", [("near", [("plant",)], "")]),
])
def test_rarer_prepositions_of_place(text, expected):
    assert _relations(text) == expected


@pytest.mark.parametrize("text, expected", [
    # where the one who looks stands is not where the target is
    ("when standing by the piano, the stool on the left", [("left", [], "")]),
    ("if you stand near the counter, it is the jug on the right", [("right", [], "")]),
    # said of the target, or of someone else, it places them
    ("a lamp standing beside the piano", [("near", [("piano",)], "")]),
])
def test_where_the_viewer_stands_is_not_a_relation(text, expected):
    assert _relations(text) == expected


@pytest.mark.parametrize("text, seat", [
    # sitting said of anyone, or of the listener in a condition, places the one who looks
    ("the radio on the left when you are seated on the daybed", ("sofa",)),
    ("the speaker on the right when seated on the daybed", ("sofa",)),
    # on "it": on the thing just named
    ("the green pillow at the right end of the daybed, for somebody sitting on it", ("sofa",)),
    ("the plant on the left of the daybed while sitting on it", ("sofa",)),
    # said of the target, a place of the target
    ("the little jug sitting on the left of the dresser", ()),
    ("the kitten sitting on the settee", ()),
    # a person said to be on a seat is there; a person said to sit, on the seat a side is told from
    ("the reading light on my right when I'm on the settee", ("sofa",)),
    ("the speaker to the left of the daybed when you sit", ("sofa",)),
])
def test_a_seat_in_a_condition_or_of_anyone_is_the_viewers(text, seat):
    assert parse_query(text).viewer_at == seat


def test_looking_toward_a_thing_faces_it():
    q = parse_query("the lamp on the left as you look towards the window")
    assert (q.facing, [r.kind for r in q.relations]) == (("window",), ["left"])


def test_what_the_seated_viewer_watches_is_what_they_face():
    q = parse_query("the reading light on my right when I'm on the settee watching the television")
    assert (q.viewer_at, q.facing, [r.kind for r in q.relations]) == (("sofa",), ("tv",), ["right"])
    q = parse_query("the lamp on my left when I sit on the bed watching the telly")
    assert (q.viewer_at, q.facing) == (("bed",), ("tv",))


def test_who_did_something_is_no_landmark():
    # "by" naming the doer of a passive is no place; one naming a thing still is
    q = parse_query("the green pillow on the left of the daybed, as seen by somebody sitting on it facing the fireplace")
    assert (q.viewer_at, q.facing) == (("sofa",), ("fireplace",))
    assert [(r.kind, r.landmarks) for r in q.relations] == [("left", [("sofa",)])]
    assert _relations("the vase made by my aunt by the window") == [("near", [("window",)], "")]


@pytest.mark.parametrize("text, expected", [
    # a side word made superlative is the side, written as one word, hyphenated or apart
    ("the leftmost stool", [("left", [], "")]),
    ("the right-most jug on the shelf", [("right", [], ""), ("on", [("shelf",)], "")]),
    ("the front most stool", [("front", [], "")]),
    ("the most comfortable stool", []),
    # "further from" is "farther from"
    ("the stool further from the piano", [("farthest", [("piano",)], "")]),
])
def test_superlative_side_words_and_further(text, expected):
    assert _relations(text) == expected


def test_a_thing_placed_by_this_target_is_seen_from_the_target():
    # "there is a stool by this piano": the piano is the target, with a stool near it
    assert _relations("There is a wooden stool next to this piano.") == [("near", [("stool",)], "")]


def test_the_one_in_the_middle_of_a_stack_or_a_row(tmp_path):
    # three crates stacked in one corner, three vases in a row on a far shelf: "in the middle"
    # without "of" a room is the middle one of the target's kind, upwards as well as along
    stack = make_store(tmp_path, [
        box(1, "box", (0.5, 0.5, 0.15), (0.4, 0.4, 0.3)),
        box(2, "box", (0.5, 0.5, 0.45), (0.4, 0.4, 0.3)),
        box(3, "box", (0.5, 0.5, 0.75), (0.4, 0.4, 0.3)),
        box(4, "vase", (3.6, 3.8, 1.2), (0.1, 0.1, 0.2)),
        box(5, "vase", (3.9, 3.8, 1.2), (0.1, 0.1, 0.2)),
        box(6, "vase", (4.2, 3.8, 1.2), (0.1, 0.1, 0.2)),
        box(7, "table", (2.5, 2.0, 0.4), (1.0, 1.0, 0.8)),
    ], name="stack")
    assert spatial(stack, "pick the crate sitting in the middle")[0] == 2
    assert spatial(stack, "the vase in the middle")[0] == 5
    assert spatial(stack, "the vase nearest the middle of the bedroom")[0] == 4


# Three seats in a row along the north wall of a study: an office chair, a chair, an office chair
# (on a rug); a window beyond them, a wall lamp over the middle one; a desk with its lamp, a floor
# lamp beside it.
SEATS = [
    box(1, "office chair", (1.0, 3.5, 0.45), (0.5, 0.5, 0.9)),
    box(2, "chair", (2.0, 3.5, 0.45), (0.5, 0.5, 0.9)),
    box(3, "office chair", (3.0, 3.5, 0.45), (0.5, 0.5, 0.9)),
    box(4, "window", (3.6, 3.98, 1.5), (1.0, 0.04, 1.2)),
    box(5, "wall lamp", (2.0, 3.98, 1.8), (0.2, 0.1, 0.2)),
    box(6, "lamp", (3.2, 0.5, 0.5), (0.3, 0.3, 1.0)),
    box(7, "rug", (3.0, 3.3, 0.005), (1.2, 1.2, 0.01)),
    box(8, "desk", (4.5, 0.5, 0.375), (1.0, 0.6, 0.75)),
    box(9, "desk lamp", (4.5, 0.5, 0.95), (0.2, 0.2, 0.4)),
]


@pytest.mark.parametrize("query, best", [
    # the plain chair is second nearest to the window: the name it is asked by settles a near tie
    ("that chair closest to the window", 2),
    ("that office chair closest to the window", 3),
    # a relation one seat meets and the other does not still decides: an office chair is a chair
    ("the chair standing on the rug", 3),
    # a word the landmark supplies is no extra word: the desk lamp is as literally "the lamp" here
    ("the lamp closest to the desk", 9),
])
def test_literal_name_breaks_near_ties_only(tmp_path, query, best):
    assert spatial(make_store(tmp_path, SEATS), query)[0] == best


def _extremes(text: str) -> list[str]:
    return [r.value for r in parse_query(text).relations if r.kind == "extreme"]


def test_a_negation_ends_with_its_sentence():
    pot = parse_query("Not the big pan. The small red pot on the hob.")
    assert pot.target == ("pot",) and [(r.kind, r.negated) for r in pot.relations if r.kind != "extreme"] == [("on", False)]
    mirror = parse_query("Not that one! The round mirror over the basin.")
    assert [(r.kind, r.negated) for r in mirror.relations] == [("above", False)]


def test_the_one_after_a_leading_exclusion_has_its_own_attributes():
    # the kind comes from the excluded phrase, the colour from the one asked for
    mug = parse_query("Not the red mug by the sink, the blue one.")
    assert mug.target == ("cup",) and mug.attrs == (("color", "blue"),)


@pytest.mark.parametrize("text, kept, size", [
    # the parser heads the kept phrase with its material noun ("oak", "brass"), not with "one"
    ("Not the long black bench - the short oak one near the window.", ("material", "wood"), "short"),
    ("Never the tiny glass lamp: the big brass one beside the bed.", ("material", "metal"), "large"),
])
def test_the_one_after_a_leading_exclusion_takes_nothing_from_the_phrase_ruled_out(text, kept, size):
    query = parse_query(text)
    assert kept in query.attrs and ("size", size) in query.attrs
    assert not {("color", "black"), ("material", "glass")} & set(query.attrs)
    assert [r.value for r in query.relations if r.kind == "extreme"] == [size]


def test_the_one_before_a_later_exclusion_has_its_own_attributes():
    # the kind comes from the phrase ruled out after "not", the looks and the place from the one asked for
    kettle = parse_query("I'd like the small black one near the door, not the big white kettle.")
    assert kettle.target == ("kettle",) and set(kettle.attrs) == {("color", "black"), ("size", "small")}
    assert ("extreme", "tall") not in [(r.kind, r.value) for r in kettle.relations]


def test_a_relation_takes_no_landmark_from_past_a_negation():
    # "with a chipped rim": no thing after "with" before the exclusion, so no landmark at all
    cup = parse_query("the green one with a chipped rim, not the jar of honey")
    assert not [r for r in cup.relations if r.landmarks and not r.negated]


@pytest.mark.parametrize("text, expected", [
    ("the vase on a shelf of the hall cabinet", [("in", [("cabinet",)], "")]),
    ("the cushion on the seat of the sofa", [("in", [("sofa",)], "")]),
    ("the towel on a shelf of the bathroom", [("on", [("shelf",)], "")]),  # a room is no whole
    ("the left stool of the three stools", [("left", [], "")]),              # nor one of the same kind
])
def test_a_part_of_a_landmark_stands_for_the_landmark(text, expected):
    assert _relations(text) == expected


def test_on_a_shelf_of_a_bookcase_is_in_the_bookcase_at_that_height(tmp_path):
    store = make_store(tmp_path, [
        box(1, "bookcase", (1.0, 0.3, 1.0), (0.8, 0.3, 2.0)),
        box(2, "book", (1.0, 0.3, 1.6), (0.2, 0.15, 0.25)),   # high up in the bookcase
        box(3, "book", (0.8, 0.3, 0.4), (0.2, 0.15, 0.25)),   # low in it
        box(4, "shelf", (4.0, 3.8, 1.8), (0.8, 0.25, 0.04)),  # a wall shelf across the room, higher still
        box(5, "book", (4.0, 3.8, 1.945), (0.2, 0.15, 0.25)),  # resting on the wall shelf
    ])
    assert spatial(store, "the book on the top shelf of the bookcase")[0] == 2
    assert spatial(store, "the book on the lowest shelf of the bookcase")[0] == 3
    assert spatial(store, "the book on the wall shelf")[0] == 5


def test_a_room_said_before_a_landmark_picks_the_landmark_in_that_room(tmp_path):
    store = make_store(tmp_path, [
        {**box(1, "bookshelf", (0.3, 1.0, 0.9), (0.35, 1.0, 1.8)), "room": "living room"},
        {**box(2, "book", (0.7, 1.0, 0.1), (0.2, 0.15, 0.05)), "room": "living room"},
        {**box(3, "bookshelf", (6.3, 1.0, 0.9), (0.35, 1.0, 1.8)), "room": "office"},
        {**box(4, "book", (5.9, 1.0, 0.1), (0.2, 0.15, 0.05)), "room": "office"},
    ])
    assert spatial(store, "the book beside the office bookcase")[0] == 4
    assert spatial(store, "the book beside the living room bookcase")[0] == 2


@pytest.mark.parametrize("text, expected", [
    # a height word on the target's own noun, or the target "on top" / "at the bottom"
    ("grab the bottom drawer", ["low"]),
    ("the upper cupboard over the hob", ["high"]),
    ("the mug that sits on top", ["high"]),
    ("the crate at the bottom", ["low"]),
    # on another thing's noun, or said of what lies on the target: not the target's height
    ("the mug on the top shelf", []),
    # on a part of a landmark: where the target sits in it
    ("the box on the bottom shelf of the wardrobe", ["low"]),
    ("the vase on the top shelf of the hall cabinet", ["high"]),
    ("the dresser that has a radio resting on top", []),
    # a place on a plan ("top left") and a described top ("a marble top") are not heights
    ("the stool in the top left corner", []),
    ("the marble top table", []),
    # "high" or "low" beside "up" or "down": a height, said either way round
    ("the jar kept high up in the pantry", ["high"]),
    ("the crate stored down low by the stairs", ["low"]),
    ("a high stool", []),
])
def test_height_words(text, expected):
    assert _extremes(text) == expected


def test_a_verb_particle_is_no_place_but_a_two_word_cue_is():
    assert _relations("pick the armchair across from the sofa") == [("opposite", [("sofa",)], "")]
    assert _relations("switch off the lamp") == []


# Two boxes on a long bench; four smaller ones on the floor against its end.
BOXES = [
    box(1, "bench", (1.0, 1.0, 0.25), (2.0, 0.6, 0.5)),
    box(2, "box", (0.5, 1.0, 0.7), (0.4, 0.4, 0.4)),
    box(3, "box", (1.5, 1.0, 0.75), (0.5, 0.5, 0.5)),
    box(4, "box", (2.15, 1.0, 0.15), (0.3, 0.3, 0.3)),
    box(5, "box", (2.15, 0.5, 0.125), (0.25, 0.25, 0.25)),
    box(6, "box", (2.1, 1.5, 0.1), (0.2, 0.2, 0.2)),
    box(7, "box", (2.08, 0.75, 0.08), (0.15, 0.15, 0.15)),
]


def test_a_comparison_is_made_among_what_meets_the_contact_relations(tmp_path):
    store = make_store(tmp_path, BOXES)
    assert spatial(store, "the smaller box on the bench")[0] == 2
    assert spatial(store, "the smallest box")[0] == 7


def test_which_way_a_thing_is_turned_is_no_place():
    assert _relations("this armchair is turned to the right. it is green.") == []
    assert _relations("the stool by the sofa is facing left") == [("near", [("sofa",)], "")]
    assert _relations("the stool next to the sofa on the right") == [("near", [("sofa",)], ""), ("right", [], "")]


# A study with cabinets: two plain cabinets by the door, two filing cabinets further along.
CABINETS = [
    box(1, "file cabinet", (0.3, 2.0, 0.5), (0.5, 0.6, 1.0)),
    box(2, "file cabinet", (0.3, 3.5, 0.5), (0.5, 0.6, 1.0)),
    box(3, "cabinet", (1.5, 0.3, 0.5), (0.5, 0.4, 1.0)),
    box(5, "cabinet", (0.3, 0.8, 0.5), (0.5, 0.4, 1.0)),
    box(4, "door", (2.5, 0.02, 1.0), (0.9, 0.05, 2.0)),
]


def test_a_name_said_in_full_is_not_a_coarser_labels(tmp_path):
    store = make_store(tmp_path, CABINETS)
    # the plain cabinet is nearest the door, but the request names the file cabinets in full
    assert spatial(store, "the file cabinet nearest the door")[0] == 1
    assert spatial(store, "the cabinet nearest the door")[0] == 3


@pytest.mark.parametrize("text, target, facing", [
    # the noun after the comma is the target, the viewpoint clause's own noun where one looks from
    ("Facing the bookcase, the stool on the right.", ("stool",), ("bookshelf",)),
    ("when you face the fireplace, the armchair on the left", ("armchair",), ("fireplace",)),
    # no noun of its own after the comma: the viewpoint's kind is the target's
    ("facing the stools, the one on the left", ("stool",), ()),
    # a noun a relation takes after the comma is a landmark, not the target
    ("facing the stools, the one on the left, next to the plant", ("stool",), ()),
])
def test_the_noun_after_a_viewpoint_clause_is_the_target(text, target, facing):
    q = parse_query(text)
    assert (q.target, q.facing) == (target, facing)


@pytest.mark.parametrize("query, best", [
    ("the nightstand to the east of the bed", 3),          # compass words: x east, y north on the plan
    ("which nightstand is at the western end of the bed", 2),
    ("the southern plant", 17),
    ("the plant in the north-east", 15),
])
def test_compass_words_are_sides_on_the_plan_whoever_looks(room, query, best):
    assert spatial(room, query)[0] == best


@pytest.mark.parametrize("query, best", [
    ("the chair between those two red ones", 11),           # "ones": others of the target's kind, with their colour
    ("which chair sits between both red ones?", 11),
    ("the chair by the door, not the blue one", 10),      # an excluded "one" is no landmark
])
def test_a_one_the_relation_takes_is_another_of_the_targets_kind(room, query, best):
    assert spatial(room, query)[0] == best


@pytest.mark.parametrize("text", ["red mug beside blue one", "a red mug beside a blue one"])
def test_a_one_the_parser_hangs_as_a_number_is_still_the_landmark(text):
    # without its article "blue one" parses as an adjective with a number; it is another mug all the same
    q = parse_query(text)
    assert [(r.kind, r.landmarks, r.landmark_attrs) for r in q.relations] == [("near", [("cup",)], [(("color", "blue"),)])]


def test_a_pronoun_the_targets_relation_takes_is_the_thing_named_before(room):
    # the box cannot be under itself: "it" is the desk of the sentence before
    query = "There is a wooden desk in the bedroom. Take me to the box under it."
    assert _relations(query) == [("under", [("desk",)], "")]
    assert spatial(room, query)[0] == 7
    # said of the target, "it" stays the target: the monitor is what sits on the chair's table
    assert _relations("this is a chair. it stands next to a table. there is a monitor on it.") == [
        ("near", [("table",)], ""), ("with", [("monitor",)], "")]


def test_what_the_speaker_wants_is_the_target_after_a_sentence_that_sets_the_scene():
    vase = parse_query("There is a tall cabinet in the hall. I would like the vase standing on it.")
    assert vase.target == ("vase",) and [(r.kind, r.landmarks) for r in vase.relations] == [("on", [("cabinet",)])]
    chair = parse_query("This is a brown chair. I think it is near the door.")  # a description still comes first
    assert chair.target == ("chair",)


@pytest.mark.parametrize("text", ["lamp closest bed", "lamp closest to bed", "that lamp closest to the bed"])
def test_nearness_typed_without_articles_takes_its_noun(text):
    assert parse_query(text).target == ("lamp",) and _relations(text) == [("closest", [("bed",)], "")]


def test_one_as_a_count_of_a_noun_is_no_landmark():
    assert _relations("the desk with only one lamp on it") == [("with", [("lamp",)], "")]


def test_a_landmark_of_the_targets_own_kind_is_told_apart_by_its_attributes(tmp_path):
    # three green chairs in a row and a black one after them: only the last green one is by it;
    # sharing the landmark's name ("chair") makes no chair "by the chair" on its own
    objects = [box(i, "chair", (float(i), 1.0, 0.45), (0.45, 0.45, 0.9), tags={"color": "green"}) for i in (1, 2, 3)]
    objects.append(box(4, "chair", (4.0, 1.0, 0.45), (0.45, 0.45, 0.9), tags={"color": "black"}))
    store = make_store(tmp_path, objects)
    assert spatial(store, "the green chair beside the black one")[0] == 3
    assert spatial(store, "a green chair next to the black chair")[0] == 3


def test_the_viewer_stands_in_the_targets_own_room_not_every_room_of_its_type(tmp_path):
    # two bedrooms: the viewer looks at the near bed from the middle of its own room (looking
    # north, left is west), not from between both rooms
    objects = [box(1, "bed", (2.0, 3.0, 0.3), (1.6, 2.0, 0.6)),
               box(2, "nightstand", (0.9, 3.7, 0.3), (0.4, 0.4, 0.6)),
               box(3, "nightstand", (3.1, 3.7, 0.3), (0.4, 0.4, 0.6)),
               box(4, "wardrobe", (0.3, 0.5, 1.0), (0.6, 1.0, 2.0)),
               box(5, "bed", (10.0, 1.0, 0.3), (1.6, 2.0, 0.6), room="guest bedroom"),
               box(6, "desk", (10.0, 9.0, 0.4), (1.2, 0.6, 0.8), room="guest bedroom")]
    store = make_store(tmp_path, objects)
    assert spatial(store, "looking at the bed, I want the nightstand to my left")[0] == 2


@pytest.mark.parametrize("query, best", [
    ("seen from the sofa, the right-hand lamp", 5),       # the viewer sits on the sofa, looking into the room
    ("Sitting on the couch, which lamp is to my left?", 4),
    ("the right-hand lamp as you look from the foot of the sofa", 4),  # at its foot: facing the sofa
    ("the lamp on my left when I'm on the sofa watching the television", 4),
    ("the lamp to the right of the sofa as you sit", 5),
])
def test_the_viewer_can_sit_or_stand_at_a_landmark(tmp_path, query, best):
    lounge = [box(1, "sofa", (2.0, 0.5, 0.4), (2.0, 0.9, 0.8), room="living room"),
              box(2, "side table", (0.6, 0.5, 0.3), (0.5, 0.5, 0.6), room="living room"),
              box(3, "side table", (3.4, 0.5, 0.3), (0.5, 0.5, 0.6), room="living room"),
              box(4, "lamp", (0.6, 0.5, 0.8), (0.3, 0.3, 0.4), room="living room"),
              box(5, "lamp", (3.4, 0.5, 0.8), (0.3, 0.3, 0.4), room="living room"),
              box(6, "tv", (2.0, 4.0, 1.0), (1.2, 0.1, 0.7), room="living room")]
    assert spatial(make_store(tmp_path, lounge), query)[0] == best


# An open-plan floor: a work room and a studio (both offices to the lexicon), a kitchen corner
# with two stools and a fridge, and a dining table beside a small round garden table.
FLOOR = [
    box(1, "chair", (1.0, 1.0, 0.45), (0.5, 0.5, 0.9), room="work room", caption="A grey conference chair."),
    box(2, "chair", (2.5, 1.0, 0.45), (0.5, 0.5, 0.9), room="work room", caption="A grey conference chair."),
    box(3, "tv", (3.4, 1.0, 1.2), (0.05, 1.2, 0.7), room="work room", caption="A large display on the wall."),
    box(4, "chair", (6.0, 1.0, 0.45), (0.5, 0.5, 0.9), room="studio", caption="A black swivel office chair."),
    box(5, "monitor", (6.3, 1.0, 0.9), (0.1, 0.5, 0.4), room="studio", caption="A computer screen."),
    box(6, "stool", (1.0, 5.0, 0.4), (0.4, 0.4, 0.8), room="kitchen", caption="A tall bar stool."),
    box(7, "stool", (2.0, 5.0, 0.4), (0.4, 0.4, 0.8), room="kitchen", caption="A tall bar stool."),
    box(8, "refrigerator", (2.9, 5.0, 0.9), (0.7, 0.7, 1.8), room="kitchen"),
    box(9, "table", (6.0, 5.0, 0.38), (1.6, 0.9, 0.75), room="kitchen", caption="A long oak dining table."),
    box(10, "chair", (6.0, 5.8, 0.45), (0.5, 0.5, 0.9), room="kitchen",
        caption="A wooden chair with a green seat cushion."),
    box(11, "table", (9.0, 5.0, 0.36), (0.6, 0.6, 0.72), room="kitchen", caption="A small round garden table."),
    box(12, "chair", (9.0, 5.6, 0.45), (0.5, 0.5, 0.9), room="kitchen", caption="A folding wooden chair."),
    box(13, "pillow", (1.0, 9.0, 0.5), (0.4, 0.3, 0.2), room="kitchen", tags={"color": "green"}),
    box(14, "chair", (1.8, 9.0, 0.45), (0.5, 0.5, 0.9), room="kitchen", caption="A plain wooden chair."),
]


@pytest.fixture(scope="module")
def floor(tmp_path_factory):
    return make_store(tmp_path_factory.mktemp("floor"), FLOOR)


@pytest.mark.parametrize("query, best", [
    # a class noun ranks every kind it names; the words before it narrow them when some say them
    ("the seat nearest the fridge", 7),
    ("the bar seat closer to the fridge", 7),
    ("which seat is farthest from the fridge", 12),
    # the room as the map names it, not every room of its type
    ("the chair closest to the screen in the work room", 2),
    # a landmark named more finely than the map labels it: the one whose own words say the rest
    ("a seat at the dining table", 10),
    # a part the target's caption names satisfies "with" though a loose one lies elsewhere
    ("the seat with a green cushion", 10),
])
def test_class_nouns_rooms_and_landmarks_named_in_full(floor, query, best):
    assert spatial(floor, query)[0] == best


@pytest.mark.parametrize("text, target, kind, landmark", [
    ("that stool nearer the fridge", ("stool",), "closest", ("refrigerator",)),  # nearness without "to"
    ("lamp nearest the door", ("lamp",), "closest", ("door",)),
    ("table nearest to the sofa", ("table",), "closest", ("sofa",)),  # a noun opening a fragment is no verb
])
def test_a_word_of_nearness_takes_its_noun_directly(text, target, kind, landmark):
    q = parse_query(text)
    assert q.target == target and [(r.kind, r.landmarks) for r in q.relations] == [(kind, [landmark])]


def test_a_colour_before_a_compound_describes_the_target():
    q = parse_query("the grey conference seat by the screen")
    assert q.attrs == (("color", "gray"),) and q.modifiers == frozenset({"conference"})


@pytest.mark.parametrize("query", ["It's a chair near the door. It's the blue one.",
                                   "the blue painted chair nearest the door"])
def test_the_targets_appearance_counts_wherever_the_request_gives_it(room, query):
    # the red chair 10 is nearest the door; the appearance said in another sentence or before a
    # participle still narrows the targets to the blue chair 11
    assert spatial(room, query)[0] == 11


def test_relations_are_told_apart_by_identity_not_by_address():
    # the reader files each relation's landmarks under the relation itself; filed under id(), a relation
    # read and dropped could leave its landmarks to a later one given the same address (readings that
    # changed from run to run)
    from iesm_agent.understanding.spatial import Relation
    a, b = Relation("near"), Relation("near")
    assert len({a, b}) == 2 and {a: 1}.get(b) is None


# A study (x 0-4 m) beside a garage (x 4-6 m): three stools in the study at 0.8, 2.0 and 3.4 m along x,
# a shelf and a crate in the garage, a bookcase against the study's west wall.
TWO_ROOMS = [
    box(1, "stool", (0.8, 1.0, 0.35), (0.4, 0.4, 0.7), room="study"),
    box(2, "stool", (2.0, 1.0, 0.35), (0.4, 0.4, 0.7), room="study"),
    box(3, "stool", (3.4, 1.0, 0.35), (0.4, 0.4, 0.7), room="study"),
    box(4, "bookcase", (0.2, 2.0, 1.0), (0.4, 1.2, 2.0), room="study"),
    box(5, "shelf", (5.5, 0.5, 1.0), (0.4, 1.0, 2.0), room="garage"),
    box(6, "crate", (4.6, 2.5, 0.2), (0.5, 0.4, 0.4), room="garage"),
]


@pytest.fixture(scope="module")
def two_rooms(tmp_path_factory):
    return make_store(tmp_path_factory.mktemp("two_rooms"), TWO_ROOMS, name="two_rooms")


@pytest.mark.parametrize("query, best", [
    ("the stool nearest to the garage", 3),
    ("stool closest garage", 3),
    ("which stool is furthest from the garage?", 1),
    ("the stool on the garage side", 3),
    ("the bookcase side stool", 1),
])
def test_a_room_or_a_thing_can_be_what_the_target_is_nearest(two_rooms, query, best):
    # a room said after a word of nearness, or before "side", is a place the stool is near (the box
    # around the objects shown in it), not the room the stool is in: no stool is in the garage
    assert spatial(two_rooms, query)[0] == best


@pytest.mark.parametrize("text", ["the stool nearest to the garage", "the stool on the garage side"])
def test_a_room_the_target_is_near_is_not_its_room(text):
    assert "garage" not in analyse_query(text).rooms


def test_a_room_before_a_kind_named_with_side_is_the_targets_room():
    assert analyse_query("garage side table").rooms == {"garage": 1.0}


def test_a_class_noun_the_map_uses_as_a_label_prefers_that_label(tmp_path):
    # "bucket" is a kind of container, as the box is; both are under the table, the label says "bucket"
    store = make_store(tmp_path, [box(1, "table", (1.0, 1.0, 0.4), (1.2, 0.8, 0.8)),
                                  box(2, "box", (0.7, 1.0, 0.15), (0.3, 0.3, 0.3)),
                                  box(3, "bucket", (1.3, 1.0, 0.15), (0.3, 0.3, 0.3))])
    assert analyse_query("the bucket under the table").generic is not None
    assert spatial(store, "the bucket under the table")[0] == 3


# A cot against the north wall (y 2.0-4.0), a rug to its south; one cushion at each end of the cot.
COT_ROOM = [
    box(1, "bed", (2.0, 3.0, 0.3), (1.4, 2.0, 0.6)),
    box(2, "pillow", (2.0, 3.7, 0.65), (0.5, 0.3, 0.15)),
    box(3, "pillow", (2.3, 2.3, 0.65), (0.4, 0.4, 0.15)),
    box(4, "rug", (2.0, 0.8, 0.01), (1.5, 1.0, 0.02)),
]


@pytest.mark.parametrize("query, best", [
    ("the cushion closest to the foot of the bed", 3),
    ("the cushion nearest the head of the bed", 2),
    ("the cushion furthest from the foot of the bed", 2),
])
def test_the_foot_or_head_of_a_landmark_is_its_end_away_from_or_against_the_wall(tmp_path, query, best):
    store = make_store(tmp_path, COT_ROOM, name="cot")
    assert spatial(store, query)[0] == best


def test_a_wall_the_map_shows_says_where_the_head_is(tmp_path):
    # the same cot with a wall drawn along its south end: that end is its head, whatever the room's extent
    store = make_store(tmp_path, COT_ROOM + [box(5, "wall", (2.0, 1.95, 1.2), (3.0, 0.1, 2.4))], name="cot_wall")
    assert spatial(store, "the cushion nearest the head of the bed")[0] == 3


@pytest.mark.parametrize("query, best", [
    ("the chair in the middle of the three", 11),                  # the middle of its own kind, not of the room
    ("go to the red chair nearer the desk in the bedroom", 12),    # "nearer" tagged as a noun keeps its landmark
])
def test_relations_the_tagger_could_hide(room, query, best):
    ranked = spatial(room, query)
    assert ranked and ranked[0] == best, (query, ranked)


def test_a_colon_closes_the_viewpoint_clause_and_bare_nouns_get_their_article():
    assert parse_query("facing the bed: the nightstand on the right, not the left one").facing == ("bed",)
    assert normalise("stool closest window") == "stool closest to the window"
    assert normalise("the lamp nearest it") == "the lamp nearest to it"  # a pronoun takes no article


@pytest.mark.parametrize("method", ["mtefr", "spr"])
def test_a_contrast_leaves_one_of_the_kind_asked_for(tmp_path, method):
    # both bedside tables are wooden: "not the pine one" must not rule out the white one as well
    store = make_store(tmp_path, [
        box(1, "nightstand", (0.5, 0.5, 0.3), (0.4, 0.4, 0.6), tags={"color": "brown", "material": "pine"},
            room="guest bedroom"),
        box(2, "nightstand", (3.0, 3.0, 0.3), (0.4, 0.4, 0.6), tags={"color": "white", "material": "wood"},
            room="master bedroom"),
        box(3, "table", (2.0, 1.0, 0.4), (1.0, 1.0, 0.8), tags={"color": "black", "material": "metal"},
            room="master bedroom"),
    ])
    r = Retriever(store, provider=OfflineModel(use_embeddings=False), method=method)
    assert r.ask("the bedside table in the master bedroom, not the pine one").instance_id == 2


def test_a_landmark_of_no_kind_on_the_map_is_found_by_a_caption_naming_it(tmp_path):
    # "oven" is no label here: the range's caption names one
    store = make_store(tmp_path, [
        box(1, "stove", (0.5, 3.5, 0.45), (0.6, 0.6, 0.9), caption="A white range cooker with an oven below."),
        box(2, "chair", (0.8, 2.2, 0.45), (0.45, 0.45, 0.9)),
        box(3, "chair", (3.0, 0.5, 0.45), (0.45, 0.45, 0.9)),
    ])
    assert spatial(store, "the chair closest to the oven")[:1] == [2]
    assert spatial(store, "the chair farthest from the oven")[:1] == [3]


def test_a_back_turned_to_a_thing_places_the_viewer_by_it():
    assert parse_query("With my back to the wardrobe, take me to the lamp on the left").viewer_at == ("wardrobe",)
    assert parse_query("facing away from the desk: the chair on the right").viewer_at == ("desk",)


def test_the_room_a_target_is_named_with_bounds_a_farthest(tmp_path):
    # "the kitchen chair farthest from the stove": not a chair in another room, farther still
    store = make_store(tmp_path, [
        box(1, "stove", (0.5, 3.5, 0.45), (0.6, 0.6, 0.9), room="kitchen"),
        box(2, "chair", (1.0, 2.5, 0.45), (0.45, 0.45, 0.9), room="kitchen"),
        box(3, "chair", (2.5, 1.0, 0.45), (0.45, 0.45, 0.9), room="kitchen"),
        box(4, "chair", (8.0, 1.0, 0.45), (0.45, 0.45, 0.9), room="study"),
    ])
    assert spatial(store, "the kitchen chair farthest from the stove")[:1] == [3]


def test_between_them_is_the_middle_one_of_the_targets_kind(room):
    assert parse_query("the chair in between them").relations[0].kind == "middle"
    assert spatial(room, "not the red ones, the chair in between them")[:1] == [11]


@pytest.mark.parametrize("text", ["the chair between the remaining two", "the chair in the middle of the others"])
def test_the_others_of_its_kind_make_a_middle_one(room, text):
    assert parse_query(text).relations[0].kind == "middle"
    assert spatial(room, text)[:1] == [11]


def test_a_thing_said_to_be_absent_negates_the_relation(room):
    # both nightstands carry a lamp here; the desk carries a box under it, not on it
    assert [(r.kind, r.negated) for r in parse_query("the nightstand with no lamp on it").relations] == [("with", True)]
    assert parse_query("the chair without a cushion").relations[0].negated
    assert not parse_query("the chair with a cushion").relations[0].negated
    assert not parse_query("I want tea without boiling the kettle").relations


def test_a_place_said_by_what_people_do_there_is_a_landmark():
    above = parse_query("the shelf over where we cook").relations[0]
    assert above.kind == "above" and "stove" in above.landmarks[0]
    assert parse_query("the lamp near where the books are").relations[0].landmarks == [("book",)]


@pytest.mark.parametrize("text, own", [
    ("the kettle with the black lid on the counter", set()),     # a part's colour
    ("the lamp by the olive-green cabinet", set()),             # a landmark's
    ("the grey cushion beside an orange cushion", {"gray"}),
    ("the stool that is green", {"green"}),                      # said after the noun
])
def test_the_colours_said_of_the_target(text, own):
    assert own_colours(analyse_query(text)) == own


def test_the_spatial_expert_weighs_how_near_a_colour_looks(tmp_path):
    # two stools equally near the table, neither named white: the paler one is the white one
    objects = [box(1, "table", (2.0, 2.0, 0.4), (1.0, 1.0, 0.8)),
               box(2, "stool", (2.0, 1.2, 0.3), (0.4, 0.4, 0.6), tags={"color": "charcoal"}),
               box(3, "stool", (2.0, 2.8, 0.3), (0.4, 0.4, 0.6), tags={"color": "taupe"})]
    store = make_store(tmp_path, objects)
    assert spatial(store, "the white stool beside the table")[0] == 3
    assert spatial(store, "the black stool beside the table")[0] == 2


@pytest.mark.parametrize("method", ["mtefr", "spr"])
@pytest.mark.parametrize("asked, meant", [("primary", "master"), ("principal", "master"), ("spare", "guest")])
def test_a_room_named_by_another_word_for_its_qualifier(tmp_path, method, asked, meant):
    # the map says "master" and "guest"; a request may say "primary" or "spare" for them (the room meant
    # holds the later id: a tie between the two bedrooms would pick the other one)
    other = "guest" if meant == "master" else "master"
    store = make_store(tmp_path, [
        box(1, "wardrobe", (0.5, 0.5, 1.0), (1.2, 0.6, 2.0), room=f"{other} bedroom"),
        box(2, "wardrobe", (6.0, 3.0, 1.0), (1.2, 0.6, 2.0), room=f"{meant} bedroom"),
        box(3, "bed", (6.0, 1.0, 0.3), (1.6, 2.0, 0.6), room="master bedroom"),
    ])
    r = Retriever(store, provider=OfflineModel(use_embeddings=False), method=method)
    assert r.ask(f"take me to the wardrobe in the {asked} bedroom").instance_id == 2


@pytest.mark.parametrize("asked, meant", [("primary", "master"), ("main", "master"), ("spare", "guest")])
def test_the_spatial_expert_reads_a_room_named_by_another_word_for_its_qualifier(tmp_path, asked, meant):
    # a radio on a nightstand in each bedroom: only the room tells them apart (the room meant holds the
    # earlier ids, so a tie would not pick it)
    other = "guest" if meant == "master" else "master"
    objects = [box(1, "nightstand", (6.0, 3.0, 0.3), (0.5, 0.4, 0.6), room=f"{other} bedroom"),
               box(2, "radio", (6.0, 3.0, 0.8), (0.3, 0.3, 0.4), room=f"{other} bedroom"),
               box(3, "nightstand", (6.0, 1.0, 0.3), (0.5, 0.4, 0.6), room=f"{other} bedroom")]
    objects = [box(4, "nightstand", (0.5, 3.0, 0.3), (0.5, 0.4, 0.6), room=f"{meant} bedroom"),
               box(5, "radio", (0.5, 3.0, 0.8), (0.3, 0.3, 0.4), room=f"{meant} bedroom"),
               box(6, "nightstand", (0.5, 1.0, 0.3), (0.5, 0.4, 0.6), room=f"{meant} bedroom")] + objects
    store = make_store(tmp_path, objects)
    assert spatial(store, f"the nightstand holding the radio in the {asked} bedroom")[0] == 4


def test_a_with_phrase_naming_the_targets_own_kind_is_a_part_of_it_not_a_landmark():
    # a pane is a window's, a sofa bed the couch's own part: no second object to be beside
    assert parse_query("the kitchen window with a cracked pane").relations == []
    assert parse_query("the couch with a sofa bed in it").relations == []
    assert [r.landmarks for r in parse_query("the desk with a lamp on it").relations] == [[("lamp",)]]


def test_a_verb_of_having_said_of_the_target_relates_it_to_what_it_has():
    def read(text):
        return [(r.kind, r.landmarks, r.negated) for r in parse_query(text).relations]
    assert read("the shelf that holds a vase") == [("with", [("vase",)], False)]
    assert read("which cabinet has the toaster on top") == [("with", [("toaster",)], False)]
    assert read("the table that does not have a vase") == [("with", [("vase",)], True)]
    assert read("I have a spare key, take me to the door") == []  # the speaker's, not the target's
    # a phrase that points back says where the thing is and is read from there, as before (the armchair is
    # to the lamp's right)
    assert read("the armchair that has a lamp to its left") == [("right", [("lamp",)], False)]


def test_at_the_foot_or_head_of_a_thing_is_near_that_end_of_it():
    def read(text):
        return [(r.kind, r.landmarks, r.landmark_where) for r in parse_query(text).relations]
    assert read("the slippers at the foot of the bed") == [("near", [("bed",)], "foot")]
    assert read("the bolster at the head of the sofa") == [("near", [("sofa",)], "head")]
    # "toward" a thing or an end of it is near it
    assert read("the slippers toward the head of the bed") == [("near", [("bed",)], "head")]
    # the end said by the word before "end", and the thing's own description between
    assert read("the slippers by the bottom end of the narrow bed") == [("near", [("bed",)], "foot")]
    assert read("the bolster at the top end of the old sofa") == [("near", [("sofa",)], "head")]
    assert read("the vice at one end of the workbench") == []  # which end, nothing says
    assert read("the vice at the far end of the workbench") == []


# A kitchen (x 0-4 m) with a sink on its west wall and three stools along its counter; through the
# wall a workshop (x 4-8 m) with a workbench and one stool; a shed (x 8-10 m) with one stool.
SINK_ROOMS = [
    box(1, "sink", (0.3, 2.0, 0.9), (0.5, 0.6, 0.2), room="kitchen"),
    box(2, "stool", (1.2, 1.0, 0.35), (0.35, 0.35, 0.7), room="kitchen"),
    box(3, "stool", (2.2, 1.0, 0.35), (0.35, 0.35, 0.7), room="kitchen"),
    box(4, "stool", (3.2, 1.0, 0.35), (0.35, 0.35, 0.7), room="kitchen"),
    box(5, "stool", (6.2, 1.0, 0.35), (0.35, 0.35, 0.7), room="workshop"),
    box(6, "workbench", (6.0, 3.0, 0.45), (1.5, 0.6, 0.9), room="workshop"),
    box(7, "stool", (9.0, 1.0, 0.35), (0.35, 0.35, 0.7), room="shed"),
]


@pytest.mark.parametrize("query, best", [
    ("the stool farthest from the sink", 4),  # compared with the sink's room's stools, not the shed's
    ("the stool nearest the kitchen sink", 2),
    ("the stool farthest from the workbench", 2),  # one stool beside it: no comparison there, the home's
])
def test_nearest_and_farthest_compare_within_the_landmarks_room(tmp_path, query, best):
    store = make_store(tmp_path, SINK_ROOMS)
    assert spatial(store, query)[0] == best


def test_a_landmark_in_several_rooms_compares_the_whole_home(tmp_path):
    store = make_store(tmp_path, SINK_ROOMS + [box(8, "sink", (9.7, 3.5, 0.9), (0.4, 0.4, 0.2), room="shed")])
    assert spatial(store, "the stool farthest from a sink")[0] == 5  # two sinks: among every stool


def test_a_landmark_the_labels_lack_is_found_by_the_words_said(tmp_path):
    # no label is of the heater kind "boiler" names, but a caption says it: that instance is the landmark
    store = make_store(tmp_path, [box(1, "tank", (0.3, 2.0, 1.2), (0.5, 0.4, 0.8), caption="A wall-hung gas boiler."),
                                  box(2, "stool", (1.2, 2.0, 0.35), (0.35, 0.35, 0.7)),
                                  box(3, "stool", (3.5, 2.0, 0.35), (0.35, 0.35, 0.7))])
    assert spatial(store, "the stool nearest the boiler")[0] == 2
    assert spatial(store, "the stool nearest the kiln") == []  # named nowhere: no guess


def test_a_compass_corner_of_a_thing_is_its_side():
    # the compass word says which corner of the workbench; no corner of the room is meant
    assert _relations("the stool at the south-east corner of the workbench") == [("south-east", [("table",)], "")]


def test_the_compass_corner_of_a_table_picks_the_seat_there(tmp_path):
    # a workbench in a workshop (x 0-4 m) with a stool at each corner; a stool in the far north-west
    # corner of a study (x -4-0 m, further north-west than any of them)
    seats = [(6, 0.8, 2.7), (7, 3.2, 2.7), (8, 0.8, 1.3), (9, 3.2, 1.3)]
    store = make_store(tmp_path, [box(5, "workbench", (2.0, 2.0, 0.45), (2.0, 1.0, 0.9), room="workshop"),
                                  *(box(i, "stool", (x, y, 0.35), (0.35, 0.35, 0.7), room="workshop") for i, x, y in seats),
                                  box(10, "stool", (-3.5, 3.8, 0.35), (0.35, 0.35, 0.7), room="study")])
    assert spatial(store, "the stool at the north-west corner of the workbench")[0] == 6


def test_a_compass_side_prefers_what_lies_squarely_that_way(tmp_path):
    # two stools 1.2 m from the bench: one due north of it, one north-east
    store = make_store(tmp_path, [box(1, "workbench", (2.0, 2.0, 0.45), (1.0, 0.6, 0.9)),
                                  box(2, "stool", (2.9, 2.8, 0.35), (0.35, 0.35, 0.7)),
                                  box(3, "stool", (2.0, 3.2, 0.35), (0.35, 0.35, 0.7))])
    assert spatial(store, "the stool due north of the workbench")[0] == 3


# A yard by a shed door: bins of one kind under two names, the one nearest the door a "trash can".
BINS = [
    box(1, "door", (5.0, 2.0, 1.0), (0.05, 0.9, 2.0)),
    box(2, "trash can", (4.5, 2.0, 0.4), (0.5, 0.5, 0.8)),
    box(3, "recycling bin", (3.5, 2.2, 0.4), (0.5, 0.5, 0.8)),
    box(4, "recycling bin", (1.0, 3.5, 0.4), (0.5, 0.5, 0.8)),
    box(5, "bench", (0.5, 2.8, 0.25), (0.4, 1.2, 0.5)),
]


@pytest.mark.parametrize("query, best", [
    # the map tells one kind apart by name, and the request says that name: those only
    ("the recycling bin nearest the door", 3),
    ("the recycling bin farthest from the bench", 3),
    # the other name said: the one so named, wherever it is
    ("the trash can farthest away from the shed door", 2),
])
def test_a_kind_the_map_names_two_ways_is_ranked_by_the_name_said(tmp_path, query, best):
    assert spatial(make_store(tmp_path, BINS), query)[0] == best


def test_a_one_word_name_a_subkind_also_answers_to_only_breaks_near_ties(tmp_path):
    # an armchair is a chair: "chair" said keeps it, and the relation decides
    seats = [box(1, "door", (5.0, 2.0, 1.0), (0.05, 0.9, 2.0)), box(2, "armchair", (4.3, 2.0, 0.4), (0.8, 0.8, 0.8)),
             box(3, "chair", (1.0, 1.0, 0.45), (0.45, 0.45, 0.9))]
    assert spatial(make_store(tmp_path, seats), "the chair closest to the shed door")[0] == 2


@pytest.mark.parametrize("text, relations, facing", [
    # the target turned towards a thing: near it (an object list has no orientation to read)
    ("This is a red chair. It is facing the door.", [("near", [("door",)], False)], ()),
    ("the chair which is facing the door", [("near", [("door",)], False)], ()),
    ("the chair that is not facing the door", [("near", [("door",)], True)], ()),
    ("the blue chair facing the door", [("near", [("door",)], False)], ()),
    # the viewer's way of looking, however the parse attaches it (a side needs a viewpoint)
    ("the red chair on the left when you face the door", [("left", [], False)], ("door",)),
    ("red chair on the left, facing the door", [("left", [], False)], ("door",)),
])
def test_facing_said_of_the_target_is_a_relation_said_of_the_viewer_a_viewpoint(text, relations, facing):
    q = parse_query(text)
    assert ([(r.kind, r.landmarks, r.negated) for r in q.relations], q.facing) == (relations, facing)


def test_the_chair_turned_to_the_door_is_the_one_beside_it(room):
    assert spatial(room, "It is a chair. It is facing the door.")[0] == 10
