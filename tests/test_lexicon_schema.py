"""The shipped lexicon files: each has a schema (pydantic, extra keys refused), every category
they name exists, and every phrase sits on a line of its own, so a diff of one cue is one line."""

import json
from pathlib import Path

import pytest
from pydantic import BaseModel, ConfigDict, Field

from iesm_agent.lexicon import read_data

LEXICON = Path(__file__).resolve().parent.parent / "iesm_agent" / "lexicon"
Phrase = str


class _File(BaseModel):
    model_config = ConfigDict(extra="forbid", populate_by_name=True)
    doc: str = Field(alias="_doc", min_length=1)


class Affordance(BaseModel):
    model_config = ConfigDict(extra="forbid")
    cues: list[Phrase] = Field(min_length=1)
    core: list[str] = Field(min_length=1)
    related: list[str]


class Affordances(_File):
    entries: list[Affordance] = Field(min_length=1)


class Generic(BaseModel):
    model_config = ConfigDict(extra="forbid")
    core: list[str]
    related: list[str]


class Categories(_File):
    groups: dict[str, list[Phrase]]
    parents: dict[str, list[str]]
    generic: dict[str, Generic]


class Rooms(_File):
    rooms: dict[str, list[Phrase]]
    related: list[tuple[str, str, float]]  # two rooms and how alike they are
    modifiers: list[str]
    qualifiers: list[list[str]]  # words that say which room of a type, one meaning a group


class Attributes(_File):
    colors: dict[str, list[Phrase]]
    near_colors: list[list[str]]
    shades: list[str]
    materials: dict[str, list[Phrase]]
    related_materials: list[list[str]]
    shapes: dict[str, list[Phrase]]
    sizes: dict[str, list[Phrase]]
    descriptors: dict[str, list[Phrase]]


class Language(_File):
    commands: list[Phrase]
    skip: list[str]
    boundaries: list[str]
    abstract: list[str]
    function_markers: list[str]
    collective: list[str]
    collective_strict: list[str]
    weak_heads: list[str]
    ignore: list[str]
    lemmas: dict[str, str]
    color_suffixes: list[str]
    imitation_suffixes: list[str]
    relation_cues: dict[str, list[Phrase]]
    extremes: dict[str, list[str]]
    motion_verbs: list[str]
    verb_openers: list[str]
    motion_objects: list[str]
    particles: list[str]
    path_particles: list[str]
    strandable: list[str]
    auxiliaries: list[str]
    nearness: list[str]
    use_verbs: list[str]
    places: list[str]
    exclusions: list[Phrase]
    ordinals: dict[str, list[str]]


SCHEMAS = {"affordances.json": Affordances, "categories.json": Categories, "rooms.json": Rooms,
           "attributes.json": Attributes, "language.json": Language}


def test_every_lexicon_file_has_a_schema():
    assert sorted(p.name for p in LEXICON.glob("*.json")) == sorted(SCHEMAS)


@pytest.mark.parametrize("name", sorted(SCHEMAS))
def test_a_lexicon_file_follows_its_schema_one_phrase_a_line(name):
    SCHEMAS[name].model_validate(read_data(name))
    text = (LEXICON / name).read_text(encoding="utf-8")
    assert text == json.dumps(json.loads(text), indent=2, ensure_ascii=False) + "\n"


def test_the_schema_refuses_an_unknown_key_and_an_empty_cue_list():
    with pytest.raises(ValueError):
        Affordances.model_validate({"_doc": "x", "entries": [{"cues": [], "core": ["bed"], "related": []}]})
    with pytest.raises(ValueError):
        Rooms.model_validate({"_doc": "x", "rooms": {}, "related": [], "modifiers": [], "qualifiers": [], "colour": 1})


def test_every_category_the_lexicon_names_exists():
    cats = Categories.model_validate(read_data("categories.json"))
    known = set(cats.groups)
    named = {c for e in Affordances.model_validate(read_data("affordances.json")).entries for c in e.core + e.related}
    named |= {c for g in cats.generic.values() for c in g.core + g.related}
    named |= set(cats.parents) | {p for ps in cats.parents.values() for p in ps}
    assert named - known == set()


def test_one_tokeniser_the_store_splits_what_the_lexicon_reads():
    from iesm_agent.lexicon import load_lexicon, words

    text = "The off-white L-shaped sofa's cushion / kid's room, 2nd floor"
    assert words(text) == ["the", "off", "white", "l", "shaped", "sofa", "s", "cushion", "kid", "s", "room", "2nd",
                           "floor"]
    assert [w for t in load_lexicon().tokens(text) for w in words(t)] == words(text)


def test_every_cue_word_is_a_form_the_lemmatiser_gives():
    # a noun the language table keeps plural ("jeans" stays "jeans") never reads as its singular,
    # so a cue written with the singular could never match
    from iesm_agent.lexicon import load_lexicon

    lex = load_lexicon()
    cue_words = {w for key, kinds in lex.phrases.items() if any(k == "cue" for k, _ in kinds) for w in key}
    unreachable = {w for w in cue_words if len(w) > 3 and lex.lemmas.get(w + "s") == w + "s"}
    assert unreachable == set()
