"""The offline model's memos (per prompt block, per query reading, and across queries: category
fits by what is asked, the spatial expert's scenes and kind masks) never change an answer: the
MTEFR prompts of suite-like queries on the apartment map get the same replies whatever was asked
before, in another order, or with every memo emptied before each prompt."""

from __future__ import annotations

import json

import numpy as np
import pytest

from iesm_agent.providers import FunctionModel
from iesm_agent.providers.offline import OfflineModel, prompt, spatial, tasks
from iesm_agent.retrieval import Retriever
from iesm_agent.understanding import analyse_query

#: requests of several kinds: named categories, rooms, appearance, functions, relations, kin,
#: an exclusion and a word the lexicon does not know
QUERIES = ["the grey sofa in the living room", "somewhere to sleep", "the lamp next to the bed",
           "a red leather chair in the office", "the smaller of the two bookshelves",
           "something to sit on in the kitchen", "the plant that is not on the table",
           "that chair closest to the window", "a wooden table", "the thingamajig by the sofa",
           "the tallest lamp please", "where can I wash my hands", "the big sofa"]


def _forget_everything() -> None:
    for memoised in (prompt._block_lines, prompt.focus_role, tasks._parse_candidates,
                     tasks._concept_fits, tasks._sims_to, tasks._kinds_in, spatial._scene_of, spatial._of_kind,
                     spatial._concept_pairs, spatial._scene_concepts, spatial._fits_to):
        memoised.cache_clear()
    with tasks._MEMOS_LOCK:
        tasks._MEMOS.clear()


def mtefr_messages(store, queries: list[str]) -> list:
    """The messages of every model call MTEFR makes for `queries` on `store`, in order (the
    offline model answers them, without embeddings)."""
    model = OfflineModel(use_embeddings=False)
    seen: list = []

    def answer(messages, options):
        seen.append(messages)
        return json.dumps(model.answer(messages))

    retriever = Retriever(store, provider=FunctionModel(answer), method="mtefr", cache=False)
    for query in queries:
        retriever.ask(query)
    return seen


@pytest.fixture(scope="module")
def prompts(apartment_store):
    """The messages of every model call MTEFR makes for `QUERIES`, in order."""
    seen = mtefr_messages(apartment_store, QUERIES)
    assert len(seen) >= 5 * len(QUERIES)
    return seen


def test_memoised_answers_equal_answers_from_empty_memos(prompts):
    model = OfflineModel(use_embeddings=False)
    _forget_everything()
    in_order = [model.answer(m) for m in prompts]
    _forget_everything()
    backwards = [model.answer(m) for m in reversed(prompts)][::-1]
    cold = []
    for m in prompts:
        _forget_everything()
        cold.append(model.answer(m))
    assert in_order == backwards == cold
    assert any(r.get("ranked_instance_ids") for r in in_order) and any("scores" in r for r in in_order)
    spatial_ranked = [r for m, r in zip(prompts, in_order) if "Task: rank-geometry" in m[-1].text()]
    assert any(r["ranked_instance_ids"] for r in spatial_ranked)


def test_every_candidate_score_equals_its_score_from_empty_memos(prompts):
    """The candidate matrix (label, room, description, function, text, kin fits) of each ranking
    prompt, computed after every other query's, equals the one computed with nothing memoised."""
    readings = [prompt.read_prompt(m) for m in prompts]
    readings = [r for r in readings if r.task == "rank"]

    def matrices() -> list[np.ndarray]:
        return [tasks._candidate_matrix(analyse_query(r.query), tasks._parse_candidates(r.candidate_lines))
                for r in readings]

    _forget_everything()
    warm = matrices()
    cold = []
    for r in readings:
        _forget_everything()
        cold.append(tasks._candidate_matrix(analyse_query(r.query), tasks._parse_candidates(r.candidate_lines)))
    assert len(warm) >= 4 * len(QUERIES)
    assert all(np.array_equal(w, c) for w, c in zip(warm, cold))


def test_a_block_is_read_once_and_its_category_fits_are_shared_by_queries_asking_the_same(prompts):
    model = OfflineModel(use_embeddings=False)
    _forget_everything()
    for m in prompts:
        model.answer(m)
    blocks = tasks._parse_candidates.cache_info()
    # the map's candidates, with geometry when a relation brings in the spatial expert, and without
    assert blocks.currsize == 2 and blocks.hits >= len(prompts) - len(QUERIES) - 2
    fits = tasks._concept_fits.cache_info()
    assert fits.hits >= 1 and fits.misses < len(QUERIES)  # the two sofas ask for the same kinds


def test_category_fits_equal_the_per_category_loop(prompts):
    """`_concept_fits` (each asked category against the block's once, kinds from the categories
    they are or are ancestors of) equals the loop over every category of the block; so does the
    spatial expert's fit of each instance to a kind, by distinct category or per instance."""
    from iesm_agent.lexicon import load_lexicon

    lex = load_lexicon()
    readings = [prompt.read_prompt(m) for m in prompts]
    blocks = {id(b): b for b in (tasks._parse_candidates(r.candidate_lines) for r in readings)}.values()
    asked = [analyse_query(q) for q in QUERIES + ["a chair or a stool", "where do I put my coat"]]
    weightings = [(tasks._weights_key(q.targets), tasks._weights_key(q.afford), tasks._weights_key(q.kin))
                  for q in asked] + [((), (("seat", 0.0), ("table", 0.5)), (("chair", 1.0), ("furniture", 0.7)))]
    for block in blocks:
        for targets, afford, kin in weightings:
            loop = np.array([(max((w * lex.concept_sim(c, cc) for c, w in targets), default=0.0),
                              tasks._by_kind(lex, dict(afford), cc), tasks._by_kind(lex, dict(kin), cc))
                             for cc in block.concepts], dtype=np.float64).reshape(-1, 3)
            assert np.array_equal(tasks._concept_fits(block, targets, afford, kin), loop)
    scenes = [spatial._read_scene(r) for r in readings if r.task == "rank-geometry"]
    assert scenes
    kinds = sorted({c for s in scenes for concepts in s.concepts for c, _ in concepts} | set(lex.generic))
    for scene in scenes[:1]:
        for cats in [(k,) for k in kinds] + [("chair", "seat"), ()]:
            loop = np.array([max((w * max(lex.concept_sim(q, c), spatial._member(lex, q, c))
                                  for c, w in concepts for q in cats), default=0.0) for concepts in scene.concepts])
            assert np.array_equal(spatial._fit_to(scene, cats), loop)
