"""Lexicon data and the raw-label / query analysis built on it."""

import pytest

from iesm_agent.lexicon import load_lexicon
from iesm_agent.understanding import analyse_query, label_concepts, room_of


@pytest.mark.parametrize("label,head", [
    ("cabinet kitchen", "cabinet"), ("window /outside", "window"), ("counter desk", "desk"),
    ("easy chair", "armchair"), ("wall tv", "tv"), ("set of towels", "towel"),
    ("washbasin counter", "vanity"), ("mirror frame", "mirror"), ("shelf cubby", "shelf"),
    ("bath sink", "sink"), ("kitchen sink", "sink"), ("folded chair", "folding chair"),
    ("bottom of stairs", "stairs"), ("bowl with sweets", "bowl"), ("Trash Cans", "trash can"),
    ("garden bench", "bench"), ("bedframe", "bed frame"), ("clothes bag", "bag"),
])
def test_raw_labels_resolve_to_their_head_category(label, head):
    concepts = dict(label_concepts(label))
    assert concepts.get(head) == 1.0, concepts


def test_alternatives_and_secondary_nouns():
    assert {c for c, w in label_concepts("stand/small table") if w == 1.0} == {"stand", "side table"}
    assert dict(label_concepts("box of paper")) == {"box": 1.0, "paper": 0.6}
    assert label_concepts("unknown") == (("object", 1.0),)
    assert label_concepts("zorblax") == ()


def test_a_label_that_opens_with_a_joining_word_is_read_not_raised():
    # a mapper's label may start with "of" or "with"; the join is the one between two words
    assert label_concepts("of mugs of cocoa")[0] == ("cup", 1.0)  # the lexicon reads a mug as a cup
    assert dict(label_concepts("with lid with handle"))


def test_category_similarity_is_directional():
    lex = load_lexicon()
    assert lex.concept_sim("chair", "armchair") > lex.concept_sim("armchair", "chair") > 0
    assert lex.concept_sim("sofa", "sofa") == 1.0 and lex.concept_sim("sofa", "refrigerator") == 0.0
    assert lex.phrase("couch") == lex.phrase("settee") == (("cat", "sofa"),)


@pytest.mark.parametrize("word,base", [("chairs", "chair"), ("shelves", "shelf"), ("sitting", "sit"),
                                       ("storing", "store"), ("cushioned", "cushioned"), ("glass", "glass"),
                                       ("batteries", "battery"), ("stairs", "stairs")])
def test_lemmas(word, base):
    assert load_lexicon().lemma(word) == base


@pytest.mark.parametrize("text,room", [("Living Room 2", "living room"), ("office1", "office"),
                                       ("restroom", "bathroom"), ("rec room", "rec room"),
                                       ("Sauna Deck", "sauna")])
def test_room_labels(text, room):
    assert room_of(text) == room


def test_query_analysis_separates_target_room_attributes_and_function():
    q = analyse_query("Please navigate to the light blue velvety easy chairs in the lounge")
    assert q.targets == {"armchair": 1.0} and q.rooms == {"living room": 1.0}
    assert ("color", "blue") in q.attrs and ("material", "velvet") in q.attrs
    q = analyse_query("a place to hang my coat")
    assert not q.named and q.afford["wardrobe"] == 1.0 and q.targets.get("clothes", 0) < 1.0
    q = analyse_query("the glass table near the window")
    assert q.targets == {"table": 1.0} and q.landmarks == {"window": 0.35} and ("material", "glass") in q.attrs
    q = analyse_query("the kitchen cabinet")
    assert q.rooms == {"kitchen": 0.5} and q.room_phrase is None


def test_lexicon_is_broad():
    lex = load_lexicon()
    cats = {v for kinds in lex.phrases.values() for k, v in kinds if k == "cat"}
    assert len(cats) > 150 and len(lex.affordances) > 50
    assert all(kind in {"cat", "gen", "room", "color", "material", "shape", "size", "desc", "cue"}
               for kinds in lex.phrases.values() for kind, _ in kinds)


def test_a_scan_tries_a_shorter_phrase_where_the_longer_one_is_refused():
    lex = load_lexicon()
    lemmas = ["coffee", "table"]
    assert [(s.start, s.end) for s in lex.scan(lemmas)] == [(0, 2)]
    refused = lex.scan(lemmas, fits=lambda start, end, kinds: end - start < 2)
    assert [(s.start, s.end) for s in refused] == [(0, 1), (1, 2)]
