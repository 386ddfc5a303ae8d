"""The offline model's answers: gate scores, candidate rankings and keywords."""

from __future__ import annotations

from typing import Any, Callable

import numpy as np

from ...lexicon import load_lexicon
from ...understanding import QueryInfo, Record, Slot, analyse_query, candidate_from_line, stem
from .prompt import Prompt, focus_role

#: component weights per expert role: label, room, description, affordance, text overlap, embedding
_WEIGHTS = {
    "obj":  np.array([1.0, 0.1, 0.1, 0.3, 0.2, 0.2]),
    "room": np.array([0.6, 1.0, 0.1, 0.3, 0.2, 0.1]),
    "desc": np.array([0.5, 0.1, 1.0, 0.3, 0.3, 0.3]),
    "abs":  np.array([0.4, 0.3, 0.3, 1.0, 0.2, 0.2]),
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
#: index of each component in a candidate's row
_LABEL, _ROOM, _DESC, _AFFORD, _TEXT, _EMB = range(6)
#: a candidate is "of the asked-for kind" when its category (or function) fit reaches this share
#: of the best fit among the candidates (1.0 exact, 0.9 more specific kind: all in; 0.6 parent: out)
_TIER_SHARE = 0.75
#: within the asked-for kind, how much the graded fit still counts for experts whose focus is
#: something else (a side table is as much "a table" as a table is)
_INNER_GATE_WEIGHT = {"room": 0.25, "desc": 0.25, "abs": 0.5, "all": 0.5}
#: every component counts this much on top of the focus weights, so that ties left by the focus
#: evidence are broken by the rest of the evidence before the id decides
_TIE_BREAK = 0.02


def rank(prompt: Prompt, encoder: Callable[[], Any] | None = None) -> dict:
    """Top-kappa candidate ids. `encoder()` gives the sentence encoder (or None); it is asked
    for only when embedding similarity would count: for the roles that weigh it, when the
    query carries description words or gives the lexicon nothing to go on."""
    q = analyse_query(prompt.query)
    ids, records, comp = _candidate_matrix(q, prompt.candidate_lines)
    if not len(ids):
        return {"ranked_instance_ids": []}
    role = focus_role(prompt.focus) if prompt.focus else "all"
    weights = _WEIGHTS[role].copy()
    lexical = bool(q.targets or q.afford)
    if not lexical:  # nothing lexical to go on: lean on text overlap and embeddings
        weights[_TEXT], weights[_EMB] = max(weights[_TEXT], 0.5), max(weights[_EMB], 1.0)
    wants_embeddings = weights[_EMB] > 0.25 and (not lexical or q.attrs or q.extra)
    enc = encoder() if encoder is not None and wants_embeddings else None
    if enc is not None:
        comp = comp.copy()
        comp[:, _EMB] = _embedding_scores(enc, q.text, records)
    tier, gate_col = _tiers(q, comp)
    if gate_col is not None and role != "obj":
        weights[gate_col] = min(weights[gate_col], _INNER_GATE_WEIGHT[role])
    scores = comp @ (weights + _TIE_BREAK) + tier * 10.0
    relevant = ((comp @ weights) > 1e-9) | (tier >= 2)  # the named kind stays, whatever else it lacks
    order = np.lexsort((ids, -scores))
    ranked: list[int] = []
    for i in order:
        if len(ranked) >= prompt.kappa:
            break
        if relevant[i] and int(ids[i]) not in ranked:
            ranked.append(int(ids[i]))
    return {"ranked_instance_ids": ranked}


def _tiers(q: QueryInfo, comp: np.ndarray) -> tuple[np.ndarray, int | None]:
    """Category gating. When the query names a category, candidates of that kind rank above
    partial matches, which rank above everything else, in every expert; with no category but a
    function ("something to sit on"), the same holds for the objects that serve it."""
    if q.named:
        col = _LABEL
    elif q.afford:
        col = _AFFORD
    else:
        return np.zeros(len(comp)), None
    fit = comp[:, col]
    best = float(fit.max())
    if best < 0.3:
        return np.zeros(len(comp)), None
    return np.where(fit >= _TIER_SHARE * best, 2.0, np.where(fit > 0.0, 1.0, 0.0)), col


def _candidate_matrix(q: QueryInfo, lines: list[str]) -> tuple[np.ndarray, list[Record], np.ndarray]:
    """(ids, records, components) for the candidate lines; memoised per query on the whole block
    (the same block comes with each expert prompt) and per line (lines repeat across queries)."""
    key = ("block", "\n".join(lines))
    hit = q.memo.get(key)
    if hit is not None:
        return hit
    lex = load_lexicon()
    ids: list[int] = []
    records: list[Record] = []
    rows: list[tuple[float, ...]] = []
    seen: set[int] = set()
    for line in lines:
        parsed = candidate_from_line(line)
        if parsed is None:
            continue
        ident, record = parsed
        if ident in seen:
            continue
        seen.add(ident)
        ids.append(ident)
        records.append(record)
        rows.append(_components(lex, q, record))
    out = (np.array(ids, dtype=np.int64), records,
           np.array(rows, dtype=np.float64).reshape(len(rows), 6))
    if len(q.memo) < 4096:
        q.memo[key] = out
    return out


def _components(lex, q: QueryInfo, r: Record) -> tuple[float, ...]:
    """label, room, description, affordance, text overlap (embedding filled in later).

    Memoised per query on the parts candidates share (single concepts, rooms, attribute slots),
    so a value that recurs across candidates is scored once per query."""
    memo = q.memo
    label = afford = 0.0
    for cc, wc in r.concepts:
        key = ("c", cc)
        sims = memo.get(key)
        if sims is None:
            sims = memo[key] = _concept_fit(lex, q, cc)
        label = max(label, wc * sims[0])
        afford = max(afford, wc * sims[1])
    if label and q.head_words:  # the label literally says (part of) what the query says
        label += 0.05 * len(q.head_words & r.label_words) / len(q.head_words)
    key = ("r", r.room)
    room = memo.get(key)
    if room is None:
        room = memo[key] = max((w * lex.room_sim(qr, r.room) for qr, w in q.rooms.items()
                                if r.room is not None), default=0.0)
    desc = 0.0
    if q.slots:
        desc = sum(_slot_match(lex, q, i, r) for i in range(len(q.slots))) / len(q.slots)
    text = len(q.overlap & r.stems) / len(q.overlap) if q.overlap else 0.0
    return label, room, desc, afford, text, 0.0


def _slot_match(lex, q: QueryInfo, index: int, r: Record) -> float:
    """Best match of the query's `index`-th attribute against a candidate: the same words 1.0,
    the same words up to shade 0.9, its words in the candidate's text 0.85, the same family
    0.7-0.8, a related family 0.4; -0.5 when the candidate says the opposite and nothing matches
    ("the biggest table" against a small table)."""
    memo = q.memo
    best = 0.0
    for other in r.slots:
        key = ("s", index, other)
        sim = memo.get(key)
        if sim is None:
            sim = memo[key] = _slot_sim(lex, q.slots[index], other)
        if sim > best:
            best = sim
            if best >= 1.0:
                return 1.0
    if best < 0.85:
        key = ("w", index)
        words = memo.get(key)
        if words is None:
            words = memo[key] = frozenset(stem(w) for w in q.slots[index].base.split() if w != "like")
        if words and words <= r.stems:
            best = 0.85
    if best == 0.0:
        slot = q.slots[index]
        if any(other.kind == slot.kind and any(lex.contradicts(slot.kind, a, b) for a in slot.values
                                               for b in other.values) for other in r.slots):
            return -0.5
    return best


def _slot_sim(lex, slot: Slot, other: Slot) -> float:
    if other.kind != slot.kind:
        return 0.0
    if other.surface == slot.surface:
        return 1.0
    if other.base == slot.base:
        return 0.9
    shared = slot.values & other.values
    if shared:
        return 0.7 + 0.1 * len(shared) / len(slot.values | other.values)
    if any(lex.attr_sim(slot.kind, a, b) > 0 for a in slot.values for b in other.values):
        return 0.4
    return 0.0


def _concept_fit(lex, q: QueryInfo, cc: str) -> tuple[float, float]:
    """(category fit, function fit) of one candidate category for the query."""
    label = max((wq * lex.concept_sim(qc, cc) for qc, wq in q.targets.items()), default=0.0)
    afford = 0.0
    if q.afford:
        afford = q.afford.get(cc, 0.0)
        for parent in lex.ancestors.get(cc, ()):
            afford = max(afford, 0.8 * q.afford.get(parent, 0.0))
    return label, afford


def _embedding_scores(encoder, query: str, records: list[Record]) -> np.ndarray:
    vecs = encoder.encode([query, *(r.text or "object" for r in records)])
    sims = vecs[1:] @ vecs[0]
    return np.clip((sims - 0.15) / 0.5, 0.0, 1.0)


# -- keyword ---------------------------------------------------------------------------------
def keyword(prompt: Prompt) -> dict:
    q = analyse_query(prompt.query)
    return {"object": q.target_phrase, "room": q.room_phrase}
