"""Synthetic suites worth benchmarking: paraphrase groups, id prefixes, abstract queries in plain
English, accept sets by the retriever's label kinship, unambiguous spatial landmarks."""

from __future__ import annotations

import json
import random
import re

import pytest

from iesm_agent.errors import IesmError
from iesm_agent.evals.generate import generate_suite
from iesm_agent.evals.purposes import PURPOSES
from iesm_agent.evals.spatial_queries import spatial_queries
from iesm_agent.evals.suite import load_suites
from iesm_agent.evals.vocab import Vocabulary
from iesm_agent.providers import FunctionModel
from iesm_agent.store import MapStore
from iesm_agent.store.importers.objects import import_objects


def _lines(path):
    return [json.loads(line) for line in path.read_text().splitlines()]


def _write_map(path, objects, scene_id="flat"):
    path.write_text(json.dumps({"scene_id": scene_id, "objects": objects}))
    return path


async def test_paraphrases_make_groups_of_distinct_wordings(tmp_path):
    out = tmp_path / "k3.jsonl"
    await generate_suite(["apartment"], out, ["o", "ard", "s"], per_type=4, seed=2, paraphrases=3)
    lines = _lines(out)
    groups: dict[str, list[dict]] = {}
    for q in lines:
        groups.setdefault(q["group"], []).append(q)
    assert len(groups) == 12 and all(len(g) == 3 for g in groups.values())
    for name, g in groups.items():
        assert [q["id"] for q in g] == [f"{name}-0", f"{name}-1", f"{name}-2"]
        assert len({q["query"].lower() for q in g}) == 3  # three wordings
        assert len({(q["type"], q["target"], tuple(q["accept"])) for q in g}) == 1  # one intent
    assert len(load_suites([out]).entries) == 36


async def test_one_wording_writes_no_group(tmp_path):
    out = tmp_path / "k1.jsonl"
    await generate_suite(["apartment"], out, ["o"], per_type=3, seed=2)
    assert [("group" in q, q["id"]) for q in _lines(out)] == [
        (False, "apartment-o-000"), (False, "apartment-o-001"), (False, "apartment-o-002")]


async def test_id_prefix_lets_suites_from_two_seeds_load_together(tmp_path):
    a, b = tmp_path / "a.jsonl", tmp_path / "b.jsonl"
    await generate_suite(["apartment"], a, ["o"], per_type=3, seed=1, paraphrases=2, id_prefix="s1-")
    await generate_suite(["apartment"], b, ["o"], per_type=3, seed=2, paraphrases=2, id_prefix="s2-")
    entries = load_suites([a, b]).entries
    assert len(entries) == 12
    assert {e.query.group.split("-")[0] for e in entries} == {"s1", "s2"}
    await generate_suite(["apartment"], b, ["o"], per_type=3, seed=2, paraphrases=2)  # no prefix: ids clash
    c = tmp_path / "c.jsonl"
    await generate_suite(["apartment"], c, ["o"], per_type=3, seed=3, paraphrases=2)
    with pytest.raises(IesmError, match="duplicate query id 'apartment-o-000-0'"):
        load_suites([b, c])


@pytest.mark.parametrize("options, message", [
    ({"paraphrases": 0}, "--paraphrases must be between 1 and 20"),
    ({"id_prefix": "a b"}, "--id-prefix must be"),
    ({"per_type": 0}, "--per-type must be at least 1"),
])
async def test_bad_generation_options_are_one_line_errors(tmp_path, options, message):
    with pytest.raises(IesmError, match=message) as info:
        await generate_suite(["apartment"], tmp_path / "x.jsonl", ["o"], **options)
    assert "\n" not in str(info.value)
    assert not (tmp_path / "x.jsonl").exists()


def test_cli_writes_groups_and_refuses_a_bad_prefix(tmp_path, capsys):
    from iesm_agent.cli import run

    out = tmp_path / "cli.jsonl"
    assert run(["gen-queries", "apartment", "--types", "od", "-n", "2", "--paraphrases", "2",
                "--id-prefix", "blind1-", "-o", str(out)]) == 0
    assert [q["group"] for q in _lines(out)] == ["blind1-apartment-od-000"] * 2 + ["blind1-apartment-od-001"] * 2
    assert run(["gen-queries", "apartment", "--id-prefix", "no spaces", "-o", str(tmp_path / "y.jsonl")]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "--id-prefix must be" in err


# an abstract query: verb, then one of three noun phrases, each with a purpose from the phrasebook
_PURPOSE = "(?:" + "|".join(sorted({re.escape(p) for ps in PURPOSES.values() for p in ps}, key=len, reverse=True)) + ")"
_ROOM = r"in the [a-z ]+?(?: area)?"
_ADJ = r"[a-z]+(?: [a-z]+)?"
_ARD = re.compile(
    rf"^(?:Find|Take me to|Navigate to|I need|Go to|Where can I find|Show me|I'm looking for) (?:"
    rf"something {_ADJ}(?: and {_ADJ})* for {_PURPOSE} {_ROOM}"
    rf"|the {_ADJ}(?: {_ADJ})* (?:object|thing) used for {_PURPOSE} {_ROOM}"
    rf"|something {_ROOM} for {_PURPOSE}, the {_ADJ}(?: {_ADJ})* one)\??$")


@pytest.mark.parametrize("seed", [0, 1])
async def test_abstract_queries_read_as_english(tmp_path, seed):
    out = tmp_path / "ard.jsonl"
    await generate_suite(["apartment"], out, ["ard"], per_type=20, seed=seed, paraphrases=2)
    lines = _lines(out)
    assert len(lines) >= 30
    for q in lines:
        assert _ARD.match(q["query"]), q["query"]
        assert " meant for " not in q["query"] and "  " not in q["query"]


def test_descriptions_keep_only_colour_and_material_words():
    vocab = Vocabulary.load()
    assert vocab.attributes({"color": "dark wood", "material": "wood and glass"}, "") == {"material": "wood"}
    assert vocab.attributes({"color": "blue and black and purple", "material": "plastic and mesh"}, "") == {
        "color": "blue and black", "material": "plastic"}
    assert vocab.attributes({"color": "light colored", "material": "durable and water resistant material"}, "") == {}
    assert vocab.attributes({"color": "black, white", "material": "paper"}, "") == {
        "color": "black and white", "material": "paper"}


def test_purposes_fall_back_to_a_more_general_category():
    vocab = Vocabulary.load()
    assert vocab.uses_of("folded chair") == list(PURPOSES["chair"])
    assert vocab.uses_of("stand") == []  # nothing to say: no abstract query


async def test_accept_sets_take_every_kind_of_the_named_category(tmp_path):
    objects = [
        {"id": 1, "label": "chair", "room": "office", "center": [1, 1, 0.45], "size": [0.5, 0.5, 0.9]},
        {"id": 2, "label": "desk chair", "room": "office", "center": [3, 1, 0.45], "size": [0.5, 0.5, 0.9]},
        {"id": 3, "label": "armchair", "room": "living room", "center": [6, 1, 0.45], "size": [0.9, 0.9, 0.9]},
        {"id": 4, "label": "sofa", "room": "living room", "center": [8, 1, 0.45], "size": [2.0, 0.9, 0.9]},
    ]
    path = _write_map(tmp_path / "flat.json", objects)
    out = tmp_path / "kin.jsonl"
    await generate_suite([str(path)], out, ["o", "or"], per_type=4, seed=0)
    accept = {(q["type"], q["target"]): q["accept"] for q in _lines(out)}
    assert accept["o", 1] == [1, 2, 3]     # "the chair": a desk chair and an armchair are chairs
    assert accept["or", 1] == [1, 2]       # "the chair in the office"
    assert accept["o", 3] == [3]           # "the armchair": a plain chair is not one
    assert accept["o", 4] == [4]


def _lamp_store(tmp_path, second):
    objects = [
        {"id": 1, "label": "chair", "center": [0.0, 0.0, 0.45], "size": [0.5, 0.5, 0.9]},
        {"id": 2, "label": "chair", "center": [6.0, 0.0, 0.45], "size": [0.5, 0.5, 0.9]},
        {"id": 3, "label": "lamp", "center": [0.5, 3.0, 0.8], "size": [0.3, 0.3, 1.6]},
        {"id": 4, "label": second, "center": [9.0, 5.0, 0.8], "size": [0.3, 0.3, 1.6]},
    ]
    return MapStore(import_objects(_write_map(tmp_path / "lamps.json", objects, "lamps")))


@pytest.mark.parametrize("seed", range(4))
def test_spatial_landmark_must_be_unambiguous(tmp_path, seed):
    def texts(second, wordings=1):
        store = _lamp_store(tmp_path, second)
        cats = [i.label for i in store.scene.instances]
        found = dict(spatial_queries(store, cats, [1, 2], 2, random.Random(seed), wordings=wordings))
        assert all(q.accept == (i,) and len(set(q.texts)) == wordings for i, q in found.items())
        return [t for q in found.values() for t in q.texts]

    # two lamps, or a lamp and a floor lamp: "the lamp" could be either, so it is never a landmark
    assert not any("lamp" in t for t in texts("lamp"))
    assert not any(re.search(r"\bthe lamp\b", t) for t in texts("floor lamp"))
    # one lamp: the chairs are told apart by it (three wordings each)
    single = texts("bookshelf", wordings=3)
    assert len(single) == 6 and any(re.search(r"\bthe lamp\b", t) for t in single)


async def test_model_paraphrases_see_earlier_wordings_and_repeats_are_rejected(tmp_path):
    prompts = []

    def writer(messages, options):
        text = messages[-1].text()
        prompts.append(text)
        category = json.loads(text.split("<target>")[1].split("</target>")[0])["category"]
        earlier = text.count("Other wordings of this same request") and len(
            text.split("write a differently worded request for the same object:\n")[1].split("\nVary")[0].splitlines())
        if earlier == 1 and "previous request was rejected" not in text:
            return json.dumps({"query": f"find the {category}"})  # repeats the first wording
        return json.dumps({"query": f"find the {category}" + " please" * earlier})

    out = tmp_path / "model.jsonl"
    result = await generate_suite(["apartment"], out, ["o"], per_type=2, seed=0, paraphrases=3,
                                  model=FunctionModel(writer))
    groups: dict[str, list[str]] = {}
    for q in _lines(out):
        groups.setdefault(q["group"], []).append(q["query"])
    assert len(groups) == 2
    for texts in groups.values():
        assert texts[0].startswith("find the ") and texts[1] == texts[0] + " please"
        assert texts[2] == texts[0] + " please please"
    assert result.rejected == 2 and result.fallbacks == 0  # one repeat per group, retried
    assert any('"find the' in p and "Other wordings" in p for p in prompts)
