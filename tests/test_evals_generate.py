"""Query generation: determinism, the paper's relaxations, abstract queries that never name
their category, answerability, and model-written queries with validation and fallback."""

from __future__ import annotations

import json

import pytest

from iesm_agent.errors import IesmError
from iesm_agent.evals.generate import TYPES, generate_suite, parse_types, top_categories
from iesm_agent.evals.kinship import covers
from iesm_agent.evals.suite import load_suites
from iesm_agent.evals.vocab import Vocabulary, room_name
from iesm_agent.providers import FunctionModel


@pytest.fixture(scope="module")
def vocab():
    return Vocabulary.load()


@pytest.fixture(scope="module")
def suite(tmp_path_factory):
    import asyncio

    path = tmp_path_factory.mktemp("gen") / "suite.jsonl"
    result = asyncio.run(generate_suite(["apartment"], path, per_type=8, seed=3))
    return path, result


def _queries(path):
    return [json.loads(line) for line in path.read_text().splitlines()]


async def test_same_seed_same_file_other_seed_other_file(tmp_path, suite):
    path, _ = suite
    again, other = tmp_path / "again.jsonl", tmp_path / "other.jsonl"
    await generate_suite(["apartment"], again, per_type=8, seed=3)
    await generate_suite(["apartment"], other, per_type=8, seed=4)
    assert again.read_bytes() == path.read_bytes()
    assert other.read_bytes() != path.read_bytes()


def test_suite_is_valid_and_counts_per_type(suite, apartment_store, vocab):
    path, result = suite
    entries = load_suites([path]).entries
    assert [sum(e.query.type == t for e in entries) for t in TYPES] == [8] * 5
    assert dict(result.counts) == {("apartment", t): 8 for t in TYPES}
    top = set(top_categories(apartment_store.scene, vocab))
    assert all(vocab.spoken(apartment_store.scene.instance(e.query.target).label) in top for e in entries)


def test_accept_sets_follow_the_relaxations(suite, apartment_store, vocab):
    instances = apartment_store.scene.instances
    for q in _queries(suite[0]):
        target = apartment_store.scene.instance(q["target"])
        same = [i for i in instances if covers(vocab.spoken(target.label), i.label)]
        if q["type"] == "o":
            expected = [i.id for i in same]
        elif q["type"] == "or":
            expected = [i.id for i in same if room_name(i.room_label) == room_name(target.room_label)]
            assert room_name(target.room_label) in q["query"]
        else:
            expected = [q["target"]]
        assert sorted(q["accept"]) == sorted(expected), q


def test_abstract_queries_never_name_their_category(suite, apartment_store, vocab):
    def lemmas(text):
        return " " + " ".join(vocab.lex.lemma(t) for t in vocab.lex.tokens(text)) + " "

    ard = [q for q in _queries(suite[0]) if q["type"] == "ard"]
    assert len(ard) == 8
    for q in ard:
        target = apartment_store.scene.instance(q["target"])
        said = lemmas(q["query"])
        for term in vocab.forbidden(target.label, tuple(target.alt_labels)) | {target.label}:
            assert lemmas(term) not in said, (term, q["query"])
        assert room_name(target.room_label) in q["query"]


def test_named_category_is_detected_through_synonyms_and_inflections(vocab):
    assert vocab.names_category("find the couches in the living room", "sofa") == "couch"
    assert vocab.names_category("something for sitting in the bedroom", "bed") is None
    assert vocab.names_category("a place for showering", "shower") == "shower"
    assert vocab.names_category("the chair by the window", "armchair") == "chair"  # a more general category
    assert "cabinet" in vocab.forbidden("bookshelf", ("cabinet",))


def test_types_are_only_generated_when_answerable(tmp_path):
    import asyncio

    from iesm_agent.store.fileformat import save_map
    from iesm_agent.store.model import GridSpec, Instance, SceneMap

    scene = SceneMap(scene_id="bare", grid=GridSpec(cell_size=0.1, height=2, width=2),
                     instances=[Instance(id=1, label="chair"), Instance(id=2, label="widget", room_label="lab",
                                                                          tags={"color": "red"})])
    save_map(scene, tmp_path / "bare.iesm")
    result = asyncio.run(generate_suite([str(tmp_path / "bare.iesm")], tmp_path / "s.jsonl", per_type=5))
    # no room or description for the chair; the widget has no affordance entry
    assert dict(result.counts) == {("bare.iesm", "o"): 2, ("bare.iesm", "or"): 1, ("bare.iesm", "od"): 1,
                                   ("bare.iesm", "ord"): 1, ("bare.iesm", "ard"): 0}
    assert result.shortfalls["bare.iesm", "ard"] == 5
    assert load_suites([tmp_path / "s.jsonl"]).entries[0].query.map == "bare.iesm"


def test_parse_types_rejects_unknown():
    assert parse_types("o, ard,o") == ["o", "ard"]
    with pytest.raises(IesmError, match="unknown query type"):
        parse_types("o,xyz")


async def test_model_written_queries_are_validated_retried_and_fall_back(tmp_path, vocab, apartment_store):
    prompts = []

    def writer(messages, options):
        text = messages[-1].text()
        prompts.append(text)
        category = json.loads(text.split("<target>")[1].split("</target>")[0])["category"]
        if "Query type: ard" in text:
            return json.dumps({"query": f"take me to the {category}"})  # always names it: rejected
        return f'Sure! {{"query": "please find the {category} for me"}}'

    out = tmp_path / "model.jsonl"
    result = await generate_suite(["apartment"], out, ["o", "ard"], per_type=2, seed=0, model=FunctionModel(writer))
    queries = _queries(out)
    assert [q["query"].startswith("please find the ") for q in queries if q["type"] == "o"] == [True, True]
    ard = [q for q in queries if q["type"] == "ard"]
    assert len(ard) == 2 and result.fallbacks == 2 and result.rejected == 2 * 4
    for q in ard:  # the template fallback, which never names the category
        target = apartment_store.scene.instance(q["target"])
        assert vocab.names_category(q["query"], target.label, tuple(target.alt_labels)) is None
    retries = [p for p in prompts if "previous request was rejected" in p]
    assert len(retries) == 2 * 3 and all("Never use these words" in p for p in retries)


@pytest.mark.parametrize("label, spoken", [
    ("window /outside", "window"), ("cabinet kitchen", "kitchen cabinet"), ("Sofa", "sofa"),
    ("bed for pet", "bed for pet"), ("x/y", "x"),
])
def test_queries_name_raw_labels_as_people_do(vocab, label, spoken):
    assert vocab.spoken(label) == spoken
    assert vocab.names_category(f"take me to the {spoken}", label)
