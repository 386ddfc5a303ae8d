"""The offline model's answers: gate scores, candidate rankings and keywords."""

from __future__ import annotations

import threading
import weakref
from dataclasses import dataclass
from functools import lru_cache
from typing import Any, Callable

import numpy as np

from ...lexicon import load_lexicon
from ...understanding import QueryInfo, Record, Slot, analyse_query, candidate_from_line, ground_query, stem
from .looks import colour_nearness, own_colours
from .prompt import Prompt, focus_role

_KNOWN_ROLES = {"obj": "obj", "object": "obj", "room": "room", "desc": "desc", "description": "desc",
                "abs": "abs", "abstract": "abs"}


# -- gate ------------------------------------------------------------------------------------
def gate(prompt: Prompt) -> dict:
    q = analyse_query(prompt.query)
    on_map = _named_on_map(q, prompt.candidate_lines)
    scores, hints = {}, {}
    for expert in prompt.experts:
        name = expert["name"]
        role = _KNOWN_ROLES.get(name.lower())
        if role is None:
            scores[name], hints[name] = _plugin_score(q, str(expert.get("gate_description", "")))
        else:
            scores[name], hints[name] = _role_score(q, role, on_map)
    return {"scores": scores, "hints": hints}


#: a candidate "is" the named category when its label fits it at least this well (the category
#: itself 1.0, a more specific kind 0.9, the parent kind a coarser map labels it with 0.6)
_ON_MAP_FIT = 0.6


def _named_on_map(q: QueryInfo, lines: tuple[str, ...]) -> bool:
    """True when some candidate's label is the category the query names (or a kind of it), or
    when the prompt shows no candidates to check against; False also when the query names a room
    that holds no candidate of that category but one whose label, caption or tags say the request's
    name for it ("the wardrobe in the den" and the den's "storage unit", captioned "a tall pine
    wardrobe"): the name is then the speaker's word for what the room has. Reads the
    label fit of the scorer's candidate matrix, which the experts' prompts of the same query reuse."""
    if not q.named:
        return True
    block = _parse_candidates(lines)
    if not len(block.ids):
        return True
    comp = _candidate_matrix(q, block)
    fits, room = comp[:, _LABEL], comp[:, _ROOM]
    if any(w >= 1.0 for w in q.rooms.values()) and room.max() > 0.0:
        inside = room >= room.max()  # the candidates of the room named
        said = {stem(w) for w in q.head_words}
        if said and float(fits[inside].max()) < _ON_MAP_FIT and any(
                said <= block.records[i].stems for i in np.flatnonzero(inside)):
            return False
    return float(fits.max()) >= _ON_MAP_FIT


def _role_score(q: QueryInfo, role: str, on_map: bool = True) -> tuple[int, str]:
    """0-4 per built-in expert. A named category is the decisive evidence (4) when the map has
    it: labels are the mapper's most reliable output; a category no candidate carries is some
    evidence (2), as the request may call the object by another name. A named room (3) and
    visual details (3; other loose words are weak evidence, 1) qualify it: they order its
    instances; under the paper's fusion (kappa 2, lambda 0.765) they do not outvote it, even
    together (two experts outvote a third only with weights above 0.88 of its own).
    Without a category, the function asked for decides (abstract expert 4) when the request says
    what it wants to do; a noun modifying the target that only hints at a use ("the book with
    the gold cover") is some evidence (2). A category no candidate carries, named in a request
    that says what to do, is most often what the use is done to, not where to go: the use then
    weighs 3 against the name's 2."""
    attrs = " ".join(v for _, v in q.attrs)
    loose = q.extra - _unknown_words(q)
    n_desc = len(q.attrs) + 0.5 * min(2, len(loose))
    explicit_room = any(w >= 1.0 for w in q.rooms.values()) or bool(q.unknown_room)
    if role == "obj":
        if q.named:
            return (4 if on_map else 2), q.target_phrase or ""
        return (2 if q.generic or q.unknown_target else 1 if q.targets else 0), q.target_phrase or q.unknown_target or ""
    if role == "room":
        score = 3 if explicit_room else 1 if q.rooms else 0
        return score, q.room_phrase or q.unknown_room or " ".join(q.rooms)
    if role == "desc":  # appearance words are the evidence; other loose words only hint at it
        if not q.attrs:
            return (1 if loose else 0), attrs
        if q.named:
            return 3, attrs
        return min(3 if q.afford else 4, round(1.5 + 1.5 * n_desc)), attrs
    top = [c for c, w in sorted(q.afford.items(), key=lambda kv: -kv[1]) if w >= 1.0][:4]
    if q.named:  # a use said of a thing the map does not have ("toast some bread") is the better evidence
        score = (3 if q.purpose and not on_map else 1) if q.afford else 0
    elif q.afford:
        score = 4 if q.purpose else 2
    else:
        score = 2 if q.abstract else 0
    return score, ", ".join(top)


@lru_cache(maxsize=256)
def _description_words(description: str) -> frozenset[str]:
    """Lemmas of a plug-in expert's gate description (the same for every query: about 50 us for
    the spatial expert's, which the gate scores as a plug-in before `spatial.weigh` decides)."""
    lex = load_lexicon()
    return frozenset(lex.lemma(t) for t in lex.tokens(description))


def _unknown_words(q: QueryInfo) -> frozenset[str]:
    """Lowercase words of the query's unknown target and room phrases."""
    return frozenset(" ".join(filter(None, (q.unknown_target, q.unknown_room))).lower().split())


#: function words that say nothing about which expert fits ("in", "to", "of"); spatial and
#: comparative words ("next", "under", "left") are kept: a plug-in expert may name them
_PLUGIN_STOP = frozenset({"to", "for", "that", "which", "who", "where", "when", "i", "you", "we", "they",
                          "so", "in", "inside", "into", "within", "at", "from", "with", "of", "can",
                          "could", "used", "meant", "made", "designed", "while", "if", "and", "or", "but"})


def _plugin_score(q: QueryInfo, description: str) -> tuple[int, str]:
    """An unknown expert scores by the overlap of its description with the query's words
    (2 per shared word or attribute kind, at most 4)."""
    lex = load_lexicon()
    desc_words = _description_words(description)
    query_words = {lex.lemma(t) for t in lex.tokens(q.text)} - lex.words["skip"] - _PLUGIN_STOP
    kinds = {k for k, _ in q.attrs}
    hits = sorted(query_words & desc_words) + sorted(k for k in kinds if k in desc_words)
    return min(4, 2 * len(hits)), " ".join(hits)


# -- ranking ---------------------------------------------------------------------------------
#: index of each component in a candidate's row (_USE: filled for the abstract expert only)
_LABEL, _ROOM, _DESC, _AFFORD, _TEXT, _EMB, _KIN, _USE = range(8)
_N_COMPONENTS = 8
#: a candidate is "of the asked-for kind" when its category (or function) fit reaches this share
#: of the best fit among the candidates (1.0 exact, 0.9 more specific kind: all in; 0.6 parent: out)
_TIER_SHARE = 0.75
#: within the asked-for kind, how much the graded fit still counts for the single-pass ranker
#: (a side table is as much "a table" as a table is)
_INNER_GATE_WEIGHT = 0.5
#: every component counts this much on top of the focus evidence, so that ties left by the focus
#: evidence are broken by the rest of the evidence before the id decides
_TIE_BREAK = 0.02
#: share of the room evidence left for a room of the asked-for type whose own name lacks words the
#: request uses for it ("master bedroom" asked, "guest bedroom" on the map)
_OTHER_NAMED_ROOM = 0.9
#: what each role ranks by, in order; a later key only separates candidates the earlier ones tie
_FIRST, _SECOND = 100.0, 10.0


def rank(prompt: Prompt, encoder: Callable[[], Any] | None = None) -> dict:
    """Top-kappa candidate ids, ranked by the evidence the expert's focus line names first
    (category, room, appearance or function; every kind of evidence for a prompt without a
    focus). `encoder()` gives the sentence encoder (or None): how close the whole request is to
    each candidate's label and caption counts for every request, beside the lexicon's reading."""
    q = analyse_query(prompt.query)
    block = _parse_candidates(prompt.candidate_lines)
    if q.unknown_target or q.unknown_room:
        enc = encoder() if encoder is not None else None
        q = ground_query(q, block.rooms, block.labels, enc)
    ids, records = block.ids, block.records
    if not len(ids):
        return {"ranked_instance_ids": []}
    comp = _candidate_matrix(q, block)
    role = focus_role(prompt.focus) if prompt.focus else "all"
    lexical = bool(q.targets or q.afford)
    enc = encoder() if encoder is not None else None
    if enc is not None:
        comp = _with_embeddings(q, comp, enc, block)
    if role == "abs" and enc is not None and not q.named:
        comp = _with_uses(q, comp, enc, block)
    scores, relevant = _ROLE_SCORES[role](q, comp, lexical)
    scores = scores + _TIE_BREAK * comp.sum(axis=1)
    ruled_out = _ruled_out(q, records)
    if ruled_out.any() and not ruled_out.all():  # "not the leather one": never those
        relevant = relevant & ~ruled_out
    order = np.lexsort((ids, -scores))
    ranked: list[int] = []
    for i in order:
        if len(ranked) >= prompt.kappa:
            break
        if relevant[i] and int(ids[i]) not in ranked:
            ranked.append(int(ids[i]))
    return {"ranked_instance_ids": ranked}


def _ruled_out(q: QueryInfo, records: list[Record]) -> np.ndarray:
    """(N,) bool: candidates the query excludes: of an excluded category, or with an excluded
    attribute and none of the attributes the query asks for. A contrast leaves one of the kind
    asked for: when the excluded attributes would rule out every candidate of that kind ("the
    bedside table, not the pine one" where both are wooden), they rule out none of it."""
    out = np.zeros(len(records), dtype=bool)
    if not q.excluded_targets and not q.excluded_attrs:
        return out
    lex = load_lexicon()
    wanted = set(q.attrs)
    of_kind = np.zeros(len(records), dtype=bool)
    by_attr = np.zeros(len(records), dtype=bool)
    for k, r in enumerate(records):
        kinds = [c for c, w in r.concepts if w >= 1.0]
        of_kind[k] = any(lex.concept_sim(t, c) >= 0.9 for t, w in q.targets.items() if w >= 1.0 for c in kinds)
        if any(lex.concept_sim(x, c) >= 0.9 for x in q.excluded_targets for c in kinds) and not of_kind[k]:
            out[k] = True
        elif r.attrs & q.excluded_attrs and not r.attrs & wanted:
            by_attr[k] = True
    if of_kind.any() and not (of_kind & ~by_attr & ~out).any():
        by_attr &= ~of_kind
    return out | by_attr


def _tiers(fit: np.ndarray, min_best: float) -> np.ndarray:
    """2 where `fit` reaches _TIER_SHARE of the best fit, 1 where it is positive, 0 otherwise;
    all 0 when the best fit is below `min_best` or not positive."""
    best = float(fit.max()) if len(fit) else 0.0
    if best < min_best or best <= 0.0:
        return np.zeros(len(fit))
    return (fit > 0.0).astype(np.float64) + (fit >= _TIER_SHARE * best)  # (the second implies the first)


def _kind_tier(q: QueryInfo, comp: np.ndarray) -> np.ndarray:
    """Tiers of the asked-for kind: the named category, or with no category the objects that
    serve the function asked for; all 0 when the query asks for no kind."""
    fit = comp[:, _LABEL] if q.named else comp[:, _AFFORD] if q.afford else np.zeros(len(comp))
    return _tiers(fit, 0.3)


def _label_tier(comp: np.ndarray) -> np.ndarray:
    """Tiers of the category the query names as its target, by the labels alone (what the object
    expert reads; the function asked for is the abstract expert's evidence); all 0 when only
    other things are named (a landmark's weight, 0.35, stays under 0.5)."""
    return _tiers(comp[:, _LABEL], 0.5)


def _related_kind(q: QueryInfo, comp: np.ndarray, tier: np.ndarray) -> np.ndarray:
    """Candidates of the asked-for kind, a partial or related kind, or a kind that serves the
    same purpose (stool for chair); every candidate when the query asks for no kind."""
    if not tier.any() and not comp[:, _KIN].any():
        return np.ones(len(comp), dtype=bool)
    return (tier >= 1) | (comp[:, _KIN] > 0)


#: each role's weights of the components (a constant: building the array took about 1 us a call)
_ALL_WEIGHTS = np.array([1.0, 0.6, 0.6, 0.6, 0.3, 0.3, 0.0, 0.0])
_OBJ_WEIGHTS = {lexical: np.array([0.3, 0.6, 0.6, 0.3, 0.3, 0.3 if lexical else 1.0, 0.0, 0.0])
                for lexical in (True, False)}
_DESC_WEIGHTS = np.array([0.5, 0.1, 1.0, 0.3, 0.3, 0.3, 0.3, 0.0])
for _weights in (_ALL_WEIGHTS, _OBJ_WEIGHTS[True], _OBJ_WEIGHTS[False], _DESC_WEIGHTS):
    _weights.flags.writeable = False


def _score_all(q: QueryInfo, comp: np.ndarray, lexical: bool) -> tuple[np.ndarray, np.ndarray]:
    """No focus (single pass): the asked-for kind first, then all evidence together."""
    weights = _ALL_WEIGHTS.copy()
    if not lexical:  # nothing lexical to go on: lean on text overlap and embeddings
        weights[_TEXT], weights[_EMB] = 0.5, 1.0
    tier = _kind_tier(q, comp)
    if tier.any():
        weights[_LABEL if q.named else _AFFORD] = _INNER_GATE_WEIGHT
    evidence = comp @ weights
    return _SECOND * tier + evidence, (evidence > 1e-9) | (tier >= 2)


def _score_obj(q: QueryInfo, comp: np.ndarray, lexical: bool) -> tuple[np.ndarray, np.ndarray]:
    """Category first: the kind the request names as its target (a more specific kind counts as
    that kind; never the function asked for, which is the abstract expert's evidence); the other
    evidence (room, appearance, text, function) only orders candidates of the same tier."""
    tier = _label_tier(comp)
    evidence = comp @ _OBJ_WEIGHTS[lexical]
    return _SECOND * tier + evidence, (evidence > 1e-9) | (tier >= 2)


def _plausibility(q: QueryInfo, comp: np.ndarray, tier: np.ndarray) -> np.ndarray:
    """How plausible a candidate is for the request, whatever its room: the named kind, then
    partial and related kinds, then kinds that serve the same purpose, then text evidence."""
    return (3.0 * tier + comp[:, _LABEL] + 0.5 * comp[:, _AFFORD] + 0.5 * comp[:, _KIN]
            + 0.1 * comp[:, _DESC] + 0.2 * comp[:, _TEXT] + 0.2 * comp[:, _EMB])


def _score_room(q: QueryInfo, comp: np.ndarray, lexical: bool) -> tuple[np.ndarray, np.ndarray]:
    """Room first: plausible candidates in the room the query mentions, even when none of them
    is the named kind (then related kinds, or what serves the same purpose); then the rest by
    plausibility. Objects unrelated to the request do not count as being in the room."""
    tier = _kind_tier(q, comp)
    plausible = _plausibility(q, comp, tier)
    in_room = comp[:, _ROOM] * _related_kind(q, comp, tier)
    return _FIRST * in_room + plausible, plausible > 1e-9


def _score_desc(q: QueryInfo, comp: np.ndarray, lexical: bool) -> tuple[np.ndarray, np.ndarray]:
    """How the whole request matches each candidate's caption first (attribute slots, the
    request's words in it, sentence-embedding similarity), whatever its kind; then the asked-for
    kind, then the label's fit (a red stool before a black chair for "the red chair")."""
    tier = _kind_tier(q, comp)
    desc = comp[:, _DESC] + 0.5 * comp[:, _TEXT] + 0.5 * comp[:, _EMB]
    score = _SECOND * desc + 3.0 * tier + comp[:, _LABEL]
    return score, (comp @ _DESC_WEIGHTS > 1e-9) | (tier >= 2)


def _score_abs(q: QueryInfo, comp: np.ndarray, lexical: bool) -> tuple[np.ndarray, np.ndarray]:
    """Function and intent first: the kinds that serve the purpose the query expresses (by the
    lexicon's cue words, and at _USE_WEIGHT by the uses nearest to the request in meaning, when the
    encoder gave them; for a named category, the purpose that kind serves: chair -> sofa, stool,
    bench too), then the room and caption details to choose among them, then the label."""
    if q.named:
        fn = comp[:, _AFFORD] if q.afford else np.maximum(comp[:, _LABEL], comp[:, _KIN])
    elif q.afford or comp[:, _USE].any():
        fn = comp[:, _AFFORD] + _USE_WEIGHT * comp[:, _USE]
    else:
        fn = comp[:, _TEXT] + comp[:, _EMB]
    tier = _tiers(fn, 0.0)
    details = comp[:, _ROOM] + comp[:, _DESC] + 0.3 * comp[:, _TEXT] + 0.3 * comp[:, _EMB]
    score = _SECOND * tier + details + 0.1 * fn + 0.1 * comp[:, _LABEL]
    return score, (fn + details > 1e-9)


_ROLE_SCORES = {"obj": _score_obj, "room": _score_room, "desc": _score_desc, "abs": _score_abs, "all": _score_all}


@dataclass(frozen=True, eq=False)
class _Block:
    """A fenced candidate block as the ranking reads it, once per distinct block: its candidates
    (first occurrence of an id only, in order) and what the scorer looks up per candidate, indexed
    so that a query scores each distinct category, room and label once and gathers the rows with
    numpy (a query's gate and experts, and the queries on one map, show the same block)."""

    ids: np.ndarray                       # (N,) int64 candidate ids
    records: list[Record]                 # (N,) their lexical profiles
    rooms: list[str]                      # the rooms and labels present, as `ground_query` takes them
    labels: list[str]
    concepts: tuple[str, ...]             # (C,) the distinct categories of the candidates' labels
    pair_row: np.ndarray                  # (P,) int64 candidate row of each (candidate, category) pair
    pair_concept: np.ndarray              # (P,) int64 index into `concepts`
    pair_weight: np.ndarray               # (P,) float64 the category's weight in that label
    label_words: tuple[frozenset[str], ...]        # (L,) distinct label lemma sets
    label_words_of: np.ndarray            # (N,) int64 index into `label_words`
    room_keys: tuple[tuple[str | None, frozenset[str]], ...]  # (R,) distinct (room, room name lemmas)
    room_key_of: np.ndarray               # (N,) int64 index into `room_keys`
    slots: tuple[Slot, ...]               # (S,) the distinct attribute slots of the candidates
    slot_row: np.ndarray                  # (T,) int64 candidate row of each (candidate, slot) pair
    slot_of: np.ndarray                   # (T,) int64 index into `slots`


@lru_cache(maxsize=64)
def _parse_candidates(lines: tuple[str, ...]) -> _Block:
    """The readable candidate lines as a `_Block`, memoised by the lines (`read_prompt` gives the
    same tuple for the same block text). The records are `candidate_from_line`'s own (memoised
    there), so a hit returns the very objects a miss would."""
    parsed: list[tuple[int, Record]] = []
    seen: set[int] = set()
    for line in lines:
        one = candidate_from_line(line)
        if one is not None and one[0] not in seen:
            seen.add(one[0])
            parsed.append(one)
    records = [r for _, r in parsed]
    concepts: dict[str, int] = {}
    pairs = [(row, concepts.setdefault(c, len(concepts)), w)
             for row, r in enumerate(records) for c, w in r.concepts]
    label_words: dict[frozenset[str], int] = {}
    room_keys: dict[tuple[str | None, frozenset[str]], int] = {}
    slots: dict[Slot, int] = {}
    slot_pairs = [(row, slots.setdefault(slot, len(slots))) for row, r in enumerate(records) for slot in r.slots]
    block = _Block(
        ids=np.array([i for i, _ in parsed], dtype=np.int64), records=records,
        rooms=[r.room for r in records if r.room], labels=[r.label for r in records if r.label],
        concepts=tuple(concepts),
        pair_row=np.array([p[0] for p in pairs], dtype=np.int64),
        pair_concept=np.array([p[1] for p in pairs], dtype=np.int64),
        pair_weight=np.array([p[2] for p in pairs], dtype=np.float64),
        label_words_of=np.array([label_words.setdefault(r.label_words, len(label_words)) for r in records],
                                dtype=np.int64),
        label_words=tuple(label_words),
        room_key_of=np.array([room_keys.setdefault((r.room, r.room_words), len(room_keys)) for r in records],
                             dtype=np.int64),
        room_keys=tuple(room_keys), slots=tuple(slots),
        slot_row=np.array([p[0] for p in slot_pairs], dtype=np.int64),
        slot_of=np.array([p[1] for p in slot_pairs], dtype=np.int64))
    for array in (block.ids, block.pair_row, block.pair_concept, block.pair_weight, block.label_words_of,
                  block.room_key_of, block.slot_row, block.slot_of):
        array.flags.writeable = False  # shared by every prompt showing the block
    return block


#: per reading, the scorer's values that recur across a query's prompts (the reading itself is
#: immutable and shared: its cache lives here, dropped with the reading)
_MEMOS: "weakref.WeakKeyDictionary[QueryInfo, dict]" = weakref.WeakKeyDictionary()
_MEMOS_LOCK = threading.Lock()


def reading_memo(q: QueryInfo) -> dict:
    """The offline model's cache for reading `q` (the same dict for every prompt of one query)."""
    with _MEMOS_LOCK:
        memo = _MEMOS.get(q)
        if memo is None:
            memo = _MEMOS[q] = {}
        return memo


def _candidate_matrix(q: QueryInfo, block: _Block) -> np.ndarray:
    """(N, 7) components of the block's candidates for `q`: label, room, description,
    affordance, text overlap, embedding (0 here: see `_with_embeddings`), kin. Memoised per
    query and block (the same block comes with each expert prompt); each distinct category,
    label and room is scored once per query.

    A candidate's label, function and kin fit are the best of weight x fit over its label's
    categories (0 when none fits); a label that fits gets 0.05 x the share of the query's head
    words it says literally."""
    memo = reading_memo(q)
    key = ("block", id(block))
    hit = memo.get(key)
    if hit is not None and hit[0] is block:
        return hit[1]
    lex = load_lexicon()
    n = len(block.records)
    comp = np.zeros((n, _N_COMPONENTS), dtype=np.float64)
    if len(block.pair_row):
        fits = _concept_fits(block, _weights_key(q.targets), _weights_key(q.afford), _weights_key(q.kin))
        comp[:, [_LABEL, _AFFORD, _KIN]] = _best_over_labels(block, fits)
    if q.head_words:  # the label literally says (part of) what the query says
        said = np.array([0.05 * len(q.head_words & words) / len(q.head_words) for words in block.label_words])
        label = comp[:, _LABEL]
        comp[:, _LABEL] = np.where(label != 0.0, label + said[block.label_words_of], label)
    comp[:, _ROOM] = np.array([_room_fit(lex, q, room, words, memo) for room, words in block.room_keys],
                              dtype=np.float64).reshape(-1)[block.room_key_of]
    if q.slots:
        desc = np.zeros(n, dtype=np.float64)
        own = own_colours(q)
        for slot in q.slots:  # (in order: the sum as Python's sum of the same values)
            desc = desc + _slot_match(block, slot, slot.kind == "color" and bool(slot.values & own))
        comp[:, _DESC] = desc / len(q.slots)
    if q.overlap:
        comp[:, _TEXT] = _text_overlap(q, block.records)
    comp.flags.writeable = False  # shared by the query's gate and experts
    if len(memo) < 4096:
        memo[key] = (block, comp)
    return comp


def _best_over_labels(block: _Block, fits: np.ndarray) -> np.ndarray:
    """(N, K) per candidate of `block`, the best weight x fit over its label's categories, from
    `fits` (C, K): K fits of each of the block's distinct categories (0 where none fits)."""
    best = np.zeros((len(block.records), fits.shape[1]), dtype=np.float64)
    np.maximum.at(best, block.pair_row, block.pair_weight[:, None] * fits[block.pair_concept])
    return best


def _text_overlap(q: QueryInfo, records: list[Record]) -> list[float]:
    """Share of the request's content words each candidate's label, caption and tags say; the
    words naming a landmark do not count for a candidate whose own label says them (a kettle is no
    evidence of being beside a kettle; a caption that names one is)."""
    landmark = frozenset(stem(w) for c in q.landmarks for w in c.split())
    unnamed = q.overlap - landmark
    return [len((unnamed if landmark & _label_stems(r.label) else q.overlap) & r.stems) / len(q.overlap)
            for r in records]


@lru_cache(maxsize=4096)
def _label_stems(label: str) -> frozenset[str]:
    """Stems of a raw label's words (a map's few hundred labels recur in every query)."""
    return frozenset(stem(w) for w in label.lower().split())


def _room_fit(lex, q: QueryInfo, room: str | None, room_words: frozenset[str], memo: dict) -> float:
    """How well a candidate's room fits the rooms the query names (memoised per query)."""
    key = ("r", room, room_words)
    fit = memo.get(key)
    if fit is None:
        fit = max((w * lex.room_sim(qr, room) for qr, w in q.rooms.items() if room is not None), default=0.0)
        asked = memo.get(("asked room",))
        if asked is None:  # the words the request names its room with, once per query
            asked = memo[("asked room",)] = lex.room_name_words(q.room_phrase or "")
        same = lex.room_qualifiers  # qualifiers of one meaning compare as one word ("primary": master)
        if fit and asked and not asked <= {same.get(w, w) for w in room_words}:
            fit *= _OTHER_NAMED_ROOM  # another qualifier's room of the type (the guest one, the master asked)
        memo[key] = fit
    return fit


@lru_cache(maxsize=4096)
def _slot_match(block: _Block, slot: Slot, by_look: bool = False) -> np.ndarray:
    """(N,) read-only: the best match of an attribute the query asks for (`slot`) against each
    candidate of `block`: the same words 1.0, the same words up to shade 0.9, its words in the
    candidate's text 0.85, the same family 0.7-0.8, a related family 0.4; -0.5 when the candidate
    says the opposite and nothing matches ("the biggest table" against a small table); with
    `by_look` (a colour said of the target) the other colours by how near they look. Memoised by
    the block and the slot (queries asking for "red" on one map share it); each distinct slot of
    the block is compared once."""
    lex = load_lexicon()
    n = len(block.records)
    best = np.zeros(n, dtype=np.float64)
    if len(block.slot_row):
        sims = np.array([_slot_sim(lex, slot, other, by_look) for other in block.slots], dtype=np.float64)
        np.maximum.at(best, block.slot_row, sims[block.slot_of])
    words = frozenset(stem(w) for w in slot.base.split() if w != "like")
    if words:
        said = np.array([words <= r.stems for r in block.records], dtype=bool)
        best[(best < 0.85) & said] = 0.85
    if len(block.slot_row) and not best.all():
        opposite = np.array([other.kind == slot.kind and any(lex.contradicts(slot.kind, a, b) for a in slot.values
                                                             for b in other.values) for other in block.slots])
        against = np.zeros(n, dtype=bool)
        np.logical_or.at(against, block.slot_row, opposite[block.slot_of])
        best[(best == 0.0) & against] = -0.5
    best.flags.writeable = False
    return best


#: the largest score of a colour that is neither the one asked for nor related (a related family: 0.4-0.5)
_COLOUR_NEARNESS = 0.3


def _slot_sim(lex, slot: Slot, other: Slot, by_look: bool) -> float:
    if other.kind != slot.kind:
        return 0.0
    if other.surface == slot.surface:
        return 1.0
    if other.base == slot.base:
        return 0.9
    shared = slot.values & other.values
    if shared:
        return 0.7 + 0.1 * len(shared) / len(slot.values | other.values)
    related = any(lex.attr_sim(slot.kind, a, b) > 0 for a in slot.values for b in other.values)
    if by_look:  # not the colour asked for: how near it looks orders the related ones and the others
        nearness = colour_nearness(slot, other)  # ("white": a taupe stool before a charcoal one)
        return 0.4 + 0.1 * nearness if related else _COLOUR_NEARNESS * nearness
    return 0.4 if related else 0.0


def _weights_key(weights: dict[str, float]) -> tuple[tuple[str, float], ...]:
    """A hashable form of a query's category weights (the fits below do not depend on their order)."""
    return tuple(sorted(weights.items()))


@lru_cache(maxsize=512)
def _concept_fits(block: _Block, targets: tuple[tuple[str, float], ...], afford: tuple[tuple[str, float], ...],
                  kin: tuple[tuple[str, float], ...]) -> np.ndarray:
    """(C, 3) read-only: per category of `block`, its fit to the categories the query asks for
    (the best weight x `concept_sim`, 0 when none is asked), to the functions it asks for and to
    their functional kin (`_kind_fit`). Memoised by the block and the three weightings: queries
    asking for the same things score a map's categories once ("the recliner in the den" and "the
    grey recliner" alike); a category asked for is compared with the block's once (`_sims_to`)."""
    fits = np.zeros((len(block.concepts), 3), dtype=np.float64)
    if targets:
        fits[:, 0] = np.max([wq * _sims_to(block, qc) for qc, wq in targets], axis=0)
    fits[:, 1] = _kind_fit(block, afford)
    fits[:, 2] = _kind_fit(block, kin)
    fits.flags.writeable = False
    return fits


@lru_cache(maxsize=4096)
def _sims_to(block: _Block, asked: str) -> np.ndarray:
    """(C,) read-only: `concept_sim(asked, c)` for each category c of `block`."""
    lex = load_lexicon()
    sims = np.array([lex.concept_sim(asked, cc) for cc in block.concepts], dtype=np.float64)
    sims.flags.writeable = False
    return sims


def _kind_fit(block: _Block, weights: tuple[tuple[str, float], ...]) -> np.ndarray | float:
    """Per category of `block`, `_by_kind` of `weights` (category -> weight): from the categories
    each listed kind is, or is an ancestor of (`_kinds_in`), not from every category's ancestors."""
    if not weights:
        return 0.0
    if not all(w > 0.0 for _, w in weights):  # (the max below starts from 0: positive weights only)
        lex, asked = load_lexicon(), dict(weights)
        return np.array([_by_kind(lex, asked, cc) for cc in block.concepts], dtype=np.float64)
    fit = np.zeros(len(block.concepts), dtype=np.float64)
    kinds = _kinds_in(block)
    for kind, w in weights:
        rows = kinds.get(kind)
        if rows is not None:
            fit[rows[0]] = np.maximum(fit[rows[0]], w)
            fit[rows[1]] = np.maximum(fit[rows[1]], 0.8 * w)
    return fit


@lru_cache(maxsize=64)
def _kinds_in(block: _Block) -> dict[str, tuple[np.ndarray, np.ndarray]]:
    """Kind -> (rows of `block.concepts` that are that kind, rows that descend from it)."""
    lex = load_lexicon()
    rows: dict[str, tuple[list[int], list[int]]] = {}
    for row, cc in enumerate(block.concepts):
        rows.setdefault(cc, ([], []))[0].append(row)
        for parent in lex.ancestors.get(cc, ()):
            rows.setdefault(parent, ([], []))[1].append(row)
    return {kind: (np.array(same, dtype=np.int64), np.array(below, dtype=np.int64))
            for kind, (same, below) in rows.items()}


def _by_kind(lex, weights: dict[str, float], cc: str) -> float:
    """The weight of `cc` in `weights`, or 0.8 x that of its nearest listed ancestor."""
    if not weights:
        return 0.0
    fit = weights.get(cc, 0.0)
    for parent in lex.ancestors.get(cc, ()):
        fit = max(fit, 0.8 * weights.get(parent, 0.0))
    return fit


def _with_embeddings(q: QueryInfo, comp: np.ndarray, encoder, block: _Block) -> np.ndarray:
    """A copy of `comp` (a `_candidate_matrix`) with its embedding column filled, memoised per
    query, matrix and encoder: the experts of one query that weigh embeddings ask for the same."""
    memo = reading_memo(q)
    key = ("embeddings", id(comp), id(encoder))
    hit = memo.get(key)
    if hit is not None and hit[0] is comp and hit[1] is encoder:
        return hit[2]
    out = comp.copy()
    out[:, _EMB] = _embedding_scores(encoder, q.text, block)
    out.flags.writeable = False
    if len(memo) < 4096:
        memo[key] = (comp, encoder, out)
    return out


def _embedding_scores(encoder, query: str, block: _Block) -> np.ndarray:
    """(N,) how close `query` is to each candidate's text, from 0 (cosine 0.15 or less) to 1 (0.65)."""
    sims = _text_vectors(block, encoder) @ encoder.encode([query])[0]
    return np.clip((sims - 0.15) / 0.5, 0.0, 1.0)


@lru_cache(maxsize=16)
def _text_vectors(block: _Block, encoder) -> np.ndarray:
    """(N, dim) read-only: the encoder's rows for the block's candidate texts, gathered once per
    block (from the encoder's memo, 57 rows cost about 50 us a query); a query's gate and experts
    show one block, and on a map whose candidates are all shown every query does."""
    rows = encoder.encode([r.text or "object" for r in block.records])
    rows.flags.writeable = False
    return rows


#: a use the lexicon lists stands for the request when the encoder puts one of its phrases this
#: close (cosine, all-MiniLM-L6-v2), and every use within _USE_MARGIN of the nearest counts with it
_USE_MIN, _USE_MARGIN = 0.5, 0.05
#: the uses read by meaning count half as much as the lexicon's cue words: they reorder close
#: calls and fill a reading that found no use; they do not outweigh a core use the request names
_USE_WEIGHT = 0.5


def _with_uses(q: QueryInfo, comp: np.ndarray, encoder, block: _Block) -> np.ndarray:
    """A copy of `comp` with its _USE column filled: per candidate, how well its category serves
    the uses whose phrases the encoder finds nearest to the whole request (`_nearest_uses`), read
    by the sentence's meaning rather than by the lexicon's cue words."""
    uses = _nearest_uses(encoder, q.text)
    if not uses or not len(block.pair_row):
        return comp
    fits = np.zeros((len(block.concepts), 1), dtype=np.float64)
    fits[:, 0] = _kind_fit(block, tuple(uses.items()))
    out = comp.copy()
    out[:, [_USE]] = _best_over_labels(block, fits)
    out.flags.writeable = False
    return out


def _nearest_uses(encoder, text: str) -> dict[str, float]:
    """Category -> weight of the lexicon's uses (affordance entries) nearest to `text` by the
    encoder: each entry scores its nearest cue phrase's cosine; the entries at least _USE_MIN and
    within _USE_MARGIN of the best give their categories (core 1.0-0.8, related 0.5) times their
    score over the best. Empty when no entry is near enough."""
    vectors, entry_of = _cue_vectors(encoder)
    # einsum, not `@`: at this size BLAS wakes its thread pool, whose spinning costs a server more
    # CPU than the product itself (0.09 ms on one thread)
    sims = np.einsum("kd,d->k", vectors, encoder.encode([text])[0])
    best = np.full(len(load_lexicon().affordances), -1.0)
    np.maximum.at(best, entry_of, sims)
    top = float(best.max())
    if top < _USE_MIN:
        return {}
    uses: dict[str, float] = {}
    for index in np.flatnonzero(best >= top - _USE_MARGIN):
        for concept, weight in load_lexicon().affordances[int(index)].items():
            uses[concept] = max(uses.get(concept, 0.0), weight * float(best[index]) / top)
    return uses


@lru_cache(maxsize=4)
def _cue_vectors(encoder) -> tuple[np.ndarray, np.ndarray]:
    """(K, dim) the encoder's rows for the lexicon's K affordance cue phrases (as lemmas) and (K,)
    the entry each belongs to; embedded once per encoder (and kept in its on-disk store)."""
    cues = sorted((" ".join(key), int(value)) for key, kinds in load_lexicon().phrases.items()
                  for kind, value in kinds if kind == "cue")
    rows = np.asarray(encoder.encode([c for c, _ in cues]), np.float32)
    rows.flags.writeable = False
    return rows, np.array([i for _, i in cues], dtype=np.int64)


# -- keyword ---------------------------------------------------------------------------------
def keyword(prompt: Prompt) -> dict:
    q = analyse_query(prompt.query)
    return {"object": q.target_phrase, "room": q.room_phrase}
