"""The offline model's answers: gate scores, candidate rankings and keywords."""

from __future__ import annotations

import numpy as np

from ...lexicon import load_lexicon
from .analysis import QueryInfo, Record, analyse_query, candidate_from_line
from .prompt import Prompt, focus_role

#: component weights per expert role: label, room, description, affordance, text overlap, embedding
_WEIGHTS = {
    "obj":  np.array([1.0, 0.1, 0.1, 0.3, 0.2, 0.2]),
    "room": np.array([0.6, 1.0, 0.1, 0.3, 0.2, 0.1]),
    "desc": np.array([0.5, 0.1, 1.0, 0.3, 0.3, 0.2]),
    "abs":  np.array([0.4, 0.3, 0.3, 1.0, 0.2, 0.6]),
    "all":  np.array([1.0, 0.6, 0.6, 0.6, 0.3, 0.3]),
}
_KNOWN_ROLES = {"obj": "obj", "object": "obj", "room": "room", "desc": "desc", "description": "desc",
                "abs": "abs", "abstract": "abs"}


# -- gate ------------------------------------------------------------------------------------
def gate(prompt: Prompt) -> dict:
    q = analyse_query(prompt.query)
    scores, hints = {}, {}
    for expert in prompt.experts:
        name = expert["name"]
        role = _KNOWN_ROLES.get(name.lower())
        if role is None:
            scores[name], hints[name] = _plugin_score(q, str(expert.get("gate_description", "")))
        else:
            scores[name], hints[name] = _role_score(q, role)
    return {"scores": scores, "hints": hints}


def _role_score(q: QueryInfo, role: str) -> tuple[int, str]:
    """0-4 per built-in expert. A named category decides (o) queries alone; once a room or
    details are given, those separate the instances of that category, so they score higher."""
    attrs = " ".join(v for _, v in q.attrs)
    n_desc = len(q.attrs) + 0.5 * min(2, len(q.extra))
    explicit_room = any(w >= 1.0 for w in q.rooms.values())
    if role == "obj":
        if q.named:
            return (3 if explicit_room or n_desc else 4), q.target_phrase or ""
        return (2 if q.generic else 1 if q.targets else 0), q.target_phrase or ""
    if role == "room":
        score = (4 if q.named and not n_desc else 3) if explicit_room else 1 if q.rooms else 0
        return score, q.room_phrase or " ".join(q.rooms)
    if role == "desc":
        if n_desc == 0:
            return 0, attrs
        if q.named:
            return 4, attrs
        return min(3 if q.afford else 4, round(1.5 + 1.5 * n_desc)), attrs
    top = [c for c, w in sorted(q.afford.items(), key=lambda kv: -kv[1]) if w >= 1.0][:4]
    if q.named:
        score = 1 if q.afford else 0
    elif q.afford:
        score = 4
    else:
        score = 2 if q.abstract else 0
    return score, ", ".join(top)


def _plugin_score(q: QueryInfo, description: str) -> tuple[int, str]:
    """An unknown expert scores by the overlap of its description with the query's words."""
    lex = load_lexicon()
    desc_words = {lex.lemma(t) for t in lex.tokens(description)}
    query_words = {lex.lemma(t) for t in lex.tokens(q.text)} - lex.words["skip"] - lex.words["boundaries"]
    kinds = {k for k, _ in q.attrs}
    hits = sorted(query_words & desc_words) + sorted(k for k in kinds if k in desc_words)
    return min(4, 2 * len(hits)), " ".join(hits)


# -- ranking ---------------------------------------------------------------------------------
def rank(prompt: Prompt, encoder=None) -> dict:
    q = analyse_query(prompt.query)
    parsed = [p for p in map(candidate_from_line, prompt.candidate_lines) if p is not None]
    if not parsed:
        return {"ranked_instance_ids": []}
    ids = np.array([i for i, _ in parsed], dtype=np.int64)
    records = [r for _, r in parsed]
    weights = _WEIGHTS[focus_role(prompt.focus) if prompt.focus else "all"].copy()
    lex = load_lexicon()
    comp = np.array([_components(lex, q, r) for r in records], dtype=np.float64)
    lexical = bool(q.targets or q.afford)
    if not lexical:  # nothing lexical to go on: lean on text overlap and embeddings
        weights[4], weights[5] = max(weights[4], 0.5), max(weights[5], 1.0)
    if encoder is not None and weights[5] > 0.25:
        comp[:, 5] = _embedding_scores(encoder, q.text, records)
    scores = comp @ weights
    order = np.lexsort((ids, -scores))
    ranked: list[int] = []
    for i in order:
        if scores[i] <= 1e-9 or len(ranked) >= prompt.kappa:
            break
        if int(ids[i]) not in ranked:
            ranked.append(int(ids[i]))
    return {"ranked_instance_ids": ranked}


def _components(lex, q: QueryInfo, r: Record) -> tuple[float, ...]:
    """label, room, description, affordance, text overlap (embedding filled in later).

    Memoised per query on the record's parts (concept tuples, room strings and attribute
    frozensets are distinct key types), so repeated values are scored once per query."""
    memo = q.memo
    cat = memo.get(r.concepts)
    if cat is None:
        cat = memo[r.concepts] = _concept_scores(lex, q, r.concepts)
    label, afford = cat
    if label and q.head_words:  # the label literally says (part of) what the query says
        label += 0.05 * len(q.head_words & r.label_words) / len(q.head_words)
    room = memo.get(r.room)
    if room is None:
        room = memo[r.room] = max((w * lex.room_sim(qr, r.room) for qr, w in q.rooms.items()
                                if r.room is not None), default=0.0)
    desc = memo.get(r.attrs)
    if desc is None:
        desc = 0.0
        for kind, value in q.attrs:
            desc += max((lex.attr_sim(kind, value, v) for k, v in r.attrs if k == kind), default=0.0)
        desc = memo[r.attrs] = desc / len(q.attrs) if q.attrs else 0.0
    text = len(q.extra & r.words) / len(q.extra) if q.extra else 0.0
    return label, room, desc, afford, text, 0.0


def _concept_scores(lex, q: QueryInfo, concepts: tuple[tuple[str, float], ...]) -> tuple[float, float]:
    label = afford = 0.0
    for cc, wc in concepts:
        for qc, wq in q.targets.items():
            label = max(label, wq * wc * lex.concept_sim(qc, cc))
        if q.afford:
            best = q.afford.get(cc, 0.0)
            for parent in lex.ancestors.get(cc, ()):
                best = max(best, 0.8 * q.afford.get(parent, 0.0))
            afford = max(afford, wc * best)
    return label, afford


def _embedding_scores(encoder, query: str, records: list[Record]) -> np.ndarray:
    vecs = encoder.encode([query, *(r.text or "object" for r in records)])
    sims = vecs[1:] @ vecs[0]
    return np.clip((sims - 0.15) / 0.5, 0.0, 1.0)


# -- keyword ---------------------------------------------------------------------------------
def keyword(prompt: Prompt) -> dict:
    q = analyse_query(prompt.query)
    return {"object": q.target_phrase, "room": q.room_phrase}
