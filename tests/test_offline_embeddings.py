"""The offline model weighs how close the whole request is to each candidate's text for every
request, not only for requests with words the lexicon leaves over: among candidates the reading
cannot tell apart, the one the sentence encoder finds closest comes first."""

from __future__ import annotations

import numpy as np
import pytest
from test_offline_memos import mtefr_messages

from iesm_agent.providers.offline import prompt, tasks
from iesm_agent.understanding import analyse_query


class _PointingEncoder:
    """A stand-in sentence encoder: the request and candidate texts containing `word` share one
    direction, every other text another, so similarity singles those candidates out."""

    def __init__(self, word: str, request: str):
        self.word, self.request = word, request
        self.calls = 0

    def encode(self, texts: list[str]) -> np.ndarray:
        self.calls += 1
        return np.array([[1.0, 0.0] if (t == self.request or self.word in t.lower()) else [0.0, 1.0]
                         for t in texts])


@pytest.fixture(scope="module")
def sofa_prompts(apartment_store):
    """The ranking prompts of a request the lexicon reads in full ("the sofa")."""
    readings = [prompt.read_prompt(m) for m in mtefr_messages(apartment_store, ["the sofa"])]
    return [r for r in readings if r.task == "rank"]


def test_sentence_similarity_orders_candidates_the_reading_cannot_tell_apart(sofa_prompts):
    query = analyse_query("the sofa")
    assert query.named and not query.attrs and not query.extra  # nothing left over for the lexicon
    reading = sofa_prompts[0]
    block = tasks._parse_candidates(reading.candidate_lines)
    texts = {int(i): r.text.lower() for i, r in zip(block.ids, block.records)}
    sofas = [int(i) for i, r in zip(block.ids, block.records) if any(c == "sofa" for c, w in r.concepts if w >= 1.0)]
    assert len(sofas) >= 2
    plain = tasks.rank(reading)["ranked_instance_ids"]
    lowest = max(sofas, key=plain.index)  # the sofa the lexicon ranks last
    word = next(w for w in texts[lowest].split() if len(w) > 3 and all(w not in texts[s] for s in sofas if s != lowest))
    encoder = _PointingEncoder(word, query.text)
    ranked = tasks.rank(reading, encoder=lambda: encoder)["ranked_instance_ids"]
    assert encoder.calls >= 1 and ranked[0] == lowest
