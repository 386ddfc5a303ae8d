"""Which map labels a spoken category covers, by the kinship the retriever reads labels with
(`understanding.label_concepts` and the lexicon's `concept_sim`): a label covers "chair" when it
denotes a chair or a kind of chair ("armchair", "desk chair"). Accept sets of generated (o) and
(o,r) queries, look-alikes of descriptions and spatial landmarks all use it."""

from __future__ import annotations

from functools import lru_cache

from ..lexicon import load_lexicon
from ..understanding import label_concepts

#: concept similarity from which a label's category answers a request for another (0.9: a kind of it)
KIND_SIM = 0.9


@lru_cache(maxsize=65536)
def covers(category: str, label: str) -> bool:
    """True when a person asking for `category` (a spoken category, e.g. "chair") would accept an
    instance labelled `label`: the same words, or a label denoting that category or a kind of it."""
    if category == label:
        return True
    lex = load_lexicon()
    wanted = [c for c, w in label_concepts(category) if w >= 1.0]
    return any(lex.concept_sim(q, c) >= KIND_SIM for q in wanted for c, w in label_concepts(label) if w >= 1.0)
